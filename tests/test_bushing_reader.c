/* The .gbs reader: blocks, units converted to the model's, notices, the
 * vendor's misspellings, and each input error naming its file line or block. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"
#include "usrsub/readers/bushing_reader.h"

static const double model_mm_n_kg_s[5] = {1e-3, 1.0, 1.0, 1.0, 1.0};

static const char *header(const char *length, const char *force, const char *angle)
{
    static char text[512];
    snprintf(text, sizeof text,
             "$ test bushing\n[HEADER]\nFILE_TYPE = 'gbs'\nFILE_VERSION = '1'\nFILE_FORMAT = 'ASCII'\n"
             "[UNITS]\nLENGTH = '%s'\nANGLE = '%s'\nFORCE = '%s'\nMASS = 'kg'\nTIME = 'second'\n",
             length, angle, force);
    return text;
}

static const char *activity(const char *rows)
{
    static char text[1024];
    snprintf(text, sizeof text,
             "[DIRECTIONS]\n(ACTIVITY)\n{ formulation FX FY FZ TX TY TZ }\n%s", rows);
    return text;
}

/* Writes the pieces into a file and reads it. */
static int read_gbs(const char *name, const char *const *pieces, const double *units,
                    usrsub_bushing **b, usrsub_message *notice, int *has_notice,
                    usrsub_message *msg)
{
    char text[8192] = "";
    for (const char *const *p = pieces; *p != NULL; ++p)
        strncat(text, *p, sizeof text - strlen(text) - 1);
    usrsub_read_report report = {0};
    const int status = usrsub_bushing_read(test_write_file(name, text), units, b, &report, msg);
    *notice = report.notice;
    *has_notice = report.has_notice;
    return status;
}

#define GBS(name, units, ...)                                                                 \
    read_gbs(name, (const char *const[]){__VA_ARGS__, NULL}, units, &b, &notice, &has_notice,  \
             &msg)

static const char *const all_rows =
    "'SPLINE_STIFFNESS' 1 0 0 0 0 0\n'CONSTANT_STIFFNESS' 0 1 1 0 0 0\n"
    "'CUBIC_STIFFNESS' 0 0 0 0 0 1\n'CONSTANT_DAMPING' 1 0 1 0 0 0\n"
    "'RUBBER_DAMPING' 0 0 0 0 0 0\n'HYDROMOUNT_DAMPING' 0 0 0 0 0 0\n";

static const char *const blocks =
    "[GLOBAL]\nCOUPLING = 'cylindrical'\nEPSILON = 1.0E-6\n"
    "[SPLINE_STIFFNESS_FX]\n(SPLINE_DATA)\n{ disp force }\n-0.004 -9.2\n0 0\n0.002 3.0\n0.004 9.2\n"
    "[CONSTANT_STIFFNESS_FY]\nK = 500.0\n[CONSTANT_STIFFNESS_FZ]\nK = 2.0\n"
    "[CUBIC_STIFFNESS_TZ]\nEN = -0.3\nENS = 9000\nRN = -0.15\nRNF = -700\nO = 0\nOF = 0\nOS = 3000\n"
    "RP = 0.15\nRPF = 700\nEP = 0.3\nEPS = 9000\n"
    "[CONSTANT_DAMPING_FX]\nC = 3.0\n[CONSTANT_DAMPING_FZ]\nC = 0.5\n";

