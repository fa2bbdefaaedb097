/*
 * scaled_field.c -- a test library for the implicit integrator (test_jacobian, test_bdf).
 *
 * FIESUB: a linear spring and damper, exact in its field, whose reported
 * partials are scaled on purpose:
 *     USER(k, c, kr, cr, s[, nan])
 *     field = -(k, k, k, kr, kr, kr) disp - (c, c, c, cr, cr, cr) velo
 *     dfddis = s * (-diag(k, k, k, kr, kr, kr)), dfdvel = s * (-diag(c, ..., cr))
 * s = 1: the exact partials; any other s: a wrong Newton matrix, which costs
 * BDF Newton iterations or steps but must not change the trajectory it
 * converges to. nan != 0: one entry of dfdvel is NaN (a library whose
 * partials fail).
 * GFOSUB / SCALED_SPRING_FIELD: the same field under the GFOSUB twin
 * convention (docs/interface.md §3.0), USER(I, J, k, c, kr, cr, s) for
 * SCALED_SPRING (GFOSUB-style: it measures DX..AZ and VX..WZ of I in J) and
 * USER(k, c, kr, cr, s) for SCALED_SPRING_FIELD, whose field is scaled by s
 * too: a twin that disagrees with its element when s != 1.
 */
#include <math.h>
#include <string.h>

#include "usrsub/solver_abi.h"

USRSUB_EXPORT usrsub_fiesub_fn SCALED_SPRING_FIELD;
USRSUB_EXPORT usrsub_gfosub_fn SCALED_SPRING;

static void field_of(const double *par, int npar, const double *disp, const double *velo,
                     double *field, double *dfddis, double *dfdvel, double field_scale)
{
    const double k = npar > 0 ? par[0] : 0.0, c = npar > 1 ? par[1] : 0.0;
    const double kr = npar > 2 ? par[2] : 0.0, cr = npar > 3 ? par[3] : 0.0;
    const double s = npar > 4 ? par[4] : 1.0;
    memset(dfddis, 0, 36 * sizeof(double));
    memset(dfdvel, 0, 36 * sizeof(double));
    for (int i = 0; i < 6; ++i) {
        const double ki = i < 3 ? k : kr, ci = i < 3 ? c : cr;
        field[i] = field_scale * (-ki * disp[i] - ci * velo[i]);
        dfddis[i + 6 * i] = -s * ki;
        dfdvel[i + 6 * i] = -s * ci;
    }
    if (npar > 5 && par[5] != 0.0)
        dfdvel[7] = NAN;
}

USRSUB_EXPORT void STDCALL FIESUB(int *id, double *time, double *par, int *npar, double *disp,
                                  double *velo, int *dflag, int *iflag, double *field,
                                  double *dfddis, double *dfdvel)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    field_of(par, *npar, disp, velo, field, dfddis, dfdvel, 1.0);
}

USRSUB_EXPORT void STDCALL SCALED_SPRING_FIELD(int *id, double *time, double *par, int *npar,
                                               double *disp, double *velo, int *dflag, int *iflag,
                                               double *field, double *dfddis, double *dfdvel)
{
    (void)id, (void)time, (void)dflag, (void)iflag;
    field_of(par, *npar, disp, velo, field, dfddis, dfdvel, *npar > 4 ? par[4] : 1.0);
}

/* The projection angles of I in J from the host's 3-1-3 Euler angles
 * (docs/interface.md §3.1): small rotations about one axis at a time, which
 * is all the test drives. */
USRSUB_EXPORT void STDCALL SCALED_SPRING(int *id, double *time, double *par, int *npar,
                                         int *dflag, int *iflag, double *result)
{
    (void)time, (void)dflag;
    memset(result, 0, 6 * sizeof(double));
    if (*npar < 2)
        return;
    const int markers[4] = {(int)par[0], (int)par[1], (int)par[1], (int)par[1]};
    double disp[6] = {0}, velo[6] = {0}, angles[3], dfd[36], dfv[36];
    int n = 0, err = 0;
    c_sysary("TDISP", markers, 3, disp, &n, &err);
    double rot[3];
    const char *names[3] = {"AX", "AY", "AZ"};
    for (int k = 0; k < 3; ++k) {
        c_sysfnc(names[k], markers, 2, &rot[k], &err);
        angles[k] = rot[k];
    }
    memcpy(disp + 3, angles, sizeof angles);
    c_sysary("VEL", markers, 4, velo, &n, &err);
    if (*iflag)
        return;
    field_of(par + 2, *npar - 2, disp, velo, result, dfd, dfv, 1.0);
    (void)id;
}
