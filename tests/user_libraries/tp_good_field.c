/*
 * tp_good_field.c -- test user library (FIESUB, Force_Field).
 *
 * Linear field with one cross coupling, I relative to J in J axes:
 *     field_k = -K_k disp_k - C_k velo_k,  K = (1000, 2000, 3000, 50, 60, 70),
 *                                          C = (1, 2, 3, 0.1, 0.2, 0.3),
 *     field_y += 7 * disp_ax.
 * Partials, column-major [i + 6*j] = dF_i/dx_j: dfddis = -diag(K) with
 * dfddis[1 + 6*3] = +7, dfdvel = -diag(C). All exact. USER(0) (ignored).
 * Makes no utility call; no static state.
 *
 * A correct verifier must PASS this library (field, dfddis and dfdvel all
 * agree with finite differences of the field).
 */
#include <math.h>
#include <string.h>

#include "usrsub/solver_abi.h"

static const double K[6] = {1000.0, 2000.0, 3000.0, 50.0, 60.0, 70.0};
static const double C[6] = {1.0, 2.0, 3.0, 0.1, 0.2, 0.3};
static const double KYAX = 7.0;   /* true coupling: F_y += 7 * ax */
static const double KYAX_REPORTED = 7.0; /* correct */

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
