/*
 * The static equilibrium's Newton matrix from the Jacobian
 * (sim/simulation/equilibrium_matrix.h; docs/harness.md, static
 * equilibrium) against central differences of the unbalanced loads h = M
 * udot / ucf taken here, entry by entry, at configurations moved off the
 * model's start in every unknown: a free part on springs at a turned pose
 * with products of inertia, a pendulum on a REVOLUTE between a free part and
 * ground springs, a reduced REVOLUTE and a TRANSLATIONAL with springs, and
 * the bundled four-bar, double wishbone, bushing bench and full vehicle on
 * joints. Then equilibria solved with both matrices reach the same
 * configuration, the Jacobian's matrix is taken where it costs less than
 * differences, and a run's --jacobian picks the equilibrium's matrix.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/difference_step.h"
#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraints.h"
#include "sim/simulation/equilibrium_matrix.h"
#include "sim_support.h"
#include "test_support.h"

/* Entries agree to AGREE of the largest entry of their row, or of FLOOR of
 * the matrix's largest when the row is smaller (a row nothing stiffens, a
 * part a FIXED joint holds: its entries the differences' rounding, 1e-9 of
 * the matrix's largest). The Jacobian's own differences (the constraint
 * stage's, an element's without partials) are good to about 1e-9
 * (jacobian.h), these to about as much. */
#define AGREE 1e-6
#define FLOOR 1e-3

/* SI units, gravity -9.81 along y; the parts after it. */
#define HEAD                                                                                    \
    "equilibrium matrix test\nUNITS/\n, FORCE = NEWTON\n, MASS = KILOGRAM\n, LENGTH = METER\n"   \
    ", TIME = SECOND\nACCGRAV/\n, IGRAV = 0\n, JGRAV = -9.81\n, KGRAV = 0\n"                     \
    "PART/1, GROUND\nMARKER/10, PART = 1\nMARKER/11, PART = 1, QP = 1, 0.5, 0\n"                 \
    "MARKER/12, PART = 1, QP = -0.5, 0.8, 0.3\nMARKER/13, PART = 1, QP = 0.2, 0.4, -1\n"

/* A free part turned by REULER, with products of inertia, held by three
 * springs to ground points off its centre: every unknown couples. */
static const char springs[] = HEAD
    "PART/2, MASS = 2, CM = 20, IP = 0.3, 0.2, 0.25, 0.02, -0.01, 0.03, QG = 0.1, -0.2, 0.05,"
    " REULER = 30D, 20D, -15D\n"
    "MARKER/20, PART = 2\nMARKER/21, PART = 2, QP = 0.3, 0.1, 0\n"
    "MARKER/22, PART = 2, QP = -0.2, 0.2, 0.1\nMARKER/23, PART = 2, QP = 0, -0.1, -0.3\n"
    "SFORCE/1, TRANSLATION, I = 21, J = 11, FUNCTION = -400*(DM(21,11) - 0.6)\n"
    "SFORCE/2, TRANSLATION, I = 22, J = 12, FUNCTION = -300*(DM(22,12) - 0.5)\n"
    "SFORCE/3, TRANSLATION, I = 23, J = 13, FUNCTION = -500*(DM(23,13) - 0.7)\n"
    "END\n";

/* The part's springs, and a load that reads the part's acceleration (an
 * algebraic loop: the Jacobian is by differences of every state there). */
static const char looped[] = HEAD
    "PART/2, MASS = 2, CM = 20, IP = 0.3, 0.2, 0.25, QG = 0.1, -0.2, 0.05\n"
    "MARKER/20, PART = 2\nMARKER/21, PART = 2, QP = 0.3, 0.1, 0\n"
    "MARKER/22, PART = 2, QP = -0.2, 0.2, 0.1\nMARKER/23, PART = 2, QP = 0, -0.1, -0.3\n"
    "SFORCE/1, TRANSLATION, I = 21, J = 11, FUNCTION = -400*(DM(21,11) - 0.6)\n"
    "SFORCE/2, TRANSLATION, I = 22, J = 12, FUNCTION = -300*(DM(22,12) - 0.5)\n"
    "SFORCE/3, TRANSLATION, I = 23, J = 13, FUNCTION = -500*(DM(23,13) - 0.7)\n"
    "SFORCE/4, TRANSLATION, I = 20, J = 11, FUNCTION = 0.2*ACCY(20)\n"
    "END\n";

