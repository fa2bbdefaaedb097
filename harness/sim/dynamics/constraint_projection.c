/*
 * The constraint system's projections (constraints.h): positions by Newton with
 * the mass-weighted least-change step, then velocities, onto phi = 0 and G u = r
 * after a step and at the set-up's assembly; the residuals left; and the
 * projector P = I - M^-1 G^T (G M^-1 G^T)^-1 G the BDF's Newton matrix takes
 * the couplers' share through (docs/architecture.md, the constraint system).
 */
#include <math.h>
#include <string.h>

#include "base/linalg.h"
#include "base/vecmath.h"
#include "sim/dynamics/constraint_matrix.h"
#include "sim/dynamics/constraint_parts.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/redundancy.h"

#define PROJECTION_ITERATIONS 25
#define PHI_TOLERANCE 1e-13 /* relative to the row's scale (constraints.h) */
#define ASSEMBLY_TOLERANCE 1e-8

/* The largest |phi_i| / scale_i of the active rows, the row in *at. */
static double scaled_error(const hx_dynamics *d, const double *phi, int *at)
{
    double e = 0.0;
    for (int a = 0; a < d->nactive; ++a) {
        const int i = d->active[a];
        const double ei = fabs(phi[i]) / d->rows[i].scale;
        if (ei > e || a == 0)
            e = ei, *at = i;
    }
    return e;
}

/* y's positions moved by -M^-1 x (x over u): joint coordinates, centres and
 * the quaternions by their body-axis increment. */
static void move_positions(const hx_dynamics *d, const double *x, double *y)
{
    for (int b = 0; b < d->m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        if (dof->kind == HX_DOF_REVOLUTE || dof->kind == HX_DOF_SLIDER) {
            y[dof->q] -= (1.0 / dof->mass) * x[dof->u];
            continue;
        }
        if (dof->kind != HX_DOF_FREE)
            continue;
        double dx[6], *quat = y + dof->q + 3, next[4];
        hx_constraint_matrix_inverse_mass(d, b, x + dof->u, dx);
        for (int c = 0; c < 3; ++c)
            y[dof->q + c] -= dx[c];
        const double angle = v3_norm(dx + 3);
        if (angle == 0.0)
            continue;
        const double s = -sin(0.5 * angle) / angle;
        const double inc[4] = {cos(0.5 * angle), s * dx[3], s * dx[4], s * dx[5]};
        quat_mul(next, quat, inc);
        memcpy(quat, next, sizeof next);
        quat_normalize(quat);
    }
}

/* Positions: Newton on phi(q) = 0 over the active rows with the mass-weighted
 * least-change step, quaternions made unit first; the largest scaled residual of
 * the active rows left in *err, its row in *worst. 0, or -1 (dd->message: a
 * singular matrix or a failed row). */
static int newton_positions(const hx_dynamics *d, hx_dynamics_data *dd, double t, double *y,
                            double *err, int *worst)
{
    for (int k = 0; k < d->m->nbodies; ++k)
        if (d->dof[k].kind == HX_DOF_FREE)
            quat_normalize(y + d->dof[k].q + 3);
    *err = 0.0, *worst = 0;
    if (d->nrows == 0)
        return 0;
    const int n = d->nactive;
    hx_constraint_work w = hx_constraint_work_parts(d, dd);
    for (int it = 0;; ++it) {
        if (hx_constraint_rows_eval(d, dd, t, y, w.G, w.phi, NULL) != 0)
            return -1;
        *err = scaled_error(d, w.phi, worst);
        if (*err <= PHI_TOLERANCE || it == PROJECTION_ITERATIONS)
            return 0;
        const int formed = hx_constraint_matrix_form(d, w.G, w.W, w.A);
        for (int a = 0; a < n; ++a)
            w.step[a] = w.phi[d->active[a]];
        if (formed != 0 || hx_constraint_matrix_solve(d, w.A, w.step) != 0)
            return hx_dynamics_fail(dd, "the constraint Jacobian is singular at t = %g", t);
        hx_constraint_transpose_apply(d, w.G, w.step, w.x);
        move_positions(d, w.x, y);
    }
}

int hx_constraints_assemble(const hx_dynamics *d, hx_dynamics_data *dd, double t, double *y)
{
    double err;
    int worst;
    if (newton_positions(d, dd, t, y, &err, &worst) != 0)
        return -1;
    return err > ASSEMBLY_TOLERANCE ? hx_dynamics_fail(dd, "the active rows are not met") : 0;
}

