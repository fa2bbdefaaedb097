/*
 * Accelerations in requests (docs/interface.md §7.13, §8.3, §8.5): ACCX ..
 * WDTM at output times, from the right-hand side evaluated at the output
 * state (sim/dynamics/accelerations.h, frames/acceleration_measures.h):
 * a free fall's ACCZ = -g; a pendulum at the bottom, its centre pulled up by
 * w^2 L, and at rest in the pendulum's own frame (L); a free body turned by a
 * known torque, alpha = T / I about a body axis that is not the world's; a
 * spring's mass, ACCX = -k x / m at every row of a run (the value at the
 * row's state, not an earlier one's); ACCX in a general constraint refused
 * with its file, line and column; REQUEST/ACCELERATION and Post_Request's
 * MARKER_ACCELERATION in Adams' order (F1 ACCM, F2..F4 ACCX..ACCZ in RM's
 * axes, F5 WDTM, F6..F8 WDTX..WDTZ), in a run's CSV and at a state.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expr/evaluate.h"
#include "model/expr/expr.h"
#include "model_runs.h"
#include "sim/dynamics/accelerations.h"
#include "sim/dynamics/reactions.h"
#include "sim/simulation/requests.h"
#include "sim_support.h"
#include "test_support.h"

/* A free body falling under (0, 0, -9.81), thrown at (1, 0, 5) and spinning
 * at 2 rad/s about z: its centre's acceleration is -9.81 z exactly, whatever
 * its speed; its spin is constant (isotropic inertia: no angular
 * acceleration). Marker 21 on it at (1, 0, 0) from the centre turns at w = 2
 * about z: its acceleration adds the centripetal -w^2 r = (-4, 0, 0). */
static const char falling[] =
    "falling\n"
    "ACCGRAV/, IGRAV=0, JGRAV=0, KGRAV=-9.81\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, REULER=90D,90D,0\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, VX=1, VZ=5, WZ=2, WM=20\n"
    "MARKER/20, PART=2, QP=0,0,1\n"
    "MARKER/21, PART=2, QP=1,0,1\n"
    "REQUEST/7, F2=ACCX(20)\\F3=ACCY(20)\\F4=ACCZ(20)\\F1=ACCM(20)\\\n"
    ", F6=WDTX(20)\\F7=WDTY(20)\\F8=WDTZ(20)\\F5=WDTM(20)\n"
    "REQUEST/8, F2=ACCX(21,10)\\F3=ACCY(21,0,10)\\F4=ACCZ(21,10,10,10)\\F1=ACCM(21,10,10)\n"
    "REQUEST/9, ACCELERATION, I=21, J=10, RM=11\n"
    "END\n";

