/*
 * A coupler's rotations between two moving bodies over many turns
 * (docs/interface.md §2, sim/dynamics/joint_turns.h): a carrier turning
 * about z with two gears on revolutes to it, coupled 2:1 (all three joints
 * between moving bodies), run for 10 s with DOPRI5 and with BDF while the
 * gears turn 5.7 and 11.4 times against the carrier; the angles measured
 * here from the bodies' quaternions and unwrapped here against the closed
 * form, and the coupler's relation between them; a step that turns more
 * than pi refused, naming the coupler, the joint and the step; the
 * integrators' accept hook, which moves the count, called at accepted steps
 * alone.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim/ode/integrator.h"
#include "sim/simulation/simulation.h"
#include "sim_support.h"
#include "test_support.h"

/* Carrier (2) on a revolute to ground about z at the origin; gear A (3) at
 * z = 0.2 and gear B (4) at z = -0.2 on revolutes to the carrier about the
 * same axis; the coupler p_A - 2 p_B = 0 of the gears' angles to the
 * carrier; a torque Ta = 0.1 on gear A from ground about z. The carrier
 * starts at 3 rad/s, gear B at 5 (2 against the carrier), gear A at 7 (4:
 * the coupler's rate). No gravity. */
static const char turning_model[] =
    "<MotionSolve><Model>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"3\" inertia_xx=\"0.5\" inertia_yy=\"0.6\""
    " inertia_zz=\"0.7\" w_ic_z=\"3\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
    "<Reference_Marker id=\"21\" body_id=\"2\" pos_z=\"0.2\"/>\n"
    "<Reference_Marker id=\"22\" body_id=\"2\" pos_z=\"-0.2\"/>\n"
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1.2\" inertia_xx=\"0.2\" inertia_yy=\"0.2\""
    " inertia_zz=\"0.15\" w_ic_z=\"7\"/>\n"
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_z=\"0.2\"/>\n"
    "<Body_Rigid id=\"4\" cg_id=\"40\" mass=\"0.8\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""
    " inertia_zz=\"0.05\" w_ic_z=\"5\"/>\n"
    "<Reference_Marker id=\"40\" body_id=\"4\" pos_z=\"-0.2\"/>\n"
    "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"20\" j_marker_id=\"10\"/>\n"
    "<Constraint_Joint id=\"2\" type=\"REVOLUTE\" i_marker_id=\"30\" j_marker_id=\"21\"/>\n"
    "<Constraint_Joint id=\"3\" type=\"REVOLUTE\" i_marker_id=\"40\" j_marker_id=\"22\"/>\n"
    "<Force_Scalar_TwoBody id=\"1\" type=\"TORQUE\" i_marker_id=\"30\" j_marker_id=\"10\""
    " val=\"0.1\"/>\n"
    "<Constraint_Coupler id=\"1\" joint1_id=\"2\" freedom_1=\"R\" joint2_id=\"3\""
    " freedom_2=\"R\" coefficients=\"1, -2\"/>\n"
    "</Model></MotionSolve>\n";

/* Body b's rotation matrix (row-major) from its unit quaternion in y (the
 * ground's: the identity). */
static void body_rotation(const sim *s, int row, int body, double R[9])
{
    if (s->dynamics.dof[body].kind == HX_DOF_GROUND) {
        for (int k = 0; k < 9; ++k)
            R[k] = k % 4 == 0 ? 1.0 : 0.0;
        return;
    }
    const double *q = s->path.y + (size_t)row * (size_t)s->path.n + s->dynamics.dof[body].q + 3;
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double n = w * w + x * x + y * y + z * z;
    R[0] = (w * w + x * x - y * y - z * z) / n, R[1] = 2 * (x * y - w * z) / n;
    R[2] = 2 * (x * z + w * y) / n, R[3] = 2 * (x * y + w * z) / n;
    R[4] = (w * w - x * x + y * y - z * z) / n, R[5] = 2 * (y * z - w * x) / n;
    R[6] = 2 * (x * z - w * y) / n, R[7] = 2 * (y * z + w * x) / n;
    R[8] = (w * w - x * x - y * y + z * z) / n;
}

/* The angle of body i against body j about z (every marker unturned): the
 * z rotation of R_j^T R_i, in (-pi, pi]. */
static double angle_against(const sim *s, int row, int i, int j)
{
    double Ri[9], Rj[9];
    body_rotation(s, row, i, Ri);
    body_rotation(s, row, j, Rj);
    double c = 0.0, sn = 0.0; /* (R_j^T R_i)[0][0] and [1][0] */
    for (int k = 0; k < 3; ++k) {
        c += Rj[3 * k] * Ri[3 * k];
        sn += Rj[3 * k + 1] * Ri[3 * k];
    }
    return atan2(sn, c);
}

/* Carrier angle th, gear B's angle to it p, gear A's r p (r = 2). With IC
 * 0.7, IA 0.15, IB 0.05 about z and every centre on the axis:
 *   T = 1/2 [IC th'^2 + IA (th' + r p')^2 + IB (th' + p')^2],
 *   M = [IC + IA + IB, r IA + IB; r IA + IB, r^2 IA + IB] = [0.9, 0.35; 0.35, 0.65];
 * Ta on gear A (absolute angle th + r p): Q = (Ta, r Ta) = (0.1, 0.2);
 * det = 0.585 - 0.1225 = 0.4625, (a, b) = M^-1 Q = (0.065 - 0.07, 0.18 -
 * 0.035) / det = (-0.0108108, 0.3135135) rad/s^2, constant: th = 3 t + a
 * t^2 / 2, p = 2 t + b t^2 / 2 (35.68 rad, 5.68 turns, at t = 10). */
