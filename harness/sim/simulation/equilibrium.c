/*
 * Static equilibrium (equilibrium.h): damped Newton on the parts' unbalanced
 * generalized forces at u = 0, h(q) = M udot(q, 0) / ucf (the constrained
 * accelerations of the right-hand side, so the loads projected on the
 * constraints' free motions), in the velocity coordinates (a free part's
 * centre in world axes and its turn in body axes; a reduced joint's
 * coordinate). The Newton matrix K = dh/dx from the dynamics' Jacobian
 * (equilibrium_matrix.c), or by central differences of h, each increment
 * applied to the positions as a step of the integrators applies a velocity
 * (hx_bodies_advance_positions: quaternions turned, kept unit); the
 * constraints kept to first order by their rows G in the saddle system
 *     [ K + R   G^T ] [dx]   [-h]
 *     [ G       0   ] [mu] = [ 0]
 * and each iterate projected back onto phi = 0. docs/harness.md, static
 * equilibrium, says the method, the tolerance and the errors.
 */
#include "sim/simulation/equilibrium.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/clock.h"
#include "base/difference_step.h"
#include "base/linalg.h"
#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/loads.h"
#include "sim/simulation/equilibrium_matrix.h"

/* R: a stiffness this small against the model's (its force per length, or
 * per radian times its length), or against its stiffest entry, on the
 * diagonal. A direction nothing holds and nothing pushes along (a spherical
 * pendulum's spin about the vertical) then takes no step; one that the load
 * pushes along and nothing holds (a falling part) shows as a step R alone
 * carries: no equilibrium. */
#define REGULARIZATION 1e-8
#define REGULARIZATION_STIFFEST 1e-12 /* a direction stiff parts cancel in (a part on stiff
                                       * springs not yet loaded, turning about its pivot)
                                       * keeps a pivot above the elimination's floor, 1e-14
                                       * of the largest entry */
#define UNHELD_SHARE 0.1  /* of the unbalanced loads carried by R: nothing holds a part */
#define UNHELD_ITERATIONS 3 /* iterations in a row of it: no equilibrium */
#define DAMPINGS 20       /* raisings of R for a step within the limits */
#define MAX_TURN 0.5      /* radians a Newton step turns a part at most */
#define MAX_SHIFT 0.5     /* of the model's length a Newton step moves a part at most */
#define HALVINGS 8        /* of a step that does not lower the unbalanced loads */
#define DIFFERENCE 1e-5   /* the Jacobian's eps (base/difference_step.h) */

typedef struct solver {
    const hx_dynamics *d;
    hx_dynamics_data *dd;
    hx_jacobian *jac;    /* K from it (NULL: by differences of h) */
    double *values, *work; /* the Jacobian's values; 2 nu for K's columns */
    long evaluations;    /* right-hand sides taken here */
    double t, L, F;      /* the time, the model's length and force */
    int nv, na;          /* unknowns; size of the saddle system */
    int *var;            /* per unknown: its velocity (index into u) */
    int *body;           /* per unknown: its part */
    double *scale;       /* per unknown: F, or F L for a turn */
    double *length;      /* per unknown: L, or 1 for a turn */
    double *reg;         /* per unknown: R's diagonal, in the system's units */
    double *ydot, *trial; /* n each */
    double *gen;         /* nu: the generalized forces */
    double *h, *hp, *hm, *dx; /* nv each */
    double *A, *b;       /* na x na, na */
    double *A0;          /* the saddle system with R, kept for solves with R raised */
    double *phi, *G;     /* nrows, 12 a row */
} solver;

static int is_turn(const hx_body_dof *dof, int c)
{
    return dof->kind == HX_DOF_REVOLUTE || (dof->kind == HX_DOF_FREE && c >= 3);
}

/* Unknown i is a turn (radians), not a shift (a length). */
static int turns(const solver *sv, int i)
{
    const hx_body_dof *dof = &sv->d->dof[sv->body[i]];
    return is_turn(dof, sv->var[i] - dof->u);
}

