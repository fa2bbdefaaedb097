/*
 * Mount limits through the library's entries with the harness as host:
 * inside an ABM_BUSHING with offset, scale and cylindrical coupling the limits
 * see the raw deformation; limits that are all inactive change nothing; the
 * GFOSUB and FIESUB forms agree and query only what they need; input errors.
 * Then the examples: the rig through both limits of a translational and a
 * rotational direction, the powertrain held near its gap, and check.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "host/invoke.h"
#include "host/binding.h"
#include "session/session.h"
#include "frames/measures.h"
#include "sim_support.h"
#include "test_support.h"

/* The contract's formula written out (docs/interface.md §3.4), STEP as 3x^2 - 2x^3. */
static double contract_limit(double K, double E, double C, double D, double L, double q,
                             double qdot)
{
    const double p = fabs(q) - L;
    if (p <= 0.0)
        return 0.0;
    double ramp = 1.0;
    if (D > 0.0 && p < D) {
        const double x = p / D;
        ramp = x * x * (3.0 - 2.0 * x);
    }
    if (q > 0.0)
        return fmin(0.0, -K * pow(p, E) - C * qdot * ramp);
    return -fmin(0.0, -K * pow(p, E) + C * qdot * ramp);
}

/* ---- entries -------------------------------------------------------------------------- */

static const char *const limit_lines[12] = {
    "IMPACT_PARAMETERS_TRA_X_POS = 400 2 5 0.5 1.0", "IMPACT_PARAMETERS_TRA_X_NEG = 300 1.5 5 0.5 1.5",
    "IMPACT_PARAMETERS_TRA_Y_POS = 200 1 4 0 2.0",   "IMPACT_PARAMETERS_TRA_Y_NEG = 200 3 4 0.2 2.0",
    "IMPACT_PARAMETERS_TRA_Z_POS = 900 2 0 0 0.5",   "IMPACT_PARAMETERS_TRA_Z_NEG = 0 1 0 0 0",
    "IMPACT_PARAMETERS_ROT_X_POS = 5e4 1 10 0.01 0.05", "IMPACT_PARAMETERS_ROT_X_NEG = 5e4 1 10 0.01 0.05",
    "IMPACT_PARAMETERS_ROT_Y_POS = 8e4 2 0 0 0.02",  "IMPACT_PARAMETERS_ROT_Y_NEG = 8e4 2 0 0 0.02",
    "IMPACT_PARAMETERS_ROT_Z_POS = 3e4 1.5 6 0.02 0.1", "IMPACT_PARAMETERS_ROT_Z_NEG = 3e4 1.5 6 0.02 0.1",
};
/* the same numbers, by direction and side (0 positive, 1 negative): K E C D L */
static const double limit_values[6][2][5] = {
    {{400, 2, 5, 0.5, 1.0}, {300, 1.5, 5, 0.5, 1.5}},   {{200, 1, 4, 0, 2.0}, {200, 3, 4, 0.2, 2.0}},
    {{900, 2, 0, 0, 0.5}, {0, 1, 0, 0, 0}},             {{5e4, 1, 10, 0.01, 0.05}, {5e4, 1, 10, 0.01, 0.05}},
    {{8e4, 2, 0, 0, 0.02}, {8e4, 2, 0, 0, 0.02}},       {{3e4, 1.5, 6, 0.02, 0.1}, {3e4, 1.5, 6, 0.02, 0.1}},
};

static const char *gbi(const char *name, const char *const *lines, const char *extra)
{
    char text[4096];
    int len = snprintf(text, sizeof text,
                       "[HEADER]\nFILE_TYPE = 'gbi'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\n"
                       "FORCE = 'newton'\nMASS = 'kg'\nTIME = 'second'\n[MOUNT_LIMITS]\n");
    for (int k = 0; k < 12; ++k)
        len += snprintf(text + len, sizeof text - (size_t)len, "%s\n", lines[k]);
    snprintf(text + len, sizeof text - (size_t)len, "%s", extra);
    return test_write_file(name, text);
}

