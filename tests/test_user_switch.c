/*
 * A command file's DEACTIVATE and ACTIVATE of force elements given by user
 * routines (docs/interface.md §9.9): an SFOSUB SFORCE, a FIESUB FIELD and a
 * GFOSUB GFORCE holding a part. Switched off, none is called into the
 * right-hand side or BDF's Jacobian and the part falls freely (worked by
 * hand); activated again, each pulls it as the spring it is (the closed form
 * of a spring-mass under gravity), its force in the CSV, the energy it then
 * stores not counted as dissipated.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd/commands.h"
#include "model_runs.h"
#include "sim_support.h"
#include "test_support.h"

/* A 2 kg part at (1, 0, 0), at rest, under 9.81 along -y, held to the
 * ground's origin by three linear springs of k = 50 N/m and no free length,
 * each calling a user routine: LINE_SPRING (tests/user_libraries/tp_scalar.c,
 * -k DM along the line: -k r on I), SCALED_SPRING_FIELD and SCALED_SPRING
 * (tests/implicit_support/scaled_field.c: -k (DX, DY, DZ) of I in J, and
 * -kr the angles); and a SPRINGDAMPER of the same spring, a load (its flag
 * before the force elements': the tests keep it off, so that a flag read at
 * the wrong place shows). */
static const char *dataset(void)
{
    /* a dataset's ROUTINE names a library found in MS_USERDLL_DIR, where the
     * build puts both */
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    const char *slash = strrchr(SCALED_FIELD_LIBRARY, '/');
    const char *scaled = slash != NULL ? slash + 1 : SCALED_FIELD_LIBRARY;
    static char text[2048];
    snprintf(text, sizeof text,
             "switched: three user force elements holding a part\n"
             "ACCGRAV/JGRAV = -9.81\n"
             "PART/1, GROUND\nMARKER/10, PART = 1\n"
             "PART/2, MASS = 2, CM = 20, IP = 1, 1, 1\nMARKER/20, PART = 2, QP = 1, 0, 0\n"
             "SFORCE/1, TRANSLATION, I = 20, J = 10, FUNCTION = USER(20, 10, 50, 0)\n"
             ", ROUTINE = libtp_scalar.so::LINE_SPRING\n"
             "FIELD/2, I = 20, J = 10, FUNCTION = USER(50, 0, 5, 0, 1)\n"
             ", ROUTINE = %s::SCALED_SPRING_FIELD\n"
             "GFORCE/3, I = 20, JFLOAT = 10, RM = 10, FUNCTION = USER(20, 10, 50, 0, 5, 0, 1)\n"
             ", ROUTINE = %s::SCALED_SPRING\n"
             "SPRINGDAMPER/4, TRANSLATION, I = 20, J = 10, K = 50, C = 0, LENGTH = 0\n"
             "END\n",
             scaled, scaled);
    return test_write_file("switched.adm", text);
}

/* ---- in the equations ---------------------------------------------------------------------- */

/* Each element switched off alone, then all three, the SPRINGDAMPER off;
 * last the SPRINGDAMPER alone on: the right-hand side's accelerations are
 * gravity's and the others' (-25 x m/s^2 an element on, at x = 1), an
 * element switched off is not called (its routine's latest time stays before
 * the evaluation's), and the Jacobian agrees with differences of the switched
 * right-hand side (a Jacobian that kept an element would carry its k / m =
 * 25 where the differences have 0). */
static void switched_off_elements_are_in_neither(void **state)
{
    (void)state;
    model m;
    open_model(&m, dataset());
    assert_int_equal(m.session.model->nforces, 3);
    assert_int_equal(m.session.model->nloads, 1);
    double *y = model_state(&m), *fy = model_state(&m);
    model_initial_state(&m, y);
    const hx_body_dof *part = &m.d.dof[1];
    assert_int_equal(part->kind, HX_DOF_FREE);
    for (int off = 0; off <= 5; ++off) { /* 0: none, 1..3 that one, 4 and 5: all three */
        int on = 0;
        for (int k = 0; k < 3; ++k) {
            m.d.force_off[k] = off >= 4 || off == k + 1;
            on += !m.d.force_off[k];
        }
        m.d.load_off[0] = off != 5;
        on += !m.d.load_off[0];
        const double t = 1.0 + off; /* each evaluation later than any before */
        if (hx_dynamics_rhs(&m.d, &m.data, t, y, fy) != 0)
            fail_msg("%s", m.data.message);
        for (int k = 0; k < 3; ++k)
            assert_true((m.d.force_binding[k]->latest_time == t) == !m.d.force_off[k]);
        const double *a = fy + m.d.nq + part->u;
        assert_close(a[0], -25.0 * on, 0.0, 1e-12);
        assert_close(a[1], -9.81, 0.0, 1e-12);
        for (int j = 2; j < 6; ++j)
            assert_close(a[j], 0.0, 0.0, 1e-12);
        for (int k = 0; k < 3; ++k)
            if (m.d.force_off[k])
                for (int j = 0; j < 6; ++j) /* what the CSV and FIELD() read */
                    assert_true(m.data.element_load[6 * k + j] == 0.0);
        char what[64];
        snprintf(what, sizeof what, "user elements, case %d", off);
        y[m.d.nq + part->u + 1] = -0.7; /* moving: the velocity columns act too */
        long outside = 0;
        const double worst = jacobian_against_differences(&m.d, 0.0, y, what, &outside);
        assert_int_equal(outside, 0);
        assert_true(worst < 1e-6);
        y[m.d.nq + part->u + 1] = 0.0;
    }
    free(y), free(fy);
    close_model(&m);
}

/* ---- in a run ------------------------------------------------------------------------------ */