static void free_fall(void **state)
{
    (void)state;
    char csv[512];
    const char *path = test_write_file("falling.adm", falling);
    snprintf(csv, sizeof csv, "%s/falling.csv", test_temp_dir());
    const char *const args[] = {"--end", "1", "--output-interval", "0.25", "--quiet", NULL};
    assert_int_equal(sim_run_csv(path, csv, args), 0);
    const int first = csv_column(csv, "request7.1");
    assert_true(first > 0);
    assert_int_equal(csv_column(csv, "request8.1"), first + 8);
    assert_int_equal(csv_column(csv, "request9.1"), first + 16);
    assert_int_equal(csv_column(csv, "request9.8"), first + 23);
    assert_int_equal(csv_column(csv, "energy"), first + 24); /* appended before it */
    csv_table t;
    csv_read(csv, &t);
    assert_int_equal(t.rows, 5);
    for (int row = 0; row < t.rows; ++row) {
        /* ACCM, ACCX, ACCY, ACCZ, WDTM, WDTX, WDTY, WDTZ of the centre; then marker 21's
         * relative to the ground's 10, in 10's axes, derivatives in 10 (all the world's) */
        const double want[16] = {9.81, 0, 0, -9.81, 0, 0, 0, 0,
                                 sqrt(16 + 9.81 * 9.81), 0, 0, -9.81, 0, 0, 0, 0};
        const double time = csv_at(&t, row, 0), turn = 2 * time;
        for (int k = 0; k < 16; ++k) {
            double w = want[k];
            if (k == 9) /* -w^2 r, r = (cos 2t, sin 2t, 0) */
                w = -4 * cos(turn);
            if (k == 10)
                w = -4 * sin(turn);
            if (fabs(csv_at(&t, row, first + k) - w) > 1e-6 * (1 + fabs(w)))
                fail_msg("t = %g, column %d: %.15g, expected %.15g", time, first + k + 1,
                         csv_at(&t, row, first + k), w);
        }
        /* REQUEST/9, ACCELERATION of 21 in RM = 11's axes (x the world's y, y its z, z its
         * x): ACCM, then (a_y, a_z, a_x) = (-4 sin 2t, -9.81, -4 cos 2t); WDTM, WDT: 0 */
        const double acc[8] = {sqrt(16 + 9.81 * 9.81), -4 * sin(turn), -9.81, -4 * cos(turn),
                               0, 0, 0, 0};
        for (int k = 0; k < 8; ++k)
            if (fabs(csv_at(&t, row, first + 16 + k) - acc[k]) > 1e-6 * (1 + fabs(acc[k])))
                fail_msg("t = %g, request9.%d: %.15g, expected %.15g", time, k + 1,
                         csv_at(&t, row, first + 16 + k), acc[k]);
        /* the centre's: exactly, whatever the state */
        assert_true(csv_at(&t, row, first + 3) == -9.81);
    }
    csv_free(&t);
}

/* A pendulum (the reactions' test's): ground marker 10 at the origin, body 2
 * of mass 2 with its centre 20 at (0, -L, 0) and marker 21 at the pivot,
 * turning at w about z through the bottom, gravity -g y, on a REVOLUTE. */
static const char *pendulum(double L, double w, const char *joint)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.3\" inertia_yy=\"0.2\""
             " inertia_zz=\"0.4\" v_ic_x=\"%.17g\" w_ic_z=\"%.17g\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_y=\"%.17g\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
             "<Reference_Marker id=\"22\" body_id=\"2\" pos_x=\"0.5\" pos_y=\"%.17g\"/>\n"
             "%s\n</Model></MotionSolve>\n",
             w * L, w, -L, -L, joint);
    return text;
}

