/* Closed-form references for linear models (linear_reference.h). */
#include "tools/bench/linear_reference.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void hx_damped_oscillator(double k, double c, double f, double v0, double t, double *z,
                          double *rate)
{
    if (k == 0.0 && c == 0.0) {
        *z = v0 * t + 0.5 * f * t * t;
        *rate = v0 + f * t;
        return;
    }
    if (k == 0.0) { /* z'' + c z' = f */
        const double terminal = f / c, decay = exp(-c * t);
        *rate = terminal + (v0 - terminal) * decay;
        *z = terminal * t + (v0 - terminal) * (1.0 - decay) / c;
        return;
    }
    /* e = z - f/k: e'' + c e' + k e = 0 with e(0) = -f/k, e'(0) = v0 */
    const double e0 = -f / k, alpha = -0.5 * c, disc = c * c - 4.0 * k;
    double e, de;
    if (disc < 0.0) {
        const double beta = 0.5 * sqrt(-disc), b = (v0 - alpha * e0) / beta;
        const double decay = exp(alpha * t), cs = cos(beta * t), sn = sin(beta * t);
        e = decay * (e0 * cs + b * sn);
        de = decay * ((alpha * e0 + beta * b) * cs + (alpha * b - beta * e0) * sn);
    } else if (disc == 0.0) {
        const double b = v0 - alpha * e0, decay = exp(alpha * t);
        e = (e0 + b * t) * decay;
        de = (b + alpha * (e0 + b * t)) * decay;
    } else {
        const double root = 0.5 * sqrt(disc), r1 = alpha + root, r2 = alpha - root;
        const double a2 = (v0 - r1 * e0) / (r2 - r1), a1 = e0 - a2;
        e = a1 * exp(r1 * t) + a2 * exp(r2 * t);
        de = a1 * r1 * exp(r1 * t) + a2 * r2 * exp(r2 * t);
    }
    *z = e - e0;
    *rate = de;
}

/* The state at modal coordinates z and rates: y0's positions moved along the
 * directions, velocities along them only. */
static void state_at(const hx_linear_reference *r, const double *z, const double *rate, double *y)
{
    const int m = r->nq + r->nu;
    memcpy(y, r->y0, sizeof(double) * (size_t)r->n);
    for (int i = r->nq; i < m; ++i)
        y[i] = 0.0;
    for (int k = 0; k < r->modes; ++k) {
        const double *dir = r->direction + (size_t)k * m;
        for (int i = 0; i < r->nq; ++i)
            y[i] += dir[i] * z[k];
        for (int i = r->nq; i < m; ++i)
            y[i] += dir[i] * rate[k];
    }
}

/* Generalized accelerations along the directions (mass-weighted), and the
 * largest acceleration off them. */
static int accelerations(const hx_dynamics *d, hx_dynamics_data *dd,
                         const hx_linear_reference *r, const double *mass, const double *z,
                         const double *rate, double *y, double *ydot, double *g, double *off)
{
    state_at(r, z, rate, y);
    if (hx_dynamics_rhs(d, dd, 0.0, y, ydot) != 0)
        return -1;
    const int m = r->nq + r->nu;
    const double *a = ydot + r->nq;
    double *rest = malloc(sizeof(double) * (size_t)r->nu);
    if (rest == NULL)
        return -1;
    memcpy(rest, a, sizeof(double) * (size_t)r->nu);
    for (int k = 0; k < r->modes; ++k) {
        const double *dir = r->direction + (size_t)k * m + r->nq;
        double num = 0.0, den = 0.0;
        for (int i = 0; i < r->nu; ++i)
            num += dir[i] * mass[i] * a[i], den += dir[i] * mass[i] * dir[i];
        g[k] = num / den;
        for (int i = 0; i < r->nu; ++i)
            rest[i] -= g[k] * dir[i];
    }
    *off = 0.0;
    for (int i = 0; i < r->nu; ++i)
        *off = fmax(*off, fabs(rest[i]));
    free(rest);
    return 0;
}

