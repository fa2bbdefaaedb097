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
    assert_close(b->group_epsilon[0], 1e-3, 1e-12, 0);            /* 1e-6 m */
    assert_close(b->group_epsilon[1], 1e-6 * M_PI / 180, 1e-12, 0); /* 1e-6 degree */
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
    assert_contains(msg.text, "RUBBER_DAMPING active for FY", "no [RUBBER_DAMPING_FY] block");
    assert_int_equal(GBS("hydro.gbs", model_mm_n_kg_s, h,
                         activity("'HYDROMOUNT_DAMPING' 0 0 1 0 0 0\n")), -1);
    assert_contains(msg.text, "HYDROMOUNT_DAMPING is active for FZ", "not published");
    assert_int_equal(GBS("friction.gbs", model_mm_n_kg_s, h, activity(""),
                         "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\n"), -1);
    assert_contains(msg.text, "line 15", "[FRICTION] has no MU_DYNAMIC");
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

static const char *const friction_block =
    "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\nMU_DYNAMIC = 0.3\nEFFECT = 'SLIDING'\n"
    "TRANSITION_VELOCITY = 0.005\nBRISTLE_STIFFNESS = 1e5\nBRISTLE_DAMPING = 316\n"
    "SLIP_DAMPING = 2\nBALL_RADIUS = 0.01\nPRELOAD_TORQUE = 3\n";

/* The blocks with internal states (docs/interface.md §3.8), converted from a
 * file in m and N to a model in mm. */
static void reads_the_state_blocks(void **state)
{
    (void)state;
    usrsub_bushing *b = NULL;
    usrsub_message notice, msg;
    int has_notice;
    assert_int_equal(GBS("states.gbs", model_mm_n_kg_s, header("m", "newton", "radian"),
                         activity("'CONSTANT_STIFFNESS' 1 0 1 0 0 0\n'CONSTANT_DAMPING' 1 0 0 0 0 0\n"
                                  "'RUBBER_DAMPING' 0 0 1 0 0 0\n"),
                         "[CONSTANT_STIFFNESS_FX]\nK = 1e6\n[CONSTANT_STIFFNESS_FZ]\nK = 2e6\n"
                         "[CONSTANT_DAMPING_FX]\nC = 1000\n"
                         "[RUBBER_DAMPING_FZ]\nNPRELOADS = 1\n(PRELOAD_1)\nPRELOAD = 0\nR = 4\n"
                         "RMIN = 6\nK0 = 3e5\nC0 = 2000\nP0 = 1\nP1 = 0\nP2 = 2\n",
                         friction_block,
                         "[MOUNT_STIFFNESS]\n{ direction K C }\nFX 5e6 1e3\nTZ 2e3 0\n"), 0);
    assert_true(b->has_states);
    const usrsub_friction *f = &b->friction;
    assert_true(f->active);
    assert_false(f->stiction);
    assert_close(f->ball_radius, 10.0, 1e-12, 0);           /* 0.01 m */
    assert_close(f->transition_velocity, 5.0, 1e-12, 0);    /* 0.005 m/s */
    assert_close(f->bristle_stiffness, 100.0, 1e-12, 0);    /* 1e5 / m */
    assert_close(f->bristle_damping, 0.316, 1e-12, 0);      /* 316 s/m */
    assert_close(f->slip_damping, 0.002, 1e-12, 0);
    assert_close(f->preload_torque, 3000.0, 1e-12, 0);      /* 3 N m */
    assert_true(b->dir[2].rubber);
    assert_close(b->dir[2].rubber_r, 6.0, 0, 0);            /* RMIN above R */
    assert_close(b->dir[2].rubber_k, 300.0, 1e-12, 0);      /* N/m to N/mm */
    assert_close(b->dir[2].rubber_c, 2.0, 1e-12, 0);
    assert_true(b->dir[0].mount && b->dir[5].mount && !b->dir[1].mount);
    assert_close(b->dir[0].mount_k, 5000.0, 1e-12, 0);
    assert_close(b->dir[0].mount_c, 1.0, 1e-12, 0);
    assert_close(b->dir[5].mount_k, 2e6, 1e-12, 0);         /* N m/rad to N mm/rad */
    assert_close(b->dir[5].mount_c, 0.0, 0, 0);
    usrsub_bushing_free(b);

    /* switched off, each block is read as absent */
    assert_int_equal(GBS("off.gbs", model_mm_n_kg_s, header("mm", "newton", "radian"), activity(""),
                         "[FRICTION]\nACTIVE = 0\n[MOUNT_STIFFNESS]\nACTIVE = 0\n"), 0);
    assert_false(b->has_states);
    usrsub_bushing_free(b);
}

