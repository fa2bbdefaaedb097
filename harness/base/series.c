/* POLY, CHEBY, FORCOS, FORSIN and SHF (series.h). */
#include "base/series.h"

#include <math.h>

double hx_poly(double x, double x0, const double *a, int n, int iord)
{
    const double u = x - x0;
    double sum = 0.0;
    for (int j = n - 1; j >= iord; --j) { /* Horner on the derivative's coefficients */
        const double factor = iord == 0 ? 1.0 : iord == 1 ? j : (double)j * (j - 1);
        sum = sum * u + factor * a[j];
    }
    return sum;
}

void hx_poly_coefficient_partials(double x, double x0, int n, double *d)
{
    const double u = x - x0;
    double power = 1.0;
    for (int j = 0; j < n; ++j, power *= u)
        d[j] = power;
}

double hx_cheby(double x, double x0, const double *a, int n, int iord)
{
    const double u = x - x0;
    double t[3] = {1.0, 0.0, 0.0}, t1[3] = {u, 1.0, 0.0}; /* T, T', T'' */
    double sum = a[0] * t[iord] + (n > 1 ? a[1] * t1[iord] : 0.0);
    for (int j = 2; j < n; ++j) {
        const double next[3] = {2.0 * u * t1[0] - t[0], 2.0 * t1[0] + 2.0 * u * t1[1] - t[1],
                                4.0 * t1[1] + 2.0 * u * t1[2] - t[2]};
        for (int i = 0; i < 3; ++i)
            t[i] = t1[i], t1[i] = next[i];
        sum += a[j] * t1[iord];
    }
    return sum;
}

void hx_cheby_coefficient_partials(double x, double x0, int n, double *d)
{
    const double u = x - x0;
    for (int j = 0; j < n; ++j)
        d[j] = j == 0 ? 1.0 : j == 1 ? u : 2.0 * u * d[j - 1] - d[j - 2];
}

double hx_fourier(int cosine, double x, double x0, double w, const double *a, int n, int iord)
{
    double sum = iord == 0 ? a[0] : 0.0;
    for (int j = 1; j < n; ++j) {
        const double angle = j * w * (x - x0), c = cos(angle), s = sin(angle), f = j * w;
        const double term = cosine ? (iord == 0 ? c : iord == 1 ? -f * s : -f * f * c)
                                   : (iord == 0 ? s : iord == 1 ? f * c : -f * f * s);
        sum += a[j] * term;
    }
    return sum;
}

void hx_fourier_partials(int cosine, double x, double x0, double w, const double *a, int n,
                         double *d_dw, double *d_da)
{
    const double u = x - x0;
    double dw = 0.0;
    d_da[0] = 1.0;
    for (int j = 1; j < n; ++j) {
        const double angle = j * w * u, c = cos(angle), s = sin(angle);
        d_da[j] = cosine ? c : s;
        dw += a[j] * j * u * (cosine ? -s : c); /* d angle / dw = j u */
    }
    *d_dw = dw;
}

double hx_shf(double x, double x0, double a, double w, double phi, double b, int iord)
{
    const double angle = w * (x - x0) - phi;
    return iord == 0 ? a * sin(angle) + b
           : iord == 1 ? a * w * cos(angle)
                       : -a * w * w * sin(angle);
}

void hx_shf_partials(double x, double x0, double a, double w, double phi, double b, double d[6])
{
    (void)b;
    const double u = x - x0, angle = w * u - phi, c = cos(angle);
    d[0] = a * w * c;
    d[1] = -a * w * c;
    d[2] = sin(angle);
    d[3] = a * u * c;
    d[4] = -a * c;
    d[5] = 1.0;
}
