/* The whole bushing: offset and scale, coupled groups, preload and force
 * scale, with the 6x6 partials (include/usrsub/bushing.h). */
#include <stdlib.h>
#include <string.h>

#include "usrsub/core/bushing.h"

void usrsub_bushing_force(const usrsub_bushing *b, const double d[6], const double v[6],
                          double F[6], double *dFdd, double *dFdv)
{
    if (dFdd != NULL) {
        memset(dFdd, 0, 36 * sizeof(double));
        memset(dFdv, 0, 36 * sizeof(double));
    }
    unsigned coupled = 0;
    for (int g = 0; g < 2; ++g) {
        const int m = b->group_size[g];
        if (m < 2)
            continue;
        const usrsub_bushing_direction *dirs[3];
        double q[3], qd[3], Fg[3], J[9], Jv[9];
        for (int i = 0; i < m; ++i) {
            const int k = b->group[g][i];
            dirs[i] = &b->dir[k];
            q[i] = dirs[i]->disp_scale * d[k] - dirs[i]->offset;
            qd[i] = dirs[i]->disp_scale * v[k];
        }
        usrsub_bushing_group_force(dirs, m, b->epsilon[g], q, qd, Fg, dFdd ? J : NULL,
                                   dFdd ? Jv : NULL);
        for (int i = 0; i < m; ++i) {
            const int k = b->group[g][i];
            const double V = dirs[i]->force_scale;
            F[k] = -dirs[i]->preload + V * Fg[i];
            coupled |= 1u << k;
            if (dFdd == NULL)
                continue;
            for (int j = 0; j < m; ++j) {
                const int kj = b->group[g][j];
                dFdd[k + 6 * kj] = V * J[i * m + j] * dirs[j]->disp_scale;
                dFdv[k + 6 * kj] = V * Jv[i * m + j] * dirs[j]->disp_scale;
            }
        }
    }
    for (int k = 0; k < 6; ++k) {
        if (coupled & (1u << k))
            continue;
        const usrsub_bushing_direction *dk = &b->dir[k];
        if (!dk->active) {
            F[k] = 0.0;
            continue;
        }
        const double H = dk->disp_scale, V = dk->force_scale;
        double slope;
        const double g = usrsub_characteristic(dk, H * d[k] - dk->offset, dFdd != NULL ? &slope : NULL);
        F[k] = -dk->preload - V * (g + dk->c * H * v[k]);
        if (dFdd != NULL) {
            dFdd[k + 6 * k] = -V * slope * H;
            dFdv[k + 6 * k] = -V * dk->c * H;
        }
    }
}

void usrsub_bushing_prepare(usrsub_bushing *b)
{
    const int size = b->coupling == USRSUB_SPHERICAL ? 3 : b->coupling == USRSUB_CYLINDRICAL ? 2 : 0;
    b->uses_translation = b->uses_rotation = b->uses_velocity = 0;
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
    for (int g = 0; g < 2; ++g) {
        b->group_size[g] = 0;
        for (int i = 0; i < size; ++i)
            if (b->dir[3 * g + i].active)
                b->group[g][b->group_size[g]++] = 3 * g + i;
        if (b->group_size[g] < 2) /* one active member alone is not coupled */
            b->group_size[g] = 0;
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
