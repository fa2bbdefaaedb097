/*
 * The solver ABI: the user-subroutine entries a MotionSolve-style host looks up
 * in the library, and the utilities the library may call back in the host.
 * Our own declarations of the contract in docs/interface.md §1.
 *
 * Every subroutine argument is a pointer (Fortran by-reference). The utilities
 * take scalars by value, as the Adams-compatible C utility library does.
 */
#ifndef USRSUB_SOLVER_ABI_H
#define USRSUB_SOLVER_ABI_H

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32)
#define STDCALL __stdcall
#define USRSUB_EXPORT __declspec(dllexport)
#else
#define STDCALL
#define USRSUB_EXPORT __attribute__((visibility("default")))
#endif

/* ---- Entry types, as a host resolves them with dlsym ------------------- */

/* COUSUB (phi: 1 value), COUXX (ndisp values), COUXX2 (ndisp*ndisp, column-major). */
typedef void STDCALL usrsub_coupler_fn(int *id, double *time, double *par, int *npar,
                                       double *disp, int *ndisp, int *iflag, double *out);

/* GFOSUB: result = Fx Fy Fz Tx Ty Tz on the I marker, in J-marker axes. */
typedef void STDCALL usrsub_gfosub_fn(int *id, double *time, double *par, int *npar,
                                      int *dflag, int *iflag, double *result);

/* FIESUB: field (6), dfddis and dfdvel (6x6 column-major, [i + 6*j] = dF_i/dx_j). */
typedef void STDCALL usrsub_fiesub_fn(int *id, double *time, double *par, int *npar,
                                      double *disp, double *velo, int *dflag, int *iflag,
                                      double *field, double *dfddis, double *dfdvel);

/* YFOSUB (Force_StateEqn): stated (nstate) and output (noutpt: Fx Fy Fz Tx Ty
 * Tz on I in J axes) from states (nstate) and input (ninput). */
typedef void STDCALL usrsub_yfosub_fn(int *id, double *time, double *par, int *npar, int *dflag,
                                      int *iflag, int *nstate, double *states, int *ninput,
                                      double *input, int *noutpt, double *stated,
                                      double *output);

/* YFOXX, YFOXU, YFOYX, YFOYU: d stated/d states (nstate x nstate), d stated/d
 * input (nstate x ninput), d output/d states (noutpt x nstate), d output/d
 * input (noutpt x ninput); column-major, [i + rows*j] = d out_i / d in_j. */
typedef void STDCALL usrsub_state_partial_fn(int *id, double *time, double *par, int *npar,
                                             int *iflag, int *nstate, double *states,
                                             int *ninput, double *input, int *noutpt,
                                             double *matrix);

/* ---- Entries the library exports ---------------------------------------- */

USRSUB_EXPORT usrsub_coupler_fn COUSUB;
USRSUB_EXPORT usrsub_coupler_fn COUXX;
USRSUB_EXPORT usrsub_coupler_fn COUXX2;

/* Default force entries dispatch on par[0]: 1 bushing, 2 mount limits, 3 flexible joint. */
USRSUB_EXPORT usrsub_gfosub_fn GFOSUB;
USRSUB_EXPORT usrsub_fiesub_fn FIESUB;

/* Named entries (for usrsub_fnc_name): the same USER list without par[0]. */
USRSUB_EXPORT usrsub_gfosub_fn ABM_BUSHING;
USRSUB_EXPORT usrsub_gfosub_fn MOUNT_LIMITS;
USRSUB_EXPORT usrsub_gfosub_fn FLEX_JOINT;
USRSUB_EXPORT usrsub_fiesub_fn ABM_BUSHING_FIELD;
USRSUB_EXPORT usrsub_fiesub_fn MOUNT_LIMITS_FIELD;
USRSUB_EXPORT usrsub_fiesub_fn FLEX_JOINT_FIELD;

/* The bushing with internal states (par[0] = 1, as GFOSUB's without markers). */
USRSUB_EXPORT usrsub_yfosub_fn YFOSUB;
USRSUB_EXPORT usrsub_state_partial_fn YFOXX;
USRSUB_EXPORT usrsub_state_partial_fn YFOXU;
USRSUB_EXPORT usrsub_state_partial_fn YFOYX;
USRSUB_EXPORT usrsub_state_partial_fn YFOYU;

/* Every entry again under the name a Linux solver looks it up by: lower case
 * with a trailing underscore, as Adams' C port header and gfortran spell it
 * (docs/interface.md §1). Each is the same function as its upper-case name. */
