/*
 * The constraint elements' forces in the function language (docs/interface.md
 * §8.3): MOTION, COUPLER and GCON (id, jflag, comp, rm) from the multipliers
 * of their own rows (a motion on a reduced joint from its body's balance),
 * and FX .. TM and REQUEST/FORCE at their markers, each worked by hand at a
 * model's first state: a pendulum driven at constant angular acceleration
 * (on a reduced joint, and between two bodies: a row), a slider driven at
 * constant acceleration against gravity, two revolutes coupled with a
 * torque on one, a point mass on a general constraint DM - L. jflag 0 and 1
 * opposite (moved to J), rm's axes turned. Refusals with file:line:column.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_runs.h"
#include "sim/simulation/requests.h"
#include "sim_support.h"
#include "test_support.h"

#define TOL 1e-9

/* An output expression and its value worked by hand. */
typedef struct expected {
    const char *text;
    double want;
} expected;

static void expect_all(const evaluated *e, const expected *values, size_t count)
{
    for (size_t k = 0; k < count; ++k)
        EXPECT(e, values[k].text, values[k].want, TOL);
}

/* The model text written as name, evaluated at its first state: values. */
static void expect_at_start(const char *name, const char *text, const expected *values,
                            size_t count)
{
    evaluated e;
    evaluate_text(&e, name, text);
    expect_all(&e, values, count);
    release(&e);
}

/* 2 kg, cm 1.5 from the axis along x, Izz 0.4 about the cm: 4.9 about the
 * axis. MOTION 0.5*3*TIME**2: alpha = 3 from rest at t = 0; the motion's
 * torque is I alpha less gravity's moment r x m g = -29.43 z:
 * 4.9 * 3 + 29.43 = 44.13 about z. Marker 30 turned 90 degrees about x: its
 * y is the world's z. */
#define PENDULUM_PARTS                                                                      \
    "ACCGRAV/IGRAV = 0, JGRAV = -9.81, KGRAV = 0\n"                                        \
    "PART/1, GROUND\n"                                                                      \
    "MARKER/10, PART = 1\n"                                                                 \
    "MARKER/30, PART = 1, REULER = 0, 90D, 0\n"                                             \
    "PART/2, MASS = 2, CM = 20, IP = 0.3, 0.2, 0.4\n"                                       \
    "MARKER/20, PART = 2, QP = 1.5, 0, 0\n"                                                 \
    "MARKER/21, PART = 2\n"
#define PENDULUM_TORQUE 44.13

/* The pendulum with `joints` (the motion on joint 1, J at marker j), its
 * motion a row or not (nmotions), at its first state. */
static void pendulum(const char *name, const char *joints, int nmotions, int j)
{
    char text[2048], at_j[32];
    snprintf(text, sizeof text, "pendulum\n" PENDULUM_PARTS "%s"
             "MOTION/1, JOINT = 1, ROTATION, FUNCTION = 0.5*3*TIME**2\nEND\n", joints);
    evaluated e;
    evaluate_text(&e, name, text);
    assert_int_equal(e.m.d.nmotions, nmotions);
    const expected values[] = {
        {"MOTION(1, 0, 8, 0)", PENDULUM_TORQUE},
        {"MOTION(1, 0, 5, 0)", PENDULUM_TORQUE},
        {"MOTION(1, 0, 6, 0)", 0.0},
        {"MOTION(1, 0, 1, 0)", 0.0},
        {"MOTION(1, 0, 7, 30)", PENDULUM_TORQUE}, /* rm's y: the world's z */
        {"MOTION(1, 0, 8, 30)", 0.0},
        {"MOTION(1, 1, 8, 0)", -PENDULUM_TORQUE},
        /* at marker 21: the joint's reaction (m a_cm - m g = 9 + 19.62 up) and
         * the motion's torque; at J the opposite */
        {"TZ(21)", PENDULUM_TORQUE},
        {"FY(21)", 28.62},
    };
    expect_all(&e, values, sizeof values / sizeof values[0]);
    snprintf(at_j, sizeof at_j, "TZ(%d, 21)", j);
    EXPECT(&e, at_j, -PENDULUM_TORQUE, TOL);
    release(&e);
}

