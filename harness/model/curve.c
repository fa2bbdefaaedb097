/* A model's curve (curve.h), on the B-splines of base/bspline.h. */
#include "model/curve.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/bspline.h"
#include "base/linalg.h"

int hx_curve_check(const hx_curve *c, hx_message *msg)
{
    if (c->order < 2 || c->order > HX_BSPLINE_MAX_ORDER)
        return hx_fail(msg, "curve %d: its order is %d (2 to %d)", c->id, c->order,
                       HX_BSPLINE_MAX_ORDER);
    const int distinct = c->closed ? c->npoints - 1 : c->npoints;
    if (c->points == NULL || distinct < c->order)
        return hx_fail(msg, "curve %d: %d points are too few for a%s curve of order %d (it"
                       " needs %d)", c->id, c->npoints, c->closed ? " closed" : "n open",
                       c->order, c->order + (c->closed ? 1 : 0));
    for (int k = 0; k < 3 * c->npoints; ++k)
        if (!isfinite(c->points[k]))
            return hx_fail(msg, "curve %d: coordinate %d of point %d is not finite", c->id,
                           k % 3 + 1, k / 3 + 1);
    if (c->closed && memcmp(c->points, c->points + 3 * (c->npoints - 1), 3 * sizeof(double)) != 0)
        return hx_fail(msg, "curve %d: it is closed, but its last point is not its first",
                       c->id);
    return 0;
}

int hx_curve_through(hx_curve *c, const double *points, int n, hx_message *msg)
{
    hx_curve trial = *c;
    trial.npoints = n, trial.points = (double *)points;
    if (hx_curve_check(&trial, msg) != 0)
        return -1;
    const int m = c->closed ? n - 1 : n; /* equations: one per distinct point */
    double *sites = malloc(sizeof(double) * (size_t)n);
    double *matrix = malloc(sizeof(double) * (size_t)m * (size_t)m);
    double *work = malloc(sizeof(double) * (size_t)m * (size_t)m);
    double *rhs = malloc(sizeof(double) * (size_t)m);
    double *control = malloc(sizeof(double) * 3 * (size_t)n);
    if (!sites || !matrix || !work || !rhs || !control) {
        free(sites), free(matrix), free(work), free(rhs), free(control);
        return hx_fail(msg, "out of memory");
    }
    hx_bspline_sites(c->order, n, c->closed, sites);
    memset(matrix, 0, sizeof(double) * (size_t)m * (size_t)m);
    for (int j = 0; j < m; ++j) {
        double basis[4][HX_BSPLINE_MAX_ORDER];
        int first;
        hx_bspline_basis(c->order, n, c->closed, sites[j], basis, &first);
        for (int i = 0; i < c->order; ++i)
            matrix[(size_t)j * (size_t)m + (size_t)((first + i) % m)] += basis[0][i];
    }
    int status = 0;
    for (int axis = 0; axis < 3 && status == 0; ++axis) {
        memcpy(work, matrix, sizeof(double) * (size_t)m * (size_t)m);
        for (int j = 0; j < m; ++j)
            rhs[j] = points[3 * j + axis];
        if (hx_solve(m, work, rhs) != 0)
            status = hx_fail(msg, "curve %d: no curve of order %d passes through its points",
                             c->id, c->order);
        for (int j = 0; j < m; ++j)
            control[3 * j + axis] = rhs[j];
    }
    if (c->closed && status == 0)
        memcpy(control + 3 * m, control, 3 * sizeof(double));
    free(sites), free(matrix), free(work), free(rhs);
    if (status != 0) {
        free(control);
        return -1;
    }
    free(c->points);
    c->points = control, c->npoints = n;
    return 0;
}

void hx_curve_at(const hx_curve *c, double alpha, int component, double d[4])
{
    double basis[4][HX_BSPLINE_MAX_ORDER];
    int first;
    const double u = 0.5 * (alpha + 1.0); /* du/dalpha = 1/2 */
    hx_bspline_basis(c->order, c->npoints, c->closed, u, basis, &first);
    const int distinct = c->closed ? c->npoints - 1 : c->npoints;
    double scale = 1.0;
    for (int order = 0; order < 4; ++order, scale *= 0.5) {
        double sum = 0.0;
        for (int i = 0; i < c->order; ++i)
            sum += basis[order][i] * c->points[3 * ((first + i) % distinct) + component - 1];
        d[order] = sum * scale;
    }
}