/* A cylindrical bushing with preload, offset and scales in every direction. */
static const char *const bushing_text =
    "[HEADER]\nFILE_TYPE = 'gbs'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\nFORCE = 'newton'\n"
    "MASS = 'kg'\nTIME = 'second'\n[GLOBAL]\nCOUPLING = 'CYLINDRICAL'\n"
    "[DIRECTIONS]\n(ACTIVITY)\n{ formulation FX FY FZ TX TY TZ }\n"
    "'CONSTANT_STIFFNESS' 1 1 1 1 1 1\n'CONSTANT_DAMPING' 1 1 1 1 1 1\n"
    "[CONSTANT_STIFFNESS_FX]\nK = 100\n[CONSTANT_STIFFNESS_FY]\nK = 150\n[CONSTANT_STIFFNESS_FZ]\nK = 80\n"
    "[CONSTANT_STIFFNESS_TX]\nK = 1000\n[CONSTANT_STIFFNESS_TY]\nK = 2000\n[CONSTANT_STIFFNESS_TZ]\nK = 500\n"
    "[CONSTANT_DAMPING_FX]\nC = 2\n[CONSTANT_DAMPING_FY]\nC = 3\n[CONSTANT_DAMPING_FZ]\nC = 1\n"
    "[CONSTANT_DAMPING_TX]\nC = 20\n[CONSTANT_DAMPING_TY]\nC = 30\n[CONSTANT_DAMPING_TZ]\nC = 10\n"
    "[PRELOAD_OFFSET_SCALE]\n{ direction P Q H V }\n'FX' 10 2.0 0.8 1.1\n'FY' -5 -1.0 1.2 0.9\n"
    "'FZ' 3 0.4 1.0 1.3\n'TX' 1 0.03 0.9 1.0\n'TY' 0 -0.01 1.1 1.0\n'TZ' 2 0.05 1.0 0.7\n";


/* Body 2 beyond the x gap (3 mm past 1), turned 0.08 rad about x (past 0.05),
 * moving; strings 101 (bushing), 102 (limits), 103 (inactive limits), 104
 * (undamped translational limits). */
static const char *model(const char *name, const char *elements)
{
    static const char *const translation_only[12] = {
        "IMPACT_PARAMETERS_TRA_X_POS = 100 2 0 0 1", "IMPACT_PARAMETERS_TRA_X_NEG = 0 1 0 0 0",
        "IMPACT_PARAMETERS_TRA_Y_POS = 0 1 0 0 0",   "IMPACT_PARAMETERS_TRA_Y_NEG = 0 1 0 0 0",
        "IMPACT_PARAMETERS_TRA_Z_POS = 0 1 0 0 0",   "IMPACT_PARAMETERS_TRA_Z_NEG = 100 2 0 0 1",
        "IMPACT_PARAMETERS_ROT_X_POS = 0 1 0 0 0",   "IMPACT_PARAMETERS_ROT_X_NEG = 0 1 0 0 0",
        "IMPACT_PARAMETERS_ROT_Y_POS = 0 1 0 0 0",   "IMPACT_PARAMETERS_ROT_Y_NEG = 0 1 0 0 0",
        "IMPACT_PARAMETERS_ROT_Z_POS = 0 1 0 0 0",   "IMPACT_PARAMETERS_ROT_Z_NEG = 0 1 0 0 0",
    };
    char text[8192];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>\n"
             "<Reference_String id=\"101\" string=\"%s\"/>\n<Reference_String id=\"102\" string=\"%s\"/>\n"
             "<Reference_String id=\"103\" string=\"%s\"/>\n<Reference_String id=\"104\" string=\"%s\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"\n"
             " v_ic_x=\"3\" v_ic_y=\"-2\" v_ic_z=\"1\" w_ic_x=\"0.3\" w_ic_y=\"-0.2\" w_ic_z=\"0.1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"4\" pos_y=\"-0.7\" pos_z=\"0.2\"\n"
             " a00=\"1\" a01=\"0\" a02=\"0\" a10=\"0\" a11=\"0.99680170630261\" a12=\"-0.0799146939691727\"\n"
             " a20=\"0\" a21=\"0.0799146939691727\" a22=\"0.99680170630261\"/>\n"
             "%s</Model></MotionSolve>\n",
             test_write_file("limits_bushing.gbs", bushing_text), gbi("limits.gbi", limit_lines, ""),
             gbi("inactive.gbi", limit_lines, "ACTIVE = 0\n"),
             gbi("translation_only.gbi", translation_only, ""), elements);
    return test_write_file(name, text);
}

