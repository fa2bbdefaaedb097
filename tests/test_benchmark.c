/*
 * The benchmark's instruments: each method's stability limit against known
 * values; the fastest mode of a model against its analytic eigenvalue (a
 * stiff Control_Diff's among them); a
 * stiff model run above the limit ending unstable (and below it finishing);
 * the closed-form references against tight adaptive runs; a short
 * work-precision sweep (orders of convergence, DOPRI5 cheaper than RK4 at
 * 1e-8); long runs (bounded symplectic energy error, RK4 drift, constraint
 * residuals); outputs landing on the end time; and the bench command itself
 * in its quick form, as CI runs it.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cmd/commands.h"
#include "tools/bench/linear_reference.h"
#include "tools/bench/long_run.h"
#include "tools/bench/rhs_cost.h"
#include "sim_support.h"
#include "tools/bench/stability.h"
#include "test_support.h"
#include "tools/bench/work_precision.h"

static void stability_limits_of_each_method(void **state)
{
    (void)state;
    const double r = -1.0, i = 1.0, d = 1.0 / sqrt(2.0);
    /* on the negative real axis, the imaginary axis, and the diagonal between */
    assert_close(hx_stable_step(HX_METHOD_EULER, r, 0), 2.0, 1e-9, 0);
    assert_close(hx_stable_step(HX_METHOD_EULER, -d, d), sqrt(2.0), 1e-9, 0);
    assert_true(hx_stable_step(HX_METHOD_EULER, 0, i) < 1e-5); /* none (but rounding) */
    assert_close(hx_stable_step(HX_METHOD_RK4, r, 0), 2.78529356340528, 1e-9, 0);
    assert_close(hx_stable_step(HX_METHOD_RK4, 0, i), 2.0 * sqrt(2.0), 1e-9, 0);
    assert_close(hx_stable_step(HX_METHOD_RK4, -d, d), 2.7043534530917, 1e-9, 0);
    assert_close(hx_stable_step(HX_METHOD_DOPRI5, r, 0), 3.30656789263495, 1e-9, 0);
    /* the region touches the axis there: |R| leaves 1 slowly, found within 1e-8 */
    assert_close(hx_stable_step(HX_METHOD_DOPRI5, 0, i), 0.99718900863253, 1e-8, 0);
    assert_close(hx_stable_step(HX_METHOD_DOPRI5, -d, d), 3.29664482533247, 1e-9, 0);
    assert_close(hx_stable_step(HX_METHOD_SYMPLECTIC_EULER, 0, i), 2.0, 1e-9, 0);
    /* scaling: the step goes as 1 / |lambda| */
    assert_close(hx_stable_step(HX_METHOD_RK4, 0, 1000.0), 2.0 * sqrt(2.0) / 1000.0, 1e-9, 0);
    assert_true(isinf(hx_stable_step(HX_METHOD_RK4, 0, 0)));
}

static void open_dynamics(sim *s, const char *model, double *y)
{
    hx_message msg;
    memset(s, 0, sizeof *s);
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", EXAMPLES_DIR, model);
    if (hx_session_open(&s->session, path, stderr, &msg) != 0 ||
        hx_dynamics_init(&s->dynamics, &s->session, &msg) != 0 ||
        hx_dynamics_data_init(&s->data, &s->dynamics, &msg) != 0)
        fail_msg("%s", msg.text);
    assert_int_equal(hx_dynamics_initial_state(&s->dynamics, &s->data, y), 0);
}

static void fastest_mode_of_the_damped_oscillator(void **state)
{
    (void)state;
    sim s;
    double y[64];
    open_dynamics(&s, "damped_oscillator.xml", y);
    hx_stability st;
    hx_message msg;
    assert_int_equal(hx_estimate_stability(&s.dynamics, 0.0, y, &st, &msg), 0);
    /* z: k = 500 N/mm, c = 0.6 N s/mm on 2 kg: omega = 500 rad/s, -c/2m = -150 1/s */
    assert_close(st.magnitude, 500.0, 1e-6, 0);
    assert_close(st.re, -150.0, 1e-5, 0);
    assert_close(st.im, sqrt(500.0 * 500.0 - 150.0 * 150.0), 1e-6, 0);
    assert_close(st.max_step[HX_METHOD_RK4], hx_stable_step(HX_METHOD_RK4, -150.0, st.im), 1e-5, 0);
    sim_close(&s);
}

