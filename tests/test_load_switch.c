/*
 * A command file's DEACTIVATE and ACTIVATE of a load (docs/interface.md
 * §9.9) in BDF's Jacobian: a switched-off stiff SFORCE is in neither the
 * right-hand side nor the analytic Jacobian (which equals differences of the
 * switched right-hand side), and switched on again both are, bit for bit,
 * what they are where it was never switched off; a run clears a flag left
 * set.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "model_runs.h"
#include "sim_support.h"
#include "test_support.h"

/* A 2 kg body on a stiff damped spring to the ground's origin (SFORCE 1,
 * k = 1e5) and a soft one to marker 30 (SFORCE 2), under gravity, moving. */
static const char *const dataset =
    "switch: a stiff spring switched off and on\n"
    "ACCGRAV/JGRAV = -9.81\n"
    "PART/1, GROUND\nMARKER/10, PART = 1\nMARKER/30, PART = 1, QP = 1, 0, 0\n"
    "PART/2, MASS = 2, CM = 20, IP = 1, 2, 3, VX = 0.5, VZ = -0.2, WZ = 0.3\n"
    "MARKER/20, PART = 2, QP = 0.3, -1.1, 0.2\n"
    "SFORCE/1, TRANSLATION, I = 20, J = 10, FUNCTION = -1E5*(DM(20,10) - 1) - 50*VR(20,10)\n"
    "SFORCE/2, TRANSLATION, I = 20, J = 30, FUNCTION = -200*(DM(20,30) - 1.2)\n"
    "END\n";

/* The right-hand side and the analytic Jacobian at (t, y), malloc'ed. */
static void build(const hx_dynamics *d, double t, const double *y, double **fy, double **values,
                  int *nnz)
{
    hx_jacobian jac;
    hx_dynamics_data dd;
    hx_message msg;
    if (hx_jacobian_init(&jac, d, &msg) != 0 || hx_dynamics_data_init(&dd, d, &msg) != 0)
        fail_msg("%s", msg.text);
    *nnz = jac.pattern.nnz;
    *fy = calloc((size_t)d->n, sizeof(double));
    *values = calloc((size_t)jac.pattern.nnz + 1, sizeof(double));
    assert_non_null(*fy), assert_non_null(*values);
    if (hx_dynamics_rhs(d, &dd, t, y, *fy) != 0 || hx_jacobian_build(&jac, t, y, *fy, *values) != 0)
        fail_msg("%s", dd.failed ? dd.message : jac.dd.message);
    hx_jacobian_free(&jac);
    hx_dynamics_data_free(&dd);
}

static void open_moved(model *m, double **y)
{
    open_model(m, test_write_file("switch.adm", dataset));
    assert_int_equal(m->session.model->nloads, 2);
    assert_int_equal(m->session.model->loads[0].id, 1);
    *y = model_state(m);
    /* a state away from the start: every coordinate and velocity moved */
    hx_simulation_result r = simulate(m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, 1e-8, 0.05, *y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
}

/* Switched off, the stiff spring is in neither: the Jacobian against
 * differences of the switched right-hand side (1e5 / 2 kg of stiffness a
 * Jacobian that kept it would show), and it differs from the one with it on. */
static void a_switched_off_load_is_not_in_the_jacobian(void **state)
{
    (void)state;
    model m;
    double *y;
    open_moved(&m, &y);
    m.d.load_off[0] = 1;
    long outside = 0;
    const double worst = jacobian_against_differences(&m.d, 0.05, y, "switched off", &outside);
    assert_int_equal(outside, 0);
    assert_true(worst < 1e-6);
    double *fy_off, *off, *fy_on, *on;
    int nnz, nnz_on;
    build(&m.d, 0.05, y, &fy_off, &off, &nnz);
    m.d.load_off[0] = 0;
    build(&m.d, 0.05, y, &fy_on, &on, &nnz_on);
    assert_int_equal(nnz, nnz_on); /* the pattern is the model's, whatever is switched */
    double largest = 0.0;
    for (int k = 0; k < nnz; ++k)
        largest = fmax(largest, fabs(on[k] - off[k]));
    assert_true(largest > 1e4); /* the stiffness, k / m = 5e4 on the body's rows */
    free(fy_off), free(off), free(fy_on), free(on), free(y);
    close_model(&m);
}

/* Switched off and on again: the right-hand side and the Jacobian are bit for
 * bit those of the model never switched, at the same state; and a run that
 * finds a flag left set (the schedule's segments say on) runs as one that
 * never had it. */
static void activate_restores_the_load(void **state)
{
    (void)state;
    model m;
    double *y;
    open_moved(&m, &y);
    double *fy0, *j0, *fy1, *j1;
    int nnz0, nnz1;
    build(&m.d, 0.05, y, &fy0, &j0, &nnz0);
    m.d.load_off[0] = 1;
    double *fy_off, *j_off;
    build(&m.d, 0.05, y, &fy_off, &j_off, &nnz1);
    assert_true(memcmp(fy0, fy_off, sizeof(double) * (size_t)m.d.n) != 0);
    m.d.load_off[0] = 0; /* ACTIVATE */
    build(&m.d, 0.05, y, &fy1, &j1, &nnz1);
    assert_memory_equal(fy0, fy1, sizeof(double) * (size_t)m.d.n);
    assert_memory_equal(j0, j1, sizeof(double) * (size_t)nnz0);

    double *a = model_state(&m), *b = model_state(&m);
    hx_simulation_result r = simulate(&m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, 1e-8, 0.1, a);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    m.d.load_off[0] = 1; /* left set: a run's segments set every flag */
    r = simulate(&m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, 1e-8, 0.1, b);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    assert_memory_equal(a, b, sizeof(double) * (size_t)m.d.n);
    assert_int_equal(m.d.load_off[0], 0);
    free(fy0), free(j0), free(fy1), free(j1), free(fy_off), free(j_off), free(y), free(a),
        free(b);
    close_model(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_switched_off_load_is_not_in_the_jacobian),
        cmocka_unit_test(activate_restores_the_load),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
