/*
 * The force functions in requests (docs/interface.md §7.13, §8.3): the
 * force elements' forces by id (SFORCE, VFORCE, VTORQ, GFORCE, FIELD: jflag
 * 0 on I at I, 1 on J where the element puts it, comp 1 .. 8 in rm's axes),
 * the net force and torque at a marker (FX .. TM: every element between I
 * and J, or acting at I when J is left out, in K's axes) and REQUEST/FORCE
 * and Post_Request's MARKER_FORCE in Adams' order (F1 FM, F2..F4 FX..FZ in
 * RM's axes, F5 TM, F6..F8 TX..TZ; J left out: the action-only forces at I).
 * Every value worked by hand at a state where each component differs:
 * expression forces and a FIXED joint's reaction (the applied loads'
 * opposite, the body at rest), and user routines' forces (an SFOSUB, a
 * FIESUB, a GFOSUB, each a spring at rest of known stiffness). Refusals: in
 * a force or variable (file:line:column), an unknown id, a marker where an
 * element acts whose force is not summed.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/marker_elements.h"
#include "model/expr/functions.h"
#include "model_runs.h"
#include "sim/dynamics/element_outputs.h"
#include "sim/simulation/requests.h"
#include "sim_support.h"
#include "test_support.h"

/* Ground: 10 at the origin, 11 turned a quarter about z (x' the world's y,
 * y' its -x), 12 at (1, 0, 0). Part 2 (at rest) held to ground by the FIXED
 * JOINT/1 at 21 = 12; part 3 free. SFORCE/1 pulls 30 toward 22 with 14
 * ((2, 3, 6) / 7 apart): on 30 (-4, -6, -12), on 22 (4, 6, 12). VFORCE/2 on 23
 * is (1, 2, 3) in 11's axes, (-2, 1, 3) in the world's, its floating J 31
 * away from 23; GFORCE/3 on 24 (0.5, -1.5, 2.5) and (7, -8, 9), its J 32 away
 * from 24. SFORCE/4 is action-only on 33, 10 along (0, 3, 4) / 5 = (0, 6, 8).
 * Part 2 does not move, so the joint holds it against the rest: on 21,
 * F = -(2.5, 5.5, 17.5) and about 21 T = -(5.5, 7.5, 7), the moments of
 * (4, 6, 12) at (0, 0, 1), (-2, 1, 3) at (1, 2, 0), (0.5, -1.5, 2.5) at (1, 0, -1)
 * about (1, 0, 0) being (-6, 16, -6), (6, 0, 4), (-1.5, -0.5, 0), plus
 * (7, -8, 9). */
static const char forces[] =
    "forces\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, REULER=90D,0,0\n"
    "MARKER/12, PART=1, QP=1,0,0\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2\n"
    "MARKER/21, PART=2, QP=1,0,0\n"
    "MARKER/22, PART=2, QP=0,0,1\n"
    "MARKER/23, PART=2, QP=1,2,0\n"
    "MARKER/24, PART=2, QP=1,0,-1\n"
    "PART/3, MASS=1, CM=35, IP=1,1,1\n"
    "MARKER/35, PART=3, QP=2,3,5\n"
    "MARKER/30, PART=3, QP=2,3,7\n"
    "MARKER/31, PART=3, QP=2,3,5\n"
    "MARKER/32, PART=3, QP=-1,4,2\n"
    "MARKER/33, PART=3, QP=0,3,4\n"
    "JOINT/1, FIXED, I=21, J=12\n"
    "SFORCE/1, TRANSLATION, I=30, J=22, FUNCTION=-14\n"
    "VFORCE/2, I=23, JFLOAT=31, RM=11, FX=1\\FY=2\\FZ=3\n"
    "GFORCE/3, I=24, JFLOAT=32, RM=10, FX=0.5\\FY=-1.5\\FZ=2.5\\TX=7\\TY=-8\\TZ=9\n"
    "SFORCE/4, TRANSLATION, ACTIONONLY, I=33, J=10, FUNCTION=10\n"
    "REQUEST/5, FORCE, I=21, J=12, RM=11\n"
    "REQUEST/6, FORCE, I=33\n"
    "REQUEST/7, FORCE, I=22\n"
    "END\n";

/* REQUEST/5: the joint's reaction on 21 in 11's axes, (F.x', F.y', F.z') and
 * the torque's; REQUEST/6: the action-only force at 33; REQUEST/7: none is
 * action-only at 22 (FX(22) is SFORCE/1's, below). */