/* The same part carrying a pendulum on a REVOLUTE between them (rows). */
static const char pendulum[] = HEAD
    "PART/2, MASS = 2, CM = 20, IP = 0.3, 0.2, 0.25, QG = 0.1, -0.2, 0.05, REULER = 30D, 0, 0\n"
    "MARKER/20, PART = 2\nMARKER/21, PART = 2, QP = 0.3, 0.1, 0\n"
    "MARKER/22, PART = 2, QP = -0.2, 0.2, 0.1\nMARKER/23, PART = 2, QP = 0, -0.1, -0.3\n"
    "MARKER/24, PART = 2, QP = 0.1, -0.2, 0.05\n"
    "SFORCE/1, TRANSLATION, I = 21, J = 11, FUNCTION = -400*(DM(21,11) - 0.6)\n"
    "SFORCE/2, TRANSLATION, I = 22, J = 12, FUNCTION = -300*(DM(22,12) - 0.5)\n"
    "SFORCE/3, TRANSLATION, I = 23, J = 13, FUNCTION = -500*(DM(23,13) - 0.7)\n"
    "PART/3, MASS = 0.5, CM = 30, IP = 0.01, 0.02, 0.02\n"
    "MARKER/30, PART = 3, QP = 0.4, -0.3, 0.05\nMARKER/31, PART = 3, QP = 0.1, -0.2, 0.05\n"
    "JOINT/1, REVOLUTE, I = 31, J = 24\n"
    "END\n";

/* A bar on a reduced REVOLUTE to ground with a torsion spring, and a block on
 * a reduced TRANSLATIONAL along x with a spring across. */
static const char reduced[] = HEAD
    "PART/2, MASS = 1, CM = 20, IP = 0.01, 0.08, 0.08\n"
    "MARKER/20, PART = 2, QP = 0.5, 0, 0\nMARKER/21, PART = 2\n"
    "JOINT/1, REVOLUTE, I = 21, J = 10\n"
    "SFORCE/1, ROTATION, I = 21, J = 10, FUNCTION = -10*AZ(21,10)\n"
    "PART/3, MASS = 3, CM = 30, IP = 0.1, 0.1, 0.1\n"
    "MARKER/30, PART = 3, QP = 2, 1, 0, REULER = 90D, 90D, 0\n"
    "MARKER/31, PART = 1, QP = 2, 1, 0, REULER = 90D, 90D, 0\n"
    "MARKER/32, PART = 1, QP = 3, 1.5, 0\n"
    "JOINT/2, TRANSLATIONAL, I = 30, J = 31\n"
    "SFORCE/2, TRANSLATION, I = 30, J = 32, FUNCTION = -200*(DM(30,32) - 0.8)\n"
    "END\n";

typedef struct opened {
    hx_session s;
    hx_dynamics d;
    hx_dynamics_data dd;
    hx_jacobian jac;
    double *y, *ydot, *trial, *values, *work, *K, *D, *hp, *hm, *length, *scale;
    int *var, nv;
    double L;
} opened;

/* Opens text (or, text NULL, the bundled example name) with its Jacobian,
 * its unknowns as equilibrium.c takes them (each part's velocities but a
 * driven one's), a length per unknown and a scale per load that differ from
 * one another (so that a scaling by the wrong index shows). */
static void open_model(opened *o, const char *name, const char *text)
{
    memset(o, 0, sizeof *o);
    hx_message msg;
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", EXAMPLES_DIR, name);
    if (hx_session_open(&o->s, text != NULL ? test_write_file(name, text) : path, stderr,
                        &msg) != 0 ||
        hx_dynamics_init(&o->d, &o->s, &msg) != 0 ||
        hx_dynamics_data_init(&o->dd, &o->d, &msg) != 0 ||
        hx_jacobian_init(&o->jac, &o->d, &msg) != 0)
        fail_msg("%s", msg.text);
    const hx_dynamics *d = &o->d;
    const size_t n = (size_t)d->n, nu = (size_t)d->nu;
    o->y = calloc(4 * n, sizeof(double));
    o->ydot = o->y + n, o->trial = o->y + 2 * n;
    o->values = calloc((size_t)o->jac.pattern.nnz + 2 * nu + 1, sizeof(double));
    o->work = o->values + o->jac.pattern.nnz;
    o->K = calloc(2 * nu * nu + 4 * nu + 1, sizeof(double));
    o->D = o->K + nu * nu, o->hp = o->D + nu * nu, o->hm = o->hp + nu;
    o->length = o->hm + nu, o->scale = o->length + nu;
    o->var = calloc(nu + 1, sizeof(int));
    assert_non_null(o->y), assert_non_null(o->values), assert_non_null(o->K);
    assert_non_null(o->var);
    o->L = 1.0;
    for (int k = 0; k < d->m->nmarkers; ++k)
        o->L = fmax(o->L, v3_norm(d->m->markers[k].pos0));
    for (int k = 0; k < d->m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        if (dof->kind == HX_DOF_GROUND || d->driver[k] >= 0)
            continue;
        for (int c = 0; c < (dof->kind == HX_DOF_FREE ? 6 : 1); ++c)
            o->var[o->nv++] = dof->u + c;
    }
    for (int i = 0; i < o->nv; ++i) {
        o->length[i] = o->L * (1.0 + 0.1 * i);
        o->scale[i] = 2.0 + 0.3 * i;
    }
    assert_int_equal(hx_dynamics_initial_state(d, &o->dd, o->y), 0);
}

