/*
 * A user routine that reads another element's force through the host
 * (docs/interface.md §5.1), for tests/test_user_forces.c: c_sysfnc's JOINT,
 * FZ or SFORCE, declared in its dependency pass or asked in evaluations
 * alone, turned into a force on its I marker.
 */
#include "usrsub/solver_abi.h"

typedef void STDCALL request_fn(int *id, double *time, double *par, int *npar, int *iflag,
                                double *result);
USRSUB_EXPORT usrsub_gfosub_fn READ_FORCE;
USRSUB_EXPORT request_fn REQUEST_FORCE;

/* USER(code, a, b, c, d, gx, gz[, late]): the force (gx v, 0, gz v) on I in
 * RM's axes, v c_sysfnc's JOINT(a, b, c, d) (code 1), FZ(a, b, c) (code 2) or
 * SFORCE(a, b, c, d) (code 3), 0 when the host refuses it (it reports why);
 * with late 1 asked in evaluations alone (iflag 0), not in the dependency
 * pass. */
void STDCALL READ_FORCE(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                        double *result)
{
    (void)id, (void)time, (void)dflag;
    static const char *const names[3] = {"JOINT", "FZ", "SFORCE"};
    const int code = (int)par[0];
    const int ipar[4] = {(int)par[1], (int)par[2], (int)par[3], (int)par[4]};
    for (int k = 0; k < 6; ++k)
        result[k] = 0.0;
    if (code < 1 || code > 3 || (*npar > 7 && par[7] != 0.0 && *iflag != 0))
        return;
    double v = 0.0;
    int errflg = 0;
    c_sysfnc(names[code - 1], ipar, code == 2 ? 3 : 4, &v, &errflg);
    if (errflg != 0)
        return;
    result[0] = par[5] * v;
    result[2] = par[6] * v;
}

/* USER(joint): result[2] = c_sysfnc's JOINT(joint, 0, 4, 0), a REQSUB's
 * read of a reaction (0 when the host refuses it). */
void STDCALL REQUEST_FORCE(int *id, double *time, double *par, int *npar, int *iflag,
                           double *result)
{
    (void)id, (void)time, (void)npar, (void)iflag;
    const int ipar[4] = {(int)par[0], 0, 4, 0};
    int errflg = 0;
    for (int k = 0; k < 8; ++k)
        result[k] = 0.0;
    c_sysfnc("JOINT", ipar, 4, &result[2], &errflg);
}
