/*
 * tp_step_cache.c -- test user library (GFOSUB, Force_Vector_TwoBody).
 *
 * FAULTY ON PURPOSE: "caches only across time steps". The stiffness of
 * tp_good_sysfnc.c plus a damping force from a rate estimated across time
 * steps:
 *     F_k = -K_k d_k - C_k (d_k - d_prev_k) / (time - t_prev)
 *                                   when t_prev is set and time > t_prev,
 *     F_k = -K_k d_k                otherwise,
 * with K = (1000, 2000, 3000, 50, 60, 70), C = (1, 2, 3, 0.1, 0.2, 0.3),
 * d = (DX, DY, DZ, AX, AY, AZ), USER(i_marker, j_marker). It reads only
 * DX..DZ (I,J,J) and AX..AZ (I,J) through c_sysfnc: six queries, the same in
 * both passes.
 * Static (d_prev, t_prev) (the previous step) and (d_last, t_last) (the step
 * being taken), both initially "never". On an ordinary call (iflag == 0 and
 * dflag == 0) whose time is strictly later than t_last, it FIRST shifts
 * (d_prev, t_prev) <- (d_last, t_last) and sets (d_last, t_last) <- (d, time),
 * then computes the force. Calls at t_last's time change nothing, and neither
 * do dflag or iflag calls. Two calls in a row at the same state and time
 * therefore give identical forces; only the order of calls across times
 * reveals the hidden state (the force at a given state and time depends on
 * which earlier time was called last). A component that would not be finite
 * is written as 0.
 *
 * A correct verifier must FAIL this library (element 1, GFOSUB) for hidden
 * state: the force at the same state and time depends on which calls came
 * before.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "usrsub/solver_abi.h"

static const double K[6] = {1000.0, 2000.0, 3000.0, 50.0, 60.0, 70.0};
static const double C[6] = {1.0, 2.0, 3.0, 0.1, 0.2, 0.3};

/* The hidden state: the previous step and the step being taken. */
static double d_prev[6], t_prev;
static int have_prev = 0; /* 0: t_prev is "never" */
static double d_last[6], t_last;
static int have_last = 0; /* 0: t_last is "never" */

/* par[k] as a marker id; 0 when it is missing or not a positive integer. */
static int marker_id(const double *par, int npar, int k)
{
    if (k >= npar) return 0;
    double v = par[k];
    if (!isfinite(v) || v != floor(v) || v < 1.0 || v > (double)INT_MAX) return 0;
    return (int)v;
}

/* One scalar measure; 0 when the host refuses it. */
static double measure(const char *fnc, const int *ipar, int nsize)
{
    double value = 0.0;
    int errflg = 0;
    c_sysfnc(fnc, ipar, nsize, &value, &errflg);
    return (errflg == 0 && isfinite(value)) ? value : 0.0;
}

USRSUB_EXPORT void STDCALL GFOSUB(int *id, double *time, double *par, int *npar,
                                  int *dflag, int *iflag, double *result)
{
    memset(result, 0, 6 * sizeof(double));

    int i_mk = marker_id(par, *npar, 0);
    int j_mk = marker_id(par, *npar, 1);
    if (*npar != 2 || i_mk == 0 || j_mk == 0) {
        char msg[200];
        snprintf(msg, sizeof msg,
                 "tp_step_cache: element %d: expected USER(i_marker, j_marker) with two "
                 "positive integer ids, got %d value(s)", *id, *npar);
        c_errmes(1, msg, *id, "STOP");
        return;
    }

    const int ij[2] = {i_mk, j_mk};
    const int ijj[3] = {i_mk, j_mk, j_mk};
    static const char *const dname[6] = {"DX", "DY", "DZ", "AX", "AY", "AZ"};

    double d[6];
    for (int k = 0; k < 3; ++k) d[k] = measure(dname[k], ijj, 3);
    for (int k = 3; k < 6; ++k) d[k] = measure(dname[k], ij, 2);

    /* first: a new time step shifts the history (ordinary calls only) */
    double t = *time;
    if (*iflag == 0 && *dflag == 0 && isfinite(t) && (!have_last || t > t_last)) {
        for (int k = 0; k < 6; ++k) d_prev[k] = d_last[k];
        t_prev = t_last;
        have_prev = have_last;
        for (int k = 0; k < 6; ++k) d_last[k] = d[k];
        t_last = t;
        have_last = 1;
    }

    /* then the force, with the rate across steps when there is one */
    int damped = have_prev && t > t_prev;
    double h = damped ? t - t_prev : 1.0;
    for (int k = 0; k < 6; ++k) {
        double f = -K[k] * d[k];
        if (damped) f -= C[k] * (d[k] - d_prev[k]) / h;
        result[k] = isfinite(f) ? f : 0.0;
    }
}