/* h at y (velocities as y has them: the unknowns' zero). */
static int unbalanced(solver *sv, const double *y, double *h)
{
    const hx_dynamics *d = sv->d;
    if (hx_dynamics_rhs(d, sv->dd, sv->t, y, sv->ydot) != 0)
        return -1;
    sv->evaluations++;
    hx_equilibrium_generalized(d, sv->ydot + d->nq, sv->gen);
    for (int i = 0; i < sv->nv; ++i)
        h[i] = sv->gen[sv->var[i]];
    return 0;
}

/* The largest unbalanced load relative to its scale, and the sum of squares. */
static double largest(const solver *sv, const double *h, double *squares)
{
    double worst = 0.0, sum = 0.0;
    for (int i = 0; i < sv->nv; ++i) {
        const double r = h[i] / sv->scale[i];
        worst = fmax(worst, fabs(r));
        sum += r * r;
    }
    if (squares != NULL)
        *squares = sum;
    return worst;
}

/* out = y moved by s dx in the velocity coordinates, the velocities y's. */
static void displace(const solver *sv, const double *y, const double *dx, double s, double *out)
{
    const hx_dynamics *d = sv->d;
    memcpy(out, y, sizeof(double) * (size_t)d->n);
    double *u = out + d->nq;
    memset(u, 0, sizeof(double) * (size_t)d->nu); /* a driven part stays put */
    for (int i = 0; i < sv->nv; ++i)
        u[sv->var[i]] = s * dx[i];
    hx_bodies_advance_positions(d, out, 1.0);
    memcpy(u, y + d->nq, sizeof(double) * (size_t)d->nu);
}

/* K by central differences of h into A (stride na). */
static int difference_matrix(solver *sv, const double *y)
{
    const int nv = sv->nv, na = sv->na;
    for (int j = 0; j < nv; ++j) {
        const double step = hx_difference_step(0.0, DIFFERENCE, sv->length[j]);
        memset(sv->dx, 0, sizeof(double) * (size_t)nv);
        sv->dx[j] = step;
        displace(sv, y, sv->dx, 1.0, sv->trial);
        if (unbalanced(sv, sv->trial, sv->hp) != 0)
            return -1;
        displace(sv, y, sv->dx, -1.0, sv->trial);
        if (unbalanced(sv, sv->trial, sv->hm) != 0)
            return -1;
        for (int i = 0; i < nv; ++i)
            sv->A[i * na + j] =
                (sv->hp[i] - sv->hm[i]) / (2.0 * step) * sv->length[j] / sv->scale[i];
    }
    return 0;
}

/* The saddle system at y, in units of the model (each unknown over its
 * length, each load over its scale: K's entries near 1 for gravity's
 * stiffness): K, R on its diagonal, and the active constraint rows on the
 * unknowns, each over its largest entry. */
static int newton_matrix(solver *sv, const double *y)
{
    const hx_dynamics *d = sv->d;
    const int nv = sv->nv, na = sv->na;
    memset(sv->A, 0, sizeof(double) * (size_t)na * (size_t)na);
    if (sv->jac != NULL) {
        const hx_equilibrium_unknowns x = {nv, sv->var, sv->length, sv->scale};
        if (hx_equilibrium_matrix(sv->jac, sv->t, y, &x, sv->values, sv->work, sv->A, na) != 0)
            return hx_dynamics_fail(sv->dd, "%s", sv->jac->dd.message);
    } else if (difference_matrix(sv, y) != 0) {
        return -1;
    }
    double stiffest = 0.0;
    for (int i = 0; i < nv; ++i)
        for (int j = 0; j < nv; ++j)
            stiffest = fmax(stiffest, fabs(sv->A[i * na + j]));
    for (int j = 0; j < nv; ++j) {
        sv->reg[j] = fmax(REGULARIZATION, REGULARIZATION_STIFFEST * stiffest);
        sv->A[j * na + j] += sv->reg[j];
    }
    if (na == nv)
        return 0;
    if (hx_constraints_rows(d, sv->dd, sv->t, y, sv->phi, sv->G, NULL) != 0)
        return -1;
    int k = nv;
    for (int a = 0; a < d->nactive; ++a) {
        const int r = d->active[a];
        const hx_constraint_row *row = &d->rows[r];
        double *line = sv->A + (size_t)k * na, big = 0.0;
        for (int bl = 0; bl < row->nblocks; ++bl)
            for (int c = 0; c < row->width[bl]; ++c)
                for (int i = 0; i < nv; ++i)
                    if (sv->var[i] == row->u[bl] + c) {
                        line[i] = sv->G[(size_t)d->row_values * r + row->slot[bl] + c] *
                                  sv->length[i];
                        big = fmax(big, fabs(line[i]));
                    }
        if (big == 0.0) { /* the row holds only driven parts: not the solve's */
            memset(line, 0, sizeof(double) * (size_t)nv);
            continue;
        }
        for (int i = 0; i < nv; ++i) {
            line[i] /= big;
            sv->A[i * na + k] = line[i];
        }
        ++k;
    }
    sv->na = k; /* the rows taken; the matrix's stride stays na */
    return 0;
}

