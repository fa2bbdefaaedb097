/*
 * ORIENT(system, component, I[, J]) (docs/interface.md §8.5): every one of
 * its 29 systems at rotations built here from known angles, so that each
 * expected value is an angle put in or a closed form of them; I relative to
 * a turned J; the identity; the sequences where their outer axes line up;
 * the half turn, where the Rodrigues parameters fault; and every bad
 * system, component or marker refused with its column. The slopes of every
 * system and component are checked against differences in
 * test_expr_loads.c (measure_slopes_against_differences), and a force
 * reading ORIENT through the whole Jacobian there too.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/vecmath.h"
#include "expr_support.h"

/* Ground with marker 10; bodies 2 and 3 with markers 20 and 30 at their
 * centres, their axes the bodies'. */
static const char *const model_xml =
    "<MotionSolve>\n<Model>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
    " inertia_zz=\"1\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\"/>\n"
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
    " inertia_zz=\"1\"/>\n"
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"-1\" pos_y=\"0.5\" pos_z=\"2\"/>\n"
    "</Model>\n</MotionSolve>\n";

static expr_fixture fixture;

static int setup(void **state)
{
    (void)state;
    expr_open(&fixture, "orient.xml", model_xml);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    expr_close(&fixture);
    return 0;
}

/* The rotation by angle about axis 0 (x), 1 (y) or 2 (z), row-major. */
static void about(int axis, double angle, double R[9])
{
    const double c = cos(angle), s = sin(angle);
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    m3_identity(R);
    R[3 * i + i] = c, R[3 * i + j] = -s;
    R[3 * j + i] = s, R[3 * j + j] = c;
}

/* R_a(t1) R_b(t2) R_c(t3): the axes named by the digits of "abc" (1 x, 2 y,
 * 3 z), turning about the body's axes as they turn. */
static void body_fixed(const char *abc, const double t[3], double R[9])
{
    double A[9], B[9], C[9], AB[9];
    about(abc[0] - '1', t[0], A);
    about(abc[1] - '1', t[1], B);
    about(abc[2] - '1', t[2], C);
    m3_mul(AB, A, B);
    m3_mul(R, AB, C);
}

/* t1 about a, then t2 about b, then t3 about c, all the fixed frame's axes:
 * R_c(t3) R_b(t2) R_a(t1). */
static void space_fixed(const char *abc, const double t[3], double R[9])
{
    double A[9], B[9], C[9], CB[9];
    about(abc[0] - '1', t[0], A);
    about(abc[1] - '1', t[1], B);
    about(abc[2] - '1', t[2], C);
    m3_mul(CB, C, B);
    m3_mul(R, CB, A);
}

/* Body id's axes (and so its marker's) turned to R in the world. */
static void turn(int id, const double R[9])
{
    m3_copy(fixture.frames.bodies[hx_model_body(fixture.model, id)].R, R);
    hx_frames_update(&fixture.frames);
}

static double orient(int system, int component, const char *markers)
{
    char text[64];
    snprintf(text, sizeof text, "ORIENT(%d, %d, %s)", system, component, markers);
    return expr_value(&fixture, text);
}

/* The sequences of systems 1 .. 12 (and, space-fixed, 13 .. 24), as the
 * function's definition names them. */
static const char *const sequences[12] = {"123", "231", "312", "132", "213", "321",
                                          "121", "131", "212", "232", "313", "323"};

/* J's turn in the relative cases: 1.1 rad about (1, -2, 0.5). */
static void j_turn(double R[9])
{
    double axis[3] = {1.0, -2.0, 0.5};
    v3_scale(axis, axis, 1.0 / v3_norm(axis));
    m3_axis_angle(R, axis, 1.1);
}

/* Systems 1 .. 24: the rotation built from three angles gives them back,
 * each component its own angle, I against the ground (J left out, and 10)
 * and against a turned J; a second set of angles near the ends of their
 * ranges (a first angle below -pi/2, a last one near pi, a negative middle
 * one for a Tait-Bryan sequence). */