static void close_model(opened *o)
{
    free(o->y), free(o->values), free(o->K), free(o->var);
    hx_jacobian_free(&o->jac);
    hx_dynamics_data_free(&o->dd);
    hx_dynamics_free(&o->d);
    hx_session_close(&o->s);
}

/* Every part moved off the start: a free part's centre by up to `shift` of
 * the model's length and turned by up to `turn` radians about an axis of its
 * own, a joint's coordinate by up to `turn` (or `shift` of the length); then
 * onto the constraints. */
static void move_parts(opened *o, double shift, double turn)
{
    const hx_dynamics *d = &o->d;
    double *u = o->y + d->nq;
    memset(u, 0, sizeof(double) * (size_t)d->nu);
    for (int i = 0; i < o->nv; ++i) {
        int k = 0; /* the part of unknown i */
        while (d->dof[k].kind == HX_DOF_GROUND || o->var[i] < d->dof[k].u ||
               o->var[i] >= d->dof[k].u + (d->dof[k].kind == HX_DOF_FREE ? 6 : 1))
            ++k;
        const int c = o->var[i] - d->dof[k].u;
        const int turns = d->dof[k].kind == HX_DOF_REVOLUTE ||
                          (d->dof[k].kind == HX_DOF_FREE && c >= 3);
        u[o->var[i]] = (0.5 + 0.5 * fabs(sim_uniform())) * (sim_uniform() < 0 ? -1 : 1) *
                       (turns ? turn : shift * o->L);
    }
    hx_bodies_advance_positions(d, o->y, 1.0);
    memset(u, 0, sizeof(double) * (size_t)d->nu);
    assert_int_equal(hx_constraints_project(d, &o->dd, 0.0, o->y), 0);
}

/* h (nu, M udot / ucf) at y, computed here: m a and I alpha of a free part, a
 * joint's mass times its acceleration. */
static void loads_at(opened *o, const double *y, double *h)
{
    const hx_dynamics *d = &o->d;
    assert_int_equal(hx_dynamics_rhs(d, &o->dd, 0.0, y, o->ydot), 0);
    const double *a = o->ydot + d->nq;
    for (int k = 0; k < d->m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        if (dof->kind == HX_DOF_GROUND)
            continue;
        const int w = dof->kind == HX_DOF_FREE ? 3 : 1;
        for (int c = 0; c < w; ++c)
            h[dof->u + c] = dof->mass * a[dof->u + c] / d->ucf;
        for (int r = 0; w == 3 && r < 3; ++r)
            h[dof->u + 3 + r] = (dof->inertia[3 * r] * a[dof->u + 3] +
                                 dof->inertia[3 * r + 1] * a[dof->u + 4] +
                                 dof->inertia[3 * r + 2] * a[dof->u + 5]) / d->ucf;
    }
}

/* D: central differences of h, each unknown moved as a step of the
 * integrators moves it (a turn in body axes, the quaternion kept unit). */
static void difference_matrix(opened *o)
{
    const hx_dynamics *d = &o->d;
    const int nv = o->nv;
    for (int j = 0; j < nv; ++j) {
        const double step = hx_difference_step(0.0, 1e-5, 1.0);
        for (int side = 0; side < 2; ++side) {
            memcpy(o->trial, o->y, sizeof(double) * (size_t)d->n);
            double *u = o->trial + d->nq;
            memset(u, 0, sizeof(double) * (size_t)d->nu);
            u[o->var[j]] = side == 0 ? step : -step;
            hx_bodies_advance_positions(d, o->trial, 1.0);
            memcpy(u, o->y + d->nq, sizeof(double) * (size_t)d->nu);
            loads_at(o, o->trial, side == 0 ? o->hp : o->hm);
        }
        for (int i = 0; i < nv; ++i)
            o->D[i * nv + j] = (o->hp[o->var[i]] - o->hm[o->var[i]]) / (2.0 * step) *
                               o->length[j] / o->scale[i];
    }
}

/* K from the Jacobian against D at the moved configuration, entry by entry
 * (AGREE, FLOOR); returns the largest difference. */
