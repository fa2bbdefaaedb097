/*
 * tp_good_sysary.c -- test user library (GFOSUB, Force_Vector_TwoBody).
 *
 * Linear spring-damper on the deformation of I relative to J, in J axes:
 *     F_k = -K_k * d_k - C_k * v_k,   k = x, y, z, ax, ay, az
 * with K = (1000, 2000, 3000, 50, 60, 70), C = (1, 2, 3, 0.1, 0.2, 0.3).
 * USER(i_marker, j_marker).
 *
 * Measurement, in few round trips:
 *   c_sysary("DISP", {I,J,J}, 3)  -> DX, DY, DZ, psi, theta, phi (3-1-3 Euler)
 *   c_sysfnc("AZ",   {I,J},   2)  -> AZ (see below)
 *   c_sysary("VEL",  {I,J,J,J}, 4) -> VX, VY, VZ, WX, WY, WZ
 * The Euler angles are turned into R = Rz(psi) Rx(theta) Rz(phi) (columns are
 * I's axes in J) and then into projection angles
 *   AX = atan2(Y_I.Z_J, Y_I.Y_J), AY = atan2(Z_I.X_J, Z_I.Z_J),
 *   AZ = atan2(X_I.Y_J, X_I.X_J).
 * Near theta = 0 only psi + phi is defined and a host may split the two
 * arbitrarily (docs/interface.md §3.1), so while the tilt is below 60 degrees phi is
 * re-derived from the host's AZ: the rebuilt R then reproduces AZ exactly and
 * does not depend on the psi/phi split (exact at theta = 0). Without that one
 * extra query the torque would be wrong at rest for such a host.
 * The dependency pass (iflag != 0) makes exactly the same three queries and
 * evaluates the same law on the zeros the host returns (atan2(0, 0) = 0,
 * cos(0) = 1: no division by zero). No static state.
 *
 * A correct verifier must PASS this library.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "usrsub/solver_abi.h"

static const double K[6] = {1000.0, 2000.0, 3000.0, 50.0, 60.0, 70.0};
static const double C[6] = {1.0, 2.0, 3.0, 0.1, 0.2, 0.3};

static int marker_id(const double *par, int npar, int k)
{
    if (k >= npar) return 0;
    double v = par[k];
    if (!isfinite(v) || v != floor(v) || v < 1.0 || v > (double)INT_MAX) return 0;
    return (int)v;
}

/* Six values of one c_sysary query; zeros when the host refuses it. */
static void measure6(const char *fnc, const int *ipar, int nsize, double out[6])
{
    double buf[12] = {0};
    int n = 0, errflg = 0;
    c_sysary(fnc, ipar, nsize, buf, &n, &errflg);
    for (int k = 0; k < 6; ++k)
        out[k] = (errflg == 0 && n >= 6 && isfinite(buf[k])) ? buf[k] : 0.0;
}

static double measure1(const char *fnc, const int *ipar, int nsize)
{
    double value = 0.0;
    int errflg = 0;
    c_sysfnc(fnc, ipar, nsize, &value, &errflg);
    return (errflg == 0 && isfinite(value)) ? value : 0.0;
}

/* Projection angles of R = Rz(psi) Rx(theta) Rz(phi); az_host fixes the
 * psi/phi split while cos(theta) > 0.5. */
static void projection_angles(double psi, double theta, double phi, double az_host,
                              double a[3])
{
    double cps = cos(psi), sps = sin(psi), ct = cos(theta), st = sin(theta);
    if (ct > 0.5) {
        /* X_I's xy part is Rz2(psi) diag(1, ct) (cos phi, sin phi) and points
         * along (cos AZ, sin AZ): solve for phi. */
        double ca = cos(az_host), sa = sin(az_host);
        double ux = cps * ca + sps * sa;  /* Rz2(-psi) (ca, sa) */
        double uy = -sps * ca + cps * sa;
        phi = atan2(uy / ct, ux);
    }
    double cph = cos(phi), sph = sin(phi);
    double R[3][3] = {
        {cps * cph - sps * ct * sph, -cps * sph - sps * ct * cph, sps * st},
        {sps * cph + cps * ct * sph, -sps * sph + cps * ct * cph, -cps * st},
        {st * sph, st * cph, ct},
    };
    a[0] = atan2(R[2][1], R[1][1]); /* Y_I.Z_J, Y_I.Y_J */
    a[1] = atan2(R[0][2], R[2][2]); /* Z_I.X_J, Z_I.Z_J */
    a[2] = atan2(R[1][0], R[0][0]); /* X_I.Y_J, X_I.X_J */
}

USRSUB_EXPORT void STDCALL GFOSUB(int *id, double *time, double *par, int *npar,
                                  int *dflag, int *iflag, double *result)
{
    (void)time;
    (void)dflag;
    (void)iflag; /* the same queries and law in both passes */
    memset(result, 0, 6 * sizeof(double));

    int i_mk = marker_id(par, *npar, 0);
    int j_mk = marker_id(par, *npar, 1);
    if (*npar != 2 || i_mk == 0 || j_mk == 0) {
        char msg[200];
        snprintf(msg, sizeof msg,
                 "tp_good_sysary: element %d: expected USER(i_marker, j_marker) with two "
                 "positive integer ids, got %d value(s)", *id, *npar);
        c_errmes(1, msg, *id, "STOP");
        return;
    }

    const int ij[2] = {i_mk, j_mk};
    const int ijj[3] = {i_mk, j_mk, j_mk};
    const int ijjj[4] = {i_mk, j_mk, j_mk, j_mk};

    double disp[6], vel[6], d[6];
    measure6("DISP", ijj, 3, disp);
    double az = measure1("AZ", ij, 2);
    measure6("VEL", ijjj, 4, vel);

    d[0] = disp[0];
    d[1] = disp[1];
    d[2] = disp[2];
    projection_angles(disp[3], disp[4], disp[5], az, d + 3);

    for (int k = 0; k < 6; ++k) result[k] = -K[k] * d[k] - C[k] * vel[k];
}