/* The saddle system compacted to the rows taken (stride sv->na) and kept in
 * A0; na the stride it was built with. */
static void keep_matrix(solver *sv, int na)
{
    const int n = sv->na;
    if (n != na)
        for (int i = 0; i < n; ++i)
            memmove(sv->A + (size_t)i * n, sv->A + (size_t)i * na, sizeof(double) * (size_t)n);
    memcpy(sv->A0, sv->A, sizeof(double) * (size_t)n * (size_t)n);
}

/* The Newton step with R times `damping` into sv->dx (sv->b keeps it in the
 * system's units). */
static int newton_step(solver *sv, double damping)
{
    const int n = sv->na;
    memcpy(sv->A, sv->A0, sizeof(double) * (size_t)n * (size_t)n);
    for (int j = 0; j < sv->nv; ++j)
        sv->A[j * n + j] += (damping - 1.0) * sv->reg[j];
    for (int i = 0; i < n; ++i)
        sv->b[i] = i < sv->nv ? -sv->h[i] / sv->scale[i] : 0.0;
    if (hx_solve(n, sv->A, sv->b) != 0)
        return -1;
    for (int i = 0; i < sv->nv; ++i)
        sv->dx[i] = sv->b[i] * sv->length[i];
    /* a step against the loads (their work -h.dx < 0: up to an unstable equilibrium, a
     * pendulum started above the horizontal to the top) is turned to go with them */
    double work = 0.0;
    for (int i = 0; i < sv->nv; ++i)
        work += sv->h[i] * sv->dx[i];
    if (work < 0.0)
        for (int i = 0; i < sv->nv; ++i)
            sv->dx[i] = -sv->dx[i];
    return 0;
}

/* How far dx goes beyond the step's limits: its largest ratio to them. */
static double beyond_limits(const solver *sv)
{
    double ratio = 0.0;
    for (int i = 0; i < sv->nv; ++i)
        ratio = fmax(ratio, fabs(sv->dx[i]) / (turns(sv, i) ? MAX_TURN : MAX_SHIFT * sv->L));
    return ratio;
}

/* A part's unbalanced force and torque relative to F and F L. */
static void part_residual(const solver *sv, const double *h, int body, double *force,
                          double *torque)
{
    double f2 = 0.0, t2 = 0.0;
    for (int i = 0; i < sv->nv; ++i)
        if (sv->body[i] == body) {
            const double v = h[i] / sv->scale[i];
            if (turns(sv, i))
                t2 += v * v;
            else
                f2 += v * v;
        }
    *force = sqrt(f2) * sv->F;
    *torque = sqrt(t2) * sv->F * sv->L;
}

/* No equilibrium: the part the regularization carries the most of the step
 * for, with its unbalanced load. */
