/*
 * Adaptive Dormand-Prince 5(4): FSAL, PI step-size control, dense output at
 * the output times, and the standard stiffness detection (after Hairer,
 * Norsett and Wanner's DOPRI5).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sim/ode/integration.h"

static const double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
static const double a21 = 1.0 / 5;
static const double a31 = 3.0 / 40, a32 = 9.0 / 40;
static const double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
static const double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                    a54 = -212.0 / 729;
static const double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                    a64 = 49.0 / 176, a65 = -5103.0 / 18656;
static const double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192,
                    a75 = -2187.0 / 6784, a76 = 11.0 / 84;
static const double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                    e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
static const double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                    d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                    d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

static double error_norm(const double *e, const double *y0, const double *y1, int n,
                         double rtol, double atol)
{
    double s = 0.0;
    for (int i = 0; i < n; ++i) {
        const double sk = atol + rtol * fmax(fabs(y0[i]), fabs(y1[i]));
        s += (e[i] / sk) * (e[i] / sk);
    }
    return sqrt(s / n);
}

/* Hairer's starting step: an Euler trial scaled to the tolerance. */
static int initial_step(hx_integration *r, double t, const double *y, const double *f0, double *work,
                        double *h_out)
{
    const hx_ode *o = r->ode;
    const int n = o->n;
    const double rtol = r->opt->rtol, atol = r->opt->atol;
    double dnf = 0.0, dny = 0.0;
    for (int i = 0; i < n; ++i) {
        const double sk = atol + rtol * fabs(y[i]);
        dnf += (f0[i] / sk) * (f0[i] / sk);
        dny += (y[i] / sk) * (y[i] / sk);
    }
    double h = (dnf <= 1e-10 || dny <= 1e-10) ? 1e-6 : 0.01 * sqrt(dny / dnf);
    const double span = r->opt->t_end - t;
    if (r->opt->max_step > 0.0)
        h = fmin(h, r->opt->max_step);
    h = fmin(h, span);
    double *y1 = work, *f1 = work + n;
    for (int i = 0; i < n; ++i)
        y1[i] = y[i] + h * f0[i];
    if (hx_integration_evaluate(r, t + h, y1, f1) != 0)
        return -1;
    double der2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double sk = atol + rtol * fabs(y[i]);
        der2 += ((f1[i] - f0[i]) / sk) * ((f1[i] - f0[i]) / sk);
    }
    der2 = sqrt(der2 / n) / h;
    const double der12 = fmax(fabs(der2), sqrt(dnf / n));
    const double h1 = der12 <= 1e-15 ? fmax(1e-6, fabs(h) * 1e-3) : pow(0.01 / der12, 0.2);
    h = fmin(100.0 * fabs(h), h1);
    if (r->opt->max_step > 0.0)
        h = fmin(h, r->opt->max_step);
    *h_out = fmin(h, span);
    return 0;
}

