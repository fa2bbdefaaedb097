/*
 * A user-subroutine element of the model bound to the functions of its
 * library, and the calls of those functions: each call is bound to the host
 * (host/call.h) with the state its queries are answered from.
 */
#ifndef HX_HOST_BINDING_H
#define HX_HOST_BINDING_H

#include "host/call.h"
#include "host/loader.h"
#include "model/model.h"
#include "usrsub/solver_abi.h"

typedef enum hx_binding_kind {
    HX_BIND_COUPLER, /* Constraint_Coupler: COUSUB, COUXX, COUXX2 */
    HX_BIND_GFOSUB,  /* Force_Vector_TwoBody, Force_Vector_OneBody, Force_Scalar_TwoBody */
    HX_BIND_FIESUB,  /* Force_Field */
    HX_BIND_YFOSUB,  /* Force_StateEqn: YFOSUB, YFOXX, YFOXU, YFOYX, YFOYU */
    HX_BIND_REQSUB,  /* Post_Request: eight values */
    HX_BIND_VARSUB,  /* Reference_Variable of type USERSUB: one value */
    HX_BIND_DIFSUB,  /* Control_Diff: its state's rate */
    HX_BIND_MOTSUB   /* Motion_Joint: the joint's motion, its rate and acceleration */
} hx_binding_kind;

/* The routines that are not forces, in the classic form: every argument by
 * address (docs/interface.md §7.12). REQSUB(id, time, par, npar, iflag,
 * result[8]); VARSUB and DIFSUB (dflag) and MOTSUB (iord) return one value. */
typedef void STDCALL hx_reqsub_fn(int *id, double *time, double *par, int *npar, int *iflag,
                                  double *result);
typedef void STDCALL hx_value_fn(int *id, double *time, double *par, int *npar, int *flag,
                                 int *iflag, double *value);
struct hx_record;

/* The last call of a binding, kept where another process can read it when
 * the call never returns (check runs each element in a child process). */
typedef struct hx_call_log {
    volatile unsigned long begun;    /* calls begun */
    volatile unsigned long returned; /* calls that returned */
    const char *routine;             /* one of the binding's names */
    int iflag, dflag;
    double time;
    int nargs;
    double args[12];                 /* disp (and velo) of couplers and FIESUB; the
                                      * first inputs of YFOSUB */
} hx_call_log;

typedef struct hx_binding {
    hx_binding_kind kind;
    int index;           /* in the model's couplers[], forces[], stateeqns[] or routines[] */
    int id;
    const char *element; /* "Constraint_Coupler", "Force_Vector_TwoBody", "Force_Field",
                          * "Force_StateEqn", "Post_Request", ... */
    char *library;       /* resolved path */
    const char *names[5]; /* as the model names them, or the default names */
    /* the symbols bound for them: NAME, name_ or name (hx_loader_entry) */
    char symbols[5][HX_ENTRY_NAME_MAX];
    usrsub_coupler_fn *coupler[3]; /* phi, dphi/dM, d2phi/dM2 */
    usrsub_gfosub_fn *gfosub; /* GFOSUB, or VFOSUB / VTOSUB (part): three values */
    enum hx_user_output part;
    usrsub_fiesub_fn *fiesub;
    usrsub_yfosub_fn *yfosub;
    /* YFOXX, YFOXU, YFOYX, YFOYU (names[1..4]); NULL when the library does not
     * export the default name: the harness then takes differences of YFOSUB */
    usrsub_state_partial_fn *state_partial[4];
    hx_reqsub_fn *reqsub;
    hx_value_fn *value; /* VARSUB, DIFSUB, MOTSUB */
    /* the Adams C-style form (host/records.h): the element's record and the
     * functions bound; NULL for the classic form */
    struct hx_record *record;
    double *par;         /* the USER list handed to the entries */
    int npar;
    /* GFOSUB elements: the library's FIESUB twin of the element, when it
     * exports one (docs/interface.md §3.0: NAME_FIELD for a named entry NAME,
     * FIESUB for GFOSUB), with the USER list less the I and J marker ids; the
     * implicit integrator takes its partials from it. NULL: none. */
    usrsub_fiesub_fn *twin;
    char *twin_name;
    double *twin_par;
    int twin_npar;
    hx_dependencies deps; /* declared in the dependency pass */
    double latest_time;   /* the latest time any of its functions was called at */
    /* bytes the library kept allocated across the element's first calls (its
     * dependency pass, where a library sets an element up), as the C
     * library's allocator counts them; -1: not measured */
    long setup_bytes;
    /* what the host has reported of this element: each read once */
    hx_noted_queries reported_undeclared, reported_refused;
    unsigned long long reported_unoffered, reported_misused; /* host/utilities.h bits */
    unsigned long long reported_non_finite; /* noted in a dependency pass (utilities.h) */
    /* what the outputs hold before each call: 0, as a solver zeroes them; check
     * fills them with NaN once, to find an output the entry never writes */
    double output_fill;
    const hx_model *model;
    hx_messages *messages;
    hx_call_log *log;    /* NULL: calls are not logged */
} hx_binding;