static int refuse_unheld(const solver *sv, const double *share)
{
    const hx_dynamics *d = sv->d;
    int worst = sv->body[0];
    double most = 0.0;
    for (int i = 0; i < sv->nv; ++i)
        if (fabs(share[i]) > most)
            most = fabs(share[i]), worst = sv->body[i];
    double force, torque;
    part_residual(sv, sv->h, worst, &force, &torque);
    return hx_dynamics_fail(sv->dd, "no static equilibrium: nothing holds PART/%d against its"
                            " load (unbalanced force %.6g, torque %.6g at t = %g): it is free to"
                            " move where the load pushes it", d->m->bodies[worst].id, force,
                            torque, sv->t);
}

/* No convergence: the (up to three) parts with the largest unbalanced loads. */
static int refuse_unconverged(const solver *sv, int iterations, double residual)
{
    const hx_model *m = sv->d->m;
    char text[600] = "";
    size_t used = 0;
    int named[3] = {-1, -1, -1};
    for (int k = 0; k < 3; ++k) {
        double most = 0.0;
        for (int b = 0; b < m->nbodies; ++b) {
            if (b == named[0] || b == named[1] || sv->d->dof[b].kind == HX_DOF_GROUND)
                continue;
            double f, tq;
            part_residual(sv, sv->h, b, &f, &tq);
            const double r = fmax(f / sv->F, tq / (sv->F * sv->L));
            if (r > most)
                most = r, named[k] = b;
        }
        if (named[k] < 0)
            break;
        double f, tq;
        part_residual(sv, sv->h, named[k], &f, &tq);
        used += (size_t)snprintf(text + used, sizeof text - used, "%sPART/%d (force %.3g, torque"
                                 " %.3g)", k > 0 ? ", " : "", m->bodies[named[k]].id, f, tq);
        if (used >= sizeof text)
            break;
    }
    return hx_dynamics_fail(sv->dd, "no static equilibrium found in %d Newton iterations at t ="
                            " %g: the unbalanced loads are %.3g of the model's force %.6g, the"
                            " largest on %s", iterations, sv->t, residual, sv->F, text);
}

/* The model's force F, after an evaluation at the start: the largest of the
 * parts' weights, the loads (a couple over the model's length) and the force
 * elements' loads, each alone (their sum on a part is near zero near an
 * equilibrium: no scale). */
static int model_force(solver *sv)
{
    const hx_dynamics *d = sv->d;
    const hx_model *m = d->m;
    double F = 0.0;
    for (int k = 0; k < m->nbodies; ++k)
        if (d->dof[k].kind != HX_DOF_GROUND)
            F = fmax(F, m->bodies[k].mass * v3_norm(d->gravity) / d->ucf);
    for (int k = 0; k < m->nforces; ++k)
        F = fmax(F, fmax(v3_norm(sv->dd->element_load + 6 * k),
                         v3_norm(sv->dd->element_load + 6 * k + 3) / sv->L));
    for (int k = 0; k < m->nloads; ++k) {
        hx_load_share share;
        hx_message msg;
        if (d->load_off[k])
            continue;
        if (hx_load_share_at(m, &sv->dd->frames, sv->dd->turn + m->njoints, k, &share,
                             &msg) != 0)
            return hx_dynamics_fail(sv->dd, "%s", msg.text);
        for (int j = 0; j < share.count; ++j)
            F = fmax(F, fmax(v3_norm(share.F[j]), v3_norm(share.T[j]) / sv->L));
    }
    sv->F = F;
    return 0;
}