static const double request5[8] = {18.513508581573616, -5.5, 2.5, -17.5,
                                   11.640446726822816, -7.5, 5.5, -7.0};
static const double request6[8] = {10, 0, 6, 8, 0, 0, 0, 0};

static void expression_forces_and_a_joint(void **state)
{
    (void)state;
    assert_true(fabs(request5[0] - sqrt(342.75)) < 1e-14);
    assert_true(fabs(request5[4] - sqrt(135.5)) < 1e-14);
    evaluated e;
    evaluate_text(&e, "forces.adm", forces);
    const double tol = 1e-9;
    /* VFORCE/2: on I; on J (its floating J, where I is): the opposite, no torque */
    EXPECT(&e, "VFORCE(2, 0, 1, 0)", sqrt(14.0), tol);
    EXPECT(&e, "VFORCE(2, 0, 2, 0)", -2.0, tol);
    EXPECT(&e, "VFORCE(2, 0, 3, 0)", 1.0, tol);
    EXPECT(&e, "VFORCE(2, 0, 4, 0)", 3.0, tol);
    EXPECT(&e, "VFORCE(2, 1, 2, 0)", 2.0, tol);
    EXPECT(&e, "VFORCE(2, 1, 4, 0)", -3.0, tol);
    EXPECT(&e, "VFORCE(2, 1, 5, 0)", 0.0, tol);
    EXPECT(&e, "VFORCE(2, 0, 2, 11)", 1.0, tol); /* its own RM's components */
    EXPECT(&e, "VFORCE(2, 0, 3, 11)", 2.0, tol);
    /* GFORCE/3 (VTORQ names the same element, as MotionSolve's pages do) */
    EXPECT(&e, "GFORCE(3, 0, 5, 0)", sqrt(194.0), tol);
    EXPECT(&e, "VTORQ(3, 0, 6, 0)", 7.0, tol);
    EXPECT(&e, "GFORCE(3, 0, 7, 0)", -8.0, tol);
    EXPECT(&e, "GFORCE(3, 0, 8, 0)", 9.0, tol);
    EXPECT(&e, "GFORCE(3, 1, 6, 0)", -7.0, tol);
    EXPECT(&e, "GFORCE(3, 1, 3, 0)", 1.5, tol);
    EXPECT(&e, "GFORCE(3, 0, 6, 11)", -8.0, tol);
    EXPECT(&e, "GFORCE(3, 0, 7, 11)", -7.0, tol);
    EXPECT(&e, "SFORCE(1, 0, 1, 0)", 14.0, tol);
    EXPECT(&e, "SFORCE(1, 1, 4, 0)", 12.0, tol);
    /* the joint's reaction */
    EXPECT(&e, "JOINT(1, 0, 2, 0)", -2.5, tol);
    EXPECT(&e, "JOINT(1, 0, 6, 0)", -5.5, tol);
    EXPECT(&e, "JOINT(1, 1, 8, 0)", 7.0, tol);
    /* FX .. TM between 21 and 12: the joint's */
    EXPECT(&e, "FX(21, 12)", -2.5, tol);
    EXPECT(&e, "FY(21, 12)", -5.5, tol);
    EXPECT(&e, "FZ(21, 12)", -17.5, tol);
    EXPECT(&e, "TX(21, 12)", -5.5, tol);
    EXPECT(&e, "TY(21, 12)", -7.5, tol);
    EXPECT(&e, "TZ(21, 12)", -7.0, tol);
    EXPECT(&e, "FM(21)", sqrt(342.75), tol);
    EXPECT(&e, "TM(21, 12)", sqrt(135.5), tol);
    EXPECT(&e, "FX(21, 12, 11)", -5.5, tol);
    EXPECT(&e, "FY(21, 12, 11)", 2.5, tol);
    EXPECT(&e, "TY(21, 0, 11)", 5.5, tol);
    /* at J: the opposite (the same point) */
    EXPECT(&e, "FX(12, 21)", 2.5, tol);
    EXPECT(&e, "TZ(12, 21)", 7.0, tol);
    EXPECT(&e, "FZ(12)", 17.5, tol);
    /* SFORCE/1 at 22 and 30; nothing between 22 and 31 */
    EXPECT(&e, "FX(22)", 4.0, tol);
    EXPECT(&e, "FY(22, 30)", 6.0, tol);
    EXPECT(&e, "FX(22, 0, 11)", 6.0, tol);
    EXPECT(&e, "FY(22, 0, 11)", -4.0, tol);
    EXPECT(&e, "FZ(22, 0, 11)", 12.0, tol);
    EXPECT(&e, "FM(22, 31)", 0.0, tol);
    EXPECT(&e, "FX(30)", -4.0, tol);
    /* a floating J is where its I is: the reaction's torque has no lever there */
    EXPECT(&e, "FX(31)", 2.0, tol);
    EXPECT(&e, "TM(31)", 0.0, tol);
    EXPECT(&e, "TX(32, 24)", -7.0, tol);
    EXPECT(&e, "TY(32)", 8.0, tol);
    EXPECT(&e, "FZ(32)", -2.5, tol);
    /* the action-only force on 33; nothing on 10 from it */
    EXPECT(&e, "FY(33)", 6.0, tol);
    EXPECT(&e, "FZ(33, 10)", 8.0, tol);
    EXPECT(&e, "FM(10)", 0.0, tol);
    /* REQUEST/5, /6, /7 at the state */
    const hx_model *m = e.m.session.model;
    assert_int_equal(m->nrequests, 3);
    double got[8];
    hx_message msg;
    for (int k = 0; k < 3; ++k) {
        assert_int_equal(m->requests[k].kind, HX_REQUEST_FORCE);
        assert_int_equal(hx_requests_values(&e.m.data.frames, k, NULL, &e.outputs, got, &msg), 0);
        for (int j = 0; j < 8; ++j) {
            const double want = k == 0 ? request5[j] : k == 1 ? request6[j] : 0.0;
            if (fabs(got[j] - want) > tol)
                fail_msg("REQUEST/%d F%d = %.15g, expected %.15g", 5 + k, j + 1, got[j], want);
        }
    }
    /* without what an output time knows: a fault naming the request */
    assert_int_equal(hx_requests_values(&e.m.data.frames, 0, NULL, NULL, got, &msg), -1);
    assert_contains(msg.text, "forces.adm:", "REQUEST/5: FORCE: no forces were given");
    release(&e);
}