typedef struct hx_bindings {
    hx_binding *items;
    int count;
    hx_loader loader;
} hx_bindings;

/* Loads the libraries and resolves the functions of every user element. */
int hx_bind(const hx_model *m, hx_messages *messages, hx_bindings *b, hx_message *msg);
void hx_bindings_free(hx_bindings *b);

/* The binding of a coupler or force element, or NULL (built-in element). */
hx_binding *hx_binding_of_coupler(hx_bindings *b, int coupler_index);
hx_binding *hx_binding_of_force(hx_bindings *b, int force_index);
hx_binding *hx_binding_of_stateeqn(hx_bindings *b, int element_index);
hx_binding *hx_binding_of_routine(hx_bindings *b, int routine_index);

/* The name of function `which` of b as the library exports it (the symbol
 * bound), or as the model names it when it is not exported. */
const char *hx_binding_routine(const hx_binding *b, int which);

/* A call record of function `which` of b at state s, recording into (iflag)
 * or checking against b->deps. */
void hx_binding_call_init(hx_binding *b, hx_call *call, int which, const hx_frames *s, int iflag);


/* Calls at state s (its time is the call's time); call (may be NULL) is the
 * record the call is bound with, set up by hx_binding_call_init. */
void hx_invoke_coupler(hx_binding *b, int which, const hx_frames *s, const double *disp, int ndisp,
                     int iflag, double *out, hx_call *call);
/* A Force_Vector_TwoBody's, Force_Vector_OneBody's or Force_Scalar_TwoBody's
 * routine: values receives what the routine itself returns, in the layout
 * its entry type documents (hx_force_routine_values of them: GFOSUB's force
 * and torque, VFOSUB's force, VTOSUB's torque, SFOSUB's one value). What the
 * harness makes of them (their axes, the direction of a scalar) is the
 * dynamics' (sim/dynamics/element_forces.h); check judges these values. */
void hx_invoke_gfosub(hx_binding *b, const hx_frames *s, int dflag, int iflag, double *values,
                      hx_call *call);
void hx_invoke_fiesub(hx_binding *b, const hx_frames *s, const double disp[6], const double velo[6],
                    int dflag, int iflag, double field[6], double dfddis[36], double dfdvel[36],
                    hx_call *call);
/* A routine that is not a force at state s: REQSUB's eight values, or the
 * one value of VARSUB, DIFSUB (flag: dflag) or MOTSUB (flag: iord). */
void hx_invoke_routine(hx_binding *b, const hx_frames *s, int flag, int iflag, double *values,
                     hx_call *call);
/* YFOSUB of a Force_StateEqn at state s (its time): states (nstate) and
 * input (ninput), the caller's copies, which a library may write into;
 * stated (nstate) and output (6) receive its results. */
void hx_invoke_yfosub(hx_binding *b, const hx_frames *s, double *states, double *input, int dflag,
                    int iflag, double *stated, double output[6], hx_call *call);
/* Partial routine `which` (0 YFOXX, 1 YFOXU, 2 YFOYX, 3 YFOYU; it must be
 * exported) at states and input, into matrix (column-major, its rows first). */
void hx_invoke_yfosub_partial(hx_binding *b, int which, const hx_frames *s, double *states,
                           double *input, double *matrix, hx_call *call);

/* The FIESUB twin of a GFOSUB element (b->twin must be set), at the
 * deformation of its I marker relative to its J marker; it may not query.
 * Its messages go to `messages` (the caller's, kept apart from the session's:
 * a twin that refuses the list disqualifies itself, it does not stop the run). */
void hx_invoke_twin(hx_binding *b, const hx_frames *s, const double disp[6], const double velo[6],
                  double field[6], double dfddis[36], double dfdvel[36], hx_messages *messages);

#endif
