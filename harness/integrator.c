/* Explicit integrators (integrator.h). */
#include "integrator.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void hx_integrator_defaults(hx_integrator_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->method = HX_METHOD_RK4;
    opt->rtol = 1e-6;
    opt->atol = 1e-9;
}

const char *hx_method_name(hx_method method)
{
    switch (method) {
    case HX_METHOD_EULER: return "euler";
    case HX_METHOD_SYMPLECTIC_EULER: return "symplectic-euler";
    case HX_METHOD_RK4: return "rk4";
    case HX_METHOD_DOPRI5: return "dopri5";
    }
    return "?";
}

int hx_method_parse(const char *name, hx_method *method)
{
    for (int k = HX_METHOD_EULER; k <= HX_METHOD_DOPRI5; ++k)
        if (strcmp(name, hx_method_name((hx_method)k)) == 0) {
            *method = (hx_method)k;
            return 0;
        }
    return -1;
}

int hx_method_order(hx_method method)
{
    switch (method) {
    case HX_METHOD_EULER:
    case HX_METHOD_SYMPLECTIC_EULER: return 1;
    case HX_METHOD_RK4: return 4;
    case HX_METHOD_DOPRI5: return 5;
    }
    return 0;
}

const char *hx_status_text(hx_status status)
{
    switch (status) {
    case HX_INTEGRATION_OK: return "finished";
    case HX_INTEGRATION_FAILED: return "failed (the model reported an error)";
    case HX_INTEGRATION_UNSTABLE: return "unstable (the state diverged)";
    case HX_INTEGRATION_STEP_TOO_SMALL: return "step size too small";
    case HX_INTEGRATION_TOO_MANY_STEPS: return "too many steps";
    case HX_INTEGRATION_STOPPED: return "stopped";
    }
    return "?";
}

static double norm(const double *y, int n)
{
    double s = 0.0;
    for (int k = 0; k < n; ++k)
        s += y[k] * y[k];
    return sqrt(s);
}

typedef struct run {
    const hx_ode *ode;
    const hx_integrator_options *opt;
    hx_integrator_stats *stats;
    double limit; /* unstable above this norm */
    double t0;
    long outputs; /* output times emitted: the next is t0 + (outputs + 1) interval */
} run;

/* The next output time (counted, not summed, so that the last one lands on
 * the end however many there are). */
static double next_output(const run *r)
{
    const double t = r->t0 + (double)(r->outputs + 1) * r->opt->output_interval;
    return fabs(t - r->opt->t_end) <= 1e-9 * r->opt->output_interval ? r->opt->t_end : t;
}

static int evaluate(run *r, double t, const double *y, double *ydot)
{
    r->stats->evaluations++;
    return r->ode->rhs(r->ode->ctx, t, y, ydot);
}

/* Positions and velocities finite and not grown without bound (the other
 * components, such as accumulated work, may grow legitimately). */
static int finite_and_bounded(const run *r, const double *y)
{
    const int m = r->ode->nq + r->ode->nu > 0 ? r->ode->nq + r->ode->nu : r->ode->n;
    if (!isfinite(norm(y, r->ode->n)))
        return 0;
    return norm(y, m) <= r->limit;
}

/* ---- fixed steps ----------------------------------------------------------------- */

static int fixed_step(run *r, hx_method method, double t, double h, double *y, double *work)
{
    const hx_ode *o = r->ode;
    const int n = o->n;
    double *k1 = work, *k2 = k1 + n, *k3 = k2 + n, *k4 = k3 + n, *tmp = k4 + n;
    if (evaluate(r, t, y, k1) != 0)
        return -1;
    switch (method) {
    case HX_METHOD_EULER:
        for (int i = 0; i < n; ++i)
            y[i] += h * k1[i];
        return 0;
    case HX_METHOD_SYMPLECTIC_EULER:
        /* velocities first, then positions with the new velocities */
        for (int i = o->nq; i < n; ++i)
            y[i] += h * k1[i];
        o->advance(o->ctx, y, h);
        return 0;
    case HX_METHOD_RK4:
        for (int i = 0; i < n; ++i)
            tmp[i] = y[i] + 0.5 * h * k1[i];
        if (evaluate(r, t + 0.5 * h, tmp, k2) != 0)
            return -1;
        for (int i = 0; i < n; ++i)
            tmp[i] = y[i] + 0.5 * h * k2[i];
        if (evaluate(r, t + 0.5 * h, tmp, k3) != 0)
            return -1;
        for (int i = 0; i < n; ++i)
            tmp[i] = y[i] + h * k3[i];
        if (evaluate(r, t + h, tmp, k4) != 0)
            return -1;
        for (int i = 0; i < n; ++i)
            y[i] += h * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]) / 6.0;
        return 0;
    default:
        return -1;
    }
}