/* The motion on a body's only joint to ground: the body's balance. */
static void motion_on_a_reduced_joint(void **state)
{
    (void)state;
    pendulum("reduced.adm", "JOINT/1, REVOLUTE, I = 21, J = 10\n", 0, 10);
}

/* The same pendulum on a body fixed to ground: the revolute and its motion
 * are rows, and the motion's torque is its multiplier's. */
static void motion_as_a_row(void **state)
{
    (void)state;
    pendulum("row.adm", "PART/3, MASS = 1, CM = 40, IP = 1, 1, 1\n"
             "MARKER/40, PART = 3\n"
             "MARKER/41, PART = 3\n"
             "JOINT/2, FIXED, I = 41, J = 10\n"
             "JOINT/1, REVOLUTE, I = 21, J = 41\n", 1, 41);
}

/* A 3 kg slider on an axis up the world's y (J's z), I 2 above J, driven at
 * 2 up: the motion's force m (a + g) = 6 + 29.43 up on I; on J the
 * opposite, along the line from I (no moment at J). */
static void slider_driven_against_gravity(void **state)
{
    (void)state;
    const double F = 6.0 + 29.43;
    const expected values[] = {
        {"MOTION(2, 0, 1, 0)", F},
        {"MOTION(2, 0, 2, 0)", 0.0},
        {"MOTION(2, 0, 3, 0)", F},
        {"MOTION(2, 0, 4, 0)", 0.0},
        {"MOTION(2, 0, 5, 0)", 0.0},
        {"MOTION(2, 0, 4, 10)", F}, /* 10's z is the world's y */
        {"MOTION(2, 1, 3, 0)", -F},
        {"MOTION(2, 1, 1, 0)", F},
        {"MOTION(2, 1, 5, 0)", 0.0},
        {"FY(21, 10)", F},
    };
    expect_at_start("slider.adm", "slider\n"
                    "ACCGRAV/IGRAV = 0, JGRAV = -9.81, KGRAV = 0\n"
                    "PART/1, GROUND\n"
                    "MARKER/10, PART = 1, QP = 1, -2, 0, REULER = 0, -90D, 0\n"
                    "PART/2, MASS = 3, CM = 20, IP = 1, 1, 1\n"
                    "MARKER/20, PART = 2, QP = 1, 0, 0\n"
                    "MARKER/21, PART = 2, QP = 1, 0, 0, REULER = 0, -90D, 0\n"
                    "JOINT/1, TRANSLATIONAL, I = 21, J = 10\n"
                    "MOTION/2, JOINT = 1, TRANSLATION, FUNCTION = TIME**2\nEND\n",
                    values, sizeof values / sizeof values[0]);
}

/* Two wheels on revolutes to ground, 0.5 and 1.5 about their axes, coupled
 * theta1 + 2 theta2 = 0, 3 on the first: lambda = -(3 / 0.5) / (1 / 0.5 +
 * 4 / 1.5) = -9/7, the coupler's torque -9/7 on the first wheel and -18/7
 * on the second (J1 alpha1 - 3 = 0.5 * 24/7 - 3, J2 alpha2 = 1.5 * -12/7). */