static double compare(opened *o, const char *what)
{
    const hx_equilibrium_unknowns x = {o->nv, o->var, o->length, o->scale};
    if (hx_equilibrium_matrix(&o->jac, 0.0, o->y, &x, o->values, o->work, o->K, o->nv) != 0)
        fail_msg("%s", o->jac.dd.message);
    difference_matrix(o);
    double worst = 0.0, biggest = 0.0;
    for (int i = 0; i < o->nv * o->nv; ++i)
        biggest = fmax(biggest, fabs(o->D[i]));
    assert_true(biggest > 0.0); /* something is stiff */
    for (int i = 0; i < o->nv; ++i) {
        double row = FLOOR * biggest;
        for (int j = 0; j < o->nv; ++j)
            row = fmax(row, fabs(o->D[i * o->nv + j]));
        for (int j = 0; j < o->nv; ++j) {
            const double diff = fabs(o->K[i * o->nv + j] - o->D[i * o->nv + j]) / row;
            if (!(diff <= AGREE))
                fail_msg("%s: K[%d][%d] = %.12g from the Jacobian, %.12g by differences (the"
                         " row's largest %.3g)", what, i, j, o->K[i * o->nv + j],
                         o->D[i * o->nv + j], row);
            worst = fmax(worst, diff);
        }
    }
    printf("  %s: %d unknowns, largest difference %.2g of its row\n", what, o->nv, worst);
    return worst;
}

/* A model, and how far its parts are moved off its start. */
typedef struct matrix_case {
    const char *name, *text; /* text NULL: the bundled example */
    double shift, turn;
} matrix_case;

static const matrix_case cases[] = {
    {"eqm_springs.adm", springs, 0.05, 0.3},
    {"eqm_pendulum.adm", pendulum, 0.05, 0.3},
    {"eqm_reduced.adm", reduced, 0.05, 0.3},
    {"four_bar.xml", NULL, 0.02, 0.2},
    {"double_wishbone.xml", NULL, 0.002, 0.02},
    {"bench_bushing.xml", NULL, 0.002, 0.05},
    {"full_vehicle_joints.xml", NULL, 0.001, 0.01},
};

static void matrix_matches_differences(void **state)
{
    const matrix_case *c = *state;
    opened o;
    srand(7);
    open_model(&o, c->name, c->text);
    move_parts(&o, c->shift, c->turn);
    compare(&o, c->name);
    close_model(&o);
}

/* From the same moved start, the equilibrium with K from the Jacobian and by
 * differences: the same configuration, the Jacobian's in fewer right-hand
 * sides. */
static void same_equilibrium_both_ways(const matrix_case *c)
{
    const char *name = c->name;
    opened o;
    srand(11);
    open_model(&o, name, c->text);
    move_parts(&o, c->shift, c->turn);
    const size_t n = (size_t)o.d.n;
    memcpy(o.trial, o.y, sizeof(double) * n);
    hx_equilibrium_result analytic, differences;
    hx_message msg;
    if (hx_equilibrium_solve(&o.d, &o.dd, &o.jac, 0.0, o.y, &analytic, &msg) != 0 ||
        hx_equilibrium_solve(&o.d, &o.dd, NULL, 0.0, o.trial, &differences, &msg) != 0)
        fail_msg("%s: %s", name, msg.text);
    assert_true(analytic.analytic && !differences.analytic);
    assert_true(analytic.iterations >= 1);
    assert_true(analytic.evaluations < differences.evaluations);
    for (int k = 0; k < o.d.nq; ++k)
        if (fabs(o.y[k] - o.trial[k]) > 1e-9 * o.L)
            fail_msg("%s: position %d at %.15g with the Jacobian's K, %.15g with differences",
                     name, k, o.y[k], o.trial[k]);
    printf("  %s: %d and %d iterations, %ld and %ld right-hand sides\n", name,
           analytic.iterations, differences.iterations, analytic.evaluations,
           differences.evaluations);
    close_model(&o);
}

static void equilibria_agree(void **state)
{
    (void)state;
    for (int k = 0; k < 4; ++k) /* the three above and the four-bar */
        same_equilibrium_both_ways(&cases[k]);
}

/* Where the Jacobian's matrix costs less than differences: a model on force
 * elements (the springs; the full vehicle on joints, its four corners
 * apart), not a linkage whose constraint stage differences all its parts'
 * columns (the four-bar: 39 columns, 18 unknowns), nor a model with an
 * algebraic loop; there the Jacobian's matrix, asked for, still reaches the
 * equilibrium differences reach. */