static void reads_and_converts_units(void **state)
{
    (void)state;
    usrsub_bushing *b;
    usrsub_message notice, msg;
    int has_notice;
    /* the file in m, kN and degrees; the model in mm, N and radians */
    const int status = GBS("convert.gbs", model_mm_n_kg_s, header("m", "knewton", "degree"),
                           activity(all_rows), blocks,
                           "[PRELOAD_OFFSET_SCALE]\n{ direction P Q H V }\n'FZ' 0.1 0.001 1.0 1.2\n"
                           "TZ 0.02 5.0 0.9 1.0\n");
    if (status != 0)
        fail_msg("%s", msg.text);
    assert_false(has_notice);
    assert_int_equal(b->coupling, USRSUB_CYLINDRICAL);
    assert_int_equal(b->group_size[0], 2); /* x and y are active and coupled */
    assert_int_equal(b->group_size[1], 0); /* only tz of the rotations */
    assert_close(b->epsilon[0], 1e-3, 1e-12, 0);            /* 1e-6 m */
    assert_close(b->epsilon[1], 1e-6 * M_PI / 180, 1e-12, 0); /* 1e-6 degree */
    assert_close(b->dir[1].k, 500.0, 1e-12, 0);              /* kN/m = N/mm */
    assert_close(b->dir[0].c, 3.0, 1e-12, 0);                /* kN s/m = N s/mm */
    double slope;
    /* the spline: 0.002 m, 3.0 kN -> 2 mm, 3000 N */
    assert_close(usrsub_characteristic(&b->dir[0], 2.0, &slope), 3000.0, 1e-12, 0);
    /* cubic in kN m/degree: 3000 kN m/deg at O = 3000 * 1e6 N mm / (pi/180) per rad */
    usrsub_characteristic(&b->dir[5], 0.0, &slope);
    assert_close(slope, 3000.0 * 1e6 / (M_PI / 180), 1e-12, 0);
    assert_close(b->dir[5].cubic.ep, 0.3 * M_PI / 180, 1e-12, 0);
    /* preload 0.1 kN, offset 0.001 m; torque preload 0.02 kN m, offset 5 degrees */
    assert_close(b->dir[2].preload, 100.0, 1e-12, 0);
    assert_close(b->dir[2].offset, 1.0, 1e-12, 0);
    assert_close(b->dir[2].force_scale, 1.2, 0, 0);
    assert_close(b->dir[5].preload, 20000.0, 1e-12, 0);
    assert_close(b->dir[5].offset, 5 * M_PI / 180, 1e-12, 0);
    assert_close(b->dir[5].disp_scale, 0.9, 0, 0);
    assert_true(b->uses_translation && b->uses_rotation && b->uses_velocity);
    assert_false(b->dir[3].active);
    usrsub_bushing_free(b);
}

static void without_units_values_are_used_as_they_are(void **state)
{
    (void)state;
    usrsub_bushing *b;
    usrsub_message notice, msg;
    int has_notice;
    assert_int_equal(GBS("nomodelunits.gbs", NULL, header("m", "knewton", "degree"),
                         activity(all_rows), blocks), 0);
    assert_true(has_notice);
    assert_contains(notice.text, "declares no units", "as they are");
    assert_close(b->dir[1].k, 500.0, 0, 0);
    usrsub_bushing_free(b);
    assert_int_equal(GBS("nounitsblock.gbs", model_mm_n_kg_s,
                         "[HEADER]\nFILE_TYPE = 'gbs'\n", activity(all_rows), blocks), 0);
    assert_true(has_notice);
    assert_contains(notice.text, "no [UNITS] block");
    usrsub_bushing_free(b);
}

static void case_and_vendor_misspellings(void **state)
{
    (void)state;
    usrsub_bushing *b;
    usrsub_message notice, msg;
    int has_notice;
    const int status = GBS("spelling.gbs", model_mm_n_kg_s, header("mm", "newton", "radian"),
                           "[directions]\n(activity)\n{ Formulation fx fy fz tx ty tz }\n"
                           "'cubic_siffness' 0 0 0 0 0 1\n'ruber_damping' 0 0 0 0 0 0\n",
                           "[Cubic_Siffness_TZ]\nen = -0.3\nENS = 9000\nRN = -0.15\nRNF = -700\n"
                           "O = 0\nOF = 0\nOS = 3000\nRPF = 700\nEP = 0.3\nEPS = 9000\n");
    if (status != 0)
        fail_msg("%s", msg.text);
    assert_int_equal(b->dir[5].stiffness, USRSUB_STIFFNESS_CUBIC);
    assert_close(b->dir[5].cubic.rp, 0.15, 0, 0); /* RP defaults to the middle of O..EP */
    usrsub_bushing_free(b);
}