static void open_session(hx_session *s, const char *path)
{
    hx_message msg;
    if (hx_session_open(s, path, stderr, &msg) != 0)
        fail_msg("%s", msg.text);
}

static void field(hx_session *s, int k, const double d[6], const double v[6], double F[6],
                  double dfd[36], double dfv[36])
{
    hx_invoke_field(&s->bindings.items[k], &s->frames, d, v, 0, 0, F, dfd, dfv, NULL);
    assert_int_equal(s->messages.errors, 0);
}

static void limits_in_a_bushing_see_the_raw_deformation(void **state)
{
    (void)state;
    hx_session s;
    open_session(&s, model("raw.xml", FIE(1, "(1, 101)", "FIESUB") FIE(2, "(1, 101, 102)", "FIESUB")
                                      FIE(3, "(2, 102)", "FIESUB") FIE(4, "(102)", "MOUNT_LIMITS_FIELD")));
    /* x = 2.5 is past its 1 mm gap raw but 0.5 after the 2 mm offset; y = -2.5
     * past its 2 mm gap raw, -1.5 after the -1 offset; z = 0.45 inside raw, past
     * after the offset; the rotations on both sides of theirs */
    const double states[4][12] = {
        {2.5, -2.5, 0.45, 0.07, -0.03, 0.12, 3, -2, 1, 0.3, -0.2, 0.1},
        {-2.0, 2.4, 0.9, -0.06, 0.025, -0.2, -4, 5, 2, -0.1, 0.4, -0.3},
        {1.2, -2.1, 0.6, 0.051, 0.021, 0.101, 0.5, 0.5, 0.5, 0.05, 0.05, 0.05},
        {0.5, 1.0, -0.3, 0.0, 0.01, 0.05, 1, 1, 1, 0.1, 0.1, 0.1},
    };
    int engaged = 0;
    for (int n = 0; n < 4; ++n) {
        const double *d = states[n], *v = states[n] + 6;
        double F[4][6], dfd[4][36], dfv[4][36];
        for (int k = 0; k < 4; ++k)
            field(&s, k, d, v, F[k], dfd[k], dfv[k]);
        for (int i = 0; i < 6; ++i) {
            const double *l = limit_values[i][d[i] < 0.0];
            const double expected = contract_limit(l[0], l[1], l[2], l[3], l[4], d[i], v[i]);
            engaged += expected != 0.0;
            assert_close(F[2][i], expected, 1e-12, 1e-12);       /* the limits alone: raw d */
            assert_close(F[3][i], F[2][i], 0, 0);                /* named entry, same force */
            assert_close(F[1][i] - F[0][i], F[2][i], 1e-12, 1e-9); /* added to the bushing */
        }
        for (int j = 0; j < 36; ++j) {
            assert_close(dfd[1][j] - dfd[0][j], dfd[2][j], 1e-12, 1e-9);
            assert_close(dfv[1][j] - dfv[0][j], dfv[2][j], 1e-12, 1e-9);
            if (j % 7 != 0) /* a limit acts along its own direction only */
                assert_true(dfd[2][j] == 0.0 && dfv[2][j] == 0.0);
        }
    }
    assert_true(engaged >= 10); /* most directions touch a limit in these states */
    hx_session_close(&s);
}

