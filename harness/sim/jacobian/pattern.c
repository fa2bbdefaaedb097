/*
 * Where the Newton matrix can be nonzero (newton_matrix.h), from the model's
 * structure: a body's rows depend on its own columns and on those of every
 * body an element, a load or a Force_StateEqn joins it to (and on that
 * element's states); a Force_StateEqn's rows on its states and on the bodies
 * its inputs measure; the coupled velocities' rows on everything any of
 * their group depends on (the constraints mix a group's rows,
 * coupler_blocks.c); a Control_Diff's row on its state and what its DIFSUB
 * declared it reads (routine_blocks.c); the work accumulators' rows on
 * nothing (newton_matrix.h). The diagonal is always in.
 */
#include <stdlib.h>
#include <string.h>

#include "sim/dynamics/loads.h"
#include "sim/dynamics/stateeqns.h"
#include "sim/jacobian/jacobian_parts.h"

typedef struct pairs {
    int *rows, *cols;
    long count, room;
    int failed;
} pairs;

static void add(pairs *p, int row, int col)
{
    if (p->count == p->room) {
        const long room = p->room ? 2 * p->room : 1024;
        int *r = realloc(p->rows, sizeof(int) * (size_t)room);
        if (r != NULL)
            p->rows = r;
        int *c = realloc(p->cols, sizeof(int) * (size_t)room);
        if (c != NULL)
            p->cols = c;
        if (r == NULL || c == NULL) {
            p->failed = 1;
            return;
        }
        p->room = room;
    }
    p->rows[p->count] = row;
    p->cols[p->count++] = col;
}

/* The rows of body b's velocities (or all its rows) by the columns of body c. */
static void body_by_body(pairs *p, const hx_dynamics *d, int b, int c, int all_rows)
{
    if (b < 0 || c < 0 || d->dof[b].kind == HX_DOF_GROUND)
        return;
    int rows[13], cols[13];
    const int nr = hx_jacobian_body_columns(d, b, rows), nc = hx_jacobian_body_columns(d, c, cols);
    const int first = all_rows ? 0 : nr - (d->dof[b].kind == HX_DOF_FREE ? 6 : 1);
    for (int i = first; i < nr; ++i)
        for (int j = 0; j < nc; ++j)
            add(p, rows[i], cols[j]);
}

/* Every body of `rows` (velocities) by every body of `cols`. */
static void bodies_by_bodies(pairs *p, const hx_dynamics *d, const int *rows, int nr,
                             const int *cols, int nc)
{
    for (int i = 0; i < nr; ++i)
        for (int j = 0; j < nc; ++j)
            body_by_body(p, d, rows[i], cols[j], 0);
}

static int body_of(const hx_model *m, int marker)
{
    return marker >= 0 ? m->markers[marker].body : -1;
}

static void state_element(pairs *p, const hx_dynamics *d, int k)
{
    const hx_model *m = d->m;
    const hx_stateeqn *f = &m->stateeqns[k];
    const int x0 = d->stateeqns->offset[k], ns = f->nstate;
    int measured[32];
    const int nmeasured = hx_stateeqn_input_bodies(d, k, measured, 32);
    const int out[2] = {body_of(m, f->i_marker), body_of(m, f->j_marker)};
    int geometry[35];
    memcpy(geometry, measured, sizeof(int) * (size_t)nmeasured);
    geometry[nmeasured] = out[0];
    geometry[nmeasured + 1] = out[1];
    geometry[nmeasured + 2] = body_of(m, f->ref_marker);
    for (int i = 0; i < ns; ++i) {
        for (int j = 0; j < ns; ++j)
            add(p, x0 + i, x0 + j);
        for (int l = 0; l < nmeasured; ++l) {
            int cols[13];
            const int nc = hx_jacobian_body_columns(d, measured[l], cols);
            for (int j = 0; j < nc; ++j)
                add(p, x0 + i, cols[j]);
        }
    }
    bodies_by_bodies(p, d, out, 2, geometry, nmeasured + 3);
    for (int s = 0; s < 2; ++s) {
        if (out[s] < 0 || d->dof[out[s]].kind == HX_DOF_GROUND)
            continue;
        int rows[13];
        const int nr = hx_jacobian_body_columns(d, out[s], rows);
        const int first = nr - (d->dof[out[s]].kind == HX_DOF_FREE ? 6 : 1);
        for (int i = first; i < nr; ++i)
            for (int j = 0; j < ns; ++j)
                add(p, rows[i], x0 + j);
    }
}

/* The coupled velocities' rows, group by group (coupler_blocks.c): each
 * group's rows on every column any of them has, on its velocities and its
 * bodies' positions; a group's rows are independent of another's columns. */
