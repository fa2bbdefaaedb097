/* The weighted root-mean-square norm with four partial sums (wrms_norm.h). */
#include "sim/ode/wrms_norm.h"

#include <math.h>

double hx_wrms_norm(const double *x, const double *w, sunindextype n)
{
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    sunindextype i = 0;
    for (; i + 4 <= n; i += 4) {
        const double a = x[i] * w[i], b = x[i + 1] * w[i + 1];
        const double c = x[i + 2] * w[i + 2], d = x[i + 3] * w[i + 3];
        s0 += a * a, s1 += b * b, s2 += c * c, s3 += d * d;
    }
    for (; i < n; ++i)
        s0 += (x[i] * w[i]) * (x[i] * w[i]);
    return n > 0 ? sqrt(((s0 + s1) + (s2 + s3)) / (double)n) : 0.0;
}

static sunrealtype wrms_norm_op(N_Vector x, N_Vector w)
{
    return hx_wrms_norm(NV_DATA_S(x), NV_DATA_S(w), NV_LENGTH_S(x));
}

void hx_wrms_norm_install(N_Vector v)
{
    v->ops->nvwrmsnorm = wrms_norm_op; /* clones copy the table */
}
