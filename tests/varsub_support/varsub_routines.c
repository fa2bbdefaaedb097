/*
 * VARSUB routines whose values forces, variables and Control_Diffs read
 * (docs/interface.md §7.10), for tests/test_varsub_inputs.c: a spring law of
 * a distance, a multiple of another variable read by c_sysfnc VARVAL, one
 * that turns NaN, a force that asks VARVAL (which the host answers to a
 * VARSUB or DIFSUB only), and a state equation whose input is a variable.
 * Each names what it reads in its USER list.
 */
#include <math.h>

#include "usrsub/solver_abi.h"

typedef void STDCALL value_fn(int *id, double *time, double *par, int *npar, int *dflag,
                              int *iflag, double *value);
USRSUB_EXPORT value_fn SPRING_VAR, SCALED_VAR, NAN_VAR;
USRSUB_EXPORT usrsub_gfosub_fn VARVAL_FORCE;
USRSUB_EXPORT usrsub_yfosub_fn LAG_FORCE;

/* c_sysfnc(fnc, ids); 0 when the host refuses (it reports why). */
static double ask(const char *fnc, const int *ids, int n)
{
    double value = 0.0;
    int errflg = 0;
    c_sysfnc(fnc, ids, n, &value, &errflg);
    return errflg == 0 ? value : 0.0;
}

/* USER(I, J, k, L): -k (DM(I, J) - L), a spring's force along its line. */
void STDCALL SPRING_VAR(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                        double *value)
{
    (void)id, (void)time, (void)npar, (void)dflag, (void)iflag;
    const int ids[2] = {(int)par[0], (int)par[1]};
    *value = -par[2] * (ask("DM", ids, 2) - par[3]);
}

/* USER(id, c): c VARVAL(id). */
void STDCALL SCALED_VAR(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                        double *value)
{
    (void)id, (void)time, (void)npar, (void)dflag, (void)iflag;
    const int ids[1] = {(int)par[0]};
    *value = par[1] * ask("VARVAL", ids, 1);
}

/* USER(t0): 0, then NaN from t0 on (never in the dependency pass). */
void STDCALL NAN_VAR(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                     double *value)
{
    (void)id, (void)npar, (void)dflag;
    *value = *iflag == 0 && *time >= par[0] ? NAN : 0.0;
}

/* USER(id): a force along x of VARVAL(id). */
void STDCALL VARVAL_FORCE(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                          double *result)
{
    (void)id, (void)time, (void)npar, (void)dflag, (void)iflag;
    const int ids[1] = {(int)par[0]};
    for (int k = 0; k < 6; ++k)
        result[k] = 0.0;
    result[0] = ask("VARVAL", ids, 1);
}

/* USER(tau): x' = (u - x) / tau, a force x along the reference marker's x. */
void STDCALL LAG_FORCE(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                       int *nstate, double *states, int *ninput, double *input, int *noutpt,
                       double *stated, double *output)
{
    (void)id, (void)time, (void)npar, (void)dflag, (void)iflag, (void)nstate, (void)ninput;
    (void)noutpt;
    stated[0] = (input[0] - states[0]) / par[0];
    for (int k = 0; k < 6; ++k)
        output[k] = 0.0;
    output[0] = states[0];
}