static void pendulum_at_the_bottom(void **state)
{
    (void)state;
    /* L = 1.5, w = 2: at the bottom gravity has no moment about the pivot, so
     * alpha = 0 and the centre's acceleration is the centripetal w^2 L = 4 *
     * 1.5 = 6, toward the pivot (+y); none along the path (x) */
#define ACC_REQUEST "<Post_Request id=\"3\" type=\"MARKER_ACCELERATION\" i_marker_id=\"22\"" \
                    " j_marker_id=\"10\"/>"
    static const char *const joints[2] = {
        "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>"
        ACC_REQUEST,
        "<Constraint_Joint id=\"1\" type=\"SPHERICAL\" i_marker_id=\"21\" j_marker_id=\"10\"/>"
        ACC_REQUEST};
    for (int k = 0; k < 2; ++k) { /* reduced, then rows (a free body held by a spherical) */
        evaluated e;
        evaluate_text(&e, "bottom.xml", pendulum(1.5, 2.0, joints[k]));
        assert_int_equal(e.m.d.joint_row[0] >= 0, k);
        EXPECT(&e, "ACCX(20)", 0.0, 1e-9);
        EXPECT(&e, "ACCY(20)", 6.0, 1e-9);
        EXPECT(&e, "ACCZ(20)", 0.0, 1e-9);
        EXPECT(&e, "ACCM(20, 10)", 6.0, 1e-9);
        /* relative to the pivot (at rest): the same; the pivot itself does not move */
        EXPECT(&e, "ACCY(20, 21)", 6.0, 1e-9);
        EXPECT(&e, "ACCM(21)", 0.0, 1e-9);
        /* marker 22 at (0.5, -1.5): r = 22 - pivot, a = -w^2 r = (-2, 6, 0) */
        EXPECT(&e, "ACCX(22)", -2.0, 1e-9);
        EXPECT(&e, "ACCY(22)", 6.0, 1e-9);
        /* in the pendulum's own frame (L = 21, on it) the centre is at rest
         * relative to the pivot: r'' - alpha x r - 2 w x r' + w x (w x r)
         * = (0, 6) - 0 - 2 (0, 0, 2) x (3, 0) + (0, 0, 2) x ((0, 0, 2) x (0, -1.5))
         * = (0, 6) - (0, 12) + (0, 6) = 0 */
        EXPECT(&e, "ACCX(20, 10, 0, 21)", 0.0, 1e-9);
        EXPECT(&e, "ACCY(20, 10, 0, 21)", 0.0, 1e-9);
        EXPECT(&e, "ACCM(20, 10, 21)", 0.0, 1e-9);
        /* resolved in K = 21's axes (the world's here: the body is unturned) */
        EXPECT(&e, "ACCY(20, 0, 21)", 6.0, 1e-9);
        EXPECT(&e, "WDTZ(20)", 0.0, 1e-9);
        /* MARKER_ACCELERATION of 22: |(-2, 6, 0)| = sqrt(40), (-2, 6, 0), no angular one */
        const double want[8] = {sqrt(40.0), -2, 6, 0, 0, 0, 0, 0};
        double got[8];
        hx_message msg;
        assert_int_equal(hx_requests_values(&e.m.data.frames, 0, NULL, &e.outputs, got, &msg), 0);
        for (int j = 0; j < 8; ++j)
            if (fabs(got[j] - want[j]) > 1e-9)
                fail_msg("Post_Request 3 expr%d: %.15g, expected %.15g", j + 1, got[j], want[j]);
        /* without the accelerations: refused, naming the request */
        assert_int_equal(hx_requests_values(&e.m.data.frames, 0, NULL, NULL, got, &msg), -1);
        assert_contains(msg.text, "bottom.xml:", "Post_Request 3", "no accelerations");
        release(&e);
    }
    /* away from the bottom: at 90 degrees (the centre level with the pivot) gravity
     * turns it at alpha = -m g L / (I_zz + m L^2) = -2 * 9.81 * 1.5 / (0.4 + 2 * 2.25)
     * = -29.43 / 4.9 about z, at rest (w = 0): the centre at (1.5, 0) accelerates
     * by alpha x r = (0, 1.5 alpha, 0) */
    static const char level[] =
        "<MotionSolve><Model>\n"
        "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
        "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.3\" inertia_yy=\"0.2\""
        " inertia_zz=\"0.4\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1.5\"/>\n"
        "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
        "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "</Model></MotionSolve>\n";
    evaluated e;
    evaluate_text(&e, "level.xml", level);
    const double alpha = -29.43 / 4.9;
    EXPECT(&e, "WDTZ(20)", alpha, 1e-9);
    EXPECT(&e, "WDTM(20)", -alpha, 1e-9);
    EXPECT(&e, "ACCY(20)", 1.5 * alpha, 1e-9);
    EXPECT(&e, "ACCX(20)", 0.0, 1e-9);
    release(&e);
}

/* A free body with principal moments (1, 2, 4) about its body axes, its centre
 * marker turned +90 degrees about x (REULER 0, 90D, 0: body x = world x, body
 * y = world z, body z = world -y), at rest, no gravity, turned by a torque of 3
 * about the world's -y (an SFORCE ROTATION about J's z, J on ground turned
 * the same): about its body z axis, so alpha = 3 / 4 along the world's -y.
 * Its centre does not accelerate; marker 21, 2 from the centre along the
 * world's x, does by alpha x r = (0, -0.75, 0) x (2, 0, 0) = (0, 0, 1.5). */