static void where_the_jacobian_pays(void **state)
{
    (void)state;
    static const struct {
        const char *name, *text;
        int pays;
    } models[] = {{"eqm_springs.adm", springs, 1}, {"full_vehicle_joints.xml", NULL, 1},
                  {"four_bar.xml", NULL, 0}, {"eqm_looped.adm", looped, 0}};
    for (int k = 0; k < 4; ++k) {
        opened o;
        open_model(&o, models[k].name, models[k].text);
        assert_int_equal(hx_equilibrium_jacobian_pays(&o.jac), models[k].pays);
        close_model(&o);
    }
    opened o;
    srand(5);
    open_model(&o, "eqm_looped.adm", looped);
    assert_true(o.d.m->nloop_inputs > 0);
    move_parts(&o, 0.05, 0.3);
    memcpy(o.trial, o.y, sizeof(double) * (size_t)o.d.n);
    hx_equilibrium_result with, without;
    hx_message msg;
    if (hx_equilibrium_solve(&o.d, &o.dd, &o.jac, 0.0, o.y, &with, &msg) != 0 ||
        hx_equilibrium_solve(&o.d, &o.dd, NULL, 0.0, o.trial, &without, &msg) != 0)
        fail_msg("%s", msg.text);
    assert_true(with.analytic && !without.analytic);
    assert_true(with.iterations >= 1);
    for (int k = 0; k < o.d.nq; ++k)
        assert_float_equal(o.y[k], o.trial[k], 1e-9);
    close_model(&o);
}

/* A run from the static equilibrium with the method and matrix asked for:
 * which matrix the equilibrium took, and where it left the parts (y_end). */
static int simulated_matrix(opened *o, hx_method method, hx_jacobian_method jacobian,
                            double *y_end)
{
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = method;
    so.integration.jacobian = jacobian;
    so.integration.t_end = 1e-9;
    so.integration.output_interval = 1e-9;
    so.skip_energy = 1;
    so.static_start = 1;
    hx_simulation_result r;
    if (hx_simulate(&o->d, &so, y_end, &r) != 0)
        fail_msg("%s", r.message);
    assert_int_equal(r.statics, 1);
    assert_true(r.equilibrium.iterations >= 1);
    return r.equilibrium.analytic;
}

/* run --static takes --jacobian (BDF's option) for the equilibrium's matrix,
 * with any integrator: analytic by default where it pays, differences with
 * fd or where it does not (the four-bar); the equilibrium the same; and the
 * command line takes both. */
static void run_static_takes_the_jacobian_option(void **state)
{
    (void)state;
    opened o;
    open_model(&o, "eqm_run.adm", springs);
    double *fd = o.trial, *analytic = o.y;
    assert_true(simulated_matrix(&o, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, analytic));
    assert_false(simulated_matrix(&o, HX_METHOD_DOPRI5, HX_JACOBIAN_FD, fd));
    for (size_t k = 0; k < (size_t)o.d.nq; ++k)
        assert_float_equal(analytic[k], fd[k], 1e-9);
    assert_true(simulated_matrix(&o, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, fd));
    assert_false(simulated_matrix(&o, HX_METHOD_BDF, HX_JACOBIAN_FD, fd));
    close_model(&o);
    open_model(&o, "four_bar.xml", NULL);
    assert_false(simulated_matrix(&o, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, o.y));
    close_model(&o);
    char csv[1024];
    snprintf(csv, sizeof csv, "%s/eqm_fd.csv", test_temp_dir());
    const char *const args[] = {"--quiet", "--static", "--end", "1e-6", "--jacobian", "fd", NULL};
    assert_int_equal(sim_run_csv("four_bar.xml", csv, args), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        /* a free part on springs at a turned pose; a pendulum on a REVOLUTE between
         * moving bodies; a reduced REVOLUTE and TRANSLATIONAL; the examples */
        cmocka_unit_test_prestate(matrix_matches_differences, (void *)&cases[0]),
        cmocka_unit_test_prestate(matrix_matches_differences, (void *)&cases[1]),
        cmocka_unit_test_prestate(matrix_matches_differences, (void *)&cases[2]),
        cmocka_unit_test_prestate(matrix_matches_differences, (void *)&cases[3]),
        cmocka_unit_test_prestate(matrix_matches_differences, (void *)&cases[4]),
        cmocka_unit_test_prestate(matrix_matches_differences, (void *)&cases[5]),
        cmocka_unit_test_prestate(matrix_matches_differences, (void *)&cases[6]),
        cmocka_unit_test(equilibria_agree),
        cmocka_unit_test(where_the_jacobian_pays),
        cmocka_unit_test(run_static_takes_the_jacobian_option),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
