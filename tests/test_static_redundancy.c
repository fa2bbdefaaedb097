/*
 * Redundant constraint rows found again at a static equilibrium
 * (sim/dynamics/redundancy.h, hx_redundancy_reexamine; docs/harness.md,
 * static equilibrium): a parallelogram four-bar placed with its four pivots
 * on a line, where joint 4's x row is a combination of the others and the
 * set-up removes it, hangs under gravity to where it is not. The run goes on
 * with the row back, says so, and holds every row; the set-up's set is back
 * after the run.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd/commands.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/redundancy.h"
#include "sim_support.h"
#include "test_support.h"

/* Ground pivots A = (0, 0) and D = (3, 0); the cranks (1 kg, length 1) placed
 * along -x from them, the coupler (2 kg, length 3) joining their ends at
 * B = (-1, 0) and C = (2, 0): the four pivots on the x axis, where joint 4's
 * x row is a combination of the others. Gravity along -y hangs it as a
 * parallelogram, the cranks along -y: their centres at (0, -0.5) and
 * (3, -0.5), the coupler's at (1.5, -1), where the x row is not. */
static const char parallelogram[] =
    "parallelogram hanging out of a collinear placement\n"
    "ACCGRAV/\n, IGRAV = 0\n, JGRAV = -9.81\n, KGRAV = 0\n"
    "PART/1, GROUND\nMARKER/10, PART = 1\nMARKER/11, PART = 1, QP = 3, 0, 0\n"
    "PART/2, MASS = 1, CM = 20, IP = 0.001, 0.0833333333333, 0.0833333333333\n"
    "MARKER/20, PART = 2, QP = -0.5, 0, 0\nMARKER/21, PART = 2\n"
    "MARKER/22, PART = 2, QP = -1, 0, 0\n"
    "PART/3, MASS = 2, CM = 30, IP = 0.002, 1.5, 1.5\n"
    "MARKER/30, PART = 3, QP = 0.5, 0, 0\nMARKER/31, PART = 3, QP = -1, 0, 0\n"
    "MARKER/32, PART = 3, QP = 2, 0, 0\n"
    "PART/4, MASS = 1, CM = 40, IP = 0.001, 0.0833333333333, 0.0833333333333\n"
    "MARKER/40, PART = 4, QP = 2.5, 0, 0\nMARKER/41, PART = 4, QP = 2, 0, 0\n"
    "MARKER/42, PART = 4, QP = 3, 0, 0\n"
    "JOINT/1, REVOLUTE, I = 21, J = 10\nJOINT/2, REVOLUTE, I = 31, J = 22\n"
    "JOINT/3, REVOLUTE, I = 41, J = 32\nJOINT/4, REVOLUTE, I = 42, J = 11\n"
    "END\n";

#define OUT_OF_PLANE                                                                           \
    "JOINT/4 REVOLUTE: equation 3 (x_I - x_J along z), "                                       \
    "JOINT/4 REVOLUTE: equation 4 (z_I . x_J), JOINT/4 REVOLUTE: equation 5 (z_I . y_J)"
#define X_ROW "JOINT/4 REVOLUTE: equation 1 (x_I - x_J along x)"

/* The largest residuals of every row (active and removed) at the output
 * times, on data of the test's own. */
typedef struct held {
    hx_dynamics_data dd;
    double phi, phidot;
    int outputs;
} held;

/* The removed rows' names, ", " between them. */
static void removed_names(const hx_dynamics *d, char *text, size_t size)
{
    text[0] = '\0';
    for (int k = 0; k < d->nremoved; ++k) {
        char name[160];
        const size_t used = strlen(text);
        snprintf(text + used, size - used, "%s%s", k > 0 ? ", " : "",
                 hx_redundancy_name_row(d, d->removed[k], name, sizeof name));
    }
}

/* At each output: the residuals held (the run's data left alone). */
static int observe(void *ctx, const hx_dynamics *d, hx_dynamics_data *dd, double t,
                   const double *y)
{
    (void)dd;
    held *h = ctx;
    double phi, phidot;
    if (hx_constraints_residuals(d, &h->dd, t, y, &phi, &phidot) != 0)
        return 1;
    h->phi = fmax(h->phi, phi), h->phidot = fmax(h->phidot, phidot);
    h->outputs++;
    return 0;
}

/* run --static's run in-process: DOPRI5 to 0.5 s from the equilibrium, the
 * re-examination on or off; the run's status. */
