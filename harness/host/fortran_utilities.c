/*
 * The utilities as a Fortran library calls them (docs/interface.md §5.2):
 * gfortran's names (SYSARY -> sysary_), every argument by address, LOGICAL as
 * an int, and each CHARACTER argument's length passed after the others, its
 * text blank-padded rather than terminated. Each forwards to the C form.
 */
#include <stddef.h>
#include <string.h>

#include "host/utilities.h"
#include "usrsub/solver_abi.h"

#define TEXT_MAX 1024

/* A Fortran string as C text: trailing blanks trimmed, terminated. */
static const char *c_text(const char *text, size_t length, char *buffer)
{
    if (text == NULL)
        return NULL;
    size_t n = length < TEXT_MAX - 1 ? length : TEXT_MAX - 1;
    while (n > 0 && (text[n - 1] == ' ' || text[n - 1] == '\0'))
        --n;
    memcpy(buffer, text, n);
    buffer[n] = '\0';
    return buffer;
}

/* C text into a Fortran string of the given length, blank-padded. */
static void fortran_text(const char *text, size_t n, char *out, size_t length)
{
    const size_t copied = n < length ? n : length;
    memcpy(out, text, copied);
    memset(out + copied, ' ', length - copied);
}

/* gfortran's names: declared here, where they are defined, and nowhere else */
void sysary_(const char *fnc, const int *ipar, const int *nsize, double *states, int *nstates,
             int *errflg, size_t fnc_length);
void sysfnc_(const char *fnc, const int *ipar, const int *nsize, double *value, int *errflg,
             size_t fnc_length);
void errmes_(const int *errflg, const char *msg, const int *id, const char *endflg,
             size_t msg_length, size_t endflg_length);
void usrmes_(const int *msgflg, const char *msg, const int *id, const char *msgtyp,
             size_t msg_length, size_t msgtyp_length);
void gtstrg_(const int *id, char *string, int *nchars, int *istat, size_t string_length);
void gtunts_(int *exists, double *scales, char *units, size_t units_length);
void rcnvrt_(const char *sys1, const double *coord1, const char *sys2, double *coord2,
             int *istat, size_t sys1_length, size_t sys2_length);
void tcnvrt_(const char *sys1, const double *coord1, const char *sys2, double *coord2,
             int *istat, size_t sys1_length, size_t sys2_length);
void step_(const double *x, const double *x0, const double *h0, const double *x1,
           const double *h1, const int *iord, double *value, int *errflg);
void step5_(const double *x, const double *x0, const double *h0, const double *x1,
            const double *h1, const int *iord, double *value, int *errflg);
void havsin_(const double *x, const double *x0, const double *h0, const double *x1,
             const double *h1, const int *iord, double *value, int *errflg);
void impact_(const double *x, const double *dxdt, const double *x1, const double *k,
             const double *e, const double *cmax, const double *d, const int *iord, double *vec,
             int *errflg);
void bistop_(const double *x, const double *dxdt, const double *x1, const double *x2,
             const double *k, const double *e, const double *cmax, const double *d,
             const int *iord, double *vec, int *errflg);
void poly_(const double *x, const double *x0, const double *par, const int *npar,
           const int *iord, double *value, int *errflg);
void cheby_(const double *x, const double *x0, const double *par, const int *npar,
            const int *iord, double *value, int *errflg);
void forcos_(const double *x, const double *x0, const double *w, const double *par,
             const int *npar, const int *iord, double *value, int *errflg);
void forsin_(const double *x, const double *x0, const double *w, const double *par,
             const int *npar, const int *iord, double *value, int *errflg);
void shf_(const double *x, const double *x0, const double *a, const double *w,
          const double *phi, const double *b, const int *iord, double *value, int *errflg);
void akispl_(const double *xval, const double *zval, const int *id, const int *iord,
             double *array, int *errflg);
void cubspl_(const double *xval, const double *zval, const int *id, const int *iord,
             double *array, int *errflg);
void quispl_(const double *xval, const double *zval, const int *id, const int *iord,
             double *array, int *errflg);
void gtaray_(const int *id, double *array, int *number, int *istat);
void getstm_(double *time);
void timget_(double *time);
void getinm_(int *value);
void getmod_(int *mode);
void getint_(char *value, size_t length);
void getver_(char *value, size_t length);
void syspar_(const char *fnc, const int *ipar, const int *nsize, const double *partials,
             const int *npart, int *errflg, size_t fnc_length);