static hx_status integrate_fixed(run *r, double t0, double *y)
{
    const hx_ode *o = r->ode;
    const hx_integrator_options *opt = r->opt;
    const double span = opt->t_end - t0;
    if (!(opt->step > 0.0) || !(span >= 0.0))
        return HX_INTEGRATION_FAILED;
    const long nsteps = span > 0.0 ? (long)ceil(span / opt->step - 1e-9) : 0;
    const double h = nsteps > 0 ? span / (double)nsteps : opt->step;
    long every = opt->output_interval > 0.0 ? lround(opt->output_interval / h) : 1;
    if (every < 1)
        every = 1;
    double *work = malloc(sizeof(double) * 5u * (size_t)o->n);
    if (work == NULL)
        return HX_INTEGRATION_FAILED;
    hx_status status = HX_INTEGRATION_OK;
    r->stats->last_step = h;
    for (long k = 0; k < nsteps; ++k) {
        if (opt->max_steps > 0 && k >= opt->max_steps) {
            status = HX_INTEGRATION_TOO_MANY_STEPS;
            break;
        }
        const double t = t0 + (double)k * h;
        if (fixed_step(r, opt->method, t, h, y, work) != 0) {
            status = HX_INTEGRATION_FAILED;
            break;
        }
        const double t1 = k + 1 == nsteps ? opt->t_end : t0 + (double)(k + 1) * h;
        if (o->project != NULL && o->project(o->ctx, t1, y) < 0) {
            status = HX_INTEGRATION_FAILED;
            break;
        }
        r->stats->steps++;
        r->stats->t_reached = t1;
        if (!finite_and_bounded(r, y)) {
            status = HX_INTEGRATION_UNSTABLE;
            break;
        }
        if (opt->output != NULL && ((k + 1) % every == 0 || k + 1 == nsteps) &&
            opt->output(o->ctx, t1, y) != 0) {
            status = HX_INTEGRATION_STOPPED;
            break;
        }
    }
    free(work);
    return status;
}

/* ---- Dormand-Prince 5(4) ---------------------------------------------------------------- */

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
static int initial_step(run *r, double t, const double *y, const double *f0, double *work,
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
    if (evaluate(r, t + h, y1, f1) != 0)
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

static hx_status integrate_dopri5(run *r, double t0, double *y)
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
    if (evaluate(r, t, y, k1) != 0) {
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
        failed = failed || evaluate(r, t + (cx) * h, y1, out) != 0;                           \
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
                while (!stop && (to = next_output(r)) <= t1 + 1e-12 * fabs(h)) {
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
            if (changed > 0 && !last && evaluate(r, t, y, k1) != 0) {
                status = HX_INTEGRATION_FAILED;
                break;
            }
        }
        if (!finite_and_bounded(r, y)) {
            status = HX_INTEGRATION_UNSTABLE;
            break;
        }
        if (status != HX_INTEGRATION_OK)
            break;
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

hx_status hx_integrate(const hx_ode *ode, double t0, double *y, const hx_integrator_options *opt,
                       hx_integrator_stats *stats)
{
    memset(stats, 0, sizeof *stats);
    stats->t_reached = t0;
    run r = {ode, opt, stats, 0.0, t0, 0};
    const int m = ode->nq + ode->nu > 0 ? ode->nq + ode->nu : ode->n;
    r.limit = (opt->growth_limit > 0.0 ? opt->growth_limit : 1e12) * (1.0 + norm(y, m));
    if (opt->method == HX_METHOD_SYMPLECTIC_EULER && ode->advance == NULL)
        return HX_INTEGRATION_FAILED;
    if (opt->method == HX_METHOD_DOPRI5)
        return integrate_dopri5(&r, t0, y);
    return integrate_fixed(&r, t0, y);
}