/* A body on a soft spring (omega = sqrt(200 / 2) = 10 rad/s along the line)
 * beside a stiff filter state, DIF(1)' = -1e4 DIF(1): the fastest mode is the
 * state's, lambda = -1e4 (real), and RK4's limit 2.785 / 1e4 (its reach on the
 * negative real axis, stability_limits_of_each_method). Left out of the
 * estimate, the state's mode would leave the spring's, |lambda| = 10. */
static void fastest_mode_of_a_stiff_control_diff(void **state)
{
    (void)state;
    static const char *const text =
        "ADAMS/View model\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=2, CM=20, IP=1,1,1\nMARKER/20, PART=2, QP=3,4,0\n"
        "SFORCE/7, TRANSLATION, I=20, J=10, FUNCTION=-200*(DM(20,10) - 4.9)\n"
        "DIFF/1, IC=1, FUNCTION=-1E4*DIF(1)\nEND\n";
    sim s;
    hx_message msg;
    memset(&s, 0, sizeof s);
    if (hx_session_open(&s.session, test_write_file("stiff_diff.adm", text), stderr, &msg) != 0 ||
        hx_dynamics_init(&s.dynamics, &s.session, &msg) != 0 ||
        hx_dynamics_data_init(&s.data, &s.dynamics, &msg) != 0)
        fail_msg("%s", msg.text);
    double y[64];
    assert_true(s.dynamics.n <= 64);
    assert_int_equal(hx_dynamics_initial_state(&s.dynamics, &s.data, y), 0);
    hx_stability st;
    assert_int_equal(hx_estimate_stability(&s.dynamics, 0.0, y, &st, &msg), 0);
    assert_close(st.magnitude, 1e4, 1e-6, 0);
    assert_close(st.re, -1e4, 1e-6, 0);
    assert_true(st.im == 0.0);
    assert_close(st.max_step[HX_METHOD_RK4], 2.78529356340528e-4, 1e-6, 0);
    sim_close(&s);
}

static hx_status run_fixed(const char *model, hx_method method, double step, double end)
{
    sim s;
    double y[64];
    open_dynamics(&s, model, y);
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = method;
    so.integration.step = step;
    so.integration.t_end = end;
    so.integration.output_interval = end;
    so.skip_energy = 1;
    hx_simulation_result result;
    hx_simulate(&s.dynamics, &so, NULL, &result);
    sim_close(&s);
    return result.status;
}

static void a_step_beyond_the_limit_is_reported_unstable(void **state)
{
    (void)state;
    sim s;
    double y[64];
    open_dynamics(&s, "stiff_mount.xml", y);
    hx_stability st;
    hx_message msg;
    assert_int_equal(hx_estimate_stability(&s.dynamics, 0.0, y, &st, &msg), 0);
    sim_close(&s);
    assert_close(st.magnitude, sqrt(1e9), 1e-4, 0); /* 1e6 N/mm on 1 kg */
    const double limit = st.max_step[HX_METHOD_RK4];
    printf("stiff mount: |lambda| = %.6g, RK4 limit %.4g s\n", st.magnitude, limit);
    assert_int_equal(run_fixed("stiff_mount.xml", HX_METHOD_RK4, 1.5 * limit, 0.05),
                     HX_INTEGRATION_UNSTABLE);
    assert_int_equal(run_fixed("stiff_mount.xml", HX_METHOD_RK4, 0.9 * limit, 0.05),
                     HX_INTEGRATION_OK);
    const double symplectic = st.max_step[HX_METHOD_SYMPLECTIC_EULER];
    assert_int_equal(run_fixed("stiff_mount.xml", HX_METHOD_SYMPLECTIC_EULER, 1.5 * symplectic, 0.05),
                     HX_INTEGRATION_UNSTABLE);
    /* and run warns before it starts */
    char path[1024];
    snprintf(path, sizeof path, "%s/stiff_mount.xml", EXAMPLES_DIR);
    char step[32];
    snprintf(step, sizeof step, "%g", 1.5 * limit);
    char *argv[] = {"run", path, "--end", "0.01", "--integrator", "rk4", "--step", step, "--quiet", NULL};
    fflush(stdout);
    assert_int_equal(hx_command_run(9, argv), 1);
}