static void state_block_errors_name_the_block(void **state)
{
    (void)state;
    usrsub_bushing *b = NULL;
    usrsub_message notice, msg;
    int has_notice;
    char h[512];
    snprintf(h, sizeof h, "%s", header("mm", "newton", "radian"));
    const char *rubber_row = activity("'RUBBER_DAMPING' 1 0 0 0 0 0\n");
    static const struct {
        const char *block;
        const char *needles[3];
    } cases[] = {
        {"[RUBBER_DAMPING_FX]\nNPRELOADS = 2\n", {"NPRELOADS = 2", "[RUBBER_DAMPING_FX]", "one load case"}},
        {"[RUBBER_DAMPING_FX]\nNPRELOADS = 1\n(PRELOAD_1)\nR = 5\nK0 = 1\nC0 = 1\nK1 = 1500\n",
         {"K1 = 1500", "not published", "set it to 0"}},
        {"[RUBBER_DAMPING_FX]\nNPRELOADS = 1\n(PRELOAD_1)\nR = 5\nK0 = 1\nC0 = 1\nQ0 = 2\n",
         {"Q0 = 2", "[RUBBER_DAMPING_FX]", "set it to 1"}},
        {"[RUBBER_DAMPING_FX]\nNPRELOADS = 1\n(PRELOAD_1)\nR = 0\nK0 = 1\nC0 = 1\n",
         {"line 16", "[RUBBER_DAMPING_FX]", "R (or RMIN) > 0"}},
        {"[RUBBER_DAMPING_FX]\nNPRELOADS = 1\n(PRELOAD_1)\nR = -5\nK0 = 1\nC0 = 1\n",
         {"[RUBBER_DAMPING_FX]", "got R -5,", "RMIN 0"}},
        {"[RUBBER_DAMPING_FX]\nNPRELOADS = 1\n(PRELOAD_1)\nPRELOAD = 100\nR = 3\nK0 = 1\nC0 = 1\n",
         {"PRELOAD = 100", "multiple-preload", "set"}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        assert_int_equal(GBS("rubber_error.gbs", model_mm_n_kg_s, h, rubber_row, cases[k].block), -1);
        assert_contains(msg.text, cases[k].needles[0], cases[k].needles[1], cases[k].needles[2]);
    }
    assert_int_equal(GBS("both.gbs", model_mm_n_kg_s, h,
                         activity("'CONSTANT_DAMPING' 1 0 0 0 0 0\n'RUBBER_DAMPING' 1 0 0 0 0 0\n")), -1);
    assert_contains(msg.text, "FX has more than one active damping");
    assert_int_equal(GBS("row.gbs", model_mm_n_kg_s, h, activity("'FRICTION' 0 0 0 1 0 0\n")), -1);
    assert_contains(msg.text, "line 15", "ACTIVE = 1 in its [FRICTION] block");
    assert_int_equal(GBS("mu.gbs", model_mm_n_kg_s, h, activity(""),
                         "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.3\nMU_DYNAMIC = 0.5\n"), -1);
    assert_contains(msg.text, "line 18", "MU_DYNAMIC = 0.5", "at most the static coefficient");
    assert_int_equal(GBS("reaction.gbs", model_mm_n_kg_s, h, activity(""), friction_block,
                         "USE_REACTION_FORCE = 0\n"), -1);
    assert_contains(msg.text, "USE_REACTION_FORCE = 0", "normal force");
    assert_int_equal(GBS("effect.gbs", model_mm_n_kg_s, h, activity(""), friction_block,
                         "ANALYSIS_MODES = 'STATICS'\n"), -1);
    assert_contains(msg.text, "ANALYSIS_MODES = 'STATICS'", "[FRICTION]", "DYNAMICS_ONLY");
    assert_int_equal(GBS("mount.gbs", model_mm_n_kg_s, h, activity(""),
                         "[MOUNT_STIFFNESS]\n{ direction K C }\nFX 100 1\nFX 200 0\n"), -1);
    assert_contains(msg.text, "line 18", "FX appears twice in MOUNT_STIFFNESS");
    assert_int_equal(GBS("mount_k.gbs", model_mm_n_kg_s, h, activity(""),
                         "[MOUNT_STIFFNESS]\n{ direction K C }\nTY 0 1\n"), -1);
    assert_contains(msg.text, "line 17", "mount of TY needs K > 0");
    assert_int_equal(GBS("mount_table.gbs", model_mm_n_kg_s, h, activity(""),
                         "[MOUNT_STIFFNESS]\nK = 100\n"), -1);
    assert_contains(msg.text, "line 15", "no { direction K C } table");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reads_the_state_blocks),
        cmocka_unit_test(state_block_errors_name_the_block),
        cmocka_unit_test(reads_and_converts_units),
        cmocka_unit_test(without_units_values_are_used_as_they_are),
        cmocka_unit_test(case_and_vendor_misspellings),
        cmocka_unit_test(errors_name_what_is_wrong),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