static void coupler_between_two_wheels(void **state)
{
    (void)state;
    const expected values[] = {
        {"COUPLER(1, 0, 8, 0)", -9.0 / 7.0},
        {"COUPLER(1, 0, 5, 0)", 9.0 / 7.0},
        {"COUPLER(1, 1, 8, 0)", 9.0 / 7.0},
        {"COUPLER(1, 2, 8, 0)", -18.0 / 7.0},
        {"COUPLER(1, 3, 8, 0)", 18.0 / 7.0},
        {"COUPLER(1, 2, 7, 30)", -18.0 / 7.0},
        {"COUPLER(1, 2, 2, 0)", 0.0},
        /* at the first wheel's marker: the applied torque and the coupler's */
        {"TZ(20, 10)", 3.0 - 9.0 / 7.0},
        {"TZ(31)", -18.0 / 7.0},
    };
    expect_at_start("coupler.adm", "coupler\n"
                    "PART/1, GROUND\n"
                    "MARKER/10, PART = 1\n"
                    "MARKER/11, PART = 1, QP = 2, 0, 0\n"
                    "MARKER/30, PART = 1, REULER = 0, 90D, 0\n"
                    "PART/2, MASS = 1, CM = 20, IP = 1, 1, 0.5\n"
                    "MARKER/20, PART = 2\n"
                    "PART/3, MASS = 1, CM = 31, IP = 1, 1, 1.5\n"
                    "MARKER/31, PART = 3, QP = 2, 0, 0\n"
                    "JOINT/1, REVOLUTE, I = 20, J = 10\n"
                    "JOINT/2, REVOLUTE, I = 31, J = 11\n"
                    "COUPLER/1, JOINTS = 1, 2, TYPE = R:R, SCALES = 1, 2\n"
                    "SFORCE/5, ROTATION, I = 20, J = 10, FUNCTION = 3\nEND\n",
                    values, sizeof values / sizeof values[0]);
}

/* 2 kg on a massless rod 1.5 long (DM(20,10) - 1.5), at the bottom moving 2
 * sideways: the tension m v^2 / L + m g = 16/3 + 19.62 up on the mass. */
static void gcon_holds_a_point_mass(void **state)
{
    (void)state;
    evaluated e;
    evaluate_text(&e, "gcon.adm", "gcon\n"
                  "ACCGRAV/IGRAV = 0, JGRAV = -9.81, KGRAV = 0\n"
                  "PART/1, GROUND\n"
                  "MARKER/10, PART = 1\n"
                  "MARKER/30, PART = 1, REULER = 0, 90D, 0\n"
                  "PART/2, MASS = 2, CM = 20, IP = 0.1, 0.1, 0.1, VX = 2\n"
                  "MARKER/20, PART = 2, QP = 0, -1.5, 0\n"
                  "GCON/1, I = 20, FUNCTION = DM(20, 10) - 1.5\n"
                  "REQUEST/7, FORCE, I = 20\nEND\n");
    const double tension = 16.0 / 3.0 + 19.62;
    const expected values[] = {
        {"GCON(1, 0, 1, 0)", tension},
        {"GCON(1, 0, 3, 0)", tension},
        {"GCON(1, 0, 2, 0)", 0.0},
        {"GCON(1, 0, 5, 0)", 0.0},
        {"GCON(1, 0, 3, 30)", 0.0},
        {"GCON(1, 0, 4, 30)", -tension}, /* 30's z is the world's -y */
        {"FY(20)", tension},
    };
    expect_all(&e, values, sizeof values / sizeof values[0]);
    double out[8];
    hx_message msg;
    assert_int_equal(hx_requests_values(&e.m.data.frames, 0, NULL, &e.outputs, out, &msg), 0);
    assert_true(fabs(out[2] - tension) < TOL);
    release(&e);
}

/* A 2 kg bar hinged at the origin about z (one coordinate: no rows but the
 * general constraint's), its centre 0.75 along x, its tip (1.5) held at
 * y = 0 by DY(20, 10): the tip's pull carries m g 0.75 / 1.5 = 9.81 up and
 * the hinge the other 9.81 (the general constraint's force is not the
 * joint's, though the body's balance holds both). */
