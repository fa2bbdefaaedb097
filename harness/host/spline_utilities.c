/*
 * AKISPL and CUBSPL (docs/interface.md §5.2): the model's Reference_Spline
 * (§7.11) interpolated at x by Akima's method or the natural cubic spline,
 * linearly across z between curves; the value, or the first or second
 * derivatives in x and z, as the utility pages lay out `array`.
 */
#include <math.h>

#include "base/cubic_curve.h"
#include "host/call.h"
#include "host/utilities.h"
#include "usrsub/solver_abi.h"

/* f, df/dx, d2f/dx2 of curve j at x */
static void curve(const hx_spline *s, const double *slopes, int j, double x, double out[3])
{
    const size_t offset = (size_t)j * (size_t)s->nx;
    hx_cubic_curve(s->x, s->y + offset, slopes + offset, s->nx, s->linear_extrapolate, x, out);
}

/* The spline at (x, z): f and its derivatives f_x f_z f_xx f_xz f_zz into
 * d[0..5]. Across z, linear between the two curves about z (the end two
 * beyond them); one curve does not depend on z. */
static void surface(const hx_spline *s, const double *slopes, double x, double z, double d[6])
{
    double a[3];
    if (s->nz == 1) {
        curve(s, slopes, 0, x, a);
        d[0] = a[0], d[1] = a[1], d[2] = 0.0, d[3] = a[2], d[4] = 0.0, d[5] = 0.0;
        return;
    }
    int j = 0;
    while (j < s->nz - 2 && z >= s->z[j + 1])
        ++j;
    double b[3];
    curve(s, slopes, j, x, a);
    curve(s, slopes, j + 1, x, b);
    const double dz = s->z[j + 1] - s->z[j], w = (z - s->z[j]) / dz;
    d[0] = a[0] + w * (b[0] - a[0]);
    d[1] = a[1] + w * (b[1] - a[1]);
    d[2] = (b[0] - a[0]) / dz;
    d[3] = a[2] + w * (b[2] - a[2]);
    d[4] = (b[1] - a[1]) / dz;
    d[5] = 0.0;
}

static void answer(hx_utility u, int akima, double xval, double zval, int id, int iord,
                   double *array, int *errflg)
{
    *errflg = 1;
    if (iord < 0 || iord > 2) {
        hx_utility_refused(u, "iord = %d (0, 1 or 2: the value or its derivatives)", iord);
        return;
    }
    if (array == NULL) {
        hx_utility_refused(u, "no array to answer in (a null pointer)");
        return;
    }
    if (!isfinite(xval) || !isfinite(zval)) {
        if (hx_utility_non_finite(u, "a non-finite argument (xval = %g, zval = %g)", xval,
                                  zval)) {
            for (int i = 0; i <= iord; ++i)
                array[i] = NAN;
            *errflg = 0;
        }
        return;
    }
    const hx_call *c = hx_host_bound();
    const hx_model *m = c != NULL ? c->model : NULL;
    if (m == NULL) {
        hx_utility_refused(u, "id %d, and no model to read it from", id);
        return;
    }
    const int k = hx_model_spline(m, id);
    if (k < 0) {
        hx_utility_refused(u, "id %d, which names no Reference_Spline of the model", id);
        return;
    }
    const hx_spline *s = &m->splines[k];
    double d[6];
    surface(s, akima ? s->akima_slope : s->cubic_slope, xval, zval, d);
    /* the value; the slopes in x and z; the second derivatives xx, xz, zz:
     * iord + 1 numbers, nothing beyond (a caller of the value may hold one) */
    static const int first[3] = {0, 1, 3};
    for (int i = 0; i <= iord; ++i)
        array[i] = d[first[iord] + i];
    *errflg = 0;
}

void c_akispl(double xval, double zval, int id, int iord, double *array, int *errflg)
{
    answer(HX_UTILITY_AKISPL, 1, xval, zval, id, iord, array, errflg);
}

void c_cubspl(double xval, double zval, int id, int iord, double *array, int *errflg)
{
    answer(HX_UTILITY_CUBSPL, 0, xval, zval, id, iord, array, errflg);
}
