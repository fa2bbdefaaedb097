/*
 * tp_direction.c -- test user library: two force routines whose value is
 * a scalar or components that the HOST turns into a world force along a
 * direction that moves with the bodies, classic C form (every argument by
 * address), exported as the upper-case names tp_direction.xml gives in
 * usrsub_fnc_name. Measured with c_sysfnc, the same queries in the
 * dependency pass (iflag set) as in an evaluation. No static state.
 *
 *   AXIAL_SPRING (SFOSUB, Force_Scalar_TwoBody type FORCE), after the
 *       solver vendor's SFOSUB example, USER(i, j, k, c, z0, mode, k2):
 *           value = -k (DZ(I,J,J) - z0) - c VZ(I,J,J,J)
 *       The host applies it along the line from J to I, whose direction
 *       moves with every coordinate of I; the value itself depends on DZ
 *       and VZ only, the two queries declared.
 *   FRAME_SPRING (VFOSUB, Force_Vector_TwoBody type ForceOnly, its
 *       ref_marker_id RM a marker on the moving I body, turned),
 *       USER(i, j, rm, kx, ky, kz, c, mode, k2):
 *           value_x = -kx DX(I,J,RM) - c VX(I,J,RM,RM)   (y, z likewise)
 *       components in RM's axes, where the host takes a VFOSUB's result;
 *       VX(I,J,RM,RM) is the rate of DX(I,J,RM) (the time derivative taken
 *       in RM). The world force turns with RM; the values depend on the
 *       six declared queries only.
 *
 * mode 0: as above. Expected verdict: PASS for both elements.
 * mode 1: an undeclared dependency: a query made only when iflag is 0,
 *       never in the dependency pass, added to the value:
 *           AXIAL_SPRING  + k2 DX(I,J)   (body I's x, which neither DZ nor
 *                                         VZ reaches)
 *           FRAME_SPRING  + k2 WX(I,J)   on value_x
 *       Expected verdict: FAIL for both elements (a read outside the
 *       declared dependencies; for AXIAL_SPRING also a dependency on body
 *       I's x that no declared query reaches).
 *
 * A malformed USER list or a refused declared query stops the run through
 * c_errmes; the extra query of mode 1 is used only when the host answers it.
 */
#include "usrsub/solver_abi.h"

USRSUB_EXPORT void STDCALL AXIAL_SPRING(int *id, double *time, double *par, int *npar,
                                        int *dflag, int *iflag, double *value);
USRSUB_EXPORT void STDCALL FRAME_SPRING(int *id, double *time, double *par, int *npar,
                                        int *dflag, int *iflag, double *result);

/* One measure; a refused query is counted in *refused. */
static double measure(const char *name, const int *ipar, int nsize, int *refused)
{
    double value = 0.0;
    int err = 0;
    c_sysfnc(name, ipar, nsize, &value, &err);
    if (err) {
        ++*refused;
        return 0.0;
    }
    return value;
}

/* The undeclared extra of mode 1: 0 when the host does not answer it. */
static double extra(const char *name, const int *ipar, int nsize)
{
    double value = 0.0;
    int err = 0;
    c_sysfnc(name, ipar, nsize, &value, &err);
    return err ? 0.0 : value;
}

static int mode_of(double p)
{
    return p == 0.0 ? 0 : p == 1.0 ? 1 : -1;
}

USRSUB_EXPORT void STDCALL AXIAL_SPRING(int *id, double *time, double *par, int *npar,
                                        int *dflag, int *iflag, double *value)
{
    (void)time, (void)dflag;
    *value = 0.0;
    if (*npar < 7) {
        c_errmes(1, "AXIAL_SPRING: USER(i, j, k, c, z0, mode, k2) expected", *id, "STOP");
        return;
    }
    const int mode = mode_of(par[5]);
    if (mode < 0) {
        c_errmes(1, "AXIAL_SPRING: USER parameter 6 (par[5], mode) must be 0 or 1", *id,
                 "STOP");
        return;
    }
    const double k = par[2], c = par[3], z0 = par[4], k2 = par[6];
    /* K (and L) = the J marker */
    const int ipar[4] = {(int)par[0], (int)par[1], (int)par[1], (int)par[1]};
    int refused = 0;
    const double dz = measure("DZ", ipar, 3, &refused);
    const double vz = measure("VZ", ipar, 4, &refused);
    if (refused) {
        c_errmes(1, "AXIAL_SPRING: the host refused DZ(I,J,J) or VZ(I,J,J,J)", *id, "STOP");
        return;
    }
    double f = -k * (dz - z0) - c * vz;
    if (mode == 1 && *iflag == 0)
        f += k2 * extra("DX", ipar, 2); /* the fault: never declared */
    *value = f;
}

USRSUB_EXPORT void STDCALL FRAME_SPRING(int *id, double *time, double *par, int *npar,
                                        int *dflag, int *iflag, double *result)
{
    (void)time, (void)dflag;
    result[0] = result[1] = result[2] = 0.0;
    if (*npar < 9) {
        c_errmes(1, "FRAME_SPRING: USER(i, j, rm, kx, ky, kz, c, mode, k2) expected", *id,
                 "STOP");
        return;
    }
    const int mode = mode_of(par[7]);
    if (mode < 0) {
        c_errmes(1, "FRAME_SPRING: USER parameter 8 (par[7], mode) must be 0 or 1", *id,
                 "STOP");
        return;
    }
    const double K[3] = {par[3], par[4], par[5]}, c = par[6], k2 = par[8];
    /* components in RM's axes, the time derivative taken in RM */
    const int ipar[4] = {(int)par[0], (int)par[1], (int)par[2], (int)par[2]};
    static const char *const dnames[3] = {"DX", "DY", "DZ"};
    static const char *const vnames[3] = {"VX", "VY", "VZ"};
    double f[3];
    int refused = 0;
    for (int n = 0; n < 3; ++n) {
        const double d = measure(dnames[n], ipar, 3, &refused);
        const double v = measure(vnames[n], ipar, 4, &refused);
        f[n] = -K[n] * d - c * v;
    }
    if (refused) {
        c_errmes(1, "FRAME_SPRING: the host refused a query DX..DZ(I,J,RM) or VX..VZ(I,J,RM,RM)",
                 *id, "STOP");
        return;
    }
    if (mode == 1 && *iflag == 0)
        f[0] += k2 * extra("WX", ipar, 2); /* the fault: never declared */
    for (int n = 0; n < 3; ++n)
        result[n] = f[n];
}