static const char torqued[] =
    "torqued\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1, REULER=0,90D,0\n"
    "MARKER/11, PART=1, REULER=90D,90D,0\n"
    "PART/2, MASS=2, CM=20, IP=1,2,4\n"
    "MARKER/20, PART=2, REULER=0,90D,0\n"
    "MARKER/21, PART=2, QP=2,0,0\n"
    "SFORCE/1, ROTATION, I=20, J=10, FUNCTION=3\n"
    "REQUEST/5, ACCELERATION, I=21, RM=11\n"
    "END\n";

static void torque_over_inertia(void **state)
{
    (void)state;
    evaluated e;
    evaluate_text(&e, "torqued.adm", torqued);
    EXPECT(&e, "WDTX(20)", 0.0, 1e-12);
    EXPECT(&e, "WDTY(20)", -0.75, 1e-12);
    EXPECT(&e, "WDTZ(20)", 0.0, 1e-12);
    EXPECT(&e, "WDTM(20)", 0.75, 1e-12);
    /* in the body's axes (K = 20): about its z */
    EXPECT(&e, "WDTZ(20, 0, 20)", 0.75, 1e-12);
    /* in K = 11's axes (x along the world's y, y along z, z along x) */
    EXPECT(&e, "WDTX(20, 0, 11)", -0.75, 1e-12);
    EXPECT(&e, "WDTY(20, 0, 11)", 0.0, 1e-12);
    EXPECT(&e, "ACCM(20)", 0.0, 1e-12);
    EXPECT(&e, "ACCZ(21)", 1.5, 1e-12);
    EXPECT(&e, "ACCZ(21, 20)", 1.5, 1e-12);
    /* relative to the body's own frame, it does not turn */
    EXPECT(&e, "WDTM(20, 21)", 0.0, 1e-12);
    /* REQUEST/5, ACCELERATION of 21 in RM = 11's axes (x the world's y, y its z, z its
     * x): ACCM 1.5, (a_y, a_z, a_x) = (0, 1.5, 0), WDTM 0.75, (alpha_y, alpha_z,
     * alpha_x) = (-0.75, 0, 0) */
    const double want[8] = {1.5, 0, 1.5, 0, 0.75, -0.75, 0, 0};
    double got[8];
    hx_message msg;
    assert_int_equal(hx_requests_values(&e.m.data.frames, 0, NULL, &e.outputs, got, &msg), 0);
    for (int j = 0; j < 8; ++j)
        if (fabs(got[j] - want[j]) > 1e-12)
            fail_msg("REQUEST/5 F%d: %.15g, expected %.15g", j + 1, got[j], want[j]);
    release(&e);
}

/* A mass of 2 on a spring of k = 50 to the ground along x (no gravity), let go
 * 0.3 from its rest length: at every row ACCX = -k x / m of the row's own x
 * (DX, the spring's stretch): the acceleration of the output state, not of a
 * step before it; the run's rows are between steps (DOPRI5's dense output). */
static const char spring[] =
    "spring\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, REULER=90D,90D,0\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2, QP=1.3,0,0\n"
    "SFORCE/1, TRANSLATION, I=20, J=10, FUNCTION=-50*(DM(20,10)-1)\n"
    "REQUEST/3, F1=DX(20,10)-1\\F2=ACCX(20)\\F3=-25*(DX(20,10)-1)\n"
    "REQUEST/4, F1=SFORCE(1,0,1,0)\\F2=SFORCE(1,0,2,0)\\F3=SFORCE(1,1,2,0)\\F4=SFORCE(1,0,3,0)\\\n"
    ", F5=SFORCE(1,1,5,0)\\F6=SFORCE(1,0,2,11)\\F7=SFORCE(1,0,4,11)\n"
    "END\n";

