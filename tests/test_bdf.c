/*
 * The implicit integrator (BDF through CVODE): differences by column groups
 * (--jacobian fd) against column by column; BDF's order of convergence on a
 * closed form; a deliberately wrong partial that must cost Newton iterations
 * (or steps) but not change the trajectory; BDF's agreement with DOPRI5 on
 * every bundled model (couplers held by the projection); run with bdf on
 * every model, and its advice on stiff models; the Newton matrix I - gamma J
 * written in one pass against CVODE's own.
 */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd/commands.h"
#include "model_runs.h"
#include "sim/jacobian/jacobian.h"
#include "sim/ode/column_groups.h"
#include "sim_support.h"
#include "test_support.h"
#include "tools/bench/linear_reference.h"

/* Differences by column groups (what --jacobian fd uses) on a chain: no two
 * columns of a group share a row of the sparsity, there are far fewer
 * groups than columns, and the grouped matrix equals the matrix of the same
 * differences taken one column at a time. */
static int rhs_of(void *ctx, double t, const double *y, double *ydot)
{
    model *m = ctx;
    return hx_dynamics_rhs(&m->d, &m->data, t, y, ydot);
}

static void differences_by_column_groups_equal_them_column_by_column(void **state)
{
    (void)state;
    char path[1024], command[2048];
    snprintf(path, sizeof path, "%s/chain_12.xml", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    snprintf(command, sizeof command, "sh %s/chain_model.sh 12 %s", SCRIPTS_DIR, path);
    assert_int_equal(system(command), 0);
    model m;
    open_model(&m, path);
    const int n = m.d.n;
    double *y = calloc((size_t)n, sizeof(double)), *fy = calloc((size_t)n, sizeof(double));
    double *h = calloc((size_t)n, sizeof(double)), *work = calloc(2 * (size_t)n, sizeof(double));
    hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-8, 0.05, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    hx_jacobian jac;
    hx_message msg;
    assert_int_equal(hx_jacobian_init(&jac, &m.d, &msg), 0);
    const hx_sparsity *sp = &jac.pattern;
    hx_column_groups g;
    assert_int_equal(hx_column_groups_build(&g, sp), 0);
    /* no row shared inside a group */
    int *owner = malloc(sizeof(int) * (size_t)n);
    for (int k = 0; k < g.count; ++k) {
        for (int i = 0; i < n; ++i)
            owner[i] = -1;
        for (int j = g.start[k]; j < g.start[k + 1]; ++j)
            for (int p = sp->colptr[g.columns[j]]; p < sp->colptr[g.columns[j] + 1]; ++p) {
                assert_int_equal(owner[sp->rowind[p]], -1);
                owner[sp->rowind[p]] = g.columns[j];
            }
    }
    printf("chain of 12 bodies: %d states, %d nonzeros, %d column groups\n", n, sp->nnz, g.count);
    assert_true(g.count < n / 3);
    double *grouped = calloc((size_t)sp->nnz, sizeof(double));
    double *single = calloc((size_t)sp->nnz, sizeof(double));
    for (int i = 0; i < n; ++i)
        h[i] = 1e-7 * fmax(1.0, fabs(y[i]));
    assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.05, y, fy), 0);
    assert_int_equal(hx_grouped_differences(&g, sp, rhs_of, &m, 0.05, y, fy, h, m.d.load_work,
                                            grouped, work), 0);
    hx_column_groups one = {n, malloc(sizeof(int) * (size_t)(n + 1)), malloc(sizeof(int) * (size_t)n)};
    for (int i = 0; i <= n; ++i)
        one.start[i] = i;
    for (int i = 0; i < n; ++i)
        one.columns[i] = i;
    assert_int_equal(hx_grouped_differences(&one, sp, rhs_of, &m, 0.05, y, fy, h, m.d.load_work,
                                            single, work), 0);
    /* against each row's largest entry (rows mix units); a column counted in
     * another's row would be wrong by the size of its entry */
    double *row = calloc((size_t)n, sizeof(double)), worst = 0.0;
    for (int p = 0; p < sp->nnz; ++p)
        row[sp->rowind[p]] = fmax(row[sp->rowind[p]], fabs(single[p]));
    for (int p = 0; p < sp->nnz; ++p)
        worst = fmax(worst, row[sp->rowind[p]] > 0.0
                                ? fabs(grouped[p] - single[p]) / row[sp->rowind[p]]
                                : fabs(grouped[p]));
    printf("  grouped against column by column: largest difference %.2g of its row\n", worst);
    assert_true(worst <= 1e-6);
    free(row);
    hx_column_groups_free(&one);
    hx_column_groups_free(&g);
    hx_jacobian_free(&jac);
    free(owner), free(grouped), free(single), free(y), free(fy), free(h), free(work);
    close_model(&m);
}