static void euler_angles_of_every_sequence_by_hand(void **state)
{
    (void)state;
    double RJ[9];
    j_turn(RJ);
    int checked = 0;
    for (int set = 0; set < 2; ++set)
        for (int system = 1; system <= 24; ++system) {
            const char *abc = sequences[(system - 1) % 12];
            const int proper = abc[0] == abc[2];
            const double t[3] = {set ? -2.5 : 0.3, set ? (proper ? 2.6 : -1.2) : 0.5,
                                 set ? 3.0 : 0.7};
            double R[9], RI[9], I3[9];
            if (system <= 12)
                body_fixed(abc, t, R);
            else
                space_fixed(abc, t, R);
            m3_identity(I3);
            turn(3, I3);
            turn(2, R);
            for (int k = 1; k <= 3; ++k) {
                const double ground = orient(system, k, "20");
                if (fabs(ground - t[k - 1]) > 1e-14)
                    fail_msg("ORIENT(%d, %d, 20) = %.17g, built from %.17g", system, k, ground,
                             t[k - 1]);
                assert_close(orient(system, k, "20, 10"), t[k - 1], 0.0, 1e-14);
                assert_close(orient(system, k, "20, 30"), t[k - 1], 0.0, 1e-14);
            }
            /* I relative to J, J turned: I's world axes R_J R */
            m3_mul(RI, RJ, R);
            turn(3, RJ);
            turn(2, RI);
            for (int k = 1; k <= 3; ++k) {
                const double relative = orient(system, k, "20, 30");
                if (fabs(relative - t[k - 1]) > 1e-13)
                    fail_msg("ORIENT(%d, %d, 20, 30) = %.17g, built from %.17g", system, k,
                             relative, t[k - 1]);
                ++checked;
            }
        }
    printf("  %d angles of the 24 sequences given back\n", checked);
}

/* Systems 25 .. 29 at R = Rz(psi) Rx(theta) Rz(phi), psi 0.3, theta 0.5,
 * phi 0.7, whose matrix and half-angle products are written out here:
 *   R = [[cp cf - sp ct sf, -cp sf - sp ct cf,  sp st],
 *        [sp cf + cp ct sf, -sp sf + cp ct cf, -cp st],
 *        [st sf,             st cf,             ct   ]],
 *   e = (cos(th/2) cos((p+f)/2), sin(th/2) cos((p-f)/2), sin(th/2) sin((p-f)/2),
 *        cos(th/2) sin((p+f)/2)): a turn of 2 acos(e0) about (e1, e2, e3);
 * system 26 at Rz(0.3) Ry(0.5) Rx(0.7): YAW 0.3, PITCH -0.5, ROLL 0.7. */
static void the_other_systems_by_hand(void **state)
{
    (void)state;
    const double p = 0.3, th = 0.5, f = 0.7;
    const double cp = cos(p), sp = sin(p), ct = cos(th), st = sin(th), cf = cos(f), sf = sin(f);
    const double R[9] = {cp * cf - sp * ct * sf, -cp * sf - sp * ct * cf, sp * st,
                         sp * cf + cp * ct * sf, -sp * sf + cp * ct * cf, -cp * st,
                         st * sf,                st * cf,                 ct};
    const double e[4] = {cos(0.25) * cos(0.5), sin(0.25) * cos(-0.2), sin(0.25) * sin(-0.2),
                         cos(0.25) * sin(0.5)};
    double RJ[9], RI[9];
    j_turn(RJ);
    m3_mul(RI, RJ, R);
    for (int relative = 0; relative < 2; ++relative) {
        double I3[9];
        m3_identity(I3);
        turn(3, relative ? RJ : I3);
        turn(2, relative ? RI : R);
        const char *const markers = relative ? "20, 30" : "20";
        const double tol = 1e-14;
        /* 25: AX = atan2(y_I.z_J, y_I.y_J), AY = atan2(z_I.x_J, z_I.z_J),
         * AZ = atan2(x_I.y_J, x_I.x_J) */
        assert_close(orient(25, 1, markers), atan2(st * cf, -sp * sf + cp * ct * cf), 0.0, tol);
        assert_close(orient(25, 2, markers), atan2(sp * st, ct), 0.0, tol);
        assert_close(orient(25, 3, markers), atan2(sp * cf + cp * ct * sf,
                                                   cp * cf - sp * ct * sf), 0.0, tol);
        for (int k = 0; k < 4; ++k) /* 27: e0 .. e3, e0 > 0; e2 < 0 here */
            assert_close(orient(27, k + 1, markers), e[k], 0.0, tol);
        for (int k = 0; k < 3; ++k) /* 28: e_k / e0 */
            assert_close(orient(28, k + 1, markers), e[k + 1] / e[0], 0.0, tol);
        for (int k = 0; k < 9; ++k) /* 29: x_I.x_J, x_I.y_J, x_I.z_J, y_I.x_J, ... */
            assert_close(orient(29, k + 1, markers), R[3 * (k % 3) + k / 3], 0.0, tol);
    }
    /* 26: YAW, PITCH (the second angle negated), ROLL; system 6 keeps the sign */
    const double ypr[3] = {0.3, 0.5, 0.7};
    double Y[9], I3[9];
    body_fixed("321", ypr, Y);
    m3_identity(I3);
    turn(3, I3);
    turn(2, Y);
    assert_close(orient(26, 1, "20"), 0.3, 0.0, 1e-15);
    assert_close(orient(26, 2, "20"), -0.5, 0.0, 1e-15);
    assert_close(orient(26, 3, "20"), 0.7, 0.0, 1e-15);
    assert_close(orient(6, 2, "20"), 0.5, 0.0, 1e-15);
    assert_close(expr_value(&fixture, "ORIENT(26, 2, 20) - PITCH(20)"), 0.0, 0.0, 0.0);
    assert_close(expr_value(&fixture, "ORIENT(11, 2, 20, 30) - THETA(20, 30)"), 0.0, 0.0, 0.0);
}

