/*
 * A model under construction, private to the model layer: the XML reader
 * fills it element by element (elements.c, from the descriptions of
 * xml_schema.h), and so does the dataset reader (adm/), then the resolve passes (resolve.c) turn the ids the
 * elements name into indices and frames, and the model is handed over.
 */
#ifndef HX_MODEL_DRAFT_H
#define HX_MODEL_DRAFT_H

#include <stdio.h>

#include "base/message.h"
#include "model/model.h"

/* What an element said before its references are resolved. */
typedef struct raw_marker {
    int body_id, rm_id;
    double pos[3], R[9]; /* relative to rm_id's frame, else to the world */
    int state;           /* 0 unresolved, 1 resolving, 2 resolved */
} raw_marker;

typedef struct raw_body {
    int cg_id, im_id, lprf_id;
    double inertia[9]; /* the tensor, in the IM marker's axes, about its origin */
} raw_body;

typedef struct raw_refs {
    int ids[4]; /* marker or joint ids, 0 when absent */
    char freedom[3];
} raw_refs;

/* A Force_StateEqn's references. */
typedef struct raw_stateeqn {
    int marker_ids[3]; /* i_marker_id, j_floating_marker_id, ref_marker_id */
    int x_array_id, u_array_id, ic_array_id; /* 0 when absent */
} raw_stateeqn;

typedef struct hx_draft {
    hx_model *m;
    const char *path;
    FILE *warnings;
    hx_message *msg;
    int failed;
    int ground_line;
    raw_marker *rmarkers; /* parallel to m->markers */
    raw_body *rbodies;    /* parallel to m->bodies */
    raw_refs *rjoints, *rcouplers, *rforces, *rloads;
    raw_stateeqn *rstateeqns; /* parallel to m->stateeqns */
    int cap_markers, cap_bodies, cap_joints, cap_couplers, cap_forces, cap_loads, cap_strings;
    int cap_variables, cap_arrays, cap_stateeqns, cap_routines;
    int cap_splines, cap_pinputs, cap_poutputs, cap_expressions;
    int cap_requests, cap_gcons;
    int *marker_slots;    /* open addressing over the markers read so far, by id */
    int nmarker_slots;
    int *body_slots;      /* the same over the bodies */
    int nbody_slots;
} hx_draft;

/* Starts a draft of a new model read from path (from_text: the text is in
 * memory, path only names it); 0, or -1 with msg (out of memory). */
int hx_draft_open(hx_draft *d, const char *path, int from_text, FILE *warnings, hx_message *msg);
/* Ends a draft: resolves it when status is 0, frees the raw arrays; the
 * model, or NULL (the model freed) when status or the resolve failed. */
hx_model *hx_draft_finish(hx_draft *d, int status);

/* The first error wins: "file:line: what"; the reader then stops (draft.c). */
void hx_draft_fail(hx_draft *d, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void hx_draft_warn(hx_draft *d, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* A zeroed new slot at the end of a model array (and of its parallel raw
 * array, when raw is not NULL); NULL when out of memory (the draft failed). */
void *hx_draft_push(hx_draft *d, void **array, int *count, int *capacity, size_t size,
                    void **raw, size_t raw_size);

/* The index of the marker read so far with this id, or -1; and the marker
 * just pushed entered (a model of thousands of markers checks each new id,
 * and finds each marker's body, without a pass over all);
 * hx_draft_enter_marker is 0, or -1 (failed). */
int hx_draft_find_marker(const hx_draft *d, int id);
int hx_draft_enter_marker(hx_draft *d);
/* The same for bodies. */
int hx_draft_find_body(const hx_draft *d, int id);
int hx_draft_enter_body(hx_draft *d);

/* The resolve passes; 0, or -1 with the draft failed. */
int hx_draft_resolve(hx_draft *d);
/* The state equations' pass (stateeqn_elements.c): arrays, variables
 * and Force_StateEqn references, after the markers; 0 or -1. */
int hx_draft_resolve_stateeqns(hx_draft *d);
/* The routines' pass (routine_elements.c): Motion_Joint's joints, after the
 * joints; 0 or -1. */
int hx_draft_resolve_routines(hx_draft *d);
/* The variables' pass (variable_programs.c): the expressions of the
 * Reference_Variable elements linked, the order they are computed in
 * (model.h's variable_order), a cycle of VARVALs refused; after the arrays
 * and the routines; 0 or -1. */
int hx_draft_link_variables(hx_draft *d);
/* The general constraints' pass (gcon_elements.c): their I markers, their
 * expressions linked and their inputs checked; 0 or -1. */
int hx_draft_link_gcons(hx_draft *d);
/* The requests' pass (request_elements.c): their markers' indices, their
 * expressions linked against the model; 0 or -1. */
int hx_draft_resolve_requests(hx_draft *d);

#endif
