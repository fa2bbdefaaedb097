/*
 * G M^-1 G^T, the matrix of the multipliers (docs/architecture.md, the
 * constraint system): M^-1 by the bodies' blocks, the matrix over the
 * active rows formed dense or, from HX_CONSTRAINT_MATRIX_ENVELOPE_ROWS
 * active rows on, by its envelope (banded for a chain: its cost grows as the
 * rows), and its solves.
 */
#include <math.h>
#include <stdlib.h>

#include "base/envelope.h"
#include "base/linalg.h"
#include "base/vecmath.h"
#include "sim/dynamics/constraint_matrix.h"

/* Whether rows i and j share a block of velocities. */
static int share(const hx_dynamics *d, int i, int j)
{
    const hx_constraint_row *ri = &d->rows[i], *rj = &d->rows[j];
    for (int a = 0; a < ri->nblocks; ++a)
        for (int b = 0; b < rj->nblocks; ++b)
            if (ri->u[a] == rj->u[b])
                return 1;
    return 0;
}

int hx_constraint_matrix_plan(hx_dynamics *d, hx_message *msg)
{
    const int n = d->nactive;
    free(d->envelope_first), free(d->envelope_start); /* a set replaced: planned again */
    d->envelope_first = NULL, d->envelope_start = NULL;
    if (n < HX_CONSTRAINT_MATRIX_ENVELOPE_ROWS)
        return 0;
    d->envelope_first = malloc(sizeof(int) * (size_t)n);
    d->envelope_start = malloc(sizeof(size_t) * ((size_t)n + 1));
    if (d->envelope_first == NULL || d->envelope_start == NULL)
        return hx_fail(msg, "out of memory");
    for (int a = 0; a < n; ++a) {
        int first = a;
        for (int b = 0; b < a && first == a; ++b)
            if (share(d, d->active[a], d->active[b]))
                first = b;
        d->envelope_first[a] = first;
    }
    hx_envelope_layout(n, d->envelope_first, d->envelope_start);
    return 0;
}

/* out = M^-1 in over one body's block of velocities. */
void hx_constraint_matrix_inverse_mass(const hx_dynamics *d, int body, const double *in, double *out)
{
    const hx_body_dof *dof = &d->dof[body];
    const double minv = 1.0 / dof->mass;
    if (dof->kind != HX_DOF_FREE) {
        out[0] = in[0] * minv;
        return;
    }
    for (int c = 0; c < 3; ++c)
        out[c] = in[c] * minv;
    m3_apply(out + 3, dof->inertia_inv, in + 3);
}

/* W = M^-1 G^T row by row, then A = G M^-1 G^T over the active rows
 * (nactive x nactive, in d->active's order). */
static void weights(const hx_dynamics *d, const double *G, double *W)
{
    for (int a = 0; a < d->nactive; ++a) {
        const int i = d->active[a];
        const hx_constraint_row *r = &d->rows[i];
        for (int b = 0; b < r->nblocks; ++b) {
            const size_t at = (size_t)d->row_values * (size_t)i + (size_t)r->slot[b];
            hx_constraint_matrix_inverse_mass(d, r->body[b], G + at, W + at);
        }
    }
}

/* (G M^-1 G^T)_ij: the products over the blocks rows i and j share. */
static double pair_product(const hx_dynamics *d, const double *G, const double *W, int i, int j)
{
    const hx_constraint_row *ri = &d->rows[i], *rj = &d->rows[j];
    const double *Wi = W + (size_t)d->row_values * (size_t)i;
    const double *Gj = G + (size_t)d->row_values * (size_t)j;
    double s = 0.0;
    for (int a = 0; a < ri->nblocks; ++a)
        for (int b = 0; b < rj->nblocks; ++b)
            if (ri->u[a] == rj->u[b])
                for (int c = 0; c < ri->width[a]; ++c)
                    s += Wi[ri->slot[a] + c] * Gj[rj->slot[b] + c];
    return s;
}

void hx_constraint_matrix_gram(const hx_dynamics *d, const double *G, double *W, double *A)
{
    const int n = d->nactive;
    weights(d, G, W);
    for (int ai = 0; ai < n; ++ai) {
        const int i = d->active[ai];
        for (int aj = 0; aj < n; ++aj)
            A[ai * n + aj] = pair_product(d, G, W, i, d->active[aj]);
    }
}

void hx_constraint_matrix_gram_all(const hx_dynamics *d, const double *G, double *W, double *A)
{
    const int n = d->nrows;
    for (int i = 0; i < n; ++i) {
        const hx_constraint_row *r = &d->rows[i];
        for (int b = 0; b < r->nblocks; ++b) {
            const size_t at = (size_t)d->row_values * (size_t)i + (size_t)r->slot[b];
            hx_constraint_matrix_inverse_mass(d, r->body[b], G + at, W + at);
        }
    }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            A[i * n + j] = pair_product(d, G, W, i, j);
}

/* Forms G M^-1 G^T at G for the solves that follow: dense into A (each
 * solve takes it apart: form it again before the next), or its envelope,
 * factored once (d->envelope_first set: hx_constraints_plan). */
int hx_constraint_matrix_form(const hx_dynamics *d, const double *G, double *W, double *A)
{
    const int *first = d->envelope_first;
    if (first == NULL) {
        hx_constraint_matrix_gram(d, G, W, A);
        return 0;
    }
    weights(d, G, W);
    for (int ai = 0; ai < d->nactive; ++ai) {
        double *row = hx_envelope_at(first, d->envelope_start, A, ai, first[ai]);
        for (int aj = first[ai]; aj <= ai; ++aj)
            row[aj - first[ai]] = pair_product(d, G, W, d->active[ai], d->active[aj]);
    }
    return hx_envelope_factor(d->nactive, first, d->envelope_start, A);
}

/* b becomes (G M^-1 G^T)^-1 b with A from form; 0, or -1 when singular. */
int hx_constraint_matrix_solve(const hx_dynamics *d, double *A, double *b)
{
    if (d->envelope_first == NULL)
        return hx_solve(d->nactive, A, b);
    hx_envelope_solve(d->nactive, d->envelope_first, d->envelope_start, A, b);
    return 0;
}
