/*
 * One call of a user subroutine as the host sees it, and the ABI's binding.
 * The utilities a library calls back (c_sysary, c_errmes, ...) carry no
 * context, so the host keeps exactly one pointer per thread: the call bound
 * around the entry's invocation. The record says which state the queries are
 * answered from and where messages go, records the queries of a dependency
 * pass, and notes what the call read outside them or asked in vain.
 */
#ifndef HX_HOST_CALL_H
#define HX_HOST_CALL_H

#include "host/messages.h"
#include "host/queries.h"

#define HX_MAX_QUERIES 16
#define HX_MAX_NOTED 8

typedef struct hx_dependencies {
    int count;
    hx_query query[HX_MAX_QUERIES];
    int overflow;
} hx_dependencies;

/* Distinct queries noted during calls (reads outside the declared ones,
 * queries the host refused), with how often. */
typedef struct hx_noted_queries {
    int count;     /* all of them */
    int distinct;  /* kept in query[] (at most HX_MAX_NOTED) */
    hx_query query[HX_MAX_NOTED];
    double time[HX_MAX_NOTED]; /* when each was first seen */
} hx_noted_queries;

typedef struct hx_call {
    const char *element;       /* for messages: "Force_Vector_TwoBody" */
    int id;
    const char *routine;       /* the entry called: "GFOSUB" */
    const hx_model *model;     /* strings and units */
    const hx_frames *frames;    /* queries are answered from it */
    hx_messages *messages;
    int may_query;             /* the routine may call c_sysary/c_sysfnc */
    int dependency_pass;       /* iflag != 0: queries are recorded into declared */
    hx_dependencies *declared; /* may be NULL: nothing recorded or checked */
    int host_calls;            /* c_sysary and c_sysfnc calls made */
    hx_noted_queries undeclared; /* reads outside declared (evaluation only) */
    hx_noted_queries refused;    /* queries the host could not answer */
    /* what earlier calls of the element already reported (kept by its binding;
     * NULL: each call reports on its own), so that a read is reported once */
    hx_noted_queries *reported_undeclared, *reported_refused;
    /* utilities (host/utilities.h, one bit each) the call asked that the host
     * does not offer, or called with arguments it refused; and the element's
     * record of those already reported (NULL: each call reports on its own) */
    unsigned long long unoffered, misused;
    unsigned long long *reported_unoffered, *reported_misused;
    /* utilities called with a non-finite argument in a dependency pass (a
     * note, not a fault: hx_utility_non_finite), and those already noted */
    unsigned long long non_finite, *reported_non_finite;
    unsigned used;             /* bit k: declared query k was asked */
    int next_declared;         /* where the look-up starts: libraries ask in order */
    /* per declared query, per value: its slot among the algebraic loop's inputs
     * (an acceleration or a force, host/loop_queries.h), among the model's
     * output queries for a REQSUB (at_output), -1 elsewhere; NULL: none */
    const int (*loop_slot)[6];
    int at_output;             /* a REQSUB: its accelerations and forces from answers */
    const double *answers;     /* at_output: the model's output queries' values at the
                                * output time of the call, by slot; NULL (a call at any
                                * other time, check's probes): zeros, as in a dependency
                                * pass */
    int perturb_query;         /* -1, or the declared query whose answer is shifted */
    int perturb_component;
    double perturb_delta;
} hx_call;

void hx_call_init(hx_call *c, const char *element, int id, const char *routine,
                  const hx_model *model, const hx_frames *fr, hx_messages *messages,
                  int dependency_pass, hx_dependencies *declared);

/* The ABI's binding: the utilities answer for this call until unbound. */
void hx_host_bind(hx_call *c);
void hx_host_unbind(void);
hx_call *hx_host_bound(void);

/* "DISP(20,10,10) VEL(20,10,10,10)", or "none". */
const char *hx_dependencies_text(const hx_dependencies *d, char *text, size_t size);
const char *hx_noted_text(const hx_noted_queries *n, char *text, size_t size);
/* Adds a query to a note (when it is new, it is kept); returns 1 when new. */
int hx_note_query(hx_noted_queries *n, const hx_query *q, double time);

#endif