/* The same requests in a run's CSV: the first row is the model's state. */
static void force_requests_in_the_csv(void **state)
{
    (void)state;
    char csv[512];
    const char *path = test_write_file("forces_run.adm", forces);
    snprintf(csv, sizeof csv, "%s/forces_run.csv", test_temp_dir());
    const char *const args[] = {"--end", "0.01", "--output-interval", "0.01", "--quiet", NULL};
    assert_int_equal(sim_run_csv(path, csv, args), 0);
    const int first = csv_column(csv, "request5.1");
    assert_true(first > 0);
    assert_int_equal(csv_column(csv, "request6.1"), first + 8);
    assert_int_equal(csv_column(csv, "request7.8"), first + 23);
    csv_table t;
    csv_read(csv, &t);
    assert_true(t.rows >= 1);
    assert_true(csv_at(&t, 0, 0) == 0.0);
    for (int k = 0; k < 24; ++k) {
        const double want = k < 8 ? request5[k] : k < 16 ? request6[k - 8] : 0.0;
        if (fabs(csv_at(&t, 0, first + k) - want) > 1e-9)
            fail_msg("request%d.%d = %.15g, expected %.15g", 5 + k / 8, k % 8 + 1,
                     csv_at(&t, 0, first + k), want);
    }
    csv_free(&t);
}

/* User routines' forces, each a spring of part 2 (at rest, turned 0.25 rad
 * about z) to ground marker 10 at the origin (ground's 11 is turned a quarter
 * about x: x' the world's x, y' its z, z' its -y): LINE_SPRING (SFOSUB, k 2, L0 0)
 * from 20 at (2, 3, 6), 7 away: -14 along (2, 3, 6) / 7 = (-4, -6, -12);
 * scaled_field's FIESUB (k 5, kr 3) at 21 = (1, -2, 0.5): (-5, 10, -2.5) and
 * about z -0.75; SCALED_SPRING (GFOSUB, k 4, kr 2) at 22 = (0.5, 1, -1.5),
 * floating J 10: (-2, -4, 6) and about z -0.5. */
