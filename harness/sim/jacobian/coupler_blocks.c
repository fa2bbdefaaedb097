/*
 * The constraint system's share of the Newton matrix (jacobian.h). The
 * couplers, the joints between free bodies and the motions on them turn the
 * bodies' free accelerations into udot = P udot_free + c(q, u)
 * (constraints.h): the rows of the coupled velocities become P times the
 * rows assembled so far, plus the derivatives of the constraint stage with
 * the free accelerations held, by central differences on the coupled bodies'
 * own columns (COUSUB, COUXX and COUXX2 are called there; a free body's 13
 * columns).
 *
 * Group by group (docs/architecture.md, the Jacobian): the coupled
 * velocities fall into groups that no row joins (the four corners of a
 * vehicle, joined to its body by bushings). G M^-1 G^T is block-diagonal
 * over them, so P is zero between groups and a group's accelerations depend
 * on its own bodies' states and free accelerations alone: its rows get the
 * columns of its own rows only (pattern.c), P is applied block by block,
 * and one evaluation of the stage moves a column of every group at once
 * (as many stage evaluations as the largest group has columns, not as all
 * groups together). This rests on every row's value reading only the
 * bodies of its blocks (constraints.c).
 */
#include <stdlib.h>
#include <string.h>

#include "sim/dynamics/constraints.h"
#include "sim/jacobian/jacobian_parts.h"

static int find_root(int *parent, int i)
{
    while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
    return i;
}

int hx_coupler_blocks_init(hx_jacobian *jac, hx_message *msg)
{
    const hx_dynamics *d = jac->d;
    const int k = jac->ncoupled, nu = d->nu;
    if (k == 0)
        return 0;
    int *parent = malloc(sizeof(int) * (size_t)nu), *group = malloc(sizeof(int) * (size_t)nu);
    int *order = malloc(sizeof(int) * (size_t)k);
    jac->group_start = malloc(sizeof(int) * ((size_t)k + 1));
    jac->group_column_start = malloc(sizeof(int) * ((size_t)k + 1));
    jac->group_columns = malloc(sizeof(int) * (size_t)(d->nq + nu));
    if (!parent || !group || !order || !jac->group_start || !jac->group_column_start ||
        !jac->group_columns) {
        free(parent), free(group), free(order);
        return hx_fail(msg, "out of memory");
    }
    /* the velocities a row touches are one group; every row's, active or not (a static
     * equilibrium may make a redundant row active for the run: redundancy.h) */
    for (int u = 0; u < nu; ++u)
        parent[u] = u, group[u] = -1;
    for (int i = 0; i < d->nrows; ++i) {
        const hx_constraint_row *r = &d->rows[i];
        for (int b = 0; b < r->nblocks; ++b)
            for (int c = 0; c < r->width[b]; ++c) {
                const int x = find_root(parent, r->u[0]), y = find_root(parent, r->u[b] + c);
                if (x != y)
                    parent[y] = x;
            }
    }
    /* groups numbered by first appearance; coupled reordered group by group,
     * each group's velocities in their former order */
    int ngroups = 0;
    for (int i = 0; i < k; ++i) {
        const int root = find_root(parent, jac->coupled[i]);
        if (group[root] < 0)
            group[root] = ngroups++;
    }
    int next = 0;
    for (int g = 0; g < ngroups; ++g) {
        jac->group_start[g] = next;
        for (int i = 0; i < k; ++i)
            if (group[find_root(parent, jac->coupled[i])] == g)
                order[next++] = jac->coupled[i];
    }
    jac->group_start[ngroups] = next;
    memcpy(jac->coupled, order, sizeof(int) * (size_t)k);
    jac->ngroups = ngroups;
    /* each group's bodies' columns: positions, then velocities, body by body */
    int ncols = 0;
    for (int g = 0; g < ngroups; ++g) {
        jac->group_column_start[g] = ncols;
        for (int b = 0; b < d->m->nbodies; ++b) {
            const hx_body_dof *dof = &d->dof[b];
            if (dof->kind == HX_DOF_GROUND || group[find_root(parent, dof->u)] != g)
                continue;
            int coupled = 0;
            for (int i = jac->group_start[g]; i < jac->group_start[g + 1] && !coupled; ++i)
                coupled = jac->coupled[i] == dof->u;
            if (coupled)
                ncols += hx_jacobian_body_columns(d, b, jac->group_columns + ncols);
        }
    }
    jac->group_column_start[ngroups] = ncols;
    free(parent), free(group), free(order);
    return 0;
}

int hx_coupler_blocks_locate(hx_jacobian *jac, hx_message *msg)
{
    const hx_sparsity *s = &jac->pattern;
    const int ng = jac->ngroups, row0 = jac->d->nq;
    if (jac->ncoupled == 0)
        return 0;
    free(jac->group_pattern), free(jac->group_pattern_start); /* a pattern widened */
    free(jac->coupled_at), free(jac->coupled_at_start);
    /* a group's columns: those where its first row is in the pattern (all its rows are) */
    long total = 0;
    int ncols = 0;
    for (int g = 0; g < ng; ++g)
        for (int c = 0; c < jac->n; ++c)
            if (hx_sparsity_find(s, row0 + jac->coupled[jac->group_start[g]], c) >= 0) {
                ncols++;
                total += jac->group_start[g + 1] - jac->group_start[g];
            }
    jac->group_pattern = malloc(sizeof(int) * ((size_t)ncols + 1));
    jac->group_pattern_start = malloc(sizeof(int) * ((size_t)ng + 1));
    jac->coupled_at = malloc(sizeof(int) * ((size_t)total + 1));
    jac->coupled_at_start = malloc(sizeof(long) * ((size_t)ng + 1));
    if (!jac->group_pattern || !jac->group_pattern_start || !jac->coupled_at ||
        !jac->coupled_at_start)
        return hx_fail(msg, "out of memory");
    ncols = 0, total = 0;
    for (int g = 0; g < ng; ++g) {
        const int first = jac->group_start[g], kg = jac->group_start[g + 1] - first;
        jac->group_pattern_start[g] = ncols;
        jac->coupled_at_start[g] = total;
        for (int c = 0; c < jac->n; ++c) {
            if (hx_sparsity_find(s, row0 + jac->coupled[first], c) < 0)
                continue;
            jac->group_pattern[ncols++] = c;
            for (int i = 0; i < kg; ++i)
                jac->coupled_at[total++] = hx_sparsity_find(s, row0 + jac->coupled[first + i], c);
        }
    }
    jac->group_pattern_start[ng] = ncols;
    jac->coupled_at_start[ng] = total;
    return 0;
}