/* ---- order of convergence on a closed form ------------------------------------------ */

/* BDF of highest order q on damped_oscillator.xml to t = 0.02 s (a period)
 * at one tolerance: its steps and its error against the closed form. */
static double bdf_error(int order, double rtol, long *steps, int *last_order)
{
    model m;
    open_model(&m, EXAMPLES_DIR "/damped_oscillator.xml");
    hx_linear_reference ref;
    hx_message msg;
    if (hx_linear_reference_build(&m.d, &ref, &msg) != 0)
        fail_msg("%s", msg.text);
    const double t_end = 0.02;
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = HX_METHOD_BDF;
    so.integration.max_order = order;
    so.integration.rtol = rtol;
    so.integration.atol = rtol * 1e-3;
    so.integration.t_end = t_end;
    so.integration.output_interval = t_end;
    so.skip_energy = 1;
    double *y = model_state(&m), *yref = model_state(&m);
    hx_simulation_result r;
    assert_int_equal(hx_simulate(&m.d, &so, y, &r), 0);
    *steps = r.stats.steps;
    *last_order = r.stats.last_order;
    memcpy(yref, ref.y0, sizeof(double) * (size_t)m.d.n);
    hx_linear_reference_state(&ref, t_end, yref);
    const double e = state_difference(&m.d, y, yref, ref.y0);
    hx_linear_reference_free(&ref);
    free(y), free(yref);
    close_model(&m);
    return e;
}

/* CVODE holds no order fixed (it starts at order 1 and takes, up to q, the
 * order that allows the longest step) and fails its error test when its
 * step may not shrink, so the order is measured as the adaptive method
 * converges: error against steps over five tolerances, the slope of their
 * least-squares line in log-log is the order (an error ratio of 2^q per
 * halving of the mean step). */
static void bdf_converges_at_its_order(void **state)
{
    (void)state;
    for (int q = 1; q <= 5; ++q) {
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        const int points = 5;
        printf("BDF up to order %d:", q);
        for (int k = 0; k < points; ++k) {
            const double rtol = pow(10.0, -(q < 3 ? 2 * q : q + 2) - k);
            long steps;
            int last;
            const double e = bdf_error(q, rtol, &steps, &last);
            assert_int_equal(last, q);
            printf(" %ld steps: %.3g;", steps, e);
            const double x = log((double)steps), yv = log(e);
            sx += x, sy += yv, sxx += x * x, sxy += x * yv;
        }
        const double slope = -(points * sxy - sx * sy) / (points * sxx - sx * sx);
        printf(" order %.2f (error ratio per halving %.3g; 2^q = %d)\n", slope, pow(2.0, slope),
               1 << q);
        assert_true(fabs(slope - q) < 0.35 + 0.1 * q);
    }
}

/* ---- a wrong partial costs iterations, not accuracy ----------------------------------- */

static void a_wrong_partial_costs_newton_iterations_not_accuracy(void **state)
{
    (void)state;
    static const double scales[] = {1.0, 3.0, 0.3};
    double *y_right = NULL;
    hx_simulation_result right = {0};
    for (int k = 0; k < 3; ++k) {
        char element[512], name[64];
        snprintf(element, sizeof element,
                 "<Force_Field id=\"1\" i_marker_id=\"20\" j_marker_id=\"10\""
                 " usrsub_param_string=\"USER(100, 0.2, 1e6, 2000, %g)\" usrsub_dll_name=\""
                 SCALED_FIELD_LIBRARY "\"/>\n", scales[k]);
        snprintf(name, sizeof name, "scaled_field_%d.xml", k);
        const char *path = scaled_field_model(name, element);
        hx_simulation_result r;
        double *y = bdf_on(path, 1e-8, 0.2, &r, NULL, NULL);
        const hx_integrator_stats *st = &r.stats;
        printf("partials scaled by %g: %s, %ld steps, %.2f Newton iterations per step, %ld"
               " convergence failures, %ld Jacobians\n", scales[k], hx_status_text(r.status),
               st->steps, (double)st->newton_iterations / (double)st->steps,
               st->convergence_failures, st->jacobians);
        if (k == 0) {
            assert_int_equal(r.status, HX_INTEGRATION_OK);
            right = r;
            y_right = y;
            continue;
        }
        /* the wrong matrix costs: more iterations a step, or failed iterations
         * and more steps */
        const double per_step = (double)st->newton_iterations / (double)st->steps;
        const double right_per_step = (double)right.stats.newton_iterations /
                                      (double)right.stats.steps;
        assert_true(r.status != HX_INTEGRATION_OK || per_step > 1.25 * right_per_step ||
                    st->convergence_failures > right.stats.convergence_failures + 10);
        /* and where it converges, it converges to the same trajectory */
        if (r.status == HX_INTEGRATION_OK) {
            model m;
            open_model(&m, path);
            double *y0 = model_state(&m);
            model_initial_state(&m, y0);
            const double diff = state_difference(&m.d, y, y_right, y0);
            printf("  end state against the exact partials' run: %.2g\n", diff);
            assert_true(diff < 1e-6);
            free(y0);
            close_model(&m);
        }
        free(y);
    }
    free(y_right);
}

