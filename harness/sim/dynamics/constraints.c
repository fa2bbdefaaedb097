/*
 * The couplers in the equations of motion (constraints.h): one Lagrange
 * multiplier each, with COUSUB/COUXX for the constraint and its Jacobian and
 * COUXX2 for the velocity-squared term; after a step, positions and
 * velocities are projected back onto phi = 0 and its rate.
 */
#include <math.h>
#include <string.h>

#include "host/invoke.h"
#include "base/linalg.h"
#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/failure.h"

#define PROJECTION_ITERATIONS 25
#define PHI_TOLERANCE 1e-13

/* The coupled joints' position/velocity offsets (jointed bodies: q and u agree). */
static int coupler_joints(const hx_dynamics *d, int k, int u_index[3])
{
    const hx_coupler *c = &d->m->couplers[k];
    for (int i = 0; i < c->njoints; ++i) {
        const int body = d->m->markers[d->m->joints[c->joint[i]].i_marker].body;
        u_index[i] = d->dof[body].u;
    }
    return c->njoints;
}

/* phi, dphi/dM and the velocity term qdot^T H qdot of coupler k. */
static int coupler_terms(const hx_dynamics *d, hx_dynamics_data *dd, int k, double t,
                         const double *y, double *phi, double grad[3], double *gamma)
{
    const hx_coupler *c = &d->m->couplers[k];
    int ui[3];
    const int n = coupler_joints(d, k, ui);
    double disp[3], rate[3];
    for (int i = 0; i < n; ++i) {
        disp[i] = y[d->dof[d->m->markers[d->m->joints[c->joint[i]].i_marker].body].q];
        rate[i] = y[d->nq + ui[i]];
    }
    hx_binding *b = d->coupler_binding[k];
    if (b == NULL) {
        *phi = 0.0;
        for (int i = 0; i < n; ++i) {
            *phi += c->coefficients[i] * disp[i];
            grad[i] = c->coefficients[i];
        }
        if (gamma != NULL)
            *gamma = 0.0;
        return n;
    }
    double hess[9] = {0};
    dd->frames.time = t; /* couplers get their state in disp: only the time is bound */
    hx_invoke_coupler(b, 0, &dd->frames, disp, n, 0, phi, NULL);
    hx_invoke_coupler(b, 1, &dd->frames, disp, n, 0, grad, NULL);
    if (gamma != NULL)
        hx_invoke_coupler(b, 2, &dd->frames, disp, n, 0, hess, NULL);
    if (hx_dynamics_check_call(d, dd, b, phi, 1, "value", t) != 0 ||
        hx_dynamics_check_call(d, dd, b, grad, n, "value", t) != 0 ||
        hx_dynamics_check_call(d, dd, b, hess, n * n, "value", t) != 0)
        return -1;
    if (gamma != NULL) {
        *gamma = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                *gamma += rate[i] * hess[i + n * j] * rate[j];
    }
    return n;
}

/* Builds G (nc x nu) and, when gamma is not NULL, the velocity terms. */
static int constraint_jacobian(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                               const double *y, double *G, double *phi, double *gamma)
{
    const int nc = d->m->ncouplers, nu = d->nu;
    memset(G, 0, sizeof(double) * (size_t)(nc * nu));
    for (int k = 0; k < nc; ++k) {
        double grad[3];
        int ui[3];
        if (coupler_terms(d, dd, k, t, y, &phi[k], grad, gamma ? &gamma[k] : NULL) < 0)
            return -1;
        const int n = coupler_joints(d, k, ui);
        for (int i = 0; i < n; ++i)
            G[k * nu + ui[i]] += grad[i];
    }
    return 0;
}

/* A = G M^-1 G^T */
static void weighted_gram(const hx_dynamics *d, const double *G, const double *minv, double *A)
{
    const int nc = d->m->ncouplers, nu = d->nu;
    for (int i = 0; i < nc; ++i)
        for (int j = 0; j < nc; ++j) {
            double s = 0.0;
            for (int k = 0; k < nu; ++k)
                s += G[i * nu + k] * minv[k] * G[j * nu + k];
            A[i * nc + j] = s;
        }
}

int hx_constraints_apply(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                         double *udot)
{
    const int nc = d->m->ncouplers;
    if (nc == 0)
        return 0;
    /* M qdd = ucf (Q + G^T lambda), G qdd = -gamma:
     * (G M^-1 G^T) lambda = -gamma/ucf - G qdd_free/ucf with qdd_free = ucf M^-1 Q. */
    double *G = dd->constraint_work, *A = G + nc * d->nu, *minv = A + nc * nc, *phi = minv + d->nu,
           *gamma = phi + nc;
    if (constraint_jacobian(d, dd, t, y, G, phi, gamma) != 0)
        return -1;
    for (int k = 0; k < d->nu; ++k)
        minv[k] = hx_bodies_inverse_mass(d, k);
    weighted_gram(d, G, minv, A);
    for (int i = 0; i < nc; ++i) {
        double s = gamma[i];
        for (int k = 0; k < d->nu; ++k)
            s += G[i * d->nu + k] * udot[k];
        dd->lambda[i] = -s / d->ucf;
    }
    if (hx_solve(nc, A, dd->lambda) != 0)
        return hx_dynamics_fail(dd, "the couplers' constraint Jacobian is singular at t = %g (redundant"
                        " or degenerate couplers)", t);
    for (int i = 0; i < nc; ++i)
        for (int k = 0; k < d->nu; ++k)
            udot[k] += d->ucf * minv[k] * G[i * d->nu + k] * dd->lambda[i];
    return 0;
}

