/*
 * tp_habits_field.c -- test user library (FIESUB, Force_Field) that
 * fills its partials only when the solver asks for them (dflag set), and
 * never writes dfdvel (its force does not depend on the rates):
 *   field = -K disp, K = (1e5, 2e5, 3e5 N/mm, 500, 600, 700 N mm/rad);
 *   dfddis = -diag(K) when *dflag.
 * Expected verdict: PASS; and the Newton matrix takes its partials (asked with
 * dflag set): tests/test_jacobian.c.
 */
#include "usrsub/solver_abi.h"

static const double K[6] = {1e5, 2e5, 3e5, 500.0, 600.0, 700.0};

USRSUB_EXPORT void STDCALL FIESUB(int *id, double *time, double *par, int *npar, double *disp,
                                  double *velo, int *dflag, int *iflag, double *field,
                                  double *dfddis, double *dfdvel)
{
    (void)id, (void)time, (void)par, (void)npar, (void)velo, (void)iflag, (void)dfdvel;
    for (int k = 0; k < 6; ++k)
        field[k] = -K[k] * disp[k];
    if (*dflag)
        for (int j = 0; j < 6; ++j)
            for (int i = 0; i < 6; ++i)
                dfddis[i + 6 * j] = i == j ? -K[i] : 0.0;
}