/* ---- BDF against DOPRI5 on every bundled model --------------------------------------- */

static void bdf_agrees_with_dopri5_on_every_bundled_model(void **state)
{
    (void)state;
    struct dirent **names;
    const int count = scandir(EXAMPLES_DIR, &names, is_model, alphasort);
    assert_true(count > 10);
    const double t_end = 0.05, rtol = 1e-12;
    int compared = 0;
    for (int k = 0; k < count; ++k) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", EXAMPLES_DIR, names[k]->d_name);
        hx_session session;
        hx_dynamics d;
        hx_message msg;
        if (hx_session_open(&session, path, NULL, &msg) != 0)
            fail_msg("%s: %s", names[k]->d_name, msg.text);
        if (hx_dynamics_init(&d, &session, &msg) != 0 || d.nq + d.nu == 0) {
            printf("%-28s no dynamics to integrate (rig or check only)\n", names[k]->d_name);
            if (d.dof != NULL)
                hx_dynamics_free(&d);
            hx_session_close(&session);
            free(names[k]);
            continue;
        }
        const int states = d.n;
        hx_dynamics_free(&d);
        hx_session_close(&session);
        if (states > 100) { /* full_vehicle.xml: 1e-12 takes it ~70 000 steps; its Newton
                             * Jacobian is compared in test_jacobian */
            printf("%-28s %d states: left to the Newton matrix's comparison\n",
                   names[k]->d_name, states);
            free(names[k]);
            continue;
        }
        model m;
        open_model(&m, path);
        double *y0 = calloc(3 * (size_t)m.d.n, sizeof(double)), *a = y0 + m.d.n, *b = a + m.d.n;
        assert_non_null(y0);
        model_initial_state(&m, y0);
        /* atol = rtol: 1e-12 mm, mm/s, rad (tighter drowns the stiff models' error
         * estimates in rounding) */
        hx_simulation_result ra =
            simulate_with(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, rtol * 0.1, 1.0, t_end, a);
        hx_simulation_result rb =
            simulate_with(&m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, rtol, 1.0, t_end, b);
        const double diff = state_difference(&m.d, a, b, y0);
        printf("%-28s BDF (%ld steps, %.3f s) against DOPRI5 (%ld steps) at t = %g: %.2g\n",
               names[k]->d_name, rb.stats.steps, rb.seconds, ra.stats.steps, t_end, diff);
        assert_int_equal(ra.status, HX_INTEGRATION_OK);
        assert_int_equal(rb.status, HX_INTEGRATION_OK);
        assert_true(diff < 1e-8);
        /* couplers and joints: CVODE's projection keeps phi = 0 as DOPRI5's does, to the
         * projection's tolerance of 1e-13 of a row's size (the model's length for a length
         * row: 600 mm for double_pendulum.xml) */
        double size = 1.0;
        for (int i = 0; i < m.d.nrows; ++i)
            size = fmax(size, m.d.rows[i].scale);
        assert_true(rb.max_phi < 1e-12 * size && rb.max_phidot < 1e-10);
        free(y0);
        close_model(&m);
        free(names[k]);
        compared++;
    }
    free(names);
    assert_true(compared > 10);
}

/* ---- run: bdf on every model, and advice that names the figures ----------------------- */

/* "usrsub-harness run MODEL ARGS..." in-process, its output captured. */
static int run_captured(const char *model_path, const char *const *args, test_captured *c)
{
    const char *argv[32] = {"run", model_path};
    for (int i = 0; args[i] != NULL && i < 29; ++i)
        argv[i + 2] = args[i];
    test_capture(hx_command_run, argv, c);
    return c->status;
}