static const char *routines_model(void)
{
    static char text[4096];
    const double c = cos(0.25), s = sin(0.25);
    char turn[128];
    snprintf(turn, sizeof turn, " a00=\"%.17g\" a10=\"%.17g\" a01=\"%.17g\" a11=\"%.17g\"", c, s,
             -s, c);
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Reference_Marker id=\"11\" body_id=\"1\" a11=\"0\" a21=\"1\" a12=\"-1\" a22=\"0\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
             " inertia_zz=\"1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"2\" pos_y=\"3\" pos_z=\"6\"%s/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"1\" pos_y=\"-2\" pos_z=\"0.5\"%s/>\n"
             "<Reference_Marker id=\"22\" body_id=\"2\" pos_x=\"0.5\" pos_y=\"1\" pos_z=\"-1.5\"%s/>\n"
             "<Force_Scalar_TwoBody id=\"1\" type=\"FORCE\" i_marker_id=\"20\" j_marker_id=\"10\""
             " usrsub_param_string=\"USER(20, 10, 2, 0)\" usrsub_fnc_name=\"LINE_SPRING\""
             " usrsub_dll_name=\"libtp_scalar.so\"/>\n"
             "<Force_Field id=\"2\" i_marker_id=\"21\" j_marker_id=\"10\""
             " usrsub_param_string=\"USER(5, 0, 3, 0)\" usrsub_dll_name=\"%s\"/>\n"
             "<Force_Vector_TwoBody id=\"3\" type=\"ForceAndTorque\" i_marker_id=\"22\""
             " j_floating_marker_id=\"10\" ref_marker_id=\"10\""
             " usrsub_param_string=\"USER(22, 10, 4, 0, 2, 0)\" usrsub_fnc_name=\"SCALED_SPRING\""
             " usrsub_dll_name=\"%s\"/>\n"
             "<Post_Request id=\"7\" type=\"MARKER_FORCE\" i_marker_id=\"21\" j_marker_id=\"10\""
             " ref_marker_id=\"11\"/>\n"
             "</Model></MotionSolve>\n",
             turn, turn, turn, SCALED_FIELD_LIBRARY, SCALED_FIELD_LIBRARY);
    return text;
}

static void user_routines_forces(void **state)
{
    (void)state;
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    evaluated e;
    evaluate_text(&e, "routines.xml", routines_model());
    const double tol = 1e-9;
    EXPECT(&e, "SFORCE(1, 0, 1, 0)", 14.0, tol);
    EXPECT(&e, "SFORCE(1, 0, 2, 0)", -4.0, tol);
    EXPECT(&e, "SFORCE(1, 1, 4, 0)", 12.0, tol);
    EXPECT(&e, "SFORCE(1, 0, 3, 11)", -12.0, tol);
    EXPECT(&e, "FIELD(2, 0, 2, 0)", -5.0, tol);
    EXPECT(&e, "FIELD(2, 0, 3, 11)", -2.5, tol);
    EXPECT(&e, "FIELD(2, 0, 4, 11)", -10.0, tol);
    EXPECT(&e, "FIELD(2, 0, 8, 0)", -0.75, tol);
    EXPECT(&e, "FIELD(2, 1, 2, 0)", 5.0, tol);
    EXPECT(&e, "FIELD(2, 1, 8, 0)", 0.75, tol);
    EXPECT(&e, "GFORCE(3, 0, 2, 0)", -2.0, tol);
    EXPECT(&e, "GFORCE(3, 0, 4, 0)", 6.0, tol);
    EXPECT(&e, "GFORCE(3, 0, 8, 0)", -0.5, tol);
    EXPECT(&e, "GFORCE(3, 1, 3, 0)", 4.0, tol);
    EXPECT(&e, "GFORCE(3, 1, 8, 0)", 0.5, tol);
    EXPECT(&e, "VFORCE(3, 0, 2, 11)", -2.0, tol);
    EXPECT(&e, "VFORCE(3, 0, 4, 11)", 4.0, tol);
    EXPECT(&e, "VTORQ(3, 0, 5, 0)", 0.5, tol);
    /* at ground's 10, every J side: (4, 6, 12) + (5, -10, 2.5) + (2, 4, -6), and
     * about z the field's 0.75 and the GFOSUB's 0.5 */
    EXPECT(&e, "FX(10)", 11.0, tol);
    EXPECT(&e, "FY(10)", 0.0, tol);
    EXPECT(&e, "FZ(10)", 8.5, tol);
    EXPECT(&e, "TZ(10)", 1.25, tol);
    EXPECT(&e, "FX(10, 21)", 5.0, tol);
    EXPECT(&e, "FX(10, 20)", 4.0, tol);
    EXPECT(&e, "FX(10, 22)", 2.0, tol);
    EXPECT(&e, "TZ(21)", -0.75, tol);
    /* Post_Request 7, MARKER_FORCE at 21 from 10 in 11's axes */
    const double want[8] = {sqrt(131.25), -5, -2.5, -10, 0.75, 0, -0.75, 0};
    double got[8];
    hx_message msg;
    assert_int_equal(e.m.session.model->requests[0].kind, HX_REQUEST_FORCE);
    assert_int_equal(hx_requests_values(&e.m.data.frames, 0, NULL, &e.outputs, got, &msg), 0);
    for (int j = 0; j < 8; ++j)
        if (fabs(got[j] - want[j]) > tol)
            fail_msg("Post_Request 7 expr%d = %.15g, expected %.15g", j + 1, got[j], want[j]);
    /* the J side of a field is moved to J's origin, a floating J's is not: with a
     * force not along the line, F (1, 2, 3) and T (4, 5, 6) on I, the field's J gets
     * -T - x_21 x F = -(4, 5, 6) - (-7, -2.5, 4) = (3, -2.5, -10) */
    const hx_model *m = e.m.session.model;
    int is_force, field, vector;
    char what[256];
    assert_int_equal(hx_marker_element_find(m, HX_FN_FIELD, 2, &is_force, &field, what,
                                            sizeof what), 0);
    assert_int_equal(is_force, 1);
    assert_int_equal(hx_marker_element_find(m, HX_FN_GFORCE, 3, &is_force, &vector, what,
                                            sizeof what), 0);
    const double load[6] = {1, 2, 3, 4, 5, 6};
    memcpy(e.m.data.element_load + 6 * field, load, sizeof load);
    memcpy(e.m.data.element_load + 6 * vector, load, sizeof load);
    hx_element_outputs_forces(&e.m.d, &e.m.data, e.forces);
    EXPECT(&e, "FIELD(2, 1, 2, 0)", -1.0, tol);
    EXPECT(&e, "FIELD(2, 1, 6, 0)", 3.0, tol);
    EXPECT(&e, "FIELD(2, 1, 7, 0)", -2.5, tol);
    EXPECT(&e, "FIELD(2, 1, 8, 0)", -10.0, tol);
    EXPECT(&e, "GFORCE(3, 1, 6, 0)", -4.0, tol);
    EXPECT(&e, "GFORCE(3, 1, 8, 0)", -6.0, tol);
    release(&e);
}