static void inactive_limits_change_nothing(void **state)
{
    (void)state;
    hx_session s;
    open_session(&s, model("inactive.xml",
                           FIE(1, "(1, 101)", "FIESUB") FIE(5, "(1, 101, 103)", "FIESUB")
                           GFO(8, "(1, 20, 10, 101)", "GFOSUB") GFO(9, "(1, 20, 10, 101, 103)", "GFOSUB")));
    const double d[6] = {5, -4, 3, 0.2, -0.2, 0.3}, v[6] = {3, -2, 1, 0.3, -0.2, 0.1};
    double F1[6], F5[6], dfd1[36], dfd5[36], dfv1[36], dfv5[36];
    field(&s, 0, d, v, F1, dfd1, dfv1);
    field(&s, 1, d, v, F5, dfd5, dfv5);
    assert_memory_equal(F1, F5, sizeof F1); /* bit for bit */
    assert_memory_equal(dfd1, dfd5, sizeof dfd1);
    assert_memory_equal(dfv1, dfv5, sizeof dfv1);
    double G8[6], G9[6];
    hx_invoke_force(&s.bindings.items[2], &s.frames, 0, 0, G8, NULL);
    hx_invoke_force(&s.bindings.items[3], &s.frames, 0, 0, G9, NULL);
    assert_memory_equal(G8, G9, sizeof G8);
    char t8[256], t9[256];
    hx_dependencies_text(&s.bindings.items[2].deps, t8, sizeof t8);
    hx_dependencies_text(&s.bindings.items[3].deps, t9, sizeof t9);
    assert_string_equal(t8, t9);
    hx_session_close(&s);
}

static void gfosub_and_fiesub_forms_agree_and_query_what_they_need(void **state)
{
    (void)state;
    hx_session s;
    open_session(&s, model("forms.xml",
                           GFO(6, "(2, 20, 10, 102)", "GFOSUB") GFO(7, "(20, 10, 102)", "MOUNT_LIMITS")
                           FIE(3, "(2, 102)", "FIESUB") GFO(10, "(2, 20, 10, 104)", "GFOSUB")));
    double G6[6], G7[6], F3[6], dfd[36], dfv[36], disp[6], velo[6];
    hx_invoke_force(&s.bindings.items[0], &s.frames, 0, 0, G6, NULL);
    hx_invoke_force(&s.bindings.items[1], &s.frames, 0, 0, G7, NULL);
    hx_force_deformation(&s.frames, 2, disp, velo);
    field(&s, 2, disp, velo, F3, dfd, dfv);
    assert_true(disp[0] > 1.0 && disp[3] > 0.05); /* the model's state is past two gaps */
    for (int i = 0; i < 6; ++i) {
        assert_close(G6[i], F3[i], 1e-12, 1e-12); /* the library measures, or the host does */
        assert_close(G7[i], G6[i], 0, 0);
    }
    assert_true(F3[0] < 0.0 && F3[3] < 0.0);
    char text[256];
    hx_dependencies_text(&s.bindings.items[0].deps, text, sizeof text);
    assert_string_equal(text, "DISP(20,10,10) AZ(20,10) VEL(20,10,10,10)");
    hx_dependencies_text(&s.bindings.items[3].deps, text, sizeof text);
    assert_string_equal(text, "TDISP(20,10,10)"); /* undamped translational limits */
    double G10[6];
    hx_invoke_force(&s.bindings.items[3], &s.frames, 0, 0, G10, NULL);
    assert_close(G10[0], -100.0 * (disp[0] - 1.0) * (disp[0] - 1.0), 1e-12, 0);
    hx_session_close(&s);
}