static void run_takes_bdf_on_every_model_and_says_when_it_is_stiff(void **state)
{
    (void)state;
    static test_captured c;
    const char *text = c.out;
    struct dirent **names;
    const int count = scandir(EXAMPLES_DIR, &names, is_model, alphasort);
    const char *const short_run[] = {"--end", "0.01", "--integrator", "bdf", "--quiet", NULL};
    for (int k = 0; k < count; ++k) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", EXAMPLES_DIR, names[k]->d_name);
        const int status = run_captured(path, short_run, &c);
        if (status != 0)
            fail_msg("run --integrator bdf %s: exit %d\n%s", names[k]->d_name, status, text);
        assert_contains(text, "finished with bdf", "Newton iterations");
        free(names[k]);
    }
    free(names);
    /* stiff for its run: an explicit method is told why bdf suits it better */
    const char *const explicit_run[] = {"--end", "1.5", "--quiet", "--output-interval", "0.1", NULL};
    assert_int_equal(run_captured(EXAMPLES_DIR "/stiff_powertrain.xml", explicit_run, &c), 0);
    printf("%s", text);
    assert_contains(text, "stiff for this run", "--integrator bdf", "holds dopri5 to steps below");
    /* not stiff: bdf is told that an explicit method is likely cheaper */
    const char *const bdf_run[] = {"--end", "1", "--integrator", "bdf", "--jacobian", "fd",
                                   "--quiet", "--output-interval", "0.1", NULL};
    assert_int_equal(run_captured(EXAMPLES_DIR "/powertrain.xml", bdf_run, &c), 0);
    printf("%s", text);
    assert_contains(text, "not stiff for this run", "--integrator dopri5",
                    "differences of the right-hand side in");
    assert_contains(text, "linear solver: dense LU (auto", "column groups", "Newton matrices took");
}

/* KLU's Newton matrix A = I - gamma J, written by the harness in one pass
 * (bdf.c's linear_system), against dense LU's, which CVODE builds itself:
 * on the powertrain the two runs take the same steps, Newton iterations and
 * Jacobians within rounding, and end in the same state. A wrong sign, a
 * missing identity or a Jacobian kept when CVODE asks for a new one shows as
 * Newton iterations and steps. */
static void the_one_pass_newton_matrix_is_cvodes(void **state)
{
    (void)state;
    hx_simulation_result r[2];
    double *y[2] = {NULL, NULL};
    for (int k = 0; k < 2; ++k) {
        model m;
        open_model(&m, EXAMPLES_DIR "/powertrain.xml");
        y[k] = model_state(&m);
        hx_simulation_options so = {0};
        hx_integrator_defaults(&so.integration);
        so.integration.method = HX_METHOD_BDF;
        so.integration.linear_solver = k ? HX_LINEAR_KLU : HX_LINEAR_DENSE;
        so.integration.rtol = 1e-6;
        so.integration.atol = 1e-9;
        so.integration.t_end = so.integration.output_interval = 0.6;
        so.integration.max_steps = 5000; /* five times what it takes: a broken matrix stops */
        so.skip_energy = 1;
        hx_simulate(&m.d, &so, y[k], &r[k]);
        assert_int_equal(r[k].status, HX_INTEGRATION_OK);
        close_model(&m);
    }
    assert_int_equal(r[0].stats.linear_solver, HX_LINEAR_DENSE);
    assert_int_equal(r[1].stats.linear_solver, HX_LINEAR_KLU);
    const hx_integrator_stats *dense = &r[0].stats, *klu = &r[1].stats;
    printf("  powertrain to 0.6 s: dense %ld steps, %ld Newton iterations, %ld Jacobians;"
           " KLU %ld, %ld, %ld\n", dense->steps, dense->newton_iterations, dense->jacobians,
           klu->steps, klu->newton_iterations, klu->jacobians);
    assert_true(labs(klu->steps - dense->steps) <= dense->steps / 20);
    assert_true(labs(klu->newton_iterations - dense->newton_iterations) <=
                dense->newton_iterations / 20);
    assert_true(labs(klu->jacobians - dense->jacobians) <= 2 + dense->jacobians / 10);
    double worst = 0.0;
    for (int i = 0; i < r[0].n; ++i)
        worst = fmax(worst, fabs(y[1][i] - y[0][i]) / (1.0 + fabs(y[0][i])));
    assert_true(worst < 1e-4);
    free(y[0]), free(y[1]);
}


int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(differences_by_column_groups_equal_them_column_by_column),
        cmocka_unit_test(the_one_pass_newton_matrix_is_cvodes),
        cmocka_unit_test(bdf_converges_at_its_order),
        cmocka_unit_test(a_wrong_partial_costs_newton_iterations_not_accuracy),
        cmocka_unit_test(bdf_agrees_with_dopri5_on_every_bundled_model),
        cmocka_unit_test(run_takes_bdf_on_every_model_and_says_when_it_is_stiff),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