static void errors_name_what_is_wrong(void **state)
{
    (void)state;
    usrsub_bushing *b = NULL;
    usrsub_message notice, msg;
    int has_notice;
    char h[512];
    snprintf(h, sizeof h, "%s", header("mm", "newton", "radian"));
    assert_int_equal(GBS("type.gbs", model_mm_n_kg_s, "[HEADER]\nFILE_TYPE = 'gbi'\n"), -1);
    assert_contains(msg.text, "type.gbs", "line 2", "FILE_TYPE is 'gbi'", "expected 'gbs'");
    assert_int_equal(GBS("nodirections.gbs", model_mm_n_kg_s, h), -1);
    assert_contains(msg.text, "no [DIRECTIONS] block");
    assert_int_equal(GBS("activity.gbs", model_mm_n_kg_s, h,
                         activity("'SPLINE_STIFFNESS' 1 0 2 0 0 0\n")), -1);
    assert_contains(msg.text, "line 15", "SPLINE_STIFFNESS, column FZ", "expected 0 or 1");
    assert_int_equal(GBS("two.gbs", model_mm_n_kg_s, h,
                         activity("'SPLINE_STIFFNESS' 1 0 0 0 0 0\n'CONSTANT_STIFFNESS' 1 0 0 0 0 0\n")), -1);
    assert_contains(msg.text, "FX has more than one active stiffness");
    assert_int_equal(GBS("missing.gbs", model_mm_n_kg_s, h,
                         activity("'CONSTANT_STIFFNESS' 0 0 0 1 0 0\n")), -1);
    assert_contains(msg.text, "CONSTANT_STIFFNESS active for TX", "no [CONSTANT_STIFFNESS_TX] block");
    assert_int_equal(GBS("rubber.gbs", model_mm_n_kg_s, h,
                         activity("'RUBER_DAMPING' 0 1 0 0 0 0\n")), -1);
    assert_contains(msg.text, "RUBBER_DAMPING is active for FY", "does not model");
    assert_int_equal(GBS("hydro.gbs", model_mm_n_kg_s, h,
                         activity("'HYDROMOUNT_DAMPING' 0 0 1 0 0 0\n")), -1);
    assert_contains(msg.text, "HYDROMOUNT_DAMPING is active for FZ");
    assert_int_equal(GBS("friction.gbs", model_mm_n_kg_s, h, activity(""),
                         "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\n"), -1);
    assert_contains(msg.text, "FRICTION is active", "line 16");
    assert_int_equal(GBS("unit.gbs", model_mm_n_kg_s, header("furlong", "newton", "radian")), -1);
    assert_contains(msg.text, "LENGTH = 'furlong'", "line 7");
    assert_int_equal(GBS("garbage.gbs", model_mm_n_kg_s, h, "this line means nothing\n"), -1);
    assert_contains(msg.text, "garbage.gbs' line 12", "cannot read 'this line means nothing'");
    assert_int_equal(GBS("spline.gbs", model_mm_n_kg_s, h, activity("'SPLINE_STIFFNESS' 1 0 0 0 0 0\n"),
                         "[SPLINE_STIFFNESS_FX]\n(SPLINE_DATA)\n{ disp force }\n0 0\n2 5\n1 7\n"), -1);
    assert_contains(msg.text, "line 18", "[SPLINE_STIFFNESS_FX]", "point 3", "strictly increasing");
    assert_int_equal(GBS("negative.gbs", model_mm_n_kg_s, h, activity("'CONSTANT_DAMPING' 1 0 0 0 0 0\n"),
                         "[CONSTANT_DAMPING_FX]\nC = -2\n"), -1);
    assert_contains(msg.text, "line 17", "C = -2", "must not be negative");
    assert_int_equal(GBS("notnumber.gbs", model_mm_n_kg_s, h, activity("'CONSTANT_STIFFNESS' 1 0 0 0 0 0\n"),
                         "[CONSTANT_STIFFNESS_FX]\nK = stiff\n"), -1);
    assert_contains(msg.text, "line 17", "K = 'stiff' is not a finite number");
    assert_int_equal(GBS("preload.gbs", model_mm_n_kg_s, h, activity(""),
                         "[PRELOAD_OFFSET_SCALE]\n{ direction P Q H V }\nFW 0 0 1 1\n"), -1);
    assert_contains(msg.text, "line 17", "expected a direction");
    assert_int_equal(GBS("cubic.gbs", model_mm_n_kg_s, h, activity("'CUBIC_STIFFNESS' 1 0 0 0 0 0\n"),
                         "[CUBIC_STIFFNESS_FX]\nEN = 1\nENS = 1\nRNF = 1\nO = 0\nOF = 0\nOS = 1\nRPF = 1\n"
                         "EP = 1\nEPS = 1\n"), -1);
    assert_contains(msg.text, "[CUBIC_STIFFNESS_FX]", "EN < RN < O < RP < EP");
    assert_int_equal(GBS("twice.gbs", model_mm_n_kg_s, h, "[GLOBAL]\n[GLOBAL]\n"), -1);
    assert_contains(msg.text, "line 13", "[GLOBAL] appears again (first at line 12)");
    usrsub_read_report report = {0};
    assert_int_equal(usrsub_bushing_read("/nonexistent/x.gbs", NULL, &b, &report, &msg), -1);
    assert_contains(msg.text, "cannot open '/nonexistent/x.gbs'");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reads_and_converts_units),
        cmocka_unit_test(without_units_values_are_used_as_they_are),
        cmocka_unit_test(case_and_vendor_misspellings),
        cmocka_unit_test(errors_name_what_is_wrong),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