static void coupled_rows(pairs *p, const hx_jacobian *jac)
{
    const hx_dynamics *d = jac->d;
    if (jac->ncoupled == 0 || jac->n <= 0)
        return;
    const size_t n = (size_t)jac->n;
    unsigned char *is_row = calloc(n, 1), *is_col = calloc(n, 1);
    if (is_row == NULL || is_col == NULL) {
        free(is_row), free(is_col);
        p->failed = 1;
        return;
    }
    const long before = p->count;
    for (int g = 0; g < jac->ngroups; ++g) {
        const int first = jac->group_start[g], last = jac->group_start[g + 1];
        memset(is_row, 0, n);
        memset(is_col, 0, n);
        for (int i = first; i < last; ++i)
            is_row[d->nq + jac->coupled[i]] = 1;
        for (long k = 0; k < before; ++k)
            if (is_row[p->rows[k]])
                is_col[p->cols[k]] = 1;
        for (int c = jac->group_column_start[g]; c < jac->group_column_start[g + 1]; ++c)
            is_col[jac->group_columns[c]] = 1; /* its bodies' positions and velocities */
        for (int c = 0; c < jac->n; ++c)
            if (is_col[c])
                for (int i = first; i < last; ++i)
                    add(p, d->nq + jac->coupled[i], c);
    }
    free(is_row), free(is_col);
}

int hx_jacobian_pattern(hx_jacobian *jac, int widen, hx_message *msg)
{
    const hx_dynamics *d = jac->d;
    const hx_model *m = d->m;
    pairs p = {0};
    for (int c = 0; widen && c < jac->pattern.n; ++c) /* the pattern so far, kept */
        for (int i = jac->pattern.colptr[c]; i < jac->pattern.colptr[c + 1]; ++i)
            add(&p, jac->pattern.rowind[i], c);
    for (int b = 0; b < m->nbodies; ++b)
        body_by_body(&p, d, b, b, 1);
    for (int k = 0; k < m->nforces; ++k) {
        const hx_force *f = &m->forces[k];
        const int axes = hx_force_output_axes(f);
        const int rows[2] = {body_of(m, f->i_marker), body_of(m, f->j_marker)};
        const int cols[3] = {rows[0], rows[1], body_of(m, axes)};
        bodies_by_bodies(&p, d, rows, 2, cols, 3);
    }
    for (int k = 0; k < m->nloads; ++k) {
        const hx_load *l = &m->loads[k];
        int bodies[HX_LOAD_BODIES_MAX];
        const int nbodies = hx_load_bodies(d, k, bodies);
        const int reacted = l->kind == HX_LOAD_VECTOR ? l->j_marker >= 0 : !l->action_only;
        const int rows[2] = {body_of(m, l->i_marker), body_of(m, l->j_marker)};
        bodies_by_bodies(&p, d, rows, reacted ? 2 : 1, bodies, nbodies);
        /* the Control_Diff states it reads (DIF): its bodies' velocity rows by
         * each state's column */
        const int ndiffs = hx_load_diffs(d, k, bodies);
        for (int i = 0; i < (reacted ? 2 : 1); ++i) {
            if (rows[i] < 0 || d->dof[rows[i]].kind == HX_DOF_GROUND)
                continue;
            int body_rows[13];
            const int nr = hx_jacobian_body_columns(d, rows[i], body_rows);
            const int first = nr - (d->dof[rows[i]].kind == HX_DOF_FREE ? 6 : 1);
            for (int r = first; r < nr; ++r)
                for (int j = 0; j < ndiffs; ++j)
                    add(&p, body_rows[r], d->diff_offset + bodies[j]);
        }
    }
    for (int k = 0; k < m->nstateeqns; ++k)
        state_element(&p, d, k);
    for (int k = 0; k < m->nroutines; ++k)
        if (m->routines[k].kind == HX_ROUTINE_DIFF) {
            int cols[DIFF_COLUMNS_MAX];
            const int nc = hx_diff_columns(d, k, cols, DIFF_COLUMNS_MAX);
            for (int j = 0; j < nc; ++j)
                add(&p, d->diff_offset + m->routines[k].slot, cols[j]);
        }
    for (int k = 0; k < d->nmotions; ++k) /* an acceleration motion's s' = v */
        if (d->motion_state[k] >= 0)
            add(&p, d->motion_state[k], d->motion_state[k] + 1);
    coupled_rows(&p, jac);
    /* an algebraic loop joins whatever its loads read to whatever moves the
     * values they read: the whole matrix, by differences (jacobian.c) */
    for (int c = 0; m->nloop_inputs > 0 && c < jac->n; ++c)
        for (int r = 0; r < jac->n; ++r)
            add(&p, r, c);
    hx_sparsity built = {0};
    const int status =
        p.failed ? -1 : hx_sparsity_from_pairs(&built, jac->n, p.rows, p.cols, p.count);
    if (status == 0) {
        hx_sparsity_free(&jac->pattern);
        jac->pattern = built;
    }
    free(p.rows);
    free(p.cols);
    return status == 0 ? 0 : hx_fail(msg, "out of memory for the Jacobian's pattern");
}