/* The loop, once the solver's work is set up; y is moved in place. */
static int solve(solver *sv, double *y, hx_equilibrium_result *result)
{
    const hx_dynamics *d = sv->d;
    for (int i = 0; i < sv->nv; ++i)
        y[d->nq + sv->var[i]] = 0.0;
    if (hx_constraints_project(d, sv->dd, sv->t, y) != 0 || unbalanced(sv, y, sv->h) != 0)
        return -1;
    if (model_force(sv) != 0)
        return -1;
    if (!(sv->F > 0.0))
        sv->F = 1.0; /* nothing loads the model: every h is zero */
    for (int i = 0; i < sv->nv; ++i)
        sv->scale[i] = turns(sv, i) ? sv->F * sv->L : sv->F;
    result->force_scale = sv->F;
    const int na = sv->na;
    int unheld_iterations = 0;
    for (int it = 0;; ++it) {
        double squares;
        const double residual = largest(sv, sv->h, &squares);
        result->iterations = it;
        result->residual = residual;
        if (residual <= HX_EQUILIBRIUM_TOLERANCE)
            return 0;
        if (it == HX_EQUILIBRIUM_ITERATIONS)
            return refuse_unconverged(sv, it, residual);
        sv->na = na;
        if (newton_matrix(sv, y) != 0)
            return -1;
        keep_matrix(sv, na);
        if (newton_step(sv, 1.0) != 0)
            return hx_dynamics_fail(sv->dd, "static equilibrium: the Newton matrix is singular"
                                    " at t = %g (constraints that lock each other?)", sv->t);
        /* the share of the loads the regularization alone carries (hp as scratch): a
         * part nothing holds, when it lasts (a direction may have no stiffness at one
         * iterate only: a pendulum on a pivot spring not yet loaded) */
        double held = 0.0, unheld = 0.0;
        for (int i = 0; i < sv->nv; ++i) {
            sv->hp[i] = sv->reg[i] * sv->b[i];
            unheld += sv->hp[i] * sv->hp[i];
            held += (sv->h[i] / sv->scale[i]) * (sv->h[i] / sv->scale[i]);
        }
        unheld_iterations = unheld > UNHELD_SHARE * UNHELD_SHARE * held ? unheld_iterations + 1
                                                                       : 0;
        if (unheld_iterations == UNHELD_ITERATIONS)
            return refuse_unheld(sv, sv->hp);
        /* a step beyond the limits: scaled down whole; when R carries it, R raised
         * (Levenberg-Marquardt) until it is within them instead, so that the direction
         * nothing holds takes a limited step while the stiff ones take theirs */
        double damping = 1.0, ratio = beyond_limits(sv);
        for (int k = 0; k < DAMPINGS && unheld_iterations > 0 && ratio > 1.0; ++k) {
            damping *= 4.0 * ratio;
            if (newton_step(sv, damping) != 0)
                return hx_dynamics_fail(sv->dd, "static equilibrium: the Newton matrix is"
                                        " singular at t = %g", sv->t);
            ratio = beyond_limits(sv);
        }
        double s = ratio > 1.0 ? 1.0 / ratio : 1.0;
        int taken = 0;
        for (int k = 0; k <= HALVINGS && !taken; ++k, s *= 0.5) {
            displace(sv, y, sv->dx, s, sv->trial);
            if (hx_constraints_project(d, sv->dd, sv->t, sv->trial) != 0 ||
                unbalanced(sv, sv->trial, sv->hm) != 0) {
                sv->dd->failed = 0; /* a trial too far: a shorter one */
                continue;
            }
            /* taken when the unbalanced loads drop, or when they still push along the
             * step (it has not passed the low point of the loads' potential on its line:
             * past a pendulum's horizontal they grow on the way down) */
            double trial_squares, along = 0.0;
            largest(sv, sv->hm, &trial_squares);
            for (int i = 0; i < sv->nv; ++i)
                along += sv->hm[i] * sv->dx[i];
            if (trial_squares < squares || along > 0.0 || k == HALVINGS) {
                memcpy(y, sv->trial, sizeof(double) * (size_t)d->n);
                memcpy(sv->h, sv->hm, sizeof(double) * (size_t)sv->nv);
                taken = 1;
            }
        }
        if (!taken)
            return hx_dynamics_fail(sv->dd, "static equilibrium: no Newton step from t = %g"
                                    " keeps the constraints", sv->t);
    }
}