#define TURN_A (-0.005 / 0.4625)
#define TURN_B (0.145 / 0.4625)

/* The run's angles, measured and unwrapped here row by row, against the
 * closed form within `within` and the coupler's relation within `relation`;
 * the largest of p returned. */
static double against_closed_form(const sim *s, double within, double relation)
{
    double th = 0.0, pa = 0.0, pb = 0.0, worst = 0.0, worst_relation = 0.0;
    for (int row = 0; row < s->path.rows; ++row) {
        const double t = s->path.t[row];
        /* each output 0.05 s from the last: under pi from it, so the nearest */
        th += remainder(angle_against(s, row, 1, 0) - th, 2 * M_PI);
        pa += remainder(angle_against(s, row, 2, 1) - pa, 2 * M_PI);
        pb += remainder(angle_against(s, row, 3, 1) - pb, 2 * M_PI);
        worst = fmax(worst, fabs(th - (3 * t + 0.5 * TURN_A * t * t)));
        worst = fmax(worst, fabs(pb - (2 * t + 0.5 * TURN_B * t * t)));
        worst_relation = fmax(worst_relation, fabs(pa - 2 * pb));
    }
    print_message("closed form within %.3g, p_A - 2 p_B within %.3g\n", worst, worst_relation);
    assert_true(worst <= within);
    assert_true(worst_relation <= relation);
    return pb;
}

static void many_turns_with_dopri5_and_bdf(void **state)
{
    (void)state;
    const char *path = test_write_file("turning_gears.xml", turning_model);
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 2; ++k) {
        sim s;
        sim_run(&s, path, methods[k], k == 0 ? 1e-10 : 1e-4, 10.0, 0.05);
        assert_int_equal(s.dynamics.nrows, 16); /* the coupler and three revolutes' five */
        assert_true(s.path.t[s.path.rows - 1] > 10.0 - 1e-9);
        const double turned = against_closed_form(&s, k == 0 ? 1e-8 : 1e-3, 1e-10);
        assert_true(turned > 5 * 2 * M_PI);
        assert_true(s.result.max_phi <= 1e-9);
        sim_close(&s);
    }
}

/* RK4 at 1 s: gear A turns 4 rad against the carrier in the first step. */
static void a_step_past_pi_is_refused(void **state)
{
    (void)state;
    const char *message = sim_rk4_refused("turning_gears_step.xml", turning_model, 1.0, 3.0);
    print_message("%s\n", message);
    assert_contains(message, "Constraint_Coupler 1: joint 2 turned", "one step, from t = 0 to 1",
                    "more than pi");
}

/* What the accept hook and the outputs saw. */
typedef struct seen {
    long accepted, outputs;
    double last; /* the last accepted time */
    int backwards; /* an accepted time not after the one before */
    double last_output;
} seen;

static int decay(void *ctx, double t, const double *y, double *ydot)
{
    (void)ctx, (void)t;
    ydot[0] = -3.0 * y[0];
    return 0;
}

static int note_accept(void *ctx, double t, const double *y)
{
    seen *s = ctx;
    (void)y;
    s->backwards |= !(t > s->last);
    s->last = t;
    s->accepted++;
    return 0;
}

static int note_output(void *ctx, double t, const double *y)
{
    seen *s = ctx;
    (void)y;
    s->outputs++;
    s->last_output = t;
    return 0;
}

/* y' = -3 y from a first step of 0.5 (DOPRI5 and BDF reject it, and more):
 * the hook once per accepted step, at increasing times, the last at the end,
 * and the 20 output times still all there. */
static void accept_hook_at_accepted_steps_alone(void **state)
{
    (void)state;
    const hx_method methods[4] = {HX_METHOD_DOPRI5, HX_METHOD_BDF, HX_METHOD_DOPRI5_ARKODE,
                                  HX_METHOD_RK4};
    for (int k = 0; k < 4; ++k) {
        seen s = {0};
        hx_ode ode = {1, 0, 0, 0, decay, NULL, NULL, &s, NULL, NULL, note_accept};
        hx_integrator_options o;
        hx_integrator_defaults(&o);
        o.method = methods[k];
        o.rtol = 1e-8;
        o.atol = 1e-12;
        o.step = methods[k] == HX_METHOD_RK4 ? 1e-3 : 0.5;
        o.t_end = 1.0;
        o.output_interval = 0.05;
        o.output = note_output;
        hx_integrator_stats stats;
        double y = 1.0;
        assert_int_equal(hx_integrate(&ode, 0.0, &y, &o, &stats), HX_INTEGRATION_OK);
        print_message("%s: %ld steps, %ld rejected, %ld accepted\n", hx_method_name(methods[k]),
                      stats.steps, stats.rejected, s.accepted);
        assert_int_equal(s.accepted, stats.steps);
        if (methods[k] != HX_METHOD_RK4)
            assert_true(stats.rejected > 0);
        assert_false(s.backwards);
        assert_close(s.last, 1.0, 0, 1e-15);
        assert_int_equal(s.outputs, 20);
        assert_close(s.last_output, 1.0, 0, 1e-15);
        assert_close(y, exp(-3.0), 1e-6, 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(many_turns_with_dopri5_and_bdf),
        cmocka_unit_test(a_step_past_pi_is_refused),
        cmocka_unit_test(accept_hook_at_accepted_steps_alone),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