void cusfnc_(const char *fnc, const double *rpar, const int *nsize, double *state, int *errflg,
             size_t fnc_length);
void analys_(const char *antype, const char *cid, const double *timbeg, const double *timend,
             const int *init, int *istat, size_t antype_length, size_t cid_length);
void datout_(int *istat);
void modify_(const char *command, int *istat, size_t command_length);
void get_step_info_(int *flag);
void fitspl_(void);
void getslv_(void);
void getcpu_(void);
void modinf_(void);
void gtcmat_(void);
void get_post_states_(void);
void put_spline_(void);
void istrng_(void);
void rstrng_(void);


void sysary_(const char *fnc, const int *ipar, const int *nsize, double *states, int *nstates,
             int *errflg, size_t fnc_length)
{
    char name[TEXT_MAX];
    c_sysary(c_text(fnc, fnc_length, name), ipar, *nsize, states, nstates, errflg);
}

void sysfnc_(const char *fnc, const int *ipar, const int *nsize, double *value, int *errflg,
             size_t fnc_length)
{
    char name[TEXT_MAX];
    c_sysfnc(c_text(fnc, fnc_length, name), ipar, *nsize, value, errflg);
}

void errmes_(const int *errflg, const char *msg, const int *id, const char *endflg,
             size_t msg_length, size_t endflg_length)
{
    char text[TEXT_MAX], end[TEXT_MAX];
    c_errmes(*errflg, c_text(msg, msg_length, text), *id, c_text(endflg, endflg_length, end));
}

void usrmes_(const int *msgflg, const char *msg, const int *id, const char *msgtyp,
             size_t msg_length, size_t msgtyp_length)
{
    char text[TEXT_MAX], type[TEXT_MAX];
    c_usrmes(*msgflg, c_text(msg, msg_length, text), *id, c_text(msgtyp, msgtyp_length, type));
}

void gtstrg_(const int *id, char *string, int *nchars, int *istat, size_t string_length)
{
    char text[TEXT_MAX];
    int n = TEXT_MAX - 1;
    c_gtstrg(*id, text, &n, istat);
    if (*istat < 0) {
        *nchars = 0;
        return;
    }
    fortran_text(text, (size_t)n, string, string_length);
    *nchars = n < (int)string_length ? n : (int)string_length;
    if ((size_t)n > string_length)
        *istat = 1; /* truncated */
}

void gtunts_(int *exists, double *scales, char *units, size_t units_length)
{
    char names[USRSUB_GTUNTS_NAMES_LENGTH];
    memset(names, ' ', sizeof names);
    c_gtunts(exists, scales, names);
    if (units != NULL)
        fortran_text(names, sizeof names, units, units_length);
}

void rcnvrt_(const char *sys1, const double *coord1, const char *sys2, double *coord2,
             int *istat, size_t sys1_length, size_t sys2_length)
{
    char a[TEXT_MAX], b[TEXT_MAX];
    c_rcnvrt(c_text(sys1, sys1_length, a), coord1, c_text(sys2, sys2_length, b), coord2, istat);
}

void tcnvrt_(const char *sys1, const double *coord1, const char *sys2, double *coord2,
             int *istat, size_t sys1_length, size_t sys2_length)
{
    char a[TEXT_MAX], b[TEXT_MAX];
    c_tcnvrt(c_text(sys1, sys1_length, a), coord1, c_text(sys2, sys2_length, b), coord2, istat);
}

void step_(const double *x, const double *x0, const double *h0, const double *x1,
           const double *h1, const int *iord, double *value, int *errflg)
{
    c_step(*x, *x0, *h0, *x1, *h1, *iord, value, errflg);
}

void step5_(const double *x, const double *x0, const double *h0, const double *x1,
            const double *h1, const int *iord, double *value, int *errflg)
{
    c_step5(*x, *x0, *h0, *x1, *h1, *iord, value, errflg);
}

void havsin_(const double *x, const double *x0, const double *h0, const double *x1,
             const double *h1, const int *iord, double *value, int *errflg)
{
    c_havsin(*x, *x0, *h0, *x1, *h1, *iord, value, errflg);
}

