/*
 * The coupler examples, checked and run through the harness against solutions
 * worked by hand: bevel gears and rack and pinion under a torque, the
 * hydraulic jack held in equilibrium (multiplier = pressure, piston forces in
 * the area ratio), the variable-ratio steering table, the open differential's
 * torque split, the user coupler against the built-in one, and energy.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "sim/dynamics/constraints.h"
#include "sim_support.h"
#include "test_support.h"
#include "usrsub/core/spline.h"
#include "usrsub/readers/table_file.h"

#define UCF 1000.0 /* mm, kg, s, N */

static void assert_constraints_held(const sim *s)
{
    assert_true(s->result.max_phi < 1e-10);
    assert_true(s->result.max_phidot < 1e-10);
}

static void check_passes_on_every_coupler_example(void **state)
{
    (void)state;
    const char *models[] = {"bevel_gears.xml", "rack_pinion.xml", "hydraulic_jack.xml",
                            "steering_rack.xml", "differential.xml", "geared_pendulums.xml",
                            "geared_pair_user.xml"};
    for (size_t k = 0; k < sizeof models / sizeof models[0]; ++k)
        assert_int_equal(sim_check(models[k]), 0);
}

static void bevel_gears_under_a_torque(void **state)
{
    (void)state;
    sim s;
    sim_run(&s, "bevel_gears.xml", HX_METHOD_RK4, 1e-3, 1.0, 0.1);
    /* J1 a1 = ucf (tau + R1 lambda), J2 a2 = ucf R2 lambda, R1 a1 + R2 a2 = 0 */
    const double J1 = 0.617, J2 = 3.122, R1 = 10, R2 = 15, tau = 0.05;
    const double alpha = UCF * tau / (J1 + J2 * (R1 / R2) * (R1 / R2));
    const int last = s.path.rows - 1;
    const double t = s.path.t[last];
    assert_close(sim_state(&s, last, sim_joint_q(&s, 1)), 1.5 * t + 0.5 * alpha * t * t, 1e-10, 0);
    assert_close(sim_state(&s, last, sim_joint_q(&s, 2)),
                 -(R1 / R2) * (1.5 * t + 0.5 * alpha * t * t), 1e-10, 0);
    assert_close(sim_lambda(&s, last, 0), -J2 * R1 * alpha / (UCF * R2 * R2), 1e-10, 0);
    assert_constraints_held(&s);
    sim_close(&s);
}

static void rack_and_pinion(void **state)
{
    (void)state;
    sim s;
    sim_run(&s, "rack_pinion.xml", HX_METHOD_RK4, 1e-3, 1.0, 0.1);
    const double alpha = UCF * 50.0 / (225.0 + 2.0 * 30.0 * 30.0);
    const int last = s.path.rows - 1;
    assert_close(sim_state(&s, last, sim_joint_q(&s, 41)), 0.5 * alpha, 1e-10, 0);
    assert_close(sim_state(&s, last, sim_joint_q(&s, 51)), -30.0 * 0.5 * alpha, 1e-10, 0);
    assert_constraints_held(&s);
    sim_close(&s);
}

static void hydraulic_jack_holds_the_car(void **state)
{
    (void)state;
    sim s;
    sim_run(&s, "hydraulic_jack.xml", HX_METHOD_RK4, 1e-3, 1.0, 0.1);
    const double A1 = 20.1885, A2 = 2018.85, pressure = 1000.0 * 9810.0 / (UCF * A2);
    for (int r = 0; r < s.path.rows; ++r) {
        assert_close(sim_lambda(&s, r, 0), pressure, 1e-9, 0);
        assert_true(fabs(sim_state(&s, r, sim_joint_q(&s, 123))) < 1e-6);
        assert_true(fabs(sim_state(&s, r, sim_joint_q(&s, 456))) < 1e-8);
    }
    /* virtual work: the piston forces lambda*A1 and lambda*A2 stand in the area ratio */
    const double t = 0.5;
    double y[16];
    for (int k = 0; k < s.dynamics.n; ++k)
        y[k] = sim_state(&s, 5, k);
    sim_evaluate(&s, t, y);
    const double F1 = hx_constraints_coupler_force(&s.dynamics, &s.data, t, y, 0, 0);
    const double F2 = hx_constraints_coupler_force(&s.dynamics, &s.data, t, y, 0, 1);
    assert_close(F2 / F1, A2 / A1, 1e-12, 0);
    assert_close(F2, 1000.0 * 9810.0 / UCF, 1e-9, 0); /* carries the car's weight */
    assert_constraints_held(&s);
    sim_close(&s);
}

