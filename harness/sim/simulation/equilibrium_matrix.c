/*
 * The static equilibrium's Newton matrix from the Jacobian
 * (equilibrium_matrix.h). J's velocity rows on the position columns are
 * d(udot)/dq with the constraint projection's dependence on q in them (the
 * coupler blocks difference the constraint stage with the free accelerations
 * held: sim/jacobian/coupler_blocks.c), so K is the derivative the central
 * differences of h take, not a frozen projection. Each unknown's column is
 * chained from the q columns as equilibrium.c's displace moves them
 * (hx_bodies_advance_positions): a free part's centre one for one in world
 * axes, its turn dtheta in body axes as dq = q (x) (0, dtheta) / 2 (the first
 * order of q (x) exp(dtheta / 2), tangent to |q| = 1, so the normalization
 * after it changes nothing to first order), a reduced joint's coordinate one
 * for one.
 */
#include "sim/simulation/equilibrium_matrix.h"

#include <string.h>

#include "base/vecmath.h"

void hx_equilibrium_generalized(const hx_dynamics *d, const double *a, double *gen)
{
    for (int k = 0; k < d->m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        if (dof->kind == HX_DOF_GROUND)
            continue;
        double *g = gen + dof->u;
        if (dof->kind != HX_DOF_FREE) {
            g[0] = dof->mass * a[dof->u] / d->ucf;
            continue;
        }
        v3_scale(g, a + dof->u, dof->mass / d->ucf);
        m3_apply(g + 3, dof->inertia, a + dof->u + 3);
        v3_scale(g + 3, g + 3, 1.0 / d->ucf);
    }
}

int hx_equilibrium_jacobian_pays(const hx_jacobian *jac)
{
    const hx_dynamics *d = jac->d;
    if (d->m->nloop_inputs > 0)
        return 0;
    int nv = 0, columns = 0;
    for (int k = 0; k < d->m->nbodies; ++k)
        if (d->dof[k].kind != HX_DOF_GROUND && d->driver[k] < 0)
            nv += d->dof[k].kind == HX_DOF_FREE ? 6 : 1;
    for (int g = 0; g < jac->ngroups; ++g) {
        const int c = jac->group_column_start[g + 1] - jac->group_column_start[g];
        columns = c > columns ? c : columns;
    }
    return 1 + 2 * columns < 2 * nv;
}

/* dudot += w J[:, col]'s velocity rows. */
static void add_column(const hx_jacobian *jac, const double *values, int col, double w,
                       double *dudot)
{
    const hx_sparsity *s = &jac->pattern;
    const int nq = jac->d->nq, nu = jac->d->nu;
    for (int p = s->colptr[col]; p < s->colptr[col + 1]; ++p) {
        const int r = s->rowind[p] - nq;
        if (r >= 0 && r < nu)
            dudot[r] += w * values[p];
    }
}

/* The part that velocity v moves, and v's place among its velocities. */
static const hx_body_dof *part_of(const hx_dynamics *d, int v, int *c)
{
    for (int k = 0; k < d->m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        const int width = dof->kind == HX_DOF_FREE ? 6 : dof->kind == HX_DOF_GROUND ? 0 : 1;
        if (v >= dof->u && v < dof->u + width) {
            *c = v - dof->u;
            return dof;
        }
    }
    return NULL;
}

int hx_equilibrium_matrix(hx_jacobian *jac, double t, const double *y,
                          const hx_equilibrium_unknowns *x, double *values, double *work,
                          double *K, int stride)
{
    const hx_dynamics *d = jac->d;
    if (hx_jacobian_build(jac, t, y, NULL, values) != 0)
        return -1;
    double *dudot = work, *gen = work + d->nu;
    for (int j = 0; j < x->nv; ++j) {
        int c = 0;
        const hx_body_dof *dof = part_of(d, x->var[j], &c);
        memset(dudot, 0, sizeof(double) * (size_t)d->nu);
        if (dof->kind != HX_DOF_FREE || c < 3) {
            add_column(jac, values, dof->q + c, 1.0, dudot); /* a centre's or a joint's */
        } else {
            const double *quat = y + dof->q + 3;
            double e[4] = {0, 0, 0, 0}, dq[4];
            e[c - 2] = 1.0;
            quat_mul(dq, quat, e);
            for (int k = 0; k < 4; ++k)
                add_column(jac, values, dof->q + 3 + k, 0.5 * dq[k], dudot);
        }
        hx_equilibrium_generalized(d, dudot, gen);
        for (int i = 0; i < x->nv; ++i)
            K[(size_t)i * (size_t)stride + (size_t)j] =
                gen[x->var[i]] * x->length[j] / x->scale[i];
    }
    return 0;
}
