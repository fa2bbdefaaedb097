/*
 * The couplers' share of the Newton matrix (newton_matrix.h). The couplers
 * turn the bodies' free accelerations into udot = P udot_free + c(q, u)
 * (constraints.h): the rows of the coupled velocities become P times the
 * rows assembled so far, plus the derivatives of the constraint stage with
 * the free accelerations held, by central differences on the coupled
 * joints' own columns (COUSUB, COUXX and COUXX2 are called there).
 */
#include <string.h>

#include "sim/dynamics/constraints.h"
#include "sim/newton/newton_parts.h"

/* The coupled rows of column c through P. */
static void project_column(hx_newton_matrix *nm, int c, double *v, double *w, int *at)
{
    const int k = nm->ncoupled, row0 = nm->d->nq;
    int any = 0;
    for (int i = 0; i < k; ++i) {
        at[i] = hx_sparsity_find(&nm->pattern, row0 + nm->coupled[i], c);
        v[i] = at[i] >= 0 ? nm->values[at[i]] : 0.0;
        any |= v[i] != 0.0;
    }
    if (!any)
        return;
    for (int i = 0; i < k; ++i) {
        double s = 0.0;
        for (int j = 0; j < k; ++j)
            s += nm->projector[i + k * j] * v[j];
        w[i] = s;
    }
    for (int i = 0; i < k; ++i) {
        if (at[i] >= 0)
            nm->values[at[i]] = w[i];
        else if (w[i] != 0.0)
            nm->outside++;
    }
}

/* The constraint stage at y with the free accelerations held: the coupled
 * velocities' accelerations into out. */
static int stage(hx_newton_matrix *nm, double t, const double *y, double *accel, double *out)
{
    hx_dynamics *d = nm->d;
    memcpy(accel, d->free_accelerations, sizeof(double) * (size_t)d->nu);
    if (hx_constraints_apply(d, t, y, accel) != 0)
        return -1;
    for (int i = 0; i < nm->ncoupled; ++i)
        out[i] = accel[nm->coupled[i]];
    return 0;
}

int hx_coupler_blocks(hx_newton_matrix *nm, double t, const double *y)
{
    hx_dynamics *d = nm->d;
    const int k = nm->ncoupled;
    if (k == 0)
        return 0;
    double *v = nm->coupler_work, *w = v + k;
    if (hx_constraints_projector(d, t, y, nm->coupled, k, w + k, nm->projector) != 0)
        return -1;
    for (int c = 0; c < nm->n; ++c)
        project_column(nm, c, v, w, nm->coupled_at);
    /* the stage's own dependence on the coupled joints' coordinates and rates */
    double *accel = nm->f_plus, *plus = nm->f_minus, *minus = plus + k;
    for (int b = 0; b < d->m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        int coupled = 0;
        for (int i = 0; i < k && !coupled; ++i)
            coupled = (dof->kind == HX_DOF_REVOLUTE || dof->kind == HX_DOF_SLIDER) &&
                      nm->coupled[i] == dof->u;
        if (!coupled)
            continue;
        const int columns[2] = {dof->q, d->nq + dof->u};
        for (int j = 0; j < 2; ++j) {
            const int c = columns[j];
            const double keep = nm->y[c], h = hx_newton_step(nm->y, c);
            nm->y[c] = keep + h;
            int status = stage(nm, t, nm->y, accel, plus);
            nm->y[c] = keep - h;
            status |= stage(nm, t, nm->y, accel, minus);
            nm->y[c] = keep;
            if (status != 0)
                return -1;
            for (int i = 0; i < k; ++i) {
                const double slope = (plus[i] - minus[i]) / (2.0 * h);
                hx_newton_add(nm, d->nq + nm->coupled[i], 1, c, &slope);
            }
        }
    }
    return 0;
}