static void closed_forms_match_tight_adaptive_runs(void **state)
{
    (void)state;
    static const char *const models[3] = {"damped_oscillator.xml", "normal_modes.xml",
                                          "geared_oscillator.xml"};
    for (int k = 0; k < 3; ++k) {
        sim s;
        double y0[64], yref[64], y[64];
        open_dynamics(&s, models[k], y0);
        hx_linear_reference ref;
        hx_message msg;
        if (hx_linear_reference_build(&s.dynamics, &ref, &msg) != 0)
            fail_msg("%s: %s", models[k], msg.text);
        if (k == 2) /* (2000 + 6000 / 4) theta'' = -2e5 theta, in kg mm^2 and N mm */
            assert_close(ref.k[0], 2e5 * 1000.0 / 3500.0, 1e-9, 0);
        hx_simulation_options so = {0};
        hx_integrator_defaults(&so.integration);
        so.integration.method = HX_METHOD_DOPRI5;
        so.integration.rtol = 1e-12;
        so.integration.atol = 1e-15;
        so.integration.t_end = 0.03;
        so.integration.output_interval = 0.03;
        so.skip_energy = 1;
        hx_simulation_result result;
        assert_int_equal(hx_simulate(&s.dynamics, &so, y, &result), 0);
        memcpy(yref, y, sizeof(double) * (size_t)s.dynamics.n);
        hx_linear_reference_state(&ref, 0.03, yref);
        double worst = 0.0, size = 0.0;
        for (int i = 0; i < s.dynamics.nq + s.dynamics.nu; ++i) {
            worst = fmax(worst, fabs(y[i] - yref[i]));
            size = fmax(size, fabs(yref[i] - (i < s.dynamics.nq ? y0[i] : 0.0)));
        }
        printf("%s: closed form against DOPRI5 at 1e-12: %.2g of %.3g\n", models[k], worst, size);
        assert_true(worst < 1e-9 * size);
        hx_linear_reference_free(&ref);
        sim_close(&s);
    }
    /* a nonlinear model has none, and says why */
    sim s;
    double y[64];
    open_dynamics(&s, "powertrain.xml", y);
    hx_linear_reference ref;
    hx_message msg;
    assert_int_equal(hx_linear_reference_build(&s.dynamics, &ref, &msg), -1);
    assert_contains(msg.text, "closed form only");
    sim_close(&s);
}

static double error_at(const hx_wp_result *r, hx_method method, int index)
{
    int seen = 0;
    for (int k = 0; k < r->npoints; ++k)
        if (r->point[k].method == method && seen++ == index)
            return r->point[k].end_error;
    return NAN;
}

