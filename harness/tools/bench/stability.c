/* Stability limits of the integrators (stability.h). */
#include "tools/bench/stability.h"

#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- each method's amplification of y' = lambda y over one step ------------------- */

static double amplification(hx_method method, double complex z)
{
    switch (method) {
    case HX_METHOD_EULER:
        return cabs(1.0 + z);
    case HX_METHOD_RK4:
        return cabs(1.0 + z * (1.0 + z / 2.0 * (1.0 + z / 3.0 * (1.0 + z / 4.0))));
    case HX_METHOD_DOPRI5: /* the fifth-order solution it propagates */
    case HX_METHOD_DOPRI5_ARKODE:
        return cabs(1.0 + z * (1.0 + z / 2.0 * (1.0 + z / 3.0 * (1.0 + z / 4.0 *
                                                            (1.0 + z / 5.0 * (1.0 + z / 5.0))))));
    case HX_METHOD_SYMPLECTIC_EULER: {
        /* on x'' = -w^2 x - 2 a x' (lambda = -a +- i sqrt(w^2 - a^2), w = |lambda|):
         * v1 = v + h (-w^2 x - 2 a v), x1 = x + h v1; the spectral radius of that map */
        const double w2 = creal(z) * creal(z) + cimag(z) * cimag(z), a = -creal(z);
        const double m11 = 1.0 - w2, m12 = 1.0 - 2.0 * a, m21 = -w2, m22 = 1.0 - 2.0 * a;
        const double tr = m11 + m22, det = m11 * m22 - m12 * m21;
        const double disc = tr * tr / 4.0 - det;
        if (disc >= 0.0)
            return fmax(fabs(tr / 2.0 + sqrt(disc)), fabs(tr / 2.0 - sqrt(disc)));
        return sqrt(fabs(det));
    }
    case HX_METHOD_BDF: /* not reached: hx_stable_step answers first */
        return 0.0;
    }
    return INFINITY;
}

double hx_stable_step(hx_method method, double re, double im)
{
    const double magnitude = hypot(re, im);
    /* BDF: A-stable at orders 1 and 2, A(alpha)-stable above (alpha = 86, 73
     * and 52 degrees at orders 3 to 5); on a lightly damped mode CVODE's
     * stability-limit detection lowers the order, not the step (bdf.c) */
    if (!(magnitude > 0.0) || method == HX_METHOD_BDF)
        return INFINITY;
    const double complex unit = (re + I * im) / magnitude;
    const double tolerance = 1e-12;
    /* the first x = h |lambda| where the amplification exceeds 1, then bisection */
    const double dx = 1e-3;
    double x = dx;
    for (; x <= 20.0; x += dx)
        if (amplification(method, x * unit) > 1.0 + tolerance)
            break;
    if (x > 20.0)
        return INFINITY;
    double lo = x - dx, hi = x;
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (amplification(method, mid * unit) > 1.0 + tolerance)
            hi = mid;
        else
            lo = mid;
    }
    return lo / magnitude;
}

/* ---- the fastest mode -------------------------------------------------------------- */

typedef struct jv_context {
    const hx_dynamics *d;
    hx_dynamics_data *dd;
    double t;
    const double *y;
    double *plus, *minus, *fplus, *fminus;
    int m; /* positions, velocities, element and Control_Diff states: the dynamics proper */
    double scale;
    int evaluations;
} jv_context;

/* out = J v on the first m components, by a central difference. */
static int jacobian_times(jv_context *c, const double *v, double *out)
{
    const int n = c->d->n, m = c->m;
    double norm = 0.0;
    for (int i = 0; i < m; ++i)
        norm += v[i] * v[i];
    norm = sqrt(norm);
    if (!(norm > 0.0)) {
        memset(out, 0, sizeof(double) * (size_t)m);
        return 0;
    }
    const double eps = 1e-6 * c->scale / norm;
    memcpy(c->plus, c->y, sizeof(double) * (size_t)n);
    memcpy(c->minus, c->y, sizeof(double) * (size_t)n);
    for (int i = 0; i < m; ++i)
        c->plus[i] += eps * v[i], c->minus[i] -= eps * v[i];
    c->evaluations += 2;
    if (hx_dynamics_rhs(c->d, c->dd, c->t, c->plus, c->fplus) != 0 ||
        hx_dynamics_rhs(c->d, c->dd, c->t, c->minus, c->fminus) != 0)
        return -1;
    for (int i = 0; i < m; ++i)
        out[i] = (c->fplus[i] - c->fminus[i]) / (2.0 * eps);
    return 0;
}

static double dot(const double *a, const double *b, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; ++i)
        s += a[i] * b[i];
    return s;
}

static double normalize(double *v, int n)
{
    const double norm = sqrt(dot(v, v, n));
    if (norm > 0.0)
        for (int i = 0; i < n; ++i)
            v[i] /= norm;
    return norm;
}

