/*
 * The flexible joint through the library's entries with the harness as host:
 * each column of K (and D) for a matrix of 36 distinct entries, the GFOSUB and
 * FIESUB forms agreeing and querying only what they need, input errors; then
 * the examples: a conservative joint keeping its energy, a damped one losing
 * it monotonically, a joint stiff but for one rotation behaving like a
 * revolute joint (parasitic motion against stiffness), and check.
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


static const char *const gfj_head =
    "[HEADER]\nFILE_TYPE = 'gfj'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\nFORCE = 'newton'\n"
    "MASS = 'kg'\nTIME = 'second'\n";

/* K_rc = 10 r + c + 1 (36 distinct), D_rc = 0.5 K_rc + 100, preload 1..6. */
static double k_entry(int r, int c)
{
    return 10.0 * r + c + 1.0;
}

static const char *numbered_gfj(void)
{
    char text[4096];
    int len = snprintf(text, sizeof text, "%s", gfj_head);
    for (int m = 0; m < 2; ++m) {
        len += snprintf(text + len, sizeof text - (size_t)len, "[%s]\n(MATRIX)\n{ x y z ax ay az }\n",
                        m ? "DAMPING" : "STIFFNESS");
        for (int r = 0; r < 6; ++r)
            for (int c = 0; c < 6; ++c)
                len += snprintf(text + len, sizeof text - (size_t)len, "%g%s",
                                m ? 0.5 * k_entry(r, c) + 100.0 : k_entry(r, c), c < 5 ? " " : "\n");
    }
    snprintf(text + len, sizeof text - (size_t)len, "[PRELOAD]\n{ fx fy fz tx ty tz }\n1 2 3 4 5 6\n");
    return test_write_file("numbered.gfj", text);
}

static const char *model(const char *name, const char *elements)
{
    char text[8192];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>\n"
             "<Reference_String id=\"701\" string=\"%s\"/>\n"
             "<Reference_String id=\"702\" string=\"%s/flex_coupled.gfj\"/>\n"
             "<Reference_String id=\"703\" string=\"%s/mount_bushing.gbs\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n%s</Model></MotionSolve>\n",
             numbered_gfj(), EXAMPLES_DIR, EXAMPLES_DIR, elements);
    return test_write_file(name, text);
}

static void open_session(hx_session *s, const char *path)
{
    hx_message msg;
    if (hx_session_open(s, path, stderr, &msg) != 0)
        fail_msg("%s", msg.text);
}

static void each_column_of_k_and_d(void **state)
{
    (void)state;
    hx_session s;
    open_session(&s, model("columns.xml", FIE(1, "(3, 701)", "FIESUB") FIE(2, "(701)", "FLEX_JOINT_FIELD")));
    /* the matrix is not symmetric: one warning, though two elements name the file */
    assert_int_equal(s.messages.notices, 1);
    assert_contains(s.messages.last_notice, "numbered.gfj", "not symmetric", "not conservative");
    for (int e = 0; e < 2; ++e)
        for (int j = 0; j < 12; ++j) {
            double disp[6] = {0}, velo[6] = {0}, F[6], dfd[36], dfv[36];
            if (j < 6)
                disp[j] = 1.0;
            else
                velo[j - 6] = 1.0;
            hx_invoke_field(&s.bindings.items[e], &s.frames, disp, velo, 0, 0, F, dfd, dfv, NULL);
            for (int r = 0; r < 6; ++r) {
                /* a unit deformation gives minus that column, plus the preload */
                const double column = j < 6 ? k_entry(r, j) : 0.5 * k_entry(r, j - 6) + 100.0;
                assert_close(F[r], (r + 1.0) - column, 1e-15, 0);
                for (int c = 0; c < 6; ++c) {
                    assert_true(dfd[r + 6 * c] == -k_entry(r, c));
                    assert_true(dfv[r + 6 * c] == -(0.5 * k_entry(r, c) + 100.0));
                }
            }
        }
    assert_int_equal(s.messages.errors, 0);
    hx_session_close(&s);
}