/* All three deactivated to 0.3 s (and the SPRINGDAMPER throughout): the part falls freely, x = 1, y = -g t^2 / 2
 * (DOPRI5 exact on the quadratic; every element would pull it at once, 50 N
 * along -x). Then `element` alone activated: from y0 = -0.44145, vy0 =
 * -2.943 at t0 = 0.3 a spring-mass of w = sqrt(50 / 2) = 5 1/s,
 * x = cos(w s), y = -g / w^2 + (y0 + g / w^2) cos(w s) + vy0 / w sin(w s),
 * s = t - t0; its force on the part in the CSV -k (x, y) from then, 0
 * before; the others' 0 throughout; no energy dissipated (no damping). With
 * DOPRI5 and with BDF (its Jacobian from each element's partials). */
static void activated_again_each_pulls_as_a_spring(void **state)
{
    (void)state;
    const char *model_path = dataset();
    static const char *const statements[3] = {"SFORCE", "FIELD", "GFORCE"};
    static const char *const integrators[2] = {"dopri5", "bdf"}; /* bdf: with its Jacobian */
    const double g = 9.81, w = 5.0, y0 = -0.5 * g * 0.09, vy0 = -g * 0.3;
    for (int trial = 0; trial < 6; ++trial) {
        const int e = trial % 3;
        const double tol = trial < 3 ? 1e-8 : 1e-6;
        char acf_text[512];
        snprintf(acf_text, sizeof acf_text,
                 "switched\n\nDEACTIVATE/SPRINGDAMPER, ID=4\n"
                 "DEACTIVATE/SFORCE, ID=1\nDEACTIVATE/FIELD, ID=2\n"
                 "DEACTIVATE/GFORCE, ID=3\nSIMULATE/DYNAMIC, END=0.3, STEPS=3\n"
                 "ACTIVATE/%s, ID=%d\nSIMULATE/DYNAMIC, END=0.6, STEPS=3\n", statements[e],
                 e + 1);
        const char *acf = test_write_file("switched.acf", acf_text);
        const char *csv = test_temp_path("switched.csv");
        assert_int_equal(sim_run_csv(model_path, csv,
                                     (const char *const[]){"--acf", acf, "--integrator",
                                                           integrators[trial / 3], "--rtol",
                                                           "1e-11", "--atol", "1e-12", "--quiet",
                                                           NULL}),
                         0);
        csv_table tb;
        csv_read(csv, &tb);
        assert_int_equal(tb.rows, 7); /* t = 0, 0.1, .., 0.6 */
        const int tc = csv_column(csv, "t"), xc = csv_column(csv, "body2.x");
        const int yc = csv_column(csv, "body2.y"), dc = csv_column(csv, "dissipated");
        int fc[3][2];
        for (int k = 0; k < 3; ++k) {
            char name[32];
            snprintf(name, sizeof name, "force%d.fx", k + 1);
            fc[k][0] = csv_column(csv, name);
            snprintf(name, sizeof name, "force%d.fy", k + 1);
            fc[k][1] = csv_column(csv, name);
            assert_true(fc[k][0] >= 0 && fc[k][1] >= 0);
        }
        assert_true(tc >= 0 && xc >= 0 && yc >= 0 && dc >= 0);
        for (int r = 0; r < 7; ++r) {
            const double t = csv_at(&tb, r, tc), s = t - 0.3;
            assert_close(t, 0.1 * r, 0.0, 1e-12);
            double x = 1.0, y = -0.5 * g * t * t;
            if (s > 1e-9) {
                x = cos(w * s);
                y = -g / (w * w) + (y0 + g / (w * w)) * cos(w * s) + vy0 / w * sin(w * s);
            }
            assert_close(csv_at(&tb, r, xc), x, 0.0, tol);
            assert_close(csv_at(&tb, r, yc), y, 0.0, tol);
            assert_close(csv_at(&tb, r, dc), 0.0, 0.0, tol);
            for (int k = 0; k < 3; ++k) {
                const int active = k == e && s > 1e-9;
                assert_close(csv_at(&tb, r, fc[k][0]), active ? -50.0 * x : 0.0, 0.0, 100 * tol);
                assert_close(csv_at(&tb, r, fc[k][1]), active ? -50.0 * y : 0.0, 0.0, 100 * tol);
            }
        }
        csv_free(&tb);
    }
}

/* An id the model lacks among the statement's elements is refused by name
 * and line: FIELD/1 is an SFORCE's id, SFORCE/2 a FIELD's. */
static void ids_the_model_lacks_are_refused(void **state)
{
    (void)state;
    const char *model_path = dataset();
    static const char *const cases[3][2] = {
        {"DEACTIVATE/FIELD, ID=1", "DEACTIVATE/FIELD: the model has no FIELD/1"},
        {"ACTIVATE/SFORCE, ID=1,2", "ACTIVATE/SFORCE: the model has no SFORCE/2"},
        {"DEACTIVATE/VFORCE, ID=3", "DEACTIVATE/VFORCE: the model has no VFORCE/3"},
    };
    for (int k = 0; k < 3; ++k) {
        char text[256];
        snprintf(text, sizeof text, "switched\n\n%s\nSIMULATE/DYNAMIC, END=0.1, STEPS=1\n",
                 cases[k][0]);
        const char *acf = test_write_file("refused.acf", text);
        test_captured c;
        test_capture(hx_command_run,
                     (const char *const[]){"run", model_path, "--acf", acf, "--quiet", NULL}, &c);
        assert_int_equal(c.status, 1);
        assert_contains(c.err, "refused.acf:3: ", cases[k][1]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(switched_off_elements_are_in_neither),
        cmocka_unit_test(activated_again_each_pulls_as_a_spring),
        cmocka_unit_test(ids_the_model_lacks_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