/* I's axes J's: every angle 0, e = (1, 0, 0, 0), the Rodrigues parameters 0,
 * the direction cosines the identity's. A proper sequence's outer axes line
 * up there: where J is turned, R_J^T R_I is the identity to rounding, and
 * only the sum of its outer angles is defined (0; the split is the
 * rounding's, as PSI's and PHI's at rest, docs/interface.md §3.1). */
static void the_identity_in_every_system(void **state)
{
    (void)state;
    double RJ[9];
    j_turn(RJ);
    turn(3, RJ);
    turn(2, RJ);
    for (int system = 1; system <= 29; ++system) {
        const int components = system == 27 ? 4 : system == 29 ? 9 : 3;
        const char *abc = sequences[(system - 1) % 12];
        if (system <= 24 && abc[0] == abc[2]) {
            assert_close(orient(system, 2, "20, 30"), 0.0, 0.0, 1e-15);
            assert_close(remainder(orient(system, 1, "20, 30") + orient(system, 3, "20, 30"),
                                   2 * M_PI), 0.0, 0.0, 1e-15);
            continue;
        }
        for (int k = 1; k <= components; ++k) {
            double expected = 0.0;
            if (system == 27 && k == 1)
                expected = 1.0;
            if (system == 29 && (k == 1 || k == 5 || k == 9))
                expected = 1.0;
            const double value = orient(system, k, "20, 30");
            if (fabs(value - expected) > 1e-15)
                fail_msg("ORIENT(%d, %d) of the identity = %.17g, not %g", system, k, value,
                         expected);
        }
    }
    /* I and the ground's axes exactly alike: every angle exactly 0 */
    double I3[9];
    m3_identity(I3);
    turn(2, I3);
    for (int system = 1; system <= 26; ++system)
        for (int k = 1; k <= 3; ++k)
            assert_true(orient(system, k, "20") == 0.0);
}

/* Where a sequence's outer axes line up only their sum (or difference) is
 * defined: it comes out right, the middle angle at its end; where they line
 * up exactly, all of it goes to the first angle. */
static void the_angles_where_the_outer_axes_line_up(void **state)
{
    (void)state;
    double R[9], I3[9];
    m3_identity(I3);
    turn(3, I3);
    /* body 1-2-3 (system 1) at +pi/2: Ry(pi/2) takes z to x, so t1 + t3 */
    body_fixed("123", (const double[]){0.3, M_PI / 2, 0.7}, R);
    turn(2, R);
    assert_close(orient(1, 2, "20"), M_PI / 2, 0.0, 1e-15);
    assert_close(orient(1, 1, "20") + orient(1, 3, "20"), 1.0, 0.0, 1e-14);
    /* at -pi/2 z goes to -x: t1 - t3 */
    body_fixed("123", (const double[]){0.3, -M_PI / 2, 0.7}, R);
    turn(2, R);
    assert_close(orient(1, 2, "20"), -M_PI / 2, 0.0, 1e-15);
    assert_close(orient(1, 1, "20") - orient(1, 3, "20"), -0.4, 0.0, 1e-14);
    /* exactly lined up: Rx(1) Ry(pi/2) = [[0, 0, 1], [s, c, 0], [-c, s, 0]] */
    const double s = sin(1.0), c = cos(1.0);
    const double locked[9] = {0, 0, 1, s, c, 0, -c, s, 0};
    turn(2, locked);
    assert_true(orient(1, 1, "20") == 1.0);
    assert_true(orient(1, 2, "20") == M_PI / 2);
    assert_true(orient(1, 3, "20") == 0.0);
    /* space 1-2-3 (system 13), the body 3-2-1 sequence of t3, t2, t1: at
     * +pi/2 its roll less its yaw, t1 - t3 */
    space_fixed("123", (const double[]){0.3, M_PI / 2, 0.7}, R);
    turn(2, R);
    assert_close(orient(13, 2, "20"), M_PI / 2, 0.0, 1e-15);
    assert_close(orient(13, 1, "20") - orient(13, 3, "20"), -0.4, 0.0, 1e-14);
    /* body 1-2-1 (system 7) at 0, a turn of t1 + t3 about x, and at pi */
    body_fixed("121", (const double[]){0.3, 0.0, 0.7}, R);
    turn(2, R);
    assert_true(orient(7, 2, "20") == 0.0);
    assert_close(orient(7, 1, "20"), 1.0, 0.0, 1e-15); /* exactly lined up: all to t1 */
    assert_true(orient(7, 3, "20") == 0.0);
    body_fixed("121", (const double[]){0.3, M_PI, 0.7}, R);
    turn(2, R);
    assert_close(orient(7, 2, "20"), M_PI, 0.0, 1e-15);
    assert_close(remainder(orient(7, 1, "20") - orient(7, 3, "20") + 0.4, 2 * M_PI), 0.0, 0.0,
                 1e-14);
}