static void gfosub_and_fiesub_forms_agree_and_query_what_they_need(void **state)
{
    (void)state;
    hx_session s;
    open_session(&s, EXAMPLES_DIR "/flex_joint_rig.xml");
    assert_int_equal(s.messages.notices, 0); /* the example matrices are sound */
    const hx_model *m = s.model;
    for (int pair = 0; pair < 2; ++pair) {
        hx_binding *field = NULL, *vector = NULL;
        for (int k = 0; k < s.bindings.count; ++k) {
            hx_binding *b = &s.bindings.items[k];
            const int id = m->forces[b->index].id;
            if (b->kind == HX_BIND_FIELD && id == 1 + pair)
                field = b;
            if (b->kind == HX_BIND_FORCE && id == 11 + pair)
                vector = b;
        }
        assert_non_null(field);
        assert_non_null(vector);
        double disp[6], velo[6], F[6], G[6], dfd[36], dfv[36];
        hx_force_deformation(&s.frames, field->index, disp, velo);
        hx_invoke_field(field, &s.frames, disp, velo, 0, 0, F, dfd, dfv, NULL);
        hx_invoke_force(vector, &s.frames, 0, 0, G, NULL);
        for (int i = 0; i < 6; ++i)
            assert_close(G[i], F[i], 1e-12, 1e-9);
        char text[256];
        hx_dependencies_text(&vector->deps, text, sizeof text);
        assert_string_equal(text, pair == 0 ? "DISP(20,10,10) AZ(20,10) VEL(20,10,10,10)" : "TDISP(20,10,10)");
        if (pair == 1) /* translational springs alone: no torque */
            assert_true(F[3] == 0.0 && F[4] == 0.0 && F[5] == 0.0);
    }
    hx_session_close(&s);
}

/* the revolute joint has no stiffness about z: the twist never enters its
 * force, so it has no use for AZ at rest (docs/interface.md §3.1) */
static void a_joint_free_about_z_does_not_ask_for_az(void **state)
{
    (void)state;
    hx_session s;
    open_session(&s, EXAMPLES_DIR "/flex_revolute.xml");
    char text[256];
    hx_dependencies_text(&s.bindings.items[0].deps, text, sizeof text);
    assert_string_equal(text, "DISP(21,10,10) VEL(21,10,10,10)");
    hx_session_close(&s);
}