static int run_static(sim_opened *o, int keep_redundant, held *h, hx_simulation_result *r,
                      double *y)
{
    hx_simulation_options so;
    memset(&so, 0, sizeof so);
    hx_integrator_defaults(&so.integration);
    so.integration.method = HX_METHOD_DOPRI5;
    so.integration.t_end = 0.5;
    so.integration.rtol = 1e-10;
    so.integration.atol = 1e-13;
    so.integration.output_interval = 0.01;
    so.static_start = 1;
    so.keep_redundant = keep_redundant;
    so.observer = observe;
    so.observer_ctx = h;
    memset(h, 0, sizeof *h);
    hx_message msg;
    if (hx_dynamics_data_init(&h->dd, &o->d, &msg) != 0)
        fail_msg("%s", msg.text);
    const int status = hx_simulate(&o->d, &so, y, r);
    hx_dynamics_data_free(&h->dd);
    return status;
}

/* The set-up removes joint 4's x row and its out-of-plane rows (the pivots
 * collinear); at the equilibrium the x row is independent again: the result
 * names it, the run from there holds every row to 1e-10 and stays at rest
 * where worked by hand, and d has the set-up's set again after it. */
static void hanging_equilibrium_keeps_the_x_row(void **state)
{
    (void)state;
    sim_opened o;
    sim_open_text(&o, "static_parallelogram.adm", parallelogram);
    char names[1024];
    removed_names(&o.d, names, sizeof names);
    assert_string_equal(names, X_ROW ", " OUT_OF_PLANE);
    held h;
    hx_simulation_result r;
    double y[64];
    assert_true(o.d.n <= 64);
    if (run_static(&o, 0, &h, &r, y) != 0)
        fail_msg("%s", r.message);
    assert_int_equal(r.statics, 1);
    assert_int_equal(r.redundancy_changes, 1);
    assert_string_equal(r.no_longer, X_ROW);
    assert_string_equal(r.now, "");
    printf("hanging equilibrium: |phi| %.3g, |dphi/dt| %.3g over %d outputs, %d Newton"
           " iterations\n", h.phi, h.phidot, h.outputs, r.equilibrium.iterations);
    assert_true(h.outputs >= 50);
    assert_true(h.phi <= 1e-10);
    assert_true(h.phidot <= 1e-10);
    const double *crank = y + o.d.dof[1].q, *coupler = y + o.d.dof[2].q;
    const double *rocker = y + o.d.dof[3].q;
    assert_float_equal(crank[0], 0.0, 1e-8);
    assert_float_equal(crank[1], -0.5, 1e-8);
    assert_float_equal(coupler[0], 1.5, 1e-8);
    assert_float_equal(coupler[1], -1.0, 1e-8);
    assert_float_equal(rocker[0], 3.0, 1e-8);
    assert_float_equal(rocker[1], -0.5, 1e-8);
    removed_names(&o.d, names, sizeof names);
    assert_string_equal(names, X_ROW ", " OUT_OF_PLANE);
    sim_close_opened(&o);
}

/* Without the second look the x row stays removed where the others no
 * longer imply it: no Newton step keeps it, and the equilibrium fails. */
static void without_the_reexamination_the_run_stops(void **state)
{
    (void)state;
    sim_opened o;
    sim_open_text(&o, "static_parallelogram_kept.adm", parallelogram);
    held h;
    hx_simulation_result r;
    double y[64];
    const int status = run_static(&o, 1, &h, &r, y);
    printf("without the re-examination: status %d, %s\n", status, r.message);
    assert_int_equal(r.redundancy_changes, 0);
    assert_int_equal(status, -1);
    sim_close_opened(&o);
}

/* run --static says which row the equilibrium kept. */
static void run_static_notes_the_change(void **state)
{
    (void)state;
    test_captured c;
    const char *path = test_write_file("static_parallelogram_run.adm", parallelogram);
    test_capture(hx_command_run,
                 (const char *const[]){"run", path, "--static", "--end", "0.01", "--quiet",
                                       NULL},
                 &c);
    assert_int_equal(c.status, 0);
    assert_non_null(strstr(c.err, "run: note: the static equilibrium at t = 0 moved the parts to"
                                  " where " X_ROW ", redundant before, is not: kept\n"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hanging_equilibrium_keeps_the_x_row),
        cmocka_unit_test(without_the_reexamination_the_run_stops),
        cmocka_unit_test(run_static_notes_the_change),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
