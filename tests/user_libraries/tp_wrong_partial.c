/*
 * tp_wrong_partial.c -- test user library (FIESUB, Force_Field).
 *
 * FAULTY ON PURPOSE. The field of tp_good_field.c:
 *     field_k = -K_k disp_k - C_k velo_k,  K = (1000, 2000, 3000, 50, 60, 70),
 *                                          C = (1, 2, 3, 0.1, 0.2, 0.3),
 *     field_y += 7 * disp_ax,
 * with dfdvel = -diag(C) and dfddis = -diag(K) correct everywhere except ONE
 * entry: dfddis[1 + 6*3] (row Fy, column ax) is reported as 5 while the true
 * dFy/dax is 7. USER(0) (ignored). No utility call; no static state.
 *
 * A correct verifier must FAIL this library (element 1, FIESUB) for a wrong
 * analytic partial and name the entry dfddis row 2 / column 4 in 1-based
 * terms, i.e. row Fy (index 1), column ax (index 3), flat index 19:
 * reported 5, finite differences give 7. No other entry (and nothing in
 * dfdvel) may be flagged.
 */
#include <math.h>
#include <string.h>

#include "usrsub/solver_abi.h"

static const double K[6] = {1000.0, 2000.0, 3000.0, 50.0, 60.0, 70.0};
static const double C[6] = {1.0, 2.0, 3.0, 0.1, 0.2, 0.3};
static const double KYAX = 7.0;   /* true coupling: F_y += 7 * ax */
static const double KYAX_REPORTED = 5.0; /* WRONG: true value is 7 */

/* USER(0): one dummy number; the state comes in disp and velo (no c_sysary). */
USRSUB_EXPORT void STDCALL FIESUB(int *id, double *time, double *par, int *npar,
                                  double *disp, double *velo, int *dflag, int *iflag,
                                  double *field, double *dfddis, double *dfdvel)
{
    (void)id;
    (void)time;
    (void)par;
    (void)npar;
    (void)dflag;
    (void)iflag;

    memset(field, 0, 6 * sizeof(double));
    memset(dfddis, 0, 36 * sizeof(double));
    memset(dfdvel, 0, 36 * sizeof(double));

    for (int k = 0; k < 6; ++k) {
        field[k] = -K[k] * disp[k] - C[k] * velo[k];
        dfddis[k + 6 * k] = -K[k];
        dfdvel[k + 6 * k] = -C[k];
    }
    field[1] += KYAX * disp[3];          /* Fy depends on ax */
    dfddis[1 + 6 * 3] = KYAX_REPORTED;   /* dFy/dax (row Fy = 1, column ax = 3) */
}