static void work_precision_orders_and_dopri5_against_rk4(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, EXAMPLES_DIR "/damped_oscillator.xml", stderr, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_wp_options o = {0.1, 1, 0, 0.0, 0, {0}, 0};
    static hx_wp_result r;
    assert_int_equal(hx_work_precision(&s, &o, &r, &msg), 0);
    hx_session_close(&s);
    assert_true(r.analytic);
    hx_wp_print(stdout, &r);
    /* halving the step divides the error by about 2^order, once in the asymptotic range */
    const double rk4 = error_at(&r, HX_METHOD_RK4, 3) / error_at(&r, HX_METHOD_RK4, 4);
    const double euler = error_at(&r, HX_METHOD_EULER, 6) / error_at(&r, HX_METHOD_EULER, 7);
    const double symplectic =
        error_at(&r, HX_METHOD_SYMPLECTIC_EULER, 6) / error_at(&r, HX_METHOD_SYMPLECTIC_EULER, 7);
    printf("error ratios per halving: euler %.3g, symplectic euler %.3g, rk4 %.3g\n", euler,
           symplectic, rk4);
    assert_true(rk4 > 12.0 && rk4 < 20.0);
    assert_true(euler > 1.7 && euler < 2.3);
    assert_true(symplectic > 1.7 && symplectic < 2.3);
    /* DOPRI5's errors follow its tolerance down to 1e-12 */
    for (int k = 0; k + 1 < 10; ++k)
        assert_true(error_at(&r, HX_METHOD_DOPRI5, k + 1) < error_at(&r, HX_METHOD_DOPRI5, k));
    const double e_rk4 = hx_wp_evaluations_at(&r, HX_METHOD_RK4, 1e-8);
    const double e_dopri5 = hx_wp_evaluations_at(&r, HX_METHOD_DOPRI5, 1e-8);
    printf("evaluations for an end-point error of 1e-8: rk4 %.0f, dopri5 %.0f\n", e_rk4, e_dopri5);
    assert_true(e_rk4 > 0.0 && e_dopri5 > 0.0);
    assert_true(e_dopri5 < e_rk4);
}