/* A half turn: the Euler parameters (0, axis) with the axis's first nonzero
 * component positive, the Rodrigues parameters a fault naming the place. */
static void a_half_turn(void **state)
{
    (void)state;
    double I3[9];
    m3_identity(I3);
    turn(3, I3);
    turn(2, (const double[]){-1, 0, 0, 0, -1, 0, 0, 0, 1}); /* pi about z */
    const double about_z[4] = {0, 0, 0, 1};
    for (int k = 0; k < 4; ++k)
        assert_true(orient(27, k + 1, "20") == about_z[k]);
    turn(2, (const double[]){-1, 0, 0, 0, 1, 0, 0, 0, -1}); /* pi about y, or -y */
    const double about_y[4] = {0, 0, 1, 0};
    for (int k = 0; k < 4; ++k)
        assert_true(orient(27, k + 1, "20") == about_y[k]);
    hx_message msg;
    const hx_expr_fault fault = expr_fault(&fixture, "1 + ORIENT(28, 2, 20)", &msg);
    assert_int_equal(fault.kind, HX_EXPR_FAULT_DOMAIN);
    assert_contains(msg.text, "test.xml:1:5: ", "ORIENT: I is turned half a turn from J, where"
                    " the Rodrigues parameters are not defined");
}

/* Each bad number named with its own column; a marker the model does not
 * have when the expression is linked. */
static void bad_systems_components_and_markers(void **state)
{
    (void)state;
    hx_message msg;
    assert_contains(expr_parse_error("ORIENT(30, 1, 20)", &msg),
                    "m.xml:10:12: ORIENT: system (argument 1) is 30: 1 to 12 the body-fixed",
                    "29 the direction cosines");
    assert_contains(expr_parse_error("ORIENT(0, 1, 20)", &msg),
                    "m.xml:10:12: ORIENT: system (argument 1) is 0");
    assert_contains(expr_parse_error("ORIENT(27, 5, 20)", &msg),
                    "m.xml:10:16: ORIENT: component (argument 2) is 5: system 27 (the Euler"
                    " parameters e0, e1, e2, e3) has components 1 to 4");
    assert_contains(expr_parse_error("ORIENT(1, 4, 20)", &msg),
                    "m.xml:10:15: ORIENT: component (argument 2) is 4: system 1 (body-fixed"
                    " 1-2-3 Euler angles) has components 1 to 3");
    assert_contains(expr_parse_error("ORIENT(29, 0, 20)", &msg),
                    "m.xml:10:16: ORIENT: component (argument 2) is 0");
    assert_contains(expr_parse_error("ORIENT(29, 10, 20)", &msg),
                    "m.xml:10:16: ORIENT: component (argument 2) is 10: system 29",
                    "components 1 to 9");
    assert_contains(expr_parse_error("ORIENT(1, 1, 0)", &msg),
                    "m.xml:10:18: ORIENT: its I marker (argument 3) is 0");
    assert_contains(expr_parse_error("ORIENT(-1, 1, 20)", &msg),
                    "m.xml:10:12: ORIENT(system, component, I[, J]): argument 1 must be written"
                    " as a whole number");
    assert_contains(expr_parse_error("ORIENT(1, 1)", &msg),
                    "m.xml:10:5: ORIENT takes 3 to 4 arguments ORIENT(system, component, I[, J]),"
                    " not 2");
    assert_contains(expr_link_error(&fixture, "2 * ORIENT(1, 1, 20, 99)", &msg),
                    "m.xml:10:9: ORIENT(1,1,20,99): no Reference_Marker 99 in the model");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(euler_angles_of_every_sequence_by_hand),
        cmocka_unit_test(the_other_systems_by_hand),
        cmocka_unit_test(the_identity_in_every_system),
        cmocka_unit_test(the_angles_where_the_outer_axes_line_up),
        cmocka_unit_test(a_half_turn),
        cmocka_unit_test(bad_systems_components_and_markers),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
