/* The serial vector's operations (vector_ops.h). Each keeps SUNDIALS'
 * arithmetic element by element (the same products and sums in the same
 * order, never contracted into fused multiply-adds: CMakeLists.txt), so that
 * CVODE takes the same steps; tests/test_vector_ops.c compares every one with
 * SUNDIALS' own, bit for bit (a NaN's sign apart), aliased and not. */
#include "sim/ode/vector_ops.h"

#include <math.h>

#define DATA(v) NV_DATA_S(v)
#define LENGTH(v) NV_LENGTH_S(v)

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

static sunrealtype wrms_norm(N_Vector x, N_Vector w)
{
    return hx_wrms_norm(DATA(x), DATA(w), LENGTH(x));
}

/* z = a x + b y. SUNDIALS rounds a (x - y) and c v1 + v2 (c the coefficient
 * that is not 1) as written, not as a x + b y: the same cases here. */
static void linear_sum(sunrealtype a, N_Vector vx, sunrealtype b, N_Vector vy, N_Vector vz)
{
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx), *y = DATA(vy); /* z may be either */
    double *z = DATA(vz);
    if (a == 1.0 && b == 1.0) {
        for (sunindextype i = 0; i < n; ++i)
            z[i] = x[i] + y[i];
    } else if ((a == 1.0 && b == -1.0) || (a == -1.0 && b == 1.0)) {
        const double *p = a == 1.0 ? x : y, *m = a == 1.0 ? y : x;
        for (sunindextype i = 0; i < n; ++i)
            z[i] = p[i] - m[i];
    } else if (a == 1.0 || b == 1.0) {
        const double c = a == 1.0 ? b : a, *v1 = a == 1.0 ? y : x, *v2 = a == 1.0 ? x : y;
        for (sunindextype i = 0; i < n; ++i)
            z[i] = c * v1[i] + v2[i];
    } else if (a == -1.0 || b == -1.0) {
        const double c = a == -1.0 ? b : a, *v1 = a == -1.0 ? y : x, *v2 = a == -1.0 ? x : y;
        for (sunindextype i = 0; i < n; ++i)
            z[i] = c * v1[i] - v2[i];
    } else if (a == b) {
        for (sunindextype i = 0; i < n; ++i)
            z[i] = a * (x[i] + y[i]);
    } else if (a == -b) {
        for (sunindextype i = 0; i < n; ++i)
            z[i] = a * (x[i] - y[i]);
    } else {
        for (sunindextype i = 0; i < n; ++i)
            z[i] = a * x[i] + b * y[i];
    }
}

static void constant(sunrealtype c, N_Vector vz)
{
    const sunindextype n = LENGTH(vz);
    double *z = DATA(vz);
    for (sunindextype i = 0; i < n; ++i)
        z[i] = c;
}

static void product(N_Vector vx, N_Vector vy, N_Vector vz)
{
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx), *y = DATA(vy);
    double *z = DATA(vz);
    for (sunindextype i = 0; i < n; ++i)
        z[i] = x[i] * y[i];
}

static void quotient(N_Vector vx, N_Vector vy, N_Vector vz)
{
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx), *y = DATA(vy);
    double *z = DATA(vz);
    for (sunindextype i = 0; i < n; ++i)
        z[i] = x[i] / y[i];
}

static void scale(sunrealtype c, N_Vector vx, N_Vector vz)
{
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx);
    double *z = DATA(vz);
    if (c == 1.0) { /* a copy: also what a NaN keeps */
        for (sunindextype i = 0; i < n; ++i)
            z[i] = x[i];
    } else if (c == -1.0) {
        for (sunindextype i = 0; i < n; ++i)
            z[i] = -x[i];
    } else {
        for (sunindextype i = 0; i < n; ++i)
            z[i] = c * x[i];
    }
}

static void absolute(N_Vector vx, N_Vector vz)
{
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx);
    double *z = DATA(vz);
    for (sunindextype i = 0; i < n; ++i)
        z[i] = fabs(x[i]);
}