/* hx_linear_reference_build's work on an evaluation's data of its own. */
static int build(const hx_dynamics *d, hx_dynamics_data *dd, hx_linear_reference *r,
                 hx_message *msg)
{
    memset(r, 0, sizeof *r);
    const hx_model *mo = d->m;
    r->n = d->n, r->nq = d->nq, r->nu = d->nu;
    const int m = d->nq + d->nu;
    int free_bodies = 0, jointed = 0;
    for (int b = 0; b < mo->nbodies; ++b)
        free_bodies += d->dof[b].kind == HX_DOF_FREE,
            jointed += d->dof[b].kind == HX_DOF_REVOLUTE || d->dof[b].kind == HX_DOF_SLIDER;
    if ((free_bodies > 0) == (jointed > 0))
        return hx_fail(msg, "closed form only for free bodies alone or jointed bodies alone");
    r->y0 = calloc((size_t)r->n, sizeof(double));
    r->direction = calloc((size_t)HX_REFERENCE_MODES * m, sizeof(double));
    double *mass = calloc((size_t)d->nu + 1, sizeof(double));
    double *y = calloc((size_t)r->n, sizeof(double)), *ydot = calloc((size_t)r->n, sizeof(double));
    double *g0 = calloc(4 * HX_REFERENCE_MODES, sizeof(double));
    int status = r->y0 && r->direction && mass && y && ydot && g0 ? 0 : hx_fail(msg, "out of memory");
    if (status == 0 && hx_dynamics_initial_state(d, dd, r->y0) != 0)
        status = hx_fail(msg, "%s", dd->message);
    for (int b = 0; status == 0 && b < mo->nbodies; ++b) { /* the mass of each velocity */
        const hx_body_dof *dof = &d->dof[b];
        if (dof->kind == HX_DOF_FREE)
            for (int i = 0; i < 6; ++i)
                mass[dof->u + i] = i < 3 ? dof->mass : 1.0;
        else if (dof->kind != HX_DOF_GROUND)
            mass[dof->u] = dof->mass;
    }
    const double *u0 = r->y0 + d->nq;
    if (status == 0 && free_bodies > 0) {
        /* each free body's three translations, from rest in rotation */
        for (int b = 0; status == 0 && b < mo->nbodies; ++b) {
            const hx_body_dof *dof = &d->dof[b];
            if (dof->kind != HX_DOF_FREE)
                continue;
            if (u0[dof->u + 3] != 0.0 || u0[dof->u + 4] != 0.0 || u0[dof->u + 5] != 0.0)
                status = hx_fail(msg, "closed form only for bodies that start without turning");
            for (int i = 0; status == 0 && i < 3 && r->modes < HX_REFERENCE_MODES; ++i) {
                double *dir = r->direction + (size_t)r->modes * m;
                dir[dof->q + i] = 1.0;
                dir[d->nq + dof->u + i] = 1.0;
                r->rate0[r->modes++] = u0[dof->u + i];
            }
        }
    } else if (status == 0) {
        /* one degree of freedom left by the couplers: along the initial velocity */
        if (d->nu - mo->ncouplers != 1)
            status = hx_fail(msg, "closed form only for one degree of freedom (%d joints, %d"
                                 " couplers)", d->nu, mo->ncouplers);
        double norm = 0.0;
        for (int i = 0; i < d->nu; ++i)
            norm = fmax(norm, fabs(u0[i]));
        if (status == 0 && !(norm > 0.0))
            status = hx_fail(msg, "closed form needs an initial velocity to set the free direction");
        if (status == 0) {
            for (int i = 0; i < d->nu; ++i) /* jointed bodies: q and u line up */
                r->direction[i] = r->direction[d->nq + i] = u0[i] / norm;
            r->rate0[r->modes++] = norm;
        }
    }
    /* k, c and f by differences of the (linear) right-hand side */
    double *z = g0 + HX_REFERENCE_MODES, *rate = z + HX_REFERENCE_MODES, *g = rate + HX_REFERENCE_MODES;
    double off = 0.0, worst_off = 0.0, scale = 0.0;
    const int modes = r->modes;
    if (status == 0 && accelerations(d, dd, r, mass, z, rate, y, ydot, g0, &off) != 0)
        status = hx_fail(msg, "%s", dd->message);
    for (int k = 0; k < modes; ++k)
        r->f[k] = g0[k], scale = fmax(scale, fabs(g0[k]));
    worst_off = off;
    const double step = 1e-3;
    for (int l = 0; status == 0 && l < modes; ++l)
        for (int kind = 0; kind < 2 && status == 0; ++kind) {
            memset(z, 0, sizeof(double) * HX_REFERENCE_MODES);
            memset(rate, 0, sizeof(double) * HX_REFERENCE_MODES);
            (kind == 0 ? z : rate)[l] = step;
            if (accelerations(d, dd, r, mass, z, rate, y, ydot, g, &off) != 0) {
                status = hx_fail(msg, "%s", dd->message);
                break;
            }
            worst_off = fmax(worst_off, off);
            for (int k = 0; k < modes; ++k) {
                const double slope = -(g[k] - g0[k]) / step;
                if (k == l)
                    (kind == 0 ? r->k : r->c)[k] = slope;
                else if (fabs(slope) > 1e-9 * (fabs(r->k[k]) + 1.0))
                    status = hx_fail(msg, "closed form only for uncoupled directions");
            }
        }
    for (int k = 0; status == 0 && k < modes; ++k)
        scale = fmax(scale, fabs(r->k[k]) * step + fabs(r->c[k]) * step);
    if (status == 0 && worst_off > 1e-9 * scale)
        status = hx_fail(msg, "closed form only when nothing but the free directions moves");
    /* linear: a state far along every direction at once follows the coefficients */
    if (status == 0) {
        for (int k = 0; k < modes; ++k)
            z[k] = 1000.0 * step * (k + 1), rate[k] = -700.0 * step * (k + 1);
        if (accelerations(d, dd, r, mass, z, rate, y, ydot, g, &off) != 0)
            status = hx_fail(msg, "%s", dd->message);
        for (int k = 0; status == 0 && k < modes; ++k) {
            const double predicted = r->f[k] - r->k[k] * z[k] - r->c[k] * rate[k];
            const double size = fabs(r->f[k]) + fabs(r->k[k] * z[k]) + fabs(r->c[k] * rate[k]);
            if (fabs(g[k] - predicted) > 1e-9 * size)
                status = hx_fail(msg, "closed form only for linear models");
        }
    }
    free(mass);
    free(y);
    free(ydot);
    free(g0);
    if (status != 0)
        hx_linear_reference_free(r);
    return status;
}

int hx_linear_reference_build(const hx_dynamics *d, hx_linear_reference *r, hx_message *msg)
{
    hx_dynamics_data dd;
    if (hx_dynamics_data_init(&dd, d, msg) != 0)
        return -1;
    const int status = build(d, &dd, r, msg);
    hx_dynamics_data_free(&dd);
    return status;
}

void hx_linear_reference_free(hx_linear_reference *r)
{
    free(r->y0);
    free(r->direction);
    r->y0 = r->direction = NULL;
    r->modes = 0;
}

void hx_linear_reference_state(const hx_linear_reference *r, double t, double *y)
{
    double z[HX_REFERENCE_MODES], rate[HX_REFERENCE_MODES];
    for (int k = 0; k < r->modes; ++k)
        hx_damped_oscillator(r->k[k], r->c[k], r->f[k], r->rate0[k], t, &z[k], &rate[k]);
    const int m = r->nq + r->nu;
    double *tmp = malloc(sizeof(double) * (size_t)r->n);
    if (tmp == NULL)
        return;
    state_at(r, z, rate, tmp);
    memcpy(y, tmp, sizeof(double) * (size_t)m);
    free(tmp);
}