hx_status hx_integrate_dopri5(hx_integration *r, double t0, double *y)
{
    const hx_ode *o = r->ode;
    const hx_integrator_options *opt = r->opt;
    const int n = o->n;
    const double safe = 0.9, beta = 0.04, expo1 = 0.2 - beta * 0.75;
    const double facc1 = 1.0 / 0.2, facc2 = 1.0 / 10.0;
    double *mem = malloc(sizeof(double) * 16u * (size_t)n);
    if (mem == NULL)
        return HX_INTEGRATION_FAILED;
    double *k1 = mem, *k2 = k1 + n, *k3 = k2 + n, *k4 = k3 + n, *k5 = k4 + n, *k6 = k5 + n,
           *k7 = k6 + n, *y1 = k7 + n, *ysti = y1 + n, *err = ysti + n, *cont = err + n,
           *yout = cont + 5 * n;
    hx_status status = HX_INTEGRATION_OK;
    double t = t0, h = opt->step, facold = 1e-4;
    int reject = 0, stiff_count = 0, nonstiff_count = 0;
    if (hx_integration_evaluate(r, t, y, k1) != 0) {
        free(mem);
        return HX_INTEGRATION_FAILED;
    }
    if (!(h > 0.0) && initial_step(r, t, y, k1, y1, &h) != 0) {
        free(mem);
        return HX_INTEGRATION_FAILED;
    }
    const double hmin = 1e-14 * fmax(fabs(t0), fabs(opt->t_end));
    while (t < opt->t_end) {
        if (opt->max_steps > 0 && r->stats->steps + r->stats->rejected >= opt->max_steps) {
            status = HX_INTEGRATION_TOO_MANY_STEPS;
            break;
        }
        if (h < hmin || !isfinite(h)) {
            status = HX_INTEGRATION_STEP_TOO_SMALL;
            break;
        }
        int last = 0;
        if (t + 1.01 * h >= opt->t_end) {
            h = opt->t_end - t;
            last = 1;
        }
        int failed = 0;
#define STAGE(out, cx, expr)                                                                  \
    do {                                                                                      \
        for (int i = 0; i < n; ++i)                                                           \
            y1[i] = y[i] + h * (expr);                                                        \
        failed = failed || hx_integration_evaluate(r, t + (cx) * h, y1, out) != 0;                           \
    } while (0)
        STAGE(k2, c2, a21 * k1[i]);
        if (!failed) STAGE(k3, c3, a31 * k1[i] + a32 * k2[i]);
        if (!failed) STAGE(k4, c4, a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
        if (!failed) STAGE(k5, c5, a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
        if (!failed) {
            STAGE(k6, 1.0, a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
            memcpy(ysti, y1, sizeof(double) * (size_t)n);
        }
        if (!failed)
            STAGE(k7, 1.0, a71 * k1[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
#undef STAGE
        if (failed) {
            status = HX_INTEGRATION_FAILED;
            break;
        }
        for (int i = 0; i < n; ++i)
            err[i] = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] +
                          e7 * k7[i]);
        const double e = error_norm(err, y, y1, n, opt->rtol, opt->atol);
        if (!isfinite(e)) {
            h *= 0.1; /* a non-finite trial: shrink hard and retry */
            r->stats->rejected++;
            reject = 1;
            continue;
        }
        const double fac11 = pow(e, expo1);
        double fac = fac11 / pow(facold, beta);
        fac = fmax(facc2, fmin(facc1, fac / safe));
        double hnew = h / fac;
        if (e > 1.0) {
            hnew = h / fmin(facc1, fac11 / safe);
            r->stats->rejected++;
            reject = 1;
            h = hnew;
            continue;
        }
        /* accepted */
        facold = fmax(e, 1e-4);
        r->stats->steps++;
        double stnum = 0.0, stden = 0.0;
        for (int i = 0; i < n; ++i) {
            stnum += (k7[i] - k6[i]) * (k7[i] - k6[i]);
            stden += (y1[i] - ysti[i]) * (y1[i] - ysti[i]);
        }
        if (stden > 0.0 && h * sqrt(stnum / stden) > 3.25) {
            nonstiff_count = 0;
            if (++stiff_count == 15 && !r->stats->stiff) {
                r->stats->stiff = 1;
                r->stats->t_stiff = t;
            }
        } else if (++nonstiff_count == 6) {
            stiff_count = 0;
        }
        /* dense output coefficients over [t, t + h] */
        double *r1 = cont, *r2 = cont + n, *r3 = cont + 2 * n, *r4 = cont + 3 * n, *r5 = cont + 4 * n;
        for (int i = 0; i < n; ++i) {
            r1[i] = y[i];
            r2[i] = y1[i] - y[i];
            r3[i] = h * k1[i] - r2[i];
            r4[i] = r2[i] - h * k7[i] - r3[i];
            r5[i] = h * (d1 * k1[i] + d3 * k3[i] + d4 * k4[i] + d5 * k5[i] + d6 * k6[i] +
                         d7 * k7[i]);
        }
        const double t1 = last ? opt->t_end : t + h;
        int stop = 0;
        if (opt->output != NULL) {
            if (opt->output_interval > 0.0) {
                double to;
                while (!stop && (to = hx_integration_next_output(r)) <= t1 + 1e-12 * fabs(h)) {
                    const double th = (to - t) / h;
                    const double th1 = 1.0 - th;
                    for (int i = 0; i < n; ++i)
                        yout[i] = r1[i] + th * (r2[i] + th1 * (r3[i] + th * (r4[i] + th1 * r5[i])));
                    if (o->project != NULL && o->project(o->ctx, to, yout) < 0) {
                        status = HX_INTEGRATION_FAILED;
                        stop = 1;
                        break;
                    }
                    stop = opt->output(o->ctx, to, yout) != 0;
                    r->outputs++;
                }
            }
        }
        memcpy(y, y1, sizeof(double) * (size_t)n);
        t = t1;
        r->stats->t_reached = t;
        r->stats->last_step = h;
        memcpy(k1, k7, sizeof(double) * (size_t)n); /* first same as last */
        if (o->project != NULL) {
            const int changed = o->project(o->ctx, t, y);
            if (changed < 0) {
                status = HX_INTEGRATION_FAILED;
                break;
            }
            if (changed > 0 && !last && hx_integration_evaluate(r, t, y, k1) != 0) {
                status = HX_INTEGRATION_FAILED;
                break;
            }
        }
        if (!hx_integration_finite_and_bounded(r, y)) {
            status = HX_INTEGRATION_UNSTABLE;
            break;
        }
        if (status != HX_INTEGRATION_OK)
            break;
        if (o->accept != NULL && o->accept(o->ctx, t, y) != 0) {
            status = HX_INTEGRATION_FAILED;
            break;
        }
        if (opt->output != NULL && opt->output_interval <= 0.0)
            stop = opt->output(o->ctx, t, y) != 0;
        if (stop) {
            status = HX_INTEGRATION_STOPPED;
            break;
        }
        if (last)
            break;
        if (opt->max_step > 0.0)
            hnew = fmin(hnew, opt->max_step);
        if (reject)
            hnew = fmin(hnew, h);
        reject = 0;
        h = hnew;
    }
    free(mem);
    return status;
}

