/*
 * The constraints' share of the Newton matrix (newton_matrix.h). The
 * couplers and the joints between free bodies turn the bodies' free
 * accelerations into udot = P udot_free + c(q, u) (constraints.h): the rows
 * of the coupled velocities become P times the rows assembled so far, plus
 * the derivatives of the constraint stage with the free accelerations held,
 * by central differences on the coupled bodies' own columns (COUSUB, COUXX
 * and COUXX2 are called there; a free body's 13 columns). The joints'
 * blocks by differences are this first part's: exact blocks are to come.
 */
#include <string.h>

#include "sim/dynamics/constraints.h"
#include "sim/jacobian/jacobian_parts.h"

/* The coupled rows of column c through P. */
static void project_column(hx_jacobian *jac, int c, double *v, double *w, int *at)
{
    const int k = jac->ncoupled, row0 = jac->d->nq;
    int any = 0;
    for (int i = 0; i < k; ++i) {
        at[i] = hx_sparsity_find(&jac->pattern, row0 + jac->coupled[i], c);
        v[i] = at[i] >= 0 ? jac->values[at[i]] : 0.0;
        any |= v[i] != 0.0;
    }
    if (!any)
        return;
    for (int i = 0; i < k; ++i) {
        double s = 0.0;
        for (int j = 0; j < k; ++j)
            s += jac->projector[i + k * j] * v[j];
        w[i] = s;
    }
    for (int i = 0; i < k; ++i) {
        if (at[i] >= 0)
            jac->values[at[i]] = w[i];
        else if (w[i] != 0.0)
            jac->outside++;
    }
}

/* The constraint stage at y with the free accelerations held: the coupled
 * velocities' accelerations into out. */
static int stage(hx_jacobian *jac, double t, const double *y, double *accel, double *out)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    memcpy(accel, dd->free_accelerations, sizeof(double) * (size_t)d->nu);
    if (hx_constraints_apply(d, dd, t, y, accel) != 0)
        return -1;
    for (int i = 0; i < jac->ncoupled; ++i)
        out[i] = accel[jac->coupled[i]];
    return 0;
}

int hx_coupler_blocks(hx_jacobian *jac, double t, const double *y)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    const int k = jac->ncoupled;
    if (k == 0)
        return 0;
    double *v = jac->coupler_work, *w = v + k;
    if (hx_constraints_projector(d, dd, t, y, jac->coupled, k, w + k, jac->projector) != 0)
        return -1;
    for (int c = 0; c < jac->n; ++c)
        project_column(jac, c, v, w, jac->coupled_at);
    /* the stage's own dependence on the coupled joints' coordinates and rates */
    double *accel = jac->f_plus, *plus = jac->f_minus, *minus = plus + k;
    for (int b = 0; b < d->m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        int coupled = 0;
        for (int i = 0; i < k && !coupled; ++i)
            coupled = dof->kind != HX_DOF_GROUND && jac->coupled[i] == dof->u;
        if (!coupled)
            continue;
        /* a jointed body's coordinate and rate; a free body's 7 positions and 6 velocities */
        const int nq = dof->kind == HX_DOF_FREE ? 7 : 1, nv = dof->kind == HX_DOF_FREE ? 6 : 1;
        for (int j = 0; j < nq + nv; ++j) {
            const int c = j < nq ? dof->q + j : d->nq + dof->u + (j - nq);
            const double keep = jac->y[c], h = hx_jacobian_step(jac->y, c);
            jac->y[c] = keep + h;
            int status = stage(jac, t, jac->y, accel, plus);
            jac->y[c] = keep - h;
            status |= stage(jac, t, jac->y, accel, minus);
            jac->y[c] = keep;
            if (status != 0)
                return -1;
            for (int i = 0; i < k; ++i) {
                const double slope = (plus[i] - minus[i]) / (2.0 * h);
                hx_jacobian_add(jac, d->nq + jac->coupled[i], 1, c, &slope);
            }
        }
    }
    return 0;
}
