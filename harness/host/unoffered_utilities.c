/*
 * The utilities of the Adams-compatible interface this host does not offer
 * (docs/interface.md §5.2): each is defined, so that a library that refers to
 * it loads (dlopen resolves every reference at once), and a call of it is
 * noted and named in check's verdict instead of answered. Where the
 * signature is documented, its error flag or status is set; outputs whose
 * layout is not documented are left as they are.
 */
#include "host/utilities.h"
#include "usrsub/solver_abi.h"

void c_tcnvrt(const char *sys1, const double *coord1, const char *sys2, double *coord2,
              int *istat)
{
    (void)sys1, (void)coord1, (void)sys2, (void)coord2;
    hx_utility_unoffered(HX_UTILITY_TCNVRT);
    *istat = 1;
}

void c_quispl(double xval, double zval, int id, int iord, double *array, int *errflg)
{
    (void)xval, (void)zval, (void)id, (void)iord, (void)array;
    hx_utility_unoffered(HX_UTILITY_QUISPL);
    *errflg = 1;
}

void c_getmod(int *mode)
{
    (void)mode;
    hx_utility_unoffered(HX_UTILITY_GETMOD);
}

void c_getint(char *value)
{
    (void)value; /* the caller's room is not passed: nothing written */
    hx_utility_unoffered(HX_UTILITY_GETINT);
}

void c_getver(char *value)
{
    (void)value;
    hx_utility_unoffered(HX_UTILITY_GETVER);
}

void c_syspar(const char *fnc, const int *ipar, int nsize, const double *partials, int npart,
              int *errflg)
{
    (void)fnc, (void)ipar, (void)nsize, (void)partials, (void)npart;
    hx_utility_unoffered(HX_UTILITY_SYSPAR);
    *errflg = 1;
}

void c_cusfnc(const char *fnc, const double *rpar, int nsize, double *state, int *errflg)
{
    (void)fnc, (void)rpar, (void)nsize, (void)state;
    hx_utility_unoffered(HX_UTILITY_CUSFNC);
    *errflg = 1;
}

void c_get_step_info(int *flag)
{
    (void)flag;
    hx_utility_unoffered(HX_UTILITY_GET_STEP_INFO);
}

void c_analys(const char *antype, const char *cid, double timbeg, double timend, int init,
              int *istat)
{
    (void)antype, (void)cid, (void)timbeg, (void)timend, (void)init;
    hx_utility_unoffered(HX_UTILITY_ANALYS);
    *istat = 1;
}

void c_datout(int *istat)
{
    hx_utility_unoffered(HX_UTILITY_DATOUT);
    *istat = 1;
}

void c_modify(const char *command, int *istat)
{
    (void)command;
    hx_utility_unoffered(HX_UTILITY_MODIFY);
    *istat = 1;
}

void c_fitspl(void) { hx_utility_unoffered(HX_UTILITY_FITSPL); }
void c_getslv(void) { hx_utility_unoffered(HX_UTILITY_GETSLV); }
void c_getcpu(void) { hx_utility_unoffered(HX_UTILITY_GETCPU); }
void c_modinf(void) { hx_utility_unoffered(HX_UTILITY_MODINF); }
void c_gtcmat(void) { hx_utility_unoffered(HX_UTILITY_GTCMAT); }
void c_get_post_states(void) { hx_utility_unoffered(HX_UTILITY_GET_POST_STATES); }
void c_put_spline(void) { hx_utility_unoffered(HX_UTILITY_PUT_SPLINE); }
void c_istrng(void) { hx_utility_unoffered(HX_UTILITY_ISTRNG); }
void c_rstrng(void) { hx_utility_unoffered(HX_UTILITY_RSTRNG); }