static void steering_rack_follows_its_table(void **state)
{
    (void)state;
    sim s;
    sim_run(&s, "steering_rack.xml", HX_METHOD_RK4, 1e-4, 0.25, 0.01);
    double *x, *y;
    int n;
    usrsub_message msg;
    assert_int_equal(usrsub_table_file_read(EXAMPLES_DIR "/steering_ratio.tbl", &x, &y, &n, &msg), 0);
    usrsub_spline f;
    assert_int_equal(usrsub_spline_init(&f, n, x, y, &msg), 0);
    free(x);
    free(y);
    const int last = s.path.rows - 1;
    const double theta = sim_state(&s, last, sim_joint_q(&s, 1));
    assert_true(theta > 3.0); /* well into the varying part of the ratio */
    for (int r = 0; r < s.path.rows; ++r)
        assert_close(sim_state(&s, r, sim_joint_q(&s, 2)),
                     usrsub_spline_eval(&f, sim_state(&s, r, sim_joint_q(&s, 1))).value, 0, 1e-10);
    usrsub_spline_free(&f);
    assert_constraints_held(&s);
    sim_close(&s);
}

static void differential_splits_torque_equally(void **state)
{
    (void)state;
    sim s;
    sim_run(&s, "differential.xml", HX_METHOD_RK4, 1e-3, 1.0, 0.1);
    /* IL aL = ucf lambda, IR aR = ucf lambda, IC aC = ucf (tau - 2 lambda), aL + aR = 2 aC */
    const double IL = 1.0e6, IR = 1.5e6, IC = 4e4, tau = 1e5;
    const double lambda = 2 * tau / IC / (1 / IL + 1 / IR + 4 / IC);
    const int last = s.path.rows - 1;
    assert_close(sim_lambda(&s, last, 0), lambda, 1e-10, 0);
    assert_close(sim_state(&s, last, sim_joint_u(&s, 1)), UCF * lambda / IL, 1e-10, 0);
    assert_close(sim_state(&s, last, sim_joint_u(&s, 2)), UCF * lambda / IR, 1e-10, 0);
    double y[16];
    for (int k = 0; k < s.dynamics.n; ++k)
        y[k] = sim_state(&s, last, k);
    sim_evaluate(&s, 1.0, y);
    const double left = hx_constraints_coupler_force(&s.dynamics, &s.data, 1.0, y, 0, 0);
    const double right = hx_constraints_coupler_force(&s.dynamics, &s.data, 1.0, y, 0, 1);
    const double carrier = hx_constraints_coupler_force(&s.dynamics, &s.data, 1.0, y, 0, 2);
    assert_close(left, right, 1e-14, 0);
    assert_close(carrier, -2.0 * left, 1e-14, 0);
    assert_constraints_held(&s);
    sim_close(&s);
}

static void user_coupler_equals_built_in(void **state)
{
    (void)state;
    sim user, builtin;
    sim_run(&user, "geared_pair_user.xml", HX_METHOD_RK4, 1e-3, 2.0, 0.01);
    sim_run(&builtin, "geared_pair_builtin.xml", HX_METHOD_RK4, 1e-3, 2.0, 0.01);
    assert_int_equal(user.path.rows, builtin.path.rows);
    double worst = 0.0;
    for (int r = 0; r < user.path.rows; ++r)
        for (int k = 0; k < user.dynamics.n - 1; ++k) {
            const double a = sim_state(&user, r, k), b = sim_state(&builtin, r, k);
            worst = fmax(worst, fabs(a - b) / fmax(1.0, fabs(b)));
        }
    printf("user vs built-in coupler: largest relative difference %.3g\n", worst);
    assert_true(worst <= 1e-12);
    assert_true(fabs(sim_state(&user, user.path.rows - 1, sim_joint_q(&user, 1))) > 0.05);
    sim_close(&user);
    sim_close(&builtin);
}

static void geared_pendulums_keep_their_energy(void **state)
{
    (void)state;
    sim coarse, fine;
    sim_run(&coarse, "geared_pendulums.xml", HX_METHOD_RK4, 2e-3, 10.0, 0.01);
    sim_run(&fine, "geared_pendulums.xml", HX_METHOD_RK4, 1e-3, 10.0, 0.01);
    const double e_coarse = coarse.result.energy_error_max / coarse.result.energy_scale;
    const double e_fine = fine.result.energy_error_max / fine.result.energy_scale;
    printf("geared pendulums, 10 s of RK4: relative energy error %.3g (h = 2 ms), %.3g (h = 1 ms)\n",
           e_coarse, e_fine);
    assert_true(e_fine < 1e-11);
    assert_true(e_coarse / e_fine > 8.0); /* shrinks with the step: the integrator's error */
    assert_constraints_held(&fine);
    sim_close(&coarse);
    sim_close(&fine);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(check_passes_on_every_coupler_example),
        cmocka_unit_test(bevel_gears_under_a_torque),
        cmocka_unit_test(rack_and_pinion),
        cmocka_unit_test(hydraulic_jack_holds_the_car),
        cmocka_unit_test(steering_rack_follows_its_table),
        cmocka_unit_test(differential_splits_torque_equally),
        cmocka_unit_test(user_coupler_equals_built_in),
        cmocka_unit_test(geared_pendulums_keep_their_energy),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