int hx_equilibrium_solve(const hx_dynamics *d, hx_dynamics_data *dd, hx_jacobian *jac,
                         double t, double *y, hx_equilibrium_result *result, hx_message *msg)
{
    memset(result, 0, sizeof *result);
    const double start = hx_seconds();
    solver sv = {.d = d, .dd = dd, .jac = jac, .t = t, .L = 1.0};
    const long jacobian_evaluations = jac != NULL ? jac->evaluations : 0;
    const long partial_calls = jac != NULL ? jac->partial_calls : 0;
    const hx_model *m = d->m;
    for (int k = 0; k < m->nmarkers; ++k) /* the model's length, as the constraints take it */
        sv.L = fmax(sv.L, v3_norm(m->markers[k].pos0));
    const size_t n = (size_t)d->n, nu = (size_t)d->nu, nr = (size_t)d->nrows;
    const size_t na = nu + (size_t)d->nactive;
    sv.var = malloc(sizeof(int) * (nu + 1));
    sv.body = malloc(sizeof(int) * (nu + 1));
    sv.scale = malloc(sizeof(double) * (nu + 1));
    sv.length = malloc(sizeof(double) * (nu + 1));
    sv.reg = malloc(sizeof(double) * (nu + 1));
    sv.ydot = malloc(sizeof(double) * (n + 1));
    sv.trial = malloc(sizeof(double) * (n + 1));
    sv.gen = calloc(nu + 1, sizeof(double));
    sv.h = malloc(sizeof(double) * (4 * nu + 1));
    sv.A = malloc(sizeof(double) * (na * na + 1));
    sv.b = malloc(sizeof(double) * (na + 1));
    sv.A0 = malloc(sizeof(double) * (na * na + 1));
    sv.phi = malloc(sizeof(double) * (nr + 1));
    sv.G = malloc(sizeof(double) * ((size_t)d->row_values * nr + 1));
    if (sv.jac != NULL) {
        sv.values = malloc(sizeof(double) * ((size_t)jac->pattern.nnz + 2 * nu + 1));
        sv.work = sv.values != NULL ? sv.values + jac->pattern.nnz : NULL;
    }
    int status = -1;
    if (!sv.var || !sv.body || !sv.scale || !sv.length || !sv.reg || !sv.ydot || !sv.trial ||
        !sv.gen || !sv.h || !sv.A || !sv.A0 || !sv.b || !sv.phi || !sv.G ||
        (sv.jac != NULL && !sv.values)) {
        hx_fail(msg, "out of memory");
    } else {
        sv.hp = sv.h + nu, sv.hm = sv.h + 2 * nu, sv.dx = sv.h + 3 * nu;
        for (int k = 0; k < m->nbodies; ++k) {
            const hx_body_dof *dof = &d->dof[k];
            if (dof->kind == HX_DOF_GROUND || d->driver[k] >= 0)
                continue; /* a driven part keeps its motion */
            const int width = dof->kind == HX_DOF_FREE ? 6 : 1;
            for (int c = 0; c < width; ++c) {
                sv.var[sv.nv] = dof->u + c;
                sv.body[sv.nv] = k;
                sv.length[sv.nv] = is_turn(dof, c) ? 1.0 : sv.L;
                sv.nv++;
            }
        }
        sv.na = sv.nv + d->nactive;
        dd->failed = 0;
        status = sv.nv == 0 ? 0 : solve(&sv, y, result);
        if (status != 0)
            hx_fail(msg, "%s", dd->message);
        result->analytic = sv.jac != NULL;
        result->seconds = hx_seconds() - start;
        result->evaluations = sv.evaluations;
        if (jac != NULL) { /* the Jacobian's own, counted here and not in a run's */
            result->evaluations += jac->evaluations - jacobian_evaluations;
            jac->evaluations = jacobian_evaluations;
            jac->partial_calls = partial_calls;
        }
    }
    free(sv.var), free(sv.body), free(sv.scale), free(sv.length), free(sv.reg), free(sv.ydot);
    free(sv.trial), free(sv.gen), free(sv.h), free(sv.A), free(sv.A0), free(sv.b), free(sv.phi);
    free(sv.G), free(sv.values);
    return status;
}
