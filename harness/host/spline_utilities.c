/*
 * AKISPL and CUBSPL (docs/interface.md §5.2): the model's Reference_Spline
 * (§7.11) interpolated at x by Akima's method or the natural cubic spline,
 * linearly across z between curves (model/spline_surface.h, which the
 * function expressions use too); the value, or the first or second
 * derivatives in x and z, as the utility pages lay out `array`.
 */
#include <math.h>

#include "host/call.h"
#include "host/utilities.h"
#include "model/spline_surface.h"
#include "usrsub/solver_abi.h"

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
    hx_spline_surface(s, akima ? HX_SPLINE_AKIMA : HX_SPLINE_CUBIC, xval, zval, d);
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
