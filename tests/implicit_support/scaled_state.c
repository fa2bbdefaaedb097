/*
 * scaled_state.c -- a test library for the Force_StateEqn host (test_state_check,
 * test_state_dynamics): a small nonlinear state equation with two states,
 * exact in its YFOSUB, whose YFOXX is scaled on purpose:
 *     USER(k, c, r, s [, crash])
 *     inputs: u0 = the first input (a deformation), u6 = the seventh (its rate;
 *             0 with fewer inputs)
 *     x1dot = r (u0 - x1) - x1 x2,      x2dot = u6 - r x2 (1 + x1^2)
 *     Fx = -k x1 - c u6,                Fy = -k x2 u0,    Fz .. Tz = 0
 * s = 1: YFOXX is d xdot/dx; any other s: YFOXX is s times it, a wrong
 * partial that check must name. crash != 0: YFOSUB writes through a null
 * pointer outside the dependency pass (check must survive it). Built twice:
 * with its four partial routines,
 * and (NO_PARTIALS) with YFOSUB alone, which the host must difference.
 */
#include <string.h>

#include "usrsub/solver_abi.h"

typedef struct law {
    double k, c, r, s;
    double u0, u6, x1, x2;
} law;

static law law_of(const double *par, int npar, const int *nstate, const double *states,
                  const int *ninput, const double *input)
{
    law l = {npar > 0 ? par[0] : 0.0, npar > 1 ? par[1] : 0.0, npar > 2 ? par[2] : 1.0,
             npar > 3 ? par[3] : 1.0, 0, 0, 0, 0};
    l.u0 = *ninput > 0 ? input[0] : 0.0;
    l.u6 = *ninput > 6 ? input[6] : 0.0;
    l.x1 = *nstate > 0 ? states[0] : 0.0;
    l.x2 = *nstate > 1 ? states[1] : 0.0;
    return l;
}

USRSUB_EXPORT void STDCALL YFOSUB(int *id, double *time, double *par, int *npar, int *dflag,
                                  int *iflag, int *nstate, double *states, int *ninput,
                                  double *input, int *noutpt, double *stated, double *output)
{
    (void)id, (void)time, (void)dflag;
    const law l = law_of(par, *npar, nstate, states, ninput, input);
    memset(output, 0, sizeof(double) * (size_t)*noutpt);
    memset(stated, 0, sizeof(double) * (size_t)*nstate);
    if (*nstate < 2 || *noutpt < 6) {
        c_errmes(1, "scaled_state: needs 2 states and 6 outputs", *id, "STOP");
        return;
    }
    if (*npar > 4 && par[4] != 0.0 && *iflag == 0) {
        volatile double *nowhere = NULL;
        *nowhere = 1.0; /* the planted crash */
    }
    stated[0] = l.r * (l.u0 - l.x1) - l.x1 * l.x2;
    stated[1] = l.u6 - l.r * l.x2 * (1.0 + l.x1 * l.x1);
    output[0] = -l.k * l.x1 - l.c * l.u6;
    output[1] = -l.k * l.x2 * l.u0;
}

#ifndef NO_PARTIALS
/* Which block: 0 d xdot/dx, 1 d xdot/du, 2 d out/dx, 3 d out/du. */
static void partials(int block, const double *par, int npar, int *nstate, double *states,
                     int *ninput, double *input, double *m)
{
    const law l = law_of(par, npar, nstate, states, ninput, input);
    const int rows = block < 2 ? *nstate : 6, cols = block % 2 == 0 ? *nstate : *ninput;
    memset(m, 0, sizeof(double) * (size_t)(rows * cols));
    if (*nstate < 2)
        return;
    switch (block) {
    case 0:
        m[0] = l.s * (-l.r - l.x2);                    /* dx1dot/dx1 */
        m[1] = l.s * (-2.0 * l.r * l.x2 * l.x1);       /* dx2dot/dx1 */
        m[0 + rows] = l.s * (-l.x1);                   /* dx1dot/dx2 */
        m[1 + rows] = l.s * (-l.r * (1.0 + l.x1 * l.x1)); /* dx2dot/dx2 */
        break;
    case 1:
        if (cols > 0)
            m[0] = l.r;                                /* dx1dot/du0 */
        if (cols > 6)
            m[1 + rows * 6] = 1.0;                     /* dx2dot/du6 */
        break;
    case 2:
        m[0] = -l.k;                                   /* dFx/dx1 */
        m[1 + rows] = -l.k * l.u0;                     /* dFy/dx2 */
        break;
    default:
        if (cols > 0)
            m[1] = -l.k * l.x2;                        /* dFy/du0 */
        if (cols > 6)
            m[rows * 6] = -l.c;                        /* dFx/du6 */
        break;
    }
}

#define PARTIAL(NAME, BLOCK)                                                                    \
    USRSUB_EXPORT void STDCALL NAME(int *id, double *time, double *par, int *npar, int *iflag,  \
                                    int *nstate, double *states, int *ninput, double *input,    \
                                    int *noutpt, double *matrix)                                \
    {                                                                                           \
        (void)id, (void)time, (void)iflag, (void)noutpt;                                        \
        partials(BLOCK, par, *npar, nstate, states, ninput, input, matrix);                     \
    }
PARTIAL(YFOXX, 0)
PARTIAL(YFOXU, 1)
PARTIAL(YFOYX, 2)
PARTIAL(YFOYU, 3)
#endif
