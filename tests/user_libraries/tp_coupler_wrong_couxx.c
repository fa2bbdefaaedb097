/*
 * tp_coupler_wrong_couxx.c -- test user library.
 *
 * Coupler (Constraint_Coupler, two joints), USER(a, b, c), e.g. USER(2.0, 0.5, 1.0):
 *     phi = a sin(M1) + b M2^3 / 3 + c M2          (M_k = disp[k-1])
 *     dphi/dM1 = a cos M1,   dphi/dM2 = b M2^2 + c
 *     d2phi/dM1^2 = -a sin M1, d2phi/dM2^2 = 2 b M2, mixed terms 0.
 * COUSUB writes phi, COUXX dfda[2], COUXX2 d2fda2[4] column-major
 * ([i + 2*j] = d2phi/dM_i dM_j). No utility call except c_errmes for a bad
 * USER list or ndisp != 2; no static state.
 *
 * FAULTY ON PURPOSE: COUXX writes dfda[1] = b M1^2 + c (the wrong joint's
 * displacement; true b M2^2 + c). COUSUB and COUXX2 are correct.
 *
 * A correct verifier must FAIL COUXX (coupler 1), entry 2 (dphi/dM2, index 1):
 * it disagrees with finite differences of COUSUB wherever M1^2 != M2^2 (so
 * not at the initial M1 = M2 = 0; along the motion M2 ~ -2 M1). It must NOT
 * fail COUXX2, which is the exact second derivative of COUSUB; blaming
 * COUXX2 because it disagrees with the wrong COUXX misattributes the fault.
 */
#include <math.h>
#include <stdio.h>

#include "usrsub/solver_abi.h"

/* phi = a sin(M1) + b M2^3 / 3 + c M2, USER(a, b, c), two coupled joints.
 * Returns 1 and the coefficients when par/ndisp fit; otherwise reports the
 * input error through c_errmes and returns 0. */
static int coefficients(int id, const double *par, int npar, int ndisp, double abc[3])
{
    const char *why = NULL;
    if (npar != 3)
        why = "expected USER(a, b, c): three numbers";
    else if (ndisp != 2)
        why = "expected a coupler of exactly two joints (ndisp = 2)";
    else if (!isfinite(par[0]) || !isfinite(par[1]) || !isfinite(par[2]))
        why = "a, b and c must be finite numbers";
    if (why != NULL) {
        char msg[200];
        snprintf(msg, sizeof msg, "tp_coupler_wrong_couxx: coupler %d: %s (npar = %d, ndisp = %d)",
                 id, why, npar, ndisp);
        c_errmes(1, msg, id, "STOP");
        return 0;
    }
    abc[0] = par[0];
    abc[1] = par[1];
    abc[2] = par[2];
    return 1;
}

static void zero(double *out, int n)
{
    for (int k = 0; k < n; ++k) out[k] = 0.0;
}

/* Count of outputs the host sized for ndisp joints (at most 3 joints). */
static int clamp_joints(int ndisp)
{
    return ndisp < 0 ? 0 : (ndisp > 3 ? 3 : ndisp);
}

USRSUB_EXPORT void STDCALL COUSUB(int *id, double *time, double *par, int *npar,
                                  double *disp, int *ndisp, int *iflag, double *phi)
{
    double abc[3];
    (void)time;
    (void)iflag;
    if (!coefficients(*id, par, *npar, *ndisp, abc)) {
        *phi = 0.0;
        return;
    }
    double m1 = disp[0], m2 = disp[1];
    *phi = abc[0] * sin(m1) + abc[1] * m2 * m2 * m2 / 3.0 + abc[2] * m2;
}

USRSUB_EXPORT void STDCALL COUXX(int *id, double *time, double *par, int *npar,
                                 double *disp, int *ndisp, int *iflag, double *dfda)
{
    double abc[3];
    (void)time;
    (void)iflag;
    if (!coefficients(*id, par, *npar, *ndisp, abc)) {
        zero(dfda, clamp_joints(*ndisp));
        return;
    }
    double m1 = disp[0], m2 = disp[1];
    (void)m1; /* not every variant of this file uses both */
    (void)m2;
    dfda[0] = abc[0] * cos(m1);
    dfda[1] = abc[1] * m1 * m1 + abc[2]; /* WRONG: should use M2 */
}

USRSUB_EXPORT void STDCALL COUXX2(int *id, double *time, double *par, int *npar,
                                  double *disp, int *ndisp, int *iflag, double *d2fda2)
{
    double abc[3];
    (void)time;
    (void)iflag;
    int n = clamp_joints(*ndisp);
    if (!coefficients(*id, par, *npar, *ndisp, abc)) {
        zero(d2fda2, n * n);
        return;
    }
    double m1 = disp[0], m2 = disp[1];
    (void)m1; /* not every variant of this file uses both */
    (void)m2;
    /* column-major: d2fda2[i + 2*j] = d2 phi / dM_i dM_j */
    d2fda2[0] = -abc[0] * sin(m1);  /* (1,1) */
    d2fda2[1] = 0.0;                 /* (2,1) */
    d2fda2[2] = 0.0;                 /* (1,2) */
    d2fda2[3] = 2.0 * abc[1] * m2;   /* (2,2) */
}