void impact_(const double *x, const double *dxdt, const double *x1, const double *k,
             const double *e, const double *cmax, const double *d, const int *iord, double *vec,
             int *errflg)
{
    c_impact(*x, *dxdt, *x1, *k, *e, *cmax, *d, *iord, vec, errflg);
}

void bistop_(const double *x, const double *dxdt, const double *x1, const double *x2,
             const double *k, const double *e, const double *cmax, const double *d,
             const int *iord, double *vec, int *errflg)
{
    c_bistop(*x, *dxdt, *x1, *x2, *k, *e, *cmax, *d, *iord, vec, errflg);
}

void poly_(const double *x, const double *x0, const double *par, const int *npar,
           const int *iord, double *value, int *errflg)
{
    c_poly(*x, *x0, par, *npar, *iord, value, errflg);
}

void cheby_(const double *x, const double *x0, const double *par, const int *npar,
            const int *iord, double *value, int *errflg)
{
    c_cheby(*x, *x0, par, *npar, *iord, value, errflg);
}

void forcos_(const double *x, const double *x0, const double *w, const double *par,
             const int *npar, const int *iord, double *value, int *errflg)
{
    c_forcos(*x, *x0, *w, par, *npar, *iord, value, errflg);
}

void forsin_(const double *x, const double *x0, const double *w, const double *par,
             const int *npar, const int *iord, double *value, int *errflg)
{
    c_forsin(*x, *x0, *w, par, *npar, *iord, value, errflg);
}

void shf_(const double *x, const double *x0, const double *a, const double *w,
          const double *phi, const double *b, const int *iord, double *value, int *errflg)
{
    c_shf(*x, *x0, *a, *w, *phi, *b, *iord, value, errflg);
}

void akispl_(const double *xval, const double *zval, const int *id, const int *iord,
             double *array, int *errflg)
{
    c_akispl(*xval, *zval, *id, *iord, array, errflg);
}

void cubspl_(const double *xval, const double *zval, const int *id, const int *iord,
             double *array, int *errflg)
{
    c_cubspl(*xval, *zval, *id, *iord, array, errflg);
}

void quispl_(const double *xval, const double *zval, const int *id, const int *iord,
             double *array, int *errflg)
{
    c_quispl(*xval, *zval, *id, *iord, array, errflg);
}

void gtaray_(const int *id, double *array, int *number, int *istat)
{
    c_gtaray(*id, array, number, istat);
}

void getstm_(double *time) { c_getstm(time); }
void timget_(double *time) { c_timget(time); }
void getinm_(int *value) { c_getinm(value); }
void getmod_(int *mode) { c_getmod(mode); }

void getint_(char *value, size_t length)
{
    (void)length;
    c_getint(value);
}

void getver_(char *value, size_t length)
{
    (void)length;
    c_getver(value);
}

void syspar_(const char *fnc, const int *ipar, const int *nsize, const double *partials,
             const int *npart, int *errflg, size_t fnc_length)
{
    char name[TEXT_MAX];
    c_syspar(c_text(fnc, fnc_length, name), ipar, *nsize, partials, *npart, errflg);
}

void cusfnc_(const char *fnc, const double *rpar, const int *nsize, double *state, int *errflg,
             size_t fnc_length)
{
    char name[TEXT_MAX];
    c_cusfnc(c_text(fnc, fnc_length, name), rpar, *nsize, state, errflg);
}

void analys_(const char *antype, const char *cid, const double *timbeg, const double *timend,
             const int *init, int *istat, size_t antype_length, size_t cid_length)
{
    char a[TEXT_MAX], b[TEXT_MAX];
    c_analys(c_text(antype, antype_length, a), c_text(cid, cid_length, b), *timbeg, *timend,
             *init, istat);
}

void datout_(int *istat) { c_datout(istat); }

void modify_(const char *command, int *istat, size_t command_length)
{
    char text[TEXT_MAX];
    c_modify(c_text(command, command_length, text), istat);
}

void get_step_info_(int *flag) { c_get_step_info(flag); }
void fitspl_(void) { c_fitspl(); }
void getslv_(void) { c_getslv(); }
void getcpu_(void) { c_getcpu(); }
void modinf_(void) { c_modinf(); }
void gtcmat_(void) { c_gtcmat(); }
void get_post_states_(void) { c_get_post_states(); }
void put_spline_(void) { c_put_spline(); }
void istrng_(void) { c_istrng(); }
void rstrng_(void) { c_rstrng(); }