static void long_runs_keep_energy_and_constraints(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, EXAMPLES_DIR "/normal_modes.xml", stderr, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_long_run se, rk;
    const double step = 0.2 / 412.3; /* a fifth over the fastest mode */
    assert_int_equal(hx_long_run_measure(&s, HX_METHOD_SYMPLECTIC_EULER, 100000, step, &se, &msg), 0);
    assert_int_equal(hx_long_run_measure(&s, HX_METHOD_RK4, 100000, step, &rk, &msg), 0);
    hx_session_close(&s);
    hx_long_run runs[2] = {se, rk};
    hx_long_run_print(stdout, runs, 2);
    /* symplectic Euler: an O(h) error that does not grow */
    assert_true(se.error_last < 1.2 * se.error_first && se.error_first < 0.2);
    assert_true(fabs(se.drift) * se.step * 100000 < 0.1 * se.error_first);
    /* RK4: tiny, but a steady loss */
    assert_true(rk.error_last > 3.0 * rk.error_first);
    assert_true(rk.drift < 0.0);
    /* a coupled model keeps its constraint */
    if (hx_session_open(&s, EXAMPLES_DIR "/geared_pendulums.xml", stderr, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_long_run coupled;
    assert_int_equal(hx_long_run_measure(&s, HX_METHOD_RK4, 100000, 1e-3, &coupled, &msg), 0);
    hx_session_close(&s);
    printf("geared pendulums, 1e5 RK4 steps: |phi| %.2g, |dphi/dt| %.2g, energy drift %.2g per s\n",
           coupled.max_phi, coupled.max_phidot, coupled.drift);
    assert_true(coupled.max_phi < 1e-10);
    assert_true(coupled.max_phidot < 1e-10);
}

static int last_time_seen;
static double last_time;

static int note_time(void *ctx, double t, const double *y)
{
    (void)ctx, (void)y;
    last_time = t;
    last_time_seen++;
    return 0;
}

static int decay(void *ctx, double t, const double *y, double *ydot)
{
    (void)ctx, (void)t;
    ydot[0] = -y[0];
    return 0;
}

static void outputs_land_on_the_end_time(void **state)
{
    (void)state;
    /* many output intervals whose sum is not exactly the end time */
    for (double rtol = 1e-3; rtol >= 1e-12; rtol /= 10.0) {
        hx_ode ode = {1, 0, 0, 0, decay, NULL, NULL, NULL, NULL, NULL, NULL};
        hx_integrator_options o;
        hx_integrator_defaults(&o);
        o.method = HX_METHOD_DOPRI5;
        o.rtol = rtol;
        o.atol = rtol * 1e-3;
        o.t_end = 0.1;
        o.output_interval = 0.1 / 50;
        o.output = note_time;
        double y = 1.0;
        hx_integrator_stats stats;
        last_time_seen = 0;
        assert_int_equal(hx_integrate(&ode, 0.0, &y, &o, &stats), HX_INTEGRATION_OK);
        assert_int_equal(last_time_seen, 50);
        assert_true(last_time == 0.1);
        assert_close(y, exp(-0.1), 10 * rtol, 0);
    }
}

static void the_quick_bench_runs(void **state)
{
    (void)state;
    char out[512];
    snprintf(out, sizeof out, "%s/quick", test_temp_dir());
    char *argv[] = {"bench", EXAMPLES_DIR "/damped_oscillator.xml", "--work-precision", "--quick",
                    "--out", out, NULL};
    fflush(stdout);
    assert_int_equal(hx_command_bench(6, argv), 0);
    char csv[600];
    snprintf(csv, sizeof csv, "%s_work_precision.csv", out);
    csv_table t;
    csv_read(csv, &t);
    assert_int_equal(t.rows, 3 * 4 + 4 * 4); /* fixed-step, and tolerance sweeps */
    csv_free(&t);
}

/* The split's two shares are differences of separately timed rounds: on a
 * loaded machine either can come out at or below zero, which bench says is
 * below the noise instead of printing a negative cost. */
static void the_cost_split_never_prints_a_negative_cost(void **state)
{
    (void)state;
    char text[512];
    const hx_rhs_cost plain = {.rhs_ns = 812.0, .harness_ns = 212.0, .user_ns = 600.0,
                               .user_calls = 4};
    hx_rhs_cost_text(&plain, text, sizeof text);
    assert_string_equal(text, "right-hand side: 812.0 ns per evaluation: the 4 user entry calls"
                              " in it 600.0 ns, the harness's own share 212.0 ns (35 % of the"
                              " user entries)");
    const hx_rhs_cost user_lost = {.rhs_ns = 500.0, .harness_ns = 530.0, .user_ns = -30.0,
                                   .user_calls = 2};
    hx_rhs_cost_text(&user_lost, text, sizeof text);
    assert_non_null(strstr(text, "in it below the noise of the timings"));
    assert_non_null(strstr(text, "own share 530.0 ns"));
    assert_null(strstr(text, "-30"));
    const hx_rhs_cost harness_lost = {.rhs_ns = 500.0, .harness_ns = -4.0, .user_ns = 504.0,
                                      .user_calls = 2};
    hx_rhs_cost_text(&harness_lost, text, sizeof text);
    assert_non_null(strstr(text, "in it 504.0 ns, the harness's own share below the noise"));
    assert_null(strstr(text, "-4"));
    const hx_rhs_cost none = {.rhs_ns = 90.0};
    hx_rhs_cost_text(&none, text, sizeof text);
    assert_string_equal(text, "right-hand side: 90.0 ns per evaluation (no user entries)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(stability_limits_of_each_method),
        cmocka_unit_test(fastest_mode_of_the_damped_oscillator),
        cmocka_unit_test(fastest_mode_of_a_stiff_control_diff),
        cmocka_unit_test(a_step_beyond_the_limit_is_reported_unstable),
        cmocka_unit_test(closed_forms_match_tight_adaptive_runs),
        cmocka_unit_test(work_precision_orders_and_dopri5_against_rk4),
        cmocka_unit_test(long_runs_keep_energy_and_constraints),
        cmocka_unit_test(outputs_land_on_the_end_time),
        cmocka_unit_test(the_quick_bench_runs),
        cmocka_unit_test(the_cost_split_never_prints_a_negative_cost),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