static void input_errors_name_the_element_and_parameter(void **state)
{
    (void)state;
    static const struct {
        const char *element;
        const char *const expected[3];
    } cases[] = {
        {FIE(21, "(2)", "FIESUB"), {"FIESUB element 21", "USER list ends", ".gbi"}},
        {FIE(22, "(2, 101)", "FIESUB"), {"FIESUB element 22", "Reference_String 101", "FILE_TYPE is 'gbs'"}},
        {FIE(23, "(2, 102, 5)", "FIESUB"), {"FIESUB element 23", "one too many", "MOUNT_LIMITS list"}},
        {FIE(24, "(2, 98)", "FIESUB"), {"FIESUB element 24", "no Reference_String 98", ".gbi"}},
        {GFO(25, "(20, 10)", "MOUNT_LIMITS"), {"MOUNT_LIMITS element 25", "USER list ends", ".gbi"}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k)
        expect_one_setup_error(model("error.xml", cases[k].element), cases[k].expected);
}

/* ---- examples --------------------------------------------------------------------------- */

/* rig CSV columns */
enum { T = 0, D0 = 1, V0 = 7, F0 = 13 };

static void rig_line(const char *element, const char *line, const char *name, csv_table *t)
{
    char csv[512];
    snprintf(csv, sizeof csv, "%s/%s", test_temp_dir(), name);
    const char *args[] = {"--element", element, "--line", line, "--end", "1", "--step", "0.002", NULL};
    assert_int_equal(sim_rig("mount_limits_rig.xml", csv, args), 0);
    csv_read(csv, t);
    assert_true(t->rows >= 500);
}

/* The rig's limits (mount_limits.gbi) in direction k: K E C D L, alike on both sides. */
static const double rig_limits[6][5] = {
    {5000, 2, 10, 0.5, 3}, {5000, 2, 10, 0.5, 3}, {8000, 1.5, 20, 0.5, 5},
    {2e6, 1, 500, 0.01, 0.1}, {2e6, 1, 500, 0.01, 0.1}, {1e6, 1, 200, 0.02, 0.3},
};
static const double rig_bushing[6][2] = {{500, 1}, {500, 1}, {800, 1.5}, {2e5, 50}, {2e5, 50}, {1e5, 30}};

static void rig_through_both_limits(void **state)
{
    (void)state;
    static const struct {
        const char *line;
        int k;
    } lines[] = {{"x,-6,6", 0}, {"z,8,-8", 2}, {"az,-0.5,0.5", 5}, {"ax,0.2,-0.2", 3}};
    for (size_t n = 0; n < sizeof lines / sizeof lines[0]; ++n) {
        const int k = lines[n].k;
        const double *l = rig_limits[k];
        csv_table alone, gfo, with_bushing, inactive;
        rig_line("1", lines[n].line, "limits_alone.csv", &alone);
        rig_line("vector:11", lines[n].line, "limits_gfosub.csv", &gfo);
        rig_line("2", lines[n].line, "limits_bushing.csv", &with_bushing);
        rig_line("3", lines[n].line, "inactive_bushing.csv", &inactive);
        int before = 0, inside = 0, after = 0;
        for (int r = 0; r < alone.rows; ++r) {
            const double q = csv_at(&alone, r, D0 + k), qdot = csv_at(&alone, r, V0 + k);
            const double f = csv_at(&alone, r, F0 + k);
            const double limit = contract_limit(l[0], l[1], l[2], l[3], l[4], q, qdot);
            assert_close(f, limit, 1e-12, 1e-9);
            assert_close(csv_at(&gfo, r, F0 + k), f, 1e-10, 1e-9);
            for (int i = 0; i < 6; ++i)
                if (i != k)
                    assert_close(csv_at(&alone, r, F0 + i), 0.0, 0, 1e-12);
            const double bushing = -(rig_bushing[k][0] * q + rig_bushing[k][1] * qdot);
            assert_close(csv_at(&with_bushing, r, F0 + k), bushing + limit, 1e-12, 1e-9);
            assert_close(csv_at(&inactive, r, F0 + k), bushing, 1e-12, 1e-9);
            if (fabs(q) < l[4])
                ++inside, assert_true(f == 0.0);
            else if (csv_at(&alone, r, T) < 0.5)
                ++before;
            else
                ++after;
        }
        /* the path crosses the gap and reaches into both limits */
        assert_true(before > 50 && inside > 50 && after > 50);
        csv_free(&alone);
        csv_free(&gfo);
        csv_free(&with_bushing);
        csv_free(&inactive);
    }
}

static void rig_plots_go_where_asked(void **state)
{
    (void)state;
    char csv[512], prefix[512], png[600];
    snprintf(csv, sizeof csv, "%s/plotted.csv", test_temp_dir());
    snprintf(prefix, sizeof prefix, "%s/limits_x", test_temp_dir());
    const char *args[] = {"--element", "2", "--line", "x,-6,6", "--end", "1", "--step", "0.01",
                          "--plot", prefix, NULL};
    assert_int_equal(sim_rig("mount_limits_rig.xml", csv, args), 0);
    static const char *const suffixes[3] = {"force_path", "deformation_path", "force_deformation"};
    for (int k = 0; k < 3; ++k) {
        snprintf(png, sizeof png, "%s_%s.png", prefix, suffixes[k]);
        FILE *f = fopen(png, "rb");
        assert_non_null(f); /* gnuplot is part of the set-up */
        unsigned char magic[4] = {0};
        assert_int_equal(fread(magic, 1, 4, f), 4);
        assert_memory_equal(magic, "\x89PNG", 4);
        fclose(f);
    }
}

static void powertrain_limits_hold_the_deflection_near_the_gap(void **state)
{
    (void)state;
    char csv[512];
    snprintf(csv, sizeof csv, "%s/powertrain.csv", test_temp_dir());
    const char *args[] = {"--end", "1.0", "--integrator", "dopri5", "--rtol", "1e-8", "--atol",
                          "1e-10", "--quiet", NULL};
    assert_int_equal(sim_run_csv("powertrain.xml", csv, args), 0);
    const int dz1 = csv_column(csv, "force1.dz"), dz2 = csv_column(csv, "force2.dz");
    const int fz1 = csv_column(csv, "force1.fz"), fz2 = csv_column(csv, "force2.fz");
    assert_true(dz1 > 0 && dz2 > 0 && fz1 > 0 && fz2 > 0);
    csv_table t;
    csv_read(csv, &t);
    double largest = 0.0;
    for (int r = 0; r < t.rows; ++r) {
        const double time = csv_at(&t, r, 0);
        if (time > 0.3 && time < 0.4) /* settled under gravity, inside the gaps */
            assert_true(fabs(csv_at(&t, r, dz1)) < 2.0 && fabs(csv_at(&t, r, dz2)) < 2.0);
        largest = fmax(largest, fmax(csv_at(&t, r, dz1), -csv_at(&t, r, dz2)));
    }
    const int end = t.rows - 1;
    const double left = csv_at(&t, end, dz1), right = csv_at(&t, end, dz2);
    /* without limits the roll puts the left mount near +3.8 mm and the right one
     * near -6.1 mm (1500 N m against 2 * 500 N/mm * (300 mm)^2 + 3 * 5e5 N mm/rad);
     * the limits hold both within 0.8 mm of the 2.5 mm gap at rest, and the
     * overshoot as the torque comes on within 1.5 mm */
    printf("powertrain: mounts at %+.3f and %+.3f mm at rest, largest %.3f mm (gap 2.5 mm)\n",
           left, right, largest);
    assert_true(left > 2.5 && left < 3.3);
    assert_true(right < -2.5 && right > -3.3);
    assert_true(largest < 4.0);
    /* at rest each mount's vertical force is its spring plus its limit */
    assert_close(csv_at(&t, end, fz1), -(500 * left + 3000 * (left - 2.5) * (left - 2.5)), 2e-3, 0);
    assert_close(csv_at(&t, end, fz2), -(500 * right - 3000 * (-right - 2.5) * (-right - 2.5)), 2e-3, 0);
    csv_free(&t);
}

static void check_passes_on_the_limit_examples(void **state)
{
    (void)state;
    assert_int_equal(sim_check("mount_limits_rig.xml"), 0);
    assert_int_equal(sim_check("powertrain.xml"), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(limits_in_a_bushing_see_the_raw_deformation),
        cmocka_unit_test(inactive_limits_change_nothing),
        cmocka_unit_test(gfosub_and_fiesub_forms_agree_and_query_what_they_need),
        cmocka_unit_test(input_errors_name_the_element_and_parameter),
        cmocka_unit_test(rig_through_both_limits),
        cmocka_unit_test(rig_plots_go_where_asked),
        cmocka_unit_test(powertrain_limits_hold_the_deflection_near_the_gap),
        cmocka_unit_test(check_passes_on_the_limit_examples),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