static void inverse(N_Vector vx, N_Vector vz)
{
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx);
    double *z = DATA(vz);
    for (sunindextype i = 0; i < n; ++i)
        z[i] = 1.0 / x[i];
}

static void add_constant(N_Vector vx, sunrealtype b, N_Vector vz)
{
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx);
    double *z = DATA(vz);
    for (sunindextype i = 0; i < n; ++i)
        z[i] = x[i] + b;
}

static sunrealtype max_norm(N_Vector vx)
{
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx);
    double largest = 0.0;
    for (sunindextype i = 0; i < n; ++i)
        largest = fabs(x[i]) > largest ? fabs(x[i]) : largest;
    return largest;
}

static sunrealtype minimum(N_Vector vx)
{
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx);
    double least = n > 0 ? x[0] : 0.0;
    for (sunindextype i = 1; i < n; ++i)
        least = x[i] < least ? x[i] : least;
    return least;
}

static void compare(sunrealtype c, N_Vector vx, N_Vector vz)
{
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx);
    double *z = DATA(vz);
    for (sunindextype i = 0; i < n; ++i)
        z[i] = fabs(x[i]) >= c ? 1.0 : 0.0;
}

/* z = sum c_k X_k, summed in k's order for each element: what SUNDIALS'
 * does in as many passes over memory as there are vectors. */
static int linear_combination(int count, sunrealtype *c, N_Vector *X, N_Vector vz)
{
    if (count < 1)
        return -1; /* as SUNDIALS' */
    if (count == 1) {
        scale(c[0], X[0], vz);
        return 0;
    }
    if (count == 2) {
        linear_sum(c[0], X[0], c[1], X[1], vz);
        return 0;
    }
    for (int k = 1; k < count; ++k)
        if (X[k] == vz) { /* z among the later terms: SUNDIALS' passes, one by one */
            if (!(X[0] == vz && c[0] == 1.0))
                scale(c[0], X[0], vz);
            for (int j = 1; j < count; ++j)
                linear_sum(c[j], X[j], 1.0, vz, vz);
            return 0;
        }
    const sunindextype n = LENGTH(vz);
    double *z = DATA(vz);
    const int keep = X[0] == vz && c[0] == 1.0;
    for (sunindextype i = 0; i < n; ++i) {
        double sum = keep ? z[i] : c[0] * DATA(X[0])[i];
        for (int k = 1; k < count; ++k)
            sum += c[k] * DATA(X[k])[i];
        z[i] = sum;
    }
    return 0;
}

/* Z_k = a_k x + Y_k for each k (CVODE's update of its history array). */
static int scale_add_multi(int count, sunrealtype *a, N_Vector vx, N_Vector *Y, N_Vector *Z)
{
    if (count < 1)
        return -1; /* as SUNDIALS' */
    if (count == 1) {
        linear_sum(a[0], vx, 1.0, Y[0], Z[0]);
        return 0;
    }
    const sunindextype n = LENGTH(vx);
    const double *x = DATA(vx);
    for (int k = 0; k < count; ++k) {
        const double *y = DATA(Y[k]);
        double *z = DATA(Z[k]);
        for (sunindextype i = 0; i < n; ++i)
            z[i] = a[k] * x[i] + y[i];
    }
    return 0;
}

void hx_vector_ops_install(N_Vector v)
{
    /* clones copy the table */
    N_Vector_Ops ops = v->ops;
    ops->nvlinearsum = linear_sum;
    ops->nvconst = constant;
    ops->nvprod = product;
    ops->nvdiv = quotient;
    ops->nvscale = scale;
    ops->nvabs = absolute;
    ops->nvinv = inverse;
    ops->nvaddconst = add_constant;
    ops->nvmaxnorm = max_norm;
    ops->nvwrmsnorm = wrms_norm;
    ops->nvmin = minimum;
    ops->nvcompare = compare;
    ops->nvlinearcombination = linear_combination;
    ops->nvscaleaddmulti = scale_add_multi;
}