static void input_errors_name_the_element_and_parameter(void **state)
{
    (void)state;
    static const struct {
        const char *element;
        const char *const expected[3];
    } cases[] = {
        {FIE(21, "(3)", "FIESUB"), {"FIESUB element 21", "USER list ends", ".gfj"}},
        {FIE(22, "(3, 703)", "FIESUB"), {"FIESUB element 22", "Reference_String 703", "FILE_TYPE is 'gbs', expected 'gfj'"}},
        {FIE(23, "(3, 702, 1)", "FIESUB"), {"FIESUB element 23", "one too many", "FLEX_JOINT list"}},
        {GFO(24, "(20, 10, 99)", "FLEX_JOINT"), {"FLEX_JOINT element 24", "no Reference_String 99", ".gfj"}},
        {FIE(25, "(4, 702)", "FIESUB"), {"FIESUB element 25", "par[0]) is 4", "3 (FLEX_JOINT)"}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k)
        expect_one_setup_error(model("error.xml", cases[k].element), cases[k].expected);
}

/* ---- dynamics ----------------------------------------------------------------------------- */

static void a_conservative_joint_keeps_its_energy(void **state)
{
    (void)state;
    sim coarse, fine;
    sim_run(&coarse, "flex_planar.xml", HX_METHOD_RK4, 1e-4, 10.0, 0.01);
    sim_run(&fine, "flex_planar.xml", HX_METHOD_RK4, 5e-5, 10.0, 0.01);
    const double e1 = coarse.result.energy_error_max / coarse.result.energy_scale;
    const double e2 = fine.result.energy_error_max / fine.result.energy_scale;
    printf("flexible joint, 10 s of RK4: relative energy error %.3g (h = 0.1 ms), %.3g (h = 0.05 ms)\n",
           e1, e2);
    /* the error is the integrator's: small, and falling with the step like h^4 or faster */
    assert_true(e1 < 5e-4);
    assert_true(e2 < e1 / 16.0);
    /* the motion stays in its plane: z and the rotations about x and y stay zero */
    const int q = fine.dynamics.dof[1].q;
    double out_of_plane = 0.0, turn = 0.0;
    for (int r = 0; r < fine.path.rows; ++r) {
        out_of_plane = fmax(out_of_plane, fabs(sim_state(&fine, r, q + 2)));
        out_of_plane = fmax(out_of_plane, fabs(sim_state(&fine, r, q + 4)));
        out_of_plane = fmax(out_of_plane, fabs(sim_state(&fine, r, q + 5)));
        turn = fmax(turn, fabs(sim_state(&fine, r, q + 6)));
    }
    sim_close(&coarse);
    sim_close(&fine);
    assert_true(out_of_plane < 1e-12);
    assert_true(turn > 2e-4); /* it does turn about z (q3 = sin(angle / 2)) */
}

static void a_damped_joint_loses_energy_monotonically(void **state)
{
    (void)state;
    char csv[512];
    snprintf(csv, sizeof csv, "%s/damped.csv", test_temp_dir());
    const char *args[] = {"--end", "2", "--integrator", "rk4", "--step", "5e-5",
                          "--output-interval", "0.001", "--quiet", NULL};
    assert_int_equal(sim_run_csv("flex_planar_damped.xml", csv, args), 0);
    const int energy = csv_column(csv, "energy");
    assert_true(energy > 0);
    csv_table t;
    csv_read(csv, &t);
    const double e0 = csv_at(&t, 0, energy);
    for (int r = 1; r < t.rows; ++r)
        assert_true(csv_at(&t, r, energy) <= csv_at(&t, r - 1, energy) + 1e-9 * e0);
    assert_true(csv_at(&t, t.rows - 1, energy) < 0.01 * e0); /* and most of it is gone */
    csv_free(&t);
}

/* Writes a copy of the example (flex_revolute.xml, flex_double_pendulum.xml) naming a .gfj of stiffness k (N/mm;
 * k (200 mm)^2 about x and y, 2 % of critical damping) into the temporary
 * folder; each k has its own file (a library parses a file once). */
static const char *revolute_like(const char *example, double k)
{
    char text[4096], gfj[64], xml[96], path[512];
    snprintf(gfj, sizeof gfj, "flex_revolute_%.0e.gfj", k);
    snprintf(xml, sizeof xml, "%s_%.0e.xml", example, k);
    const double kr = k * 200.0 * 200.0, c = 2.0 * 0.02 * sqrt(k * 1000.0 * 2.0) / 1000.0;
    const double diagonal[2][6] = {{k, k, k, kr, kr, 0}, {c, c, c, c * 4e4, c * 4e4, 0}};
    int len = snprintf(text, sizeof text, "%s", gfj_head);
    for (int m = 0; m < 2; ++m) {
        len += snprintf(text + len, sizeof text - (size_t)len, "[%s]\n(MATRIX)\n{ x y z ax ay az }\n",
                        m ? "DAMPING" : "STIFFNESS");
        for (int r = 0; r < 6; ++r)
            for (int col = 0; col < 6; ++col)
                len += snprintf(text + len, sizeof text - (size_t)len, "%.17g%s",
                                r == col ? diagonal[m][r] : 0.0, col < 5 ? " " : "\n");
    }
    test_write_file(gfj, text);
    snprintf(path, sizeof path, "%s/%s.xml", EXAMPLES_DIR, example);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    const size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = '\0';
    fclose(f);
    char *name = strstr(text, "\"flex_revolute.gfj\"");
    assert_non_null(name);
    char model[4096];
    snprintf(model, sizeof model, "%.*s\"%s\"%s", (int)(name - text), text, gfj,
             name + strlen("\"flex_revolute.gfj\""));
    return test_write_file(xml, model);
}

static void a_joint_stiff_but_for_one_rotation_is_a_revolute_joint(void **state)
{
    (void)state;
    char reference[512], csv[512];
    snprintf(reference, sizeof reference, "%s/revolute.csv", test_temp_dir());
    snprintf(csv, sizeof csv, "%s/flex_revolute.csv", test_temp_dir());
    const char *args[] = {"--end", "1", "--integrator", "dopri5", "--rtol", "1e-9", "--atol",
                          "1e-11", "--output-interval", "0.001", "--quiet", NULL};
    assert_int_equal(sim_run_csv("revolute_pendulum.xml", reference, args), 0);
    csv_table rev;
    csv_read(reference, &rev);
    const int angle = csv_column(reference, "joint1.q");
    double previous_motion = 0.0, previous_angle = 0.0;
    printf("flexible joint as a revolute joint (2 kg pendulum, 1 s):\n"
           "  %-10s %-16s %-16s %s\n", "k N/mm", "parasitic mm", "angle error rad",
           "dopri5 steps");
    for (double k = 1e3; k <= 1e5; k *= 10.0) {
        const char *model_path = revolute_like("flex_revolute", k);
        sim s;
        sim_run(&s, model_path, HX_METHOD_DOPRI5, 1e-9, 1.0, 0.001);
        const long steps = s.result.stats.steps;
        sim_close(&s);
        assert_int_equal(sim_run_csv(model_path, csv, args), 0);
        const int dx = csv_column(csv, "force1.dx"), q0 = csv_column(csv, "body2.q0"),
                  q3 = csv_column(csv, "body2.q3");
        csv_table t;
        csv_read(csv, &t);
        const int rows = t.rows < rev.rows ? t.rows : rev.rows;
        assert_true(rows > 990);
        double motion = 0.0, angle_error = 0.0;
        for (int r = 0; r < rows; ++r) {
            assert_close(csv_at(&t, r, 0), csv_at(&rev, r, 0), 0, 1e-9); /* the same times */
            const double x = csv_at(&t, r, dx), y = csv_at(&t, r, dx + 1), z = csv_at(&t, r, dx + 2);
            motion = fmax(motion, sqrt(x * x + y * y + z * z));
            const double theta = 2.0 * atan2(csv_at(&t, r, q3), csv_at(&t, r, q0));
            angle_error = fmax(angle_error, fabs(theta - csv_at(&rev, r, angle)));
        }
        csv_free(&t);
        printf("  %-10.0e %-16.3g %-16.3g %ld\n", k, motion, angle_error, steps);
        assert_true(motion > 0.0 && motion < 2.0 * 9.81 * 3.0 / k); /* below m (g + l w^2) / k */
        if (previous_motion > 0.0) {
            /* both shrink as 1/k */
            assert_true(previous_motion / motion > 7.0 && previous_motion / motion < 13.0);
            assert_true(previous_angle / angle_error > 5.0);
        }
        previous_motion = motion, previous_angle = angle_error;
    }
    assert_true(previous_angle < 1e-3);
    csv_free(&rev);
}

/* A body's turn about z from its quaternion columns (q0, q3 at column c, c + 3). */
static double turn_about_z(const csv_table *t, int r, int q0)
{
    return 2.0 * atan2(csv_at(t, r, q0 + 3), csv_at(t, r, q0));
}

/* The angle between two turns, in (-pi, pi]. */
static double angle_between(double a, double b)
{
    return remainder(a - b, 2.0 * M_PI);
}

/* The flexible joint's specification: stiff entries simulate a revolute joint between two
 * bodies. The lower link of a double pendulum on the flexible joint against the same link
 * on a revolute joint to the upper link (double_pendulum.xml: both links moving, the
 * joint's rows and multipliers): the links' angles and the pivot's parasitic motion close
 * in on the revolute joint's as 1/k. */
static void a_stiff_flexible_joint_between_moving_links_is_a_revolute_joint(void **state)
{
    (void)state;
    char reference[512], csv[512];
    snprintf(reference, sizeof reference, "%s/double_revolute.csv", test_temp_dir());
    snprintf(csv, sizeof csv, "%s/flex_double.csv", test_temp_dir());
    const char *args[] = {"--end", "1", "--integrator", "dopri5", "--rtol", "1e-10", "--atol",
                          "1e-12", "--output-interval", "0.001", "--quiet", NULL};
    assert_int_equal(sim_run_csv("double_pendulum.xml", reference, args), 0);
    csv_table rev;
    csv_read(reference, &rev);
    const int upper_q0 = csv_column(reference, "body2.q0"), lower_q0 = csv_column(reference, "body3.q0");
    double previous_motion = 0.0, previous_error = 0.0, swing = 0.0;
    printf("flexible joint as a revolute joint between moving links (1 s):\n"
           "  %-10s %-16s %s\n", "k N/mm", "parasitic mm", "angle error rad");
    for (double k = 1e3; k <= 1e5; k *= 10.0) {
        const char *model_path = revolute_like("flex_double_pendulum", k);
        assert_int_equal(sim_run_csv(model_path, csv, args), 0);
        const int dx = csv_column(csv, "force1.dx"), upper = csv_column(csv, "joint1.q"),
                  lower = csv_column(csv, "body3.q0");
        csv_table t;
        csv_read(csv, &t);
        const int rows = t.rows < rev.rows ? t.rows : rev.rows;
        assert_true(rows > 990);
        double motion = 0.0, error = 0.0;
        for (int r = 0; r < rows; ++r) {
            assert_close(csv_at(&t, r, 0), csv_at(&rev, r, 0), 0, 1e-9); /* the same times */
            const double x = csv_at(&t, r, dx), y = csv_at(&t, r, dx + 1), z = csv_at(&t, r, dx + 2);
            motion = fmax(motion, sqrt(x * x + y * y + z * z));
            const double rev_lower = turn_about_z(&rev, r, lower_q0);
            error = fmax(error, fabs(angle_between(csv_at(&t, r, upper),
                                                   turn_about_z(&rev, r, upper_q0))));
            error = fmax(error, fabs(angle_between(turn_about_z(&t, r, lower), rev_lower)));
            swing = fmax(swing, fabs(rev_lower));
        }
        csv_free(&t);
        printf("  %-10.0e %-16.3g %.3g\n", k, motion, error);
        /* the pivot carries at most the weight of one link and its centripetal force, 2 kg
         * (9.81 + 0.2 m w^2) with w well below 20 rad/s: under 200 N, so under 200 / k mm */
        assert_true(motion > 0.0 && motion < 200.0 / k);
        if (previous_motion > 0.0) {
            assert_true(previous_motion / motion > 7.0 && previous_motion / motion < 13.0);
            assert_true(previous_error / error > 5.0);
        }
        previous_motion = motion, previous_error = error;
    }
    assert_true(swing > 0.3);          /* the lower link does swing */
    assert_true(previous_error < 1e-3); /* and at k = 1e5 follows the revolute joint closely */
    csv_free(&rev);
}

static void check_passes_on_the_flexible_joint_examples(void **state)
{
    (void)state;
    assert_int_equal(sim_check("flex_joint_rig.xml"), 0);
    assert_int_equal(sim_check("flex_planar.xml"), 0);
    assert_int_equal(sim_check("flex_planar_damped.xml"), 0);
    assert_int_equal(sim_check("flex_revolute.xml"), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(each_column_of_k_and_d),
        cmocka_unit_test(gfosub_and_fiesub_forms_agree_and_query_what_they_need),
        cmocka_unit_test(a_joint_free_about_z_does_not_ask_for_az),
        cmocka_unit_test(input_errors_name_the_element_and_parameter),
        cmocka_unit_test(a_conservative_joint_keeps_its_energy),
        cmocka_unit_test(a_damped_joint_loses_energy_monotonically),
        cmocka_unit_test(a_joint_stiff_but_for_one_rotation_is_a_revolute_joint),
        cmocka_unit_test(a_stiff_flexible_joint_between_moving_links_is_a_revolute_joint),
        cmocka_unit_test(check_passes_on_the_flexible_joint_examples),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