void hx_coupler_blocks_free(hx_jacobian *jac)
{
    free(jac->group_start);
    free(jac->group_columns);
    free(jac->group_column_start);
    free(jac->group_pattern);
    free(jac->group_pattern_start);
    free(jac->coupled_at);
    free(jac->coupled_at_start);
}

/* Group g's rows through its block of P, column by column of its pattern. */
static void project_group(hx_jacobian *jac, int g, double *v, double *w)
{
    const int k = jac->ncoupled, first = jac->group_start[g], kg = jac->group_start[g + 1] - first;
    const double *P = jac->projector + first + (size_t)k * (size_t)first;
    const int *at = jac->coupled_at + jac->coupled_at_start[g];
    for (int p = jac->group_pattern_start[g]; p < jac->group_pattern_start[g + 1]; ++p, at += kg) {
        int any = 0;
        for (int i = 0; i < kg; ++i) {
            v[i] = at[i] >= 0 ? jac->values[at[i]] : 0.0;
            any |= v[i] != 0.0;
        }
        if (!any)
            continue;
        for (int i = 0; i < kg; ++i) {
            double s = 0.0;
            for (int j = 0; j < kg; ++j)
                s += P[i + (size_t)k * (size_t)j] * v[j];
            w[i] = s;
        }
        for (int i = 0; i < kg; ++i) {
            if (at[i] >= 0)
                jac->values[at[i]] = w[i];
            else if (w[i] != 0.0)
                jac->outside++;
        }
    }
}

/* The constraint stage at y with the free accelerations held: the coupled
 * velocities' accelerations into out. */
static int stage(hx_jacobian *jac, double t, const double *y, double *accel, double *out)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    memcpy(accel, dd->free_accelerations, sizeof(double) * (size_t)d->nu);
    if (hx_constraints_apply(d, dd, t, y, accel, NULL) != 0)
        return -1;
    for (int i = 0; i < jac->ncoupled; ++i)
        out[i] = accel[jac->coupled[i]];
    return 0;
}

/* Column j of every group's columns that has one moved to keep + sign h (sign 0: back). */
static void move_columns(hx_jacobian *jac, int j, const double *keep, const double *h, double sign)
{
    for (int g = 0; g < jac->ngroups; ++g) {
        const int at = jac->group_column_start[g] + j;
        if (at < jac->group_column_start[g + 1])
            jac->y[jac->group_columns[at]] = keep[g] + sign * h[g];
    }
}

int hx_coupler_blocks(hx_jacobian *jac, double t, const double *y)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    const int k = jac->ncoupled, ng = jac->ngroups;
    if (k == 0)
        return 0;
    double *v = jac->coupler_work, *w = v + k, *keep = w + k, *h = keep + k;
    if (hx_constraints_projector(d, dd, t, y, jac->coupled, k, jac->group_start, ng, h + k,
                                 jac->projector) != 0)
        return -1;
    for (int g = 0; g < ng; ++g)
        project_group(jac, g, v, w);
    /* the stage's own dependence on the coupled bodies' coordinates and rates:
     * the j-th column of every group moved at once */
    double *accel = jac->f_plus, *plus = jac->f_minus, *minus = plus + k;
    int columns = 0;
    for (int g = 0; g < ng; ++g)
        if (jac->group_column_start[g + 1] - jac->group_column_start[g] > columns)
            columns = jac->group_column_start[g + 1] - jac->group_column_start[g];
    for (int j = 0; j < columns; ++j) {
        for (int g = 0; g < ng; ++g) {
            const int at = jac->group_column_start[g] + j;
            if (at < jac->group_column_start[g + 1]) {
                const int c = jac->group_columns[at];
                keep[g] = jac->y[c], h[g] = hx_jacobian_step(jac->y, c);
            }
        }
        move_columns(jac, j, keep, h, 1.0);
        int status = stage(jac, t, jac->y, accel, plus);
        move_columns(jac, j, keep, h, -1.0);
        status |= stage(jac, t, jac->y, accel, minus);
        move_columns(jac, j, keep, h, 0.0);
        if (status != 0)
            return -1;
        for (int g = 0; g < ng; ++g) {
            const int at = jac->group_column_start[g] + j;
            if (at >= jac->group_column_start[g + 1])
                continue;
            for (int i = jac->group_start[g]; i < jac->group_start[g + 1]; ++i) {
                const double slope = (plus[i] - minus[i]) / (2.0 * h[g]);
                hx_jacobian_add(jac, d->nq + jac->coupled[i], 1, jac->group_columns[at], &slope);
            }
        }
    }
    return 0;
}
