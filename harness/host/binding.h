/*
 * A user-subroutine element of the model bound to the functions of its
 * library: the symbols found (binding.c), the element's declared
 * dependencies and what the host has reported of it, and the log of its last
 * call. Calling the functions is host/invoke.h's.
 */
#ifndef HX_HOST_BINDING_H
#define HX_HOST_BINDING_H

#include "host/call.h"
#include "host/loader.h"
#include "model/model.h"
#include "usrsub/solver_abi.h"

/* What a bound element is, by the model element it stands for; each kind has
 * its calling convention (host/invoke.h). */
typedef enum hx_binding_kind {
    HX_BIND_COUPLER,  /* Constraint_Coupler: COUSUB, COUXX, COUXX2 */
    HX_BIND_FORCE,    /* Force_Vector_TwoBody, Force_Vector_OneBody, Force_Scalar_TwoBody: a
                       * routine that asks the host for the state (GFOSUB, VFOSUB, VTOSUB,
                       * SFOSUB) */
    HX_BIND_FIELD,    /* Force_Field: FIESUB, handed the deformation */
    HX_BIND_STATEEQN, /* Force_StateEqn: YFOSUB, YFOXX, YFOXU, YFOYX, YFOYU */
    HX_BIND_REQUEST,  /* Post_Request: REQSUB, eight values */
    HX_BIND_VARIABLE, /* Reference_Variable of type USERSUB: VARSUB, one value */
    HX_BIND_DIFF,     /* Control_Diff: DIFSUB, its state's rate */
    HX_BIND_MOTION    /* Motion_Joint: MOTSUB, the joint's motion, rate and acceleration */
} hx_binding_kind;

/* Which of the model's arrays a binding's index refers to. */
typedef enum hx_binding_family {
    HX_FAMILY_COUPLER,  /* couplers[] */
    HX_FAMILY_FORCE,    /* forces[]: HX_BIND_FORCE and HX_BIND_FIELD */
    HX_FAMILY_STATEEQN, /* stateeqns[] */
    HX_FAMILY_ROUTINE   /* routines[]: request, variable, diff, motion */
} hx_binding_family;

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

/* The functions a binding calls, by kind. */
typedef union hx_binding_functions {
    usrsub_coupler_fn *coupler[3]; /* COUPLER: phi, dphi/dM, d2phi/dM2 */
    usrsub_gfosub_fn *force;       /* FORCE: GFOSUB, VFOSUB, VTOSUB or SFOSUB (part) */
    usrsub_fiesub_fn *field;       /* FIELD */
    struct {
        usrsub_yfosub_fn *rates;   /* YFOSUB */
        /* YFOXX, YFOXU, YFOYX, YFOYU (names[1..4]); NULL when the library does
         * not export the default name: the harness then takes differences of
         * YFOSUB */
        usrsub_state_partial_fn *partial[4];
    } stateeqn;
    hx_reqsub_fn *request;         /* REQUEST */
    hx_value_fn *value;            /* VARIABLE, DIFF, MOTION */
} hx_binding_functions;

typedef struct hx_binding {
    hx_binding_kind kind;
    int index;           /* in the model's array of the binding's family */
    int id;
    const char *element; /* "Constraint_Coupler", "Force_Vector_TwoBody", "Force_Field",
                          * "Force_StateEqn", "Post_Request", ... */
    char *library;       /* resolved path */
    const char *names[5]; /* as the model names them, or the default names */
    /* the symbols bound for them: NAME, name_ or name (hx_loader_entry) */
    char symbols[5][HX_ENTRY_NAME_MAX];
    hx_binding_functions fn; /* the classic form's (all NULL for the C-style form) */
    enum hx_user_output part; /* FORCE: what its routine returns (model.h) */
    /* the Adams C-style form (host/records.h): the element's record and the
     * functions bound; NULL for the classic form */
    struct hx_record *record;
    double *par;         /* the USER list handed to the entries */
    int npar;
    /* FORCE elements: the library's FIESUB twin of the element, when it
     * exports one (docs/interface.md §3.0: NAME_FIELD for a named entry NAME,
     * FIESUB for GFOSUB), with the USER list less the I and J marker ids; the
     * implicit integrator takes its partials from it. NULL: none. */
    usrsub_fiesub_fn *twin;
    char *twin_name;
    double *twin_par;
    int twin_npar;
    hx_dependencies deps; /* declared in the dependency pass */
    /* per declared query, per value: its slot among the algebraic loop's
     * inputs (an acceleration or a force: host/loop_queries.h), for a REQSUB
     * among the model's output queries; -1 elsewhere */
    int loop_slot[HX_MAX_QUERIES][6];
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

/* The binding of element `index` of the model's array `family`, or NULL (a
 * built-in coupler; no other element of those arrays is built in). */
hx_binding *hx_bindings_find(hx_bindings *bs, hx_binding_family family, int index);

/* The family of a kind. */
hx_binding_family hx_binding_family_of(hx_binding_kind kind);
/* The model line of b's element. */
int hx_binding_line(const hx_model *m, const hx_binding *b);

/* The name of function `which` of b as the library exports it (the symbol
 * bound), or as the model names it when it is not exported. */
const char *hx_binding_routine(const hx_binding *b, int which);

/* A call record of function `which` of b at frames fr, recording into
 * (iflag) or checking against b->deps. */
void hx_binding_call_init(hx_binding *b, hx_call *call, int which, const hx_frames *fr, int iflag);

#endif