int hx_estimate_stability(const hx_dynamics *d, double t, const double *y, hx_stability *out,
                          hx_message *msg)
{
    memset(out, 0, sizeof *out);
    /* the element states follow the velocities, the Control_Diff states and an
     * acceleration motion's follow them (docs/architecture.md, the layout of y):
     * bristles that slide fast,
     * or a filter's fast state, are a model's fastest mode; only the work
     * accumulators, which nothing reads, are left out */
    const int n = d->n, m = d->load_work;
    hx_dynamics_data dd;
    if (hx_dynamics_data_init(&dd, d, msg) != 0)
        return -1;
    double *work = calloc(4 * (size_t)n + 5 * (size_t)m + 8, sizeof(double));
    if (work == NULL) {
        hx_dynamics_data_free(&dd);
        return hx_fail(msg, "out of memory");
    }
    jv_context c = {d, &dd, t, y, work, work + n, work + 2 * n, work + 3 * n, m, 0.0, 0};
    double *v = work + 4 * n, *w = v + m, *w2 = w + m, *q2 = w2 + m, *tmp = q2 + m;
    for (int i = 0; i < m; ++i)
        c.scale = fmax(c.scale, fabs(y[i]));
    c.scale = fmax(c.scale, 1.0);
    int status = 0;
    unsigned seed = 12345u;
    for (int i = 0; i < m; ++i) { /* a start with some of every mode in it */
        seed = seed * 1664525u + 1013904223u;
        v[i] = ((seed >> 8) & 0xffff) / 65535.0 - 0.5;
    }
    normalize(v, m);
    double previous = 0.0, estimate = 0.0;
    for (int iteration = 0; iteration < 60 && status == 0; ++iteration) {
        if (jacobian_times(&c, v, w) != 0 || jacobian_times(&c, w, tmp) != 0) {
            status = -1;
            break;
        }
        estimate = sqrt(normalize(tmp, m)); /* |lambda|^2 of the dominant pair */
        memcpy(v, tmp, sizeof(double) * (size_t)m);
        if (!(estimate > 0.0))
            break; /* J = 0: no dynamics to limit the step */
        if (iteration > 5 && fabs(estimate - previous) <= 1e-4 * estimate)
            break;
        previous = estimate;
    }
    if (status == 0 && estimate > 0.0) {
        /* Arnoldi on span{v, J v}: the 2x2 projection holds the pair */
        double h11, h12, h21, h22;
        if (jacobian_times(&c, v, w) != 0)
            status = -1;
        if (status == 0) {
            h11 = dot(v, w, m);
            for (int i = 0; i < m; ++i)
                w2[i] = w[i] - h11 * v[i];
            h21 = normalize(w2, m);
            if (h21 <= 1e-8 * fabs(h11)) { /* a real eigenvalue */
                out->re = h11, out->im = 0.0;
            } else if (jacobian_times(&c, w2, q2) != 0) {
                status = -1;
            } else {
                h12 = dot(v, q2, m), h22 = dot(w2, q2, m);
                const double half = 0.5 * (h11 + h22), det = h11 * h22 - h12 * h21;
                const double disc = half * half - det;
                if (disc < 0.0) {
                    out->re = half, out->im = sqrt(-disc);
                } else { /* two real ones: the larger in magnitude */
                    const double a = half + sqrt(disc), b = half - sqrt(disc);
                    out->re = fabs(a) >= fabs(b) ? a : b, out->im = 0.0;
                }
            }
        }
    }
    free(work);
    if (status != 0) {
        hx_fail(msg, "the right-hand side failed while linearizing: %s", dd.message);
        hx_dynamics_data_free(&dd);
        return -1;
    }
    hx_dynamics_data_free(&dd);
    out->magnitude = hypot(out->re, out->im);
    /* central differences are good to about 1e-6 of |lambda|: a real or an
     * imaginary part below that is their noise (an undamped mode must not
     * come out slightly growing, nor a damped one slightly oscillating) */
    if (fabs(out->re) < 1e-5 * out->magnitude)
        out->re = 0.0;
    if (fabs(out->im) < 1e-5 * out->magnitude)
        out->im = 0.0;
    out->evaluations = c.evaluations;
    for (int k = 0; k < HX_METHOD_COUNT; ++k)
        out->max_step[k] = hx_stable_step((hx_method)k, out->re, out->im);
    return 0;
}

void hx_stability_text(const hx_stability *s, char *text, size_t size)
{
    int len = snprintf(text, size, "fastest mode lambda = %.4g %c %.4gi (|lambda| = %.4g); largest"
                       " stable step:", s->re, '+', s->im, s->magnitude);
    for (int k = 0; k < HX_METHOD_COUNT && len > 0 && (size_t)len < size; ++k) {
        const double h = s->max_step[k];
        len += snprintf(text + len, size - (size_t)len, "%s %s ", k ? "," : "",
                        hx_method_name((hx_method)k));
        if (isinf(h))
            len += snprintf(text + len, size - (size_t)len, "any");
        else if (h * s->magnitude < 1e-3) /* on the imaginary axis but for rounding */
            len += snprintf(text + len, size - (size_t)len, "none (grows at any step)");
        else
            len += snprintf(text + len, size - (size_t)len, "%.3g", h);
    }
}