static void spring_acceleration_is_the_rows(void **state)
{
    (void)state;
    char csv[512];
    const char *path = test_write_file("spring.adm", spring);
    snprintf(csv, sizeof csv, "%s/spring.csv", test_temp_dir());
    const char *const args[] = {"--end", "1", "--output-interval", "0.01", "--quiet", NULL};
    assert_int_equal(sim_run_csv(path, csv, args), 0);
    const int first = csv_column(csv, "request3.1");
    csv_table t;
    csv_read(csv, &t);
    assert_int_equal(t.rows, 101);
    double largest = 0.0;
    for (int row = 0; row < t.rows; ++row) {
        const double x = csv_at(&t, row, first), acc = csv_at(&t, row, first + 1);
        assert_true(fabs(acc - csv_at(&t, row, first + 2)) <= 1e-12);
        assert_true(fabs(acc + 25 * x) <= 1e-12);
        largest = fmax(largest, fabs(acc));
        /* REQUEST/4: the spring's force on I, -k x along x (I beyond J on x): FM = k |x|,
         * FX = -k x, on J (jflag 1) +k x, FY 0, no torque on J (TM); in RM = 11's axes
         * (x the world's y, y its z, z its x) FX 0 and FZ = -k x */
        const int f4 = first + 8;
        const double want[8] = {50 * fabs(x), -50 * x, 50 * x, 0, 0, 0, -50 * x, 0};
        for (int k = 0; k < 8; ++k)
            if (fabs(csv_at(&t, row, f4 + k) - want[k]) > 1e-9)
                fail_msg("row %d request4.%d: %.15g, expected %.15g", row, k + 1,
                         csv_at(&t, row, f4 + k), want[k]);
    }
    assert_true(largest > 7.0); /* it swings: 25 * 0.3 = 7.5 at the ends */
    csv_free(&t);
}

/* ACCX, WDTZ and SFORCE in a general constraint: refused where written (a
 * force or a variable reads them as an algebraic loop's inputs:
 * test_algebraic_loops.c). */
static void refused_in_general_constraints(void **state)
{
    (void)state;
    static const char *const cases[][3] = {
        {"GCON/1, I=20, FUNCTION=DX(20)-2*ACCX(20)",
         "bad.adm:6:33:", "ACCX(20): an acceleration is known only once the forces are"},
        {"GCON/1, I=20, FUNCTION=WDTZ(20,10)",
         "bad.adm:6:24:", "WDTZ(20,10): an acceleration is known only"},
        {"GCON/1, I=20, FUNCTION=1+SFORCE(1,0,2,0)",
         "bad.adm:6:26:", "SFORCE(1,0,2,0): another element's force"},
        {"REQUEST/1, F2=SFORCE(7,0,2,0)",
         "bad.adm:6:15:", "SFORCE(7,0,2,0): no Force_Scalar_TwoBody or Force_SpringDamper (SFORCE) 7"
         " in the model"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char text[1024];
        snprintf(text, sizeof text, "bad\nPART/1, GROUND\nMARKER/10, PART=1\n"
                 "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n%s\nEND\n", cases[k][0]);
        hx_message msg;
        hx_model *m = hx_model_parse(text, strlen(text), "bad.adm", NULL, &msg);
        if (m != NULL)
            fail_msg("read: %s", cases[k][0]);
        assert_contains(msg.text, cases[k][1], cases[k][2]);
    }
    /* in a request's evaluation without the accelerations: a fault naming it */
    static const char text[] = "ok\nPART/1, GROUND\nMARKER/10, PART=1\n"
                               "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
                               "REQUEST/4, F1=1\\F3=ACCZ(20)\nEND\n";
    hx_message msg;
    hx_model *m = hx_model_parse(text, strlen(text), "ok.adm", NULL, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    hx_frames fr;
    assert_int_equal(hx_frames_init(&fr, m), 0);
    double got[8];
    assert_int_equal(hx_requests_values(&fr, 0, NULL, NULL, got, &msg), -1);
    assert_contains(msg.text, "ok.adm:6:20: REQUEST/4 F3: ACCZ", "no accelerations");
    hx_frames_free(&fr);
    hx_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(free_fall),
        cmocka_unit_test(pendulum_at_the_bottom),
        cmocka_unit_test(torque_over_inertia),
        cmocka_unit_test(spring_acceleration_is_the_rows),
        cmocka_unit_test(refused_in_general_constraints),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
