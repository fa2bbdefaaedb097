/* The whole bushing: offset and scale, coupled groups, preload and force
 * scale, with the 6x6 partials (bushing.h). */
#include <stdlib.h>
#include <string.h>

#include "usrsub/core/bushing.h"

void usrsub_bushing_force(const usrsub_bushing *b, const double d[6], const double v[6],
                          double F[6], double *dFdd, double *dFdv)
{
    if (dFdd != NULL) { /* the partials are sparse: blocks and a diagonal */
        memset(dFdd, 0, 36 * sizeof(double));
        memset(dFdv, 0, 36 * sizeof(double));
    }
    for (int g = 0; g < b->ngroups; ++g) {
        const int m = b->group_size[g];
        const usrsub_bushing_direction *dirs[3];
        double q[3], qd[3], Fg[3], J[9], Jv[9];
        for (int i = 0; i < m; ++i) {
            const int k = b->group[g][i];
            dirs[i] = &b->dir[k];
            q[i] = dirs[i]->disp_scale * d[k] - dirs[i]->offset;
            qd[i] = dirs[i]->disp_scale * v[k];
        }
        usrsub_bushing_coupling_force(dirs, m, b->epsilon[g], q, qd, Fg, dFdd ? J : NULL,
                                      dFdd ? Jv : NULL);
        for (int i = 0; i < m; ++i) {
            const int k = b->group[g][i];
            const double V = dirs[i]->force_scale;
            F[k] = -dirs[i]->preload + V * Fg[i];
            if (dFdd == NULL)
                continue;
            for (int j = 0; j < m; ++j) {
                const int kj = b->group[g][j];
                dFdd[k + 6 * kj] = V * J[i + m * j] * dirs[j]->disp_scale;
                dFdv[k + 6 * kj] = V * Jv[i + m * j] * dirs[j]->disp_scale;
            }
        }
    }
    for (int n = 0; n < b->nsingle; ++n) {
        const int k = b->single[n];
        const usrsub_bushing_direction *dk = &b->dir[k];
        const double H = dk->disp_scale, V = dk->force_scale;
        double slope;
        const double g = usrsub_characteristic(dk, H * d[k] - dk->offset, dFdd != NULL ? &slope : NULL);
        F[k] = -dk->preload - V * (g + dk->c * H * v[k]);
        if (dFdd != NULL) {
            dFdd[k + 6 * k] = -V * slope * H;
            dFdv[k + 6 * k] = -V * dk->c * H;
        }
    }
    for (int n = 0; n < b->ninactive; ++n)
        F[b->inactive[n]] = 0.0;
}

void usrsub_bushing_prepare(usrsub_bushing *b)
{
    const int size = b->coupling == USRSUB_SPHERICAL ? 3 : b->coupling == USRSUB_CYLINDRICAL ? 2 : 0;
    b->uses_translation = b->uses_rotation = b->uses_velocity = 0;
    b->has_states = b->friction.active;
    for (int k = 0; k < 6; ++k)
        b->has_states |= b->dir[k].rubber || b->dir[k].mount;
    for (int k = 0; k < 6; ++k) {
        usrsub_bushing_direction *d = &b->dir[k];
        d->active = d->stiffness != USRSUB_STIFFNESS_NONE || d->damped;
        if (!d->damped)
            d->c = 0.0;
        double slope;
        d->g_at_zero = usrsub_characteristic(d, 0.0, &slope);
        if (!d->active)
            continue;
        if (k < 3)
            b->uses_translation = 1;
        else
            b->uses_rotation = 1;
        if (d->damped)
            b->uses_velocity = 1;
    }
    /* the coupled groups first (one active member alone is not coupled), then
     * each direction that is evaluated on its own, then the inactive ones */
    b->ngroups = b->nsingle = b->ninactive = 0;
    unsigned grouped = 0;
    for (int g = 0; g < 2; ++g) {
        int members[3], count = 0;
        for (int i = 0; i < size; ++i)
            if (b->dir[3 * g + i].active)
                members[count++] = 3 * g + i;
        if (count < 2)
            continue;
        b->epsilon[b->ngroups] = b->group_epsilon[g];
        b->group_size[b->ngroups] = count;
        for (int i = 0; i < count; ++i) {
            b->group[b->ngroups][i] = members[i];
            grouped |= 1u << members[i];
        }
        b->ngroups++;
    }
    /* a damped-only direction's deflection matters only inside a group */
    b->uses_twist = b->dir[5].stiffness != USRSUB_STIFFNESS_NONE || (grouped & (1u << 5)) != 0;
    for (int k = 0; k < 6; ++k) {
        if (grouped & (1u << k))
            continue;
        if (b->dir[k].active)
            b->single[b->nsingle++] = k;
        else
            b->inactive[b->ninactive++] = k;
    }
}

void usrsub_bushing_free(usrsub_bushing *b)
{
    if (b == NULL)
        return;
    for (int k = 0; k < 6; ++k)
        if (b->dir[k].spline.x != NULL)
            usrsub_spline_free(&b->dir[k].spline);
    free(b);
}