static void gcon_holds_a_hinged_bar(void **state)
{
    (void)state;
    const expected values[] = {
        {"GCON(1, 0, 3, 0)", 9.81},
        {"GCON(1, 0, 2, 0)", 0.0},
        {"GCON(1, 0, 8, 0)", 0.0},
        {"JOINT(1, 0, 3, 0)", 9.81},
        {"JOINT(1, 0, 2, 0)", 0.0},
        {"FY(20)", 9.81},
        {"FY(21)", 9.81},
    };
    expect_at_start("hinged.adm", "hinged\n"
                    "ACCGRAV/IGRAV = 0, JGRAV = -9.81, KGRAV = 0\n"
                    "PART/1, GROUND\n"
                    "MARKER/10, PART = 1\n"
                    "PART/2, MASS = 2, CM = 22, IP = 0.1, 0.1, 0.1\n"
                    "MARKER/20, PART = 2, QP = 1.5, 0, 0\n"
                    "MARKER/21, PART = 2\n"
                    "MARKER/22, PART = 2, QP = 0.75, 0, 0\n"
                    "JOINT/1, REVOLUTE, I = 21, J = 10\n"
                    "GCON/1, I = 20, FUNCTION = DY(20, 10)\nEND\n",
                    values, sizeof values / sizeof values[0]);
}

/* Refused where they are written, with the file, line and column. */
static void refusals(void **state)
{
    (void)state;
    static const char *const cases[][3] = {
        {"GCON/2, I=20, FUNCTION=MOTION(1,0,8,0)",
         "bad.adm:12:24:", "MOTION(1,0,8,0): a constraint element's force is known only once"
         " the accelerations are: here it would close an algebraic loop"},
        {"REQUEST/1, F2=MOTION(4,0,8,0)",
         "bad.adm:12:15:", "MOTION(4,0,8,0): no Motion_Joint (MOTION) 4 in the model"},
        {"REQUEST/1, F2=COUPLER(4,0,8,0)",
         "bad.adm:12:15:", "COUPLER(4,0,8,0): no Constraint_Coupler (COUPLER) 4 in the model"},
        {"REQUEST/1, F2=GCON(4,0,8,0)",
         "bad.adm:12:15:", "GCON(4,0,8,0): no Constraint_General (GCON) 4 in the model"},
        {"REQUEST/1, F2=GCON(1,1,8,0)",
         "bad.adm:12:22:", "GCON: jflag (argument 2) is 1: 0 (on its I marker"},
        {"REQUEST/1, F2=COUPLER(1,6,8,0)",
         "bad.adm:12:25:", "COUPLER: jflag (argument 2) is 6: 0 to 5"},
        {"COUPLER/1, JOINTS=1, 2, TYPE=R:R, SCALES=1, 2\nREQUEST/1, F2=COUPLER(1,4,8,0)",
         "bad.adm:13:15:", "COUPLER(1,4,8,0): jflag (argument 2) is 4: Constraint_Coupler 1"
         " couples 2 joints (jflag 0 to 3)"},
        {"GCON/2, I=10, FUNCTION=DY(30,10)\nREQUEST/1, F2=GCON(2,0,2,0)",
         "bad.adm:13:15:", "GCON(2,0,2,0): Constraint_General 2 (line 12) has its I marker on"
         " ground"},
        {"GCON/2, I=10, FUNCTION=DY(30,10)\nREQUEST/1, F2=FX(10)",
         "bad.adm:13:15:", "FX(10): Constraint_General 2 (line 12) acts at marker 10, and the"
         " harness does not sum its force"},
    };
    expect_read_errors("bad.adm", "bad\nPART/1, GROUND\nMARKER/10, PART=1\n"
                       "MARKER/11, PART=1, QP=2,0,0\n"
                       "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\nMARKER/21, PART=2\n"
                       "PART/3, MASS=1, CM=30, IP=1,1,1\nMARKER/30, PART=3, QP=2,0,0\n"
                       "JOINT/1, REVOLUTE, I=21, J=10\nJOINT/2, REVOLUTE, I=30, J=11\n", cases,
                       sizeof cases / sizeof cases[0]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(motion_on_a_reduced_joint),
        cmocka_unit_test(motion_as_a_row),
        cmocka_unit_test(slider_driven_against_gravity),
        cmocka_unit_test(coupler_between_two_wheels),
        cmocka_unit_test(gcon_holds_a_point_mass),
        cmocka_unit_test(gcon_holds_a_hinged_bar),
        cmocka_unit_test(refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
