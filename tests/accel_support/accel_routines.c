/*
 * User routines that read accelerations through the host (docs/interface.md
 * §5.1), for tests/test_user_accelerations.c: an added mass, a rate of an
 * angular acceleration, a probe of c_sysary ACC, a request that reads one
 * at its output times, and a faulty one (a force that reads one only
 * outside its dependency pass). Each names its markers in its USER list.
 */
#include "usrsub/solver_abi.h"

typedef void STDCALL value_fn(int *id, double *time, double *par, int *npar, int *dflag,
                              int *iflag, double *value);
typedef void STDCALL request_fn(int *id, double *time, double *par, int *npar, int *iflag,
                                double *result);
USRSUB_EXPORT usrsub_gfosub_fn ADDED_MASS, LATE_ADDED_MASS, ACC_PROBE;
USRSUB_EXPORT value_fn ANGULAR_DRAG;
USRSUB_EXPORT request_fn REQUEST_ACC;
USRSUB_EXPORT int accel_probe_last(double out[6]);

static int id_of(double value)
{
    return (int)value;
}

/* c_sysfnc's fnc of marker `marker` times factor; 0 when the host refuses
 * (it reports why). */
static double scaled_query(const char *fnc, double marker, double factor)
{
    const int ipar[1] = {id_of(marker)};
    double value = 0.0;
    int errflg = 0;
    c_sysfnc(fnc, ipar, 1, &value, &errflg);
    return errflg == 0 ? factor * value : 0.0;
}

/* USER(I, m_a): Fz = -m_a ACCZ(I) on I, the added mass of a body at I. */
void STDCALL ADDED_MASS(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                        double *result)
{
    (void)id, (void)time, (void)npar, (void)dflag, (void)iflag;
    for (int k = 0; k < 6; ++k)
        result[k] = 0.0;
    result[2] = scaled_query("ACCZ", par[0], -par[1]);
}

/* The same asked in evaluations alone: the dependency pass declares nothing. */
void STDCALL LATE_ADDED_MASS(int *id, double *time, double *par, int *npar, int *dflag,
                             int *iflag, double *result)
{
    for (int k = 0; k < 6; ++k)
        result[k] = 0.0;
    if (*iflag == 0)
        ADDED_MASS(id, time, par, npar, dflag, iflag, result);
}

/* USER(I, c): c WDTZ(I), a VARSUB's value or a DIFSUB's rate. */
void STDCALL ANGULAR_DRAG(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                          double *value)
{
    (void)id, (void)time, (void)npar, (void)dflag, (void)iflag;
    *value = scaled_query("WDTZ", par[0], par[1]);
}

/* The last answer of c_sysary("ACC", I, J, K) and its count, for the test. */
static double probed[6];
static int probed_count = -1;

int accel_probe_last(double out[6])
{
    for (int k = 0; k < 6; ++k)
        out[k] = probed[k];
    return probed_count;
}

/* USER(I, J, K): no force; keeps c_sysary("ACC", {I, J, K}, 3). */
void STDCALL ACC_PROBE(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                      double *result)
{
    (void)id, (void)time, (void)npar, (void)dflag, (void)iflag;
    const int ipar[3] = {id_of(par[0]), id_of(par[1]), id_of(par[2])};
    int count = 0, errflg = 0;
    c_sysary("ACC", ipar, 3, probed, &count, &errflg);
    probed_count = errflg == 0 ? count : -1;
    for (int k = 0; k < 6; ++k)
        result[k] = 0.0;
}

/* REQSUB USER(I): a request's ACCZ(I), answered at its output times. */
void STDCALL REQUEST_ACC(int *id, double *time, double *par, int *npar, int *iflag,
                        double *result)
{
    (void)id, (void)time, (void)npar, (void)iflag;
    const int ipar[1] = {id_of(par[0])};
    int errflg = 0;
    for (int k = 0; k < 8; ++k)
        result[k] = 0.0;
    c_sysfnc("ACCZ", ipar, 1, &result[3], &errflg);
}
