/* A Reference_Spline evaluated (spline_surface.h). */
#include "model/spline_surface.h"

#include "base/cubic_curve.h"

static const double *slopes_of(const hx_spline *s, hx_spline_method method)
{
    return method == HX_SPLINE_AKIMA ? s->akima_slope : s->cubic_slope;
}

/* f, df/dx, d2f/dx2 of curve j at x */
static void curve(const hx_spline *s, const double *slopes, int j, double x, double out[3])
{
    const size_t offset = (size_t)j * (size_t)s->nx;
    hx_cubic_curve(s->x, s->y + offset, slopes + offset, s->nx, s->linear_extrapolate, x, out);
}

static double curve_third(const hx_spline *s, const double *slopes, int j, double x)
{
    const size_t offset = (size_t)j * (size_t)s->nx;
    return hx_cubic_curve_third(s->x, s->y + offset, slopes + offset, s->nx,
                                s->linear_extrapolate, x);
}

/* The curve below z's pair (the end pair beyond the curves) and z's weight
 * between it and the next. */
static int pair_about(const hx_spline *s, double z, double *dz, double *w)
{
    int j = 0;
    while (j < s->nz - 2 && z >= s->z[j + 1])
        ++j;
    *dz = s->z[j + 1] - s->z[j], *w = (z - s->z[j]) / *dz;
    return j;
}

void hx_spline_surface(const hx_spline *s, hx_spline_method method, double x, double z,
                       double d[6])
{
    const double *slopes = slopes_of(s, method);
    double a[3];
    if (s->nz == 1) {
        curve(s, slopes, 0, x, a);
        d[0] = a[0], d[1] = a[1], d[2] = 0.0, d[3] = a[2], d[4] = 0.0, d[5] = 0.0;
        return;
    }
    double dz, w, b[3];
    const int j = pair_about(s, z, &dz, &w);
    curve(s, slopes, j, x, a);
    curve(s, slopes, j + 1, x, b);
    d[0] = a[0] + w * (b[0] - a[0]);
    d[1] = a[1] + w * (b[1] - a[1]);
    d[2] = (b[0] - a[0]) / dz;
    d[3] = a[2] + w * (b[2] - a[2]);
    d[4] = (b[1] - a[1]) / dz;
    d[5] = 0.0;
}

void hx_spline_surface_third(const hx_spline *s, hx_spline_method method, double x, double z,
                             double d[2])
{
    const double *slopes = slopes_of(s, method);
    if (s->nz == 1) {
        d[0] = curve_third(s, slopes, 0, x), d[1] = 0.0;
        return;
    }
    double dz, w, a[3], b[3];
    const int j = pair_about(s, z, &dz, &w);
    const double a3 = curve_third(s, slopes, j, x), b3 = curve_third(s, slopes, j + 1, x);
    curve(s, slopes, j, x, a);
    curve(s, slopes, j + 1, x, b);
    d[0] = a3 + w * (b3 - a3);
    d[1] = (b[2] - a[2]) / dz;
}
