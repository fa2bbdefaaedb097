/*
 * tp_vector.c -- test user library: the law of tp_good_sysfnc.c split
 * into a VFOSUB (Force_Vector_TwoBody ForceOnly: the force, three values) and
 * a VTOSUB (TorqueOnly: the torque, three values), in J axes:
 *     F_k = -K_k d_k - C_k v_k,  K = (1000, 2000, 3000), C = (1, 2, 3)
 *     T_k = -K_k a_k - C_k w_k,  K = (50, 60, 70),      C = (0.1, 0.2, 0.3)
 * USER(i_marker, j_marker), measured with c_sysfnc. No static state.
 * Expected verdict: PASS; and a run equals that of tp_good_sysfnc.xml.
 */
#include <string.h>

#include "usrsub/solver_abi.h"

/* the entries, as the solver's documentation gives them */
USRSUB_EXPORT void STDCALL VFOSUB(int *id, double *time, double *par, int *npar, int *dflag,
                                  int *iflag, double *result);
USRSUB_EXPORT void STDCALL VTOSUB(int *id, double *time, double *par, int *npar, int *dflag,
                                  int *iflag, double *result);

static void law(const double *par, int npar, const char *const names[6], const double K[3],
                const double C[3], double *result)
{
    memset(result, 0, 3 * sizeof(double));
    if (npar < 2)
        return;
    const int ipar[4] = {(int)par[0], (int)par[1], (int)par[1], (int)par[1]};
    for (int k = 0; k < 3; ++k) {
        double d = 0.0, v = 0.0;
        int err = 0;
        c_sysfnc(names[k], ipar, names[k][0] == 'A' ? 2 : 3, &d, &err);
        c_sysfnc(names[3 + k], ipar, names[3 + k][0] == 'W' ? 3 : 4, &v, &err);
        result[k] = -K[k] * d - C[k] * v;
    }
}

USRSUB_EXPORT void STDCALL VFOSUB(int *id, double *time, double *par, int *npar,
                                  int *dflag, int *iflag, double *result)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    static const char *const names[6] = {"DX", "DY", "DZ", "VX", "VY", "VZ"};
    law(par, *npar, names, (const double[3]){1000, 2000, 3000}, (const double[3]){1, 2, 3},
        result);
}

USRSUB_EXPORT void STDCALL VTOSUB(int *id, double *time, double *par, int *npar,
                                  int *dflag, int *iflag, double *result)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    static const char *const names[6] = {"AX", "AY", "AZ", "WX", "WY", "WZ"};
    law(par, *npar, names, (const double[3]){50, 60, 70}, (const double[3]){0.1, 0.2, 0.3},
        result);
}
