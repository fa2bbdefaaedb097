/*
 * A user-subroutine element of the model bound to the functions of its
 * library, and the calls of those functions with the host's bookkeeping
 * (current call, dependency records, host-call counts).
 */
#ifndef HX_BINDING_H
#define HX_BINDING_H

#include "host.h"
#include "loader.h"
#include "model.h"
#include "usrsub/solver_abi.h"

typedef enum hx_binding_kind {
    HX_BIND_COUPLER, /* Constraint_Coupler: COUSUB, COUXX, COUXX2 */
    HX_BIND_GFOSUB,  /* Force_Vector_TwoBody */
    HX_BIND_FIESUB   /* Force_Field */
} hx_binding_kind;

typedef struct hx_binding {
    hx_binding_kind kind;
    int index;           /* in the model's couplers[] or forces[] */
    int id;
    const char *element; /* "Constraint_Coupler", "Force_Vector_TwoBody", "Force_Field" */
    char *library;       /* resolved path */
    const char *names[3];
    usrsub_coupler_fn *coupler[3]; /* phi, dphi/dM, d2phi/dM2 */
    usrsub_gfosub_fn *gfosub;
    usrsub_fiesub_fn *fiesub;
    double *par;         /* the USER list handed to the entries */
    int npar;
    hx_dependencies deps; /* declared in the dependency pass */
    int warned_undeclared;
} hx_binding;

typedef struct hx_bindings {
    hx_binding *items;
    int count;
    hx_loader loader;
} hx_bindings;

/* Loads the libraries and resolves the functions of every user element. */
int hx_bind(const hx_model *m, hx_bindings *b, usrsub_message *msg);
void hx_bindings_free(hx_bindings *b);

/* The binding of a coupler or force element, or NULL (built-in element). */
hx_binding *hx_binding_of_coupler(hx_bindings *b, int coupler_index);
hx_binding *hx_binding_of_force(hx_bindings *b, int force_index);

/* A call record for b, recording into (iflag) or checking against b->deps. */
void hx_binding_call_init(hx_binding *b, hx_call *call, int iflag);

/* The dependency pass of every element (iflag = 1) at the current frames, as a
 * solver runs it before the analysis; returns -1 when an element stopped. */
int hx_dependency_passes(hx_bindings *b, const hx_model *m, const hx_frame *frames);

/* Calls; call (may be NULL) receives the host's record of the call. With
 * iflag set, the host records the element's queries into b->deps. */
void hx_call_coupler(hx_binding *b, int which, double time, const double *disp, int ndisp,
                     int iflag, double *out, hx_call *call);
void hx_call_gfosub(hx_binding *b, double time, int dflag, int iflag, double result[6],
                    hx_call *call);
void hx_call_fiesub(hx_binding *b, double time, const double disp[6], const double velo[6],
                    int dflag, int iflag, double field[6], double dfddis[36], double dfdvel[36],
                    hx_call *call);

#endif