/* Refused where they are written: in a general constraint (an algebraic loop
 * the harness does not solve there), an id the model does not define, a
 * marker where an element acts whose force the harness does not sum. */
static void refusals(void **state)
{
    (void)state;
    static const char *const cases[][3] = {
        {"GCON/1, I=20, FUNCTION=2*FX(20)",
         "bad.adm:8:26:", "FX(20): the forces at a marker are known only once the accelerations"
         " are: here they would close an algebraic loop"},
        {"GCON/1, I=20, FUNCTION=1+VFORCE(2,0,2,0)",
         "bad.adm:8:26:", "VFORCE(2,0,2,0): another element's force: here it would close an"
         " algebraic loop"},
        {"REQUEST/1, F2=VFORCE(9,0,2,0)",
         "bad.adm:8:15:", "VFORCE(9,0,2,0): no Force_Vector_TwoBody or Force_Vector_OneBody"
         " (VFORCE, VTORQUE, GFORCE) 9 in the model"},
        {"REQUEST/1, F2=FIELD(2,0,2,0)",
         "bad.adm:8:15:", "FIELD(2,0,2,0): no Force_Field (FIELD) 2 in the model"},
        {"REQUEST/1, F2=BUSHING(1,0,2,0)",
         "bad.adm:8:15:", "BUSHING(1,0,2,0): no Force_Bushing (BUSHING) 1 in the model"},
        {"REQUEST/1, F2=TX(99, 10)",
         "bad.adm:8:15:", "TX(99,10): no Reference_Marker 99 in the model"},
        {"GCON/1, I=10, FUNCTION=DX(20,10)\nREQUEST/1, F2=FX(10)",
         "bad.adm:9:15:", "FX(10): Constraint_General 1 (line 8) acts at marker 10, and the"
         " harness does not sum its force"},
    };
    expect_read_errors("bad.adm", "bad\nPART/1, GROUND\nMARKER/10, PART=1\n"
                       "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
                       "JOINT/1, REVOLUTE, I=20, J=10\n"
                       "VFORCE/2, I=20, JFLOAT=10, FX=1\n", cases,
                       sizeof cases / sizeof cases[0]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(expression_forces_and_a_joint),
        cmocka_unit_test(force_requests_in_the_csv),
        cmocka_unit_test(user_routines_forces),
        cmocka_unit_test(refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