int hx_constraints_project(const hx_dynamics *d, hx_dynamics_data *dd, double t, double *y)
{
    double err;
    int worst = 0;
    char name[160];
    if (newton_positions(d, dd, t, y, &err, &worst) != 0)
        return -1;
    if (d->nrows == 0)
        return 0;
    const int n = d->nactive;
    /* w.G and w.phi: the rows at the positions Newton left */
    hx_constraint_work w = hx_constraint_work_parts(d, dd);
    if (err > ASSEMBLY_TOLERANCE)
        return hx_dynamics_fail(dd, "the joints and couplers cannot be satisfied at t = %g: |phi|"
                                " %.3g (of the model's size) after %d Newton steps, the largest"
                                " at %s (a joint far from assembled, or joints that lock each"
                                " other)", t, err, PROJECTION_ITERATIONS,
                                hx_redundancy_name_row(d, worst, name, sizeof name));
    /* the removed rows follow the active ones when they are consistent */
    for (int k = 0; k < d->nremoved; ++k) {
        const int i = d->removed[k];
        if (fabs(w.phi[i]) / d->rows[i].scale > ASSEMBLY_TOLERANCE)
            return hx_dynamics_fail(dd, "a redundant constraint is not consistent at t = %g: %s,"
                                    " removed at the set-up, is off by %.3g (of the model's"
                                    " size) once the others are met (the model locks)", t,
                                    hx_redundancy_name_row(d, i, name, sizeof name),
                                    fabs(w.phi[i]) / d->rows[i].scale);
    }
    /* velocities: remove the component that violates G u = 0 */
    const int formed = hx_constraint_matrix_form(d, w.G, w.W, w.A);
    for (int a = 0; a < n; ++a)
        w.step[a] = hx_constraint_row_dot(d, w.G, d->active[a], y + d->nq, 0.0);
    for (int a = 0; a < n; ++a) /* a motion's row holds G u = f'(t), a GCON's -df/dt */
        if (d->active[a] >= d->motion_first) {
            double rate;
            if (hx_constraint_row_rate(d, dd, d->active[a], t, y, &rate) != 0)
                return -1;
            w.step[a] -= rate;
        }
    if (formed != 0 || hx_constraint_matrix_solve(d, w.A, w.step) != 0)
        return hx_dynamics_fail(dd, "the constraint Jacobian is singular at t = %g", t);
    hx_constraint_transpose_apply(d, w.G, w.step, w.x);
    for (int b = 0; b < d->m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        if (dof->kind == HX_DOF_REVOLUTE || dof->kind == HX_DOF_SLIDER) {
            y[d->nq + dof->u] -= (1.0 / dof->mass) * w.x[dof->u];
        } else if (dof->kind == HX_DOF_FREE) {
            double du[6];
            hx_constraint_matrix_inverse_mass(d, b, w.x + dof->u, du);
            for (int c = 0; c < 6; ++c)
                y[d->nq + dof->u + c] -= du[c];
        }
    }
    double phi_max, phidot_max;
    if (hx_constraints_residuals(d, dd, t, y, &phi_max, &phidot_max) != 0)
        return -1;
    dd->max_phi = fmax(dd->max_phi, phi_max);
    dd->max_phidot = fmax(dd->max_phidot, phidot_max);
    return 0;
}

int hx_constraints_residuals(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                             const double *y, double *phi_max, double *phidot_max)
{
    *phi_max = *phidot_max = 0.0;
    if (d->nrows == 0)
        return 0;
    hx_constraint_work w = hx_constraint_work_parts(d, dd);
    if (hx_constraint_rows_eval(d, dd, t, y, w.G, w.phi, NULL) != 0)
        return -1;
    *phi_max = hx_max_abs(w.phi, d->nrows);
    for (int i = 0; i < d->nrows; ++i) {
        double rate = 0.0;
        if (hx_constraint_row_rate(d, dd, i, t, y, &rate) != 0)
            return -1;
        const double off = hx_constraint_row_dot(d, w.G, i, y + d->nq, 0.0) - rate;
        *phidot_max = fmax(*phidot_max, fabs(off));
    }
    return 0;
}

int hx_constraints_projector(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                             const double *y, const int *index, int count,
                             const int *group_start, int ngroups, double *work_, double *P)
{
    const int n = d->nactive;
    hx_constraint_work w = hx_constraint_work_parts(d, dd);
    double *A = work_, *z = work_ + n * n, *s = w.x, *col = w.x + d->nu;
    if (hx_constraint_rows_eval(d, dd, t, y, w.G, w.phi, NULL) != 0)
        return -1;
    /* the envelope factored once; the dense matrix formed for each solve (which takes it apart) */
    const int dense = d->envelope_first == NULL;
    if (!dense && hx_constraint_matrix_form(d, w.G, w.W, A) != 0)
        return hx_dynamics_fail(dd, "the constraint Jacobian is singular at t = %g", t);
    int solves = 0;
    for (int g = 0; g < ngroups; ++g)
        if (group_start[g + 1] - group_start[g] > solves)
            solves = group_start[g + 1] - group_start[g];
    memset(P, 0, sizeof(double) * (size_t)count * (size_t)count);
    for (int j = 0; j < solves; ++j) {
        if (dense)
            hx_constraint_matrix_gram(d, w.G, w.W, A);
        memset(col, 0, sizeof(double) * (size_t)d->nu);
        for (int g = 0; g < ngroups; ++g) /* the j-th velocity of every group at once */
            if (group_start[g] + j < group_start[g + 1])
                col[index[group_start[g] + j]] = 1.0;
        for (int k = 0; k < n; ++k)
            z[k] = hx_constraint_row_dot(d, w.G, d->active[k], col, 0.0);
        if (hx_constraint_matrix_solve(d, A, z) != 0)
            return hx_dynamics_fail(dd, "the constraint Jacobian is singular at t = %g", t);
        hx_constraint_transpose_apply(d, w.G, z, s);
        for (int g = 0; g < ngroups; ++g) {
            const int jj = group_start[g] + j;
            if (jj >= group_start[g + 1])
                continue;
            for (int i = group_start[g]; i < group_start[g + 1]; ++i) {
                const int u = index[i], b = d->u_body[u];
                const hx_body_dof *dof = &d->dof[b];
                double ms;
                if (dof->kind != HX_DOF_FREE) {
                    ms = (1.0 / dof->mass) * s[u];
                } else {
                    double block[6];
                    hx_constraint_matrix_inverse_mass(d, b, s + dof->u, block);
                    ms = block[u - dof->u];
                }
                P[i + count * jj] = (i == jj ? 1.0 : 0.0) - ms;
            }
        }
    }
    return 0;
}