int hx_constraints_project(const hx_dynamics *d, hx_dynamics_data *dd, double t, double *y)
{
    for (int k = 0; k < d->m->nbodies; ++k)
        if (d->dof[k].kind == HX_DOF_FREE)
            quat_normalize(y + d->dof[k].q + 3);
    const int nc = d->m->ncouplers, nu = d->nu;
    if (nc == 0)
        return 0;
    double *G = dd->constraint_work, *A = G + nc * nu, *minv = A + nc * nc, *phi = minv + nu,
           *step = phi + nc;
    for (int k = 0; k < nu; ++k)
        minv[k] = hx_bodies_inverse_mass(d, k);
    /* positions: Newton on phi(q) = 0 with the mass-weighted least-change step */
    for (int it = 0;; ++it) {
        if (constraint_jacobian(d, dd, t, y, G, phi, NULL) != 0)
            return -1;
        const double err = hx_max_abs(phi, nc);
        if (err <= PHI_TOLERANCE || it == PROJECTION_ITERATIONS)
            break;
        weighted_gram(d, G, minv, A);
        memcpy(step, phi, sizeof(double) * (size_t)nc);
        if (hx_solve(nc, A, step) != 0)
            return hx_dynamics_fail(dd, "the couplers' constraint Jacobian is singular at t = %g", t);
        for (int b = 0; b < d->m->nbodies; ++b) {
            const hx_body_dof *dof = &d->dof[b];
            if (dof->kind != HX_DOF_REVOLUTE && dof->kind != HX_DOF_SLIDER)
                continue;
            double s = 0.0;
            for (int i = 0; i < nc; ++i)
                s += G[i * nu + dof->u] * step[i];
            y[dof->q] -= minv[dof->u] * s;
        }
    }
    /* velocities: remove the component that violates G u = 0 */
    weighted_gram(d, G, minv, A);
    for (int i = 0; i < nc; ++i) {
        double s = 0.0;
        for (int k = 0; k < nu; ++k)
            s += G[i * nu + k] * y[d->nq + k];
        step[i] = s;
    }
    if (hx_solve(nc, A, step) != 0)
        return hx_dynamics_fail(dd, "the couplers' constraint Jacobian is singular at t = %g", t);
    for (int k = 0; k < nu; ++k) {
        double s = 0.0;
        for (int i = 0; i < nc; ++i)
            s += G[i * nu + k] * step[i];
        y[d->nq + k] -= minv[k] * s;
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
    const int nc = d->m->ncouplers, nu = d->nu;
    if (nc == 0)
        return 0;
    double *G = dd->constraint_work, *phi = G + nc * nu + nc * nc + nu;
    if (constraint_jacobian(d, dd, t, y, G, phi, NULL) != 0)
        return -1;
    *phi_max = hx_max_abs(phi, nc);
    for (int i = 0; i < nc; ++i) {
        double s = 0.0;
        for (int k = 0; k < nu; ++k)
            s += G[i * nu + k] * y[d->nq + k];
        *phidot_max = fmax(*phidot_max, fabs(s));
    }
    return 0;
}

double hx_constraints_coupler_force(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                                    const double *y, int coupler, int joint)
{
    double phi, grad[3];
    if (coupler_terms(d, dd, coupler, t, y, &phi, grad, NULL) < 0)
        return NAN;
    return grad[joint] * dd->lambda[coupler];
}


int hx_constraints_coupled(const hx_dynamics *d, int *index)
{
    int count = 0;
    for (int k = 0; k < d->m->ncouplers; ++k) {
        int ui[3];
        const int n = coupler_joints(d, k, ui);
        for (int i = 0; i < n; ++i) {
            int seen = 0;
            for (int j = 0; j < count && !seen; ++j)
                seen = index[j] == ui[i];
            if (!seen)
                index[count++] = ui[i];
        }
    }
    return count;
}

int hx_constraints_projector(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                             const double *y, const int *index, int count, double *work,
                             double *P)
{
    const int nc = d->m->ncouplers, nu = d->nu;
    double *G = dd->constraint_work, *minv = G + nc * nu + nc * nc, *phi = minv + nu;
    double *A = work, *z = work + nc * nc;
    if (constraint_jacobian(d, dd, t, y, G, phi, NULL) != 0)
        return -1;
    for (int k = 0; k < nu; ++k)
        minv[k] = hx_bodies_inverse_mass(d, k);
    for (int j = 0; j < count; ++j) {
        weighted_gram(d, G, minv, A); /* the solve takes it apart */
        for (int k = 0; k < nc; ++k)
            z[k] = G[k * nu + index[j]];
        if (hx_solve(nc, A, z) != 0)
            return hx_dynamics_fail(dd, "the couplers' constraint Jacobian is singular at t = %g", t);
        for (int i = 0; i < count; ++i) {
            double s = 0.0;
            for (int k = 0; k < nc; ++k)
                s += G[k * nu + index[i]] * z[k];
            P[i + count * j] = (i == j ? 1.0 : 0.0) - minv[index[i]] * s;
        }
    }
    return 0;
}