USRSUB_EXPORT usrsub_coupler_fn cousub_;
USRSUB_EXPORT usrsub_coupler_fn couxx_;
USRSUB_EXPORT usrsub_coupler_fn couxx2_;
USRSUB_EXPORT usrsub_gfosub_fn gfosub_;
USRSUB_EXPORT usrsub_fiesub_fn fiesub_;
USRSUB_EXPORT usrsub_gfosub_fn abm_bushing_;
USRSUB_EXPORT usrsub_gfosub_fn mount_limits_;
USRSUB_EXPORT usrsub_gfosub_fn flex_joint_;
USRSUB_EXPORT usrsub_fiesub_fn abm_bushing_field_;
USRSUB_EXPORT usrsub_fiesub_fn mount_limits_field_;
USRSUB_EXPORT usrsub_fiesub_fn flex_joint_field_;
USRSUB_EXPORT usrsub_yfosub_fn yfosub_;
USRSUB_EXPORT usrsub_state_partial_fn yfoxx_;
USRSUB_EXPORT usrsub_state_partial_fn yfoxu_;
USRSUB_EXPORT usrsub_state_partial_fn yfoyx_;
USRSUB_EXPORT usrsub_state_partial_fn yfoyu_;

/* ---- Utilities a host provides (resolved from the host at load time) ---- */

void c_sysary(const char *fnc, const int *ipar, int nsize, double *states, int *nstates,
              int *errflg);
void c_sysfnc(const char *fnc, const int *ipar, int nsize, double *value, int *errflg);
void c_errmes(int errflg, const char *msg, int id, const char *endflg);
void c_usrmes(int msgflg, const char *msg, int id, const char *msgtyp);
void c_gtstrg(int id, char *string, int *nchars, int *istat);
/* exists: non-zero when the model declares units. scales: four values, the
 * size in SI of the model's unit of time, length, force and mass, in that
 * order (angles are radians); units: twelve characters, four names of three
 * characters, no terminator. The Adams-compatible layout that published user
 * code reads (docs/interface.md §1, docs/sources.md). */
void c_gtunts(int *exists, double *scales, char *units);

/* The other utilities of the Adams-compatible C interface (docs/interface.md
 * §5.2): scalars by value, results through pointers; iord is the order of the
 * derivative asked for (0, 1, 2). */
void c_rcnvrt(const char *sys1, const double *coord1, const char *sys2, double *coord2,
              int *istat);
void c_tcnvrt(const char *sys1, const double *coord1, const char *sys2, double *coord2,
              int *istat);
void c_step(double x, double x0, double h0, double x1, double h1, int iord, double *value,
            int *errflg);
void c_step5(double x, double x0, double h0, double x1, double h1, int iord, double *value,
             int *errflg);
void c_havsin(double x, double x0, double h0, double x1, double h1, int iord, double *value,
              int *errflg);
/* vec: iord 0: the force; 1: its slopes in x and dxdt; 2: its second
 * derivatives in (x, x), (x, dxdt), (dxdt, dxdt) */
void c_impact(double x, double dxdt, double x1, double k, double e, double cmax, double d,
              int iord, double *vec, int *errflg);
void c_bistop(double x, double dxdt, double x1, double x2, double k, double e, double cmax,
              double d, int iord, double *vec, int *errflg);
void c_poly(double x, double x0, const double *par, int npar, int iord, double *value,
            int *errflg);
void c_cheby(double x, double x0, const double *par, int npar, int iord, double *value,
             int *errflg);
void c_forcos(double x, double x0, double w, const double *par, int npar, int iord,
              double *value, int *errflg);
void c_forsin(double x, double x0, double w, const double *par, int npar, int iord,
              double *value, int *errflg);
void c_shf(double x, double x0, double a, double w, double phi, double b, int iord,
           double *value, int *errflg);
void c_akispl(double xval, double zval, int id, int iord, double *array, int *errflg);
void c_cubspl(double xval, double zval, int id, int iord, double *array, int *errflg);
void c_quispl(double xval, double zval, int id, int iord, double *array, int *errflg);
/* number: the capacity in, the count out */
void c_gtaray(int id, double *array, int *number, int *istat);
void c_getstm(double *time);
void c_timget(double *time);
void c_getinm(int *value);
void c_getmod(int *mode);
void c_getint(char *value);
void c_getver(char *value);
void c_syspar(const char *fnc, const int *ipar, int nsize, const double *partials, int npart,
              int *errflg);
void c_cusfnc(const char *fnc, const double *rpar, int nsize, double *state, int *errflg);
void c_get_step_info(int *flag);
void c_analys(const char *antype, const char *cid, double timbeg, double timend, int init,
              int *istat);
void c_datout(int *istat);
void c_modify(const char *command, int *istat);

enum usrsub_gtunts_scale {
    USRSUB_GTUNTS_TIME = 0,   /* second */
    USRSUB_GTUNTS_LENGTH = 1, /* metre */
    USRSUB_GTUNTS_FORCE = 2,  /* newton */
    USRSUB_GTUNTS_MASS = 3,   /* kilogram */
    USRSUB_GTUNTS_COUNT = 4
};
#define USRSUB_GTUNTS_NAMES_LENGTH 12 /* four names of three characters */

#ifdef __cplusplus
}
#endif

#endif
