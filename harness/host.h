/*
 * The harness as a host: it answers the library's utility calls (c_sysary,
 * c_sysfnc, c_errmes, c_usrmes, c_gtstrg, c_gtunts) from the attached model and
 * the current frames of its bodies, records what an element asks for in its
 * dependency pass, and notes reads outside those declared dependencies.
 *
 * The current call is thread-local, so several threads may evaluate elements
 * at once against the same (read-only) frames.
 */
#ifndef HX_HOST_H
#define HX_HOST_H

#include <stddef.h>
#include <stdio.h>

#include "kinematics.h"
#include "model.h"

#define HX_MAX_QUERIES 16

typedef struct hx_query {
    char fnc[8];
    int function; /* the host's code for fnc, -1 when unknown */
    int ipar[4];
    int nsize;
    int is_array; /* c_sysary (1) or c_sysfnc (0) */
} hx_query;

typedef struct hx_dependencies {
    int count;
    hx_query query[HX_MAX_QUERIES];
    int overflow;
} hx_dependencies;

/* One call of a user subroutine, as the host sees it. */
typedef struct hx_call {
    const char *element; /* for messages */
    int id;
    int dependency_pass;       /* iflag != 0: record queries into declared */
    hx_dependencies *declared; /* may be NULL: nothing recorded or checked */
    int host_calls;            /* c_sysary and c_sysfnc calls made */
    int undeclared;            /* queries outside declared (evaluation only) */
    hx_query first_undeclared;
    unsigned used;             /* bit k: declared query k was asked */
    int *warned;               /* set once the element's undeclared read was reported */
    int perturb_query;         /* -1, or the declared query whose answer is shifted */
    int perturb_component;
    double perturb_delta;
} hx_call;

void hx_host_attach(const hx_model *m);
/* Frames the host answers from (kept by pointer, not copied). */
void hx_host_set_frames(const hx_frame *bodies, double time);
/* World frame of marker index (-1: the world) at bodies: the cached one when
 * bodies are the frames set last, else computed into scratch. */
const hx_frame *hx_host_marker_frame(const hx_frame *bodies, int index, hx_frame *scratch);
/* The cache slot of marker index (NULL when the host does not keep it): it
 * holds the marker's world frame at the frames set last, for the session. */
const hx_frame *hx_host_marker_slot(int index);

void hx_call_init(hx_call *c, const char *element, int id, int dependency_pass,
                  hx_dependencies *declared);
void hx_host_begin_call(hx_call *c);
void hx_host_end_call(void);

/* c_errmes with "STOP" asks the host to end the run. */
int hx_host_stop_requested(void);
const char *hx_host_stop_message(void);
void hx_host_clear_stop(void);

/* Where c_errmes and c_usrmes text is printed (stderr by default; NULL: silent). */
void hx_host_set_message_stream(FILE *f);
int hx_host_error_count(void);
const char *hx_host_last_error(void);
int hx_host_notice_count(void);
const char *hx_host_last_notice(void);
void hx_host_reset_messages(void);

/* "DISP(11,21,21)" */
const char *hx_query_text(const hx_query *q, char *text, size_t size);
/* Text of all declared queries, space-separated ("none" when empty). */
const char *hx_dependencies_text(const hx_dependencies *d, char *text, size_t size);

/* Answers a query from frames directly (what c_sysary/c_sysfnc answer with).
 * Returns the number of values, or -1 for an unknown function or marker. */
int hx_answer_query(const hx_model *m, const hx_frame *bodies, const char *fnc,
                    const int *ipar, int nsize, double *values);

#endif
