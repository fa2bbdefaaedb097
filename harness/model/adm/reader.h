/*
 * The dataset reader's state, shared by its passes and builders (dataset.c,
 * the build_*.c files): the checked statements, the index of their ids, and
 * the helpers builders read values and report through. Private to adm/.
 */
#ifndef HX_MODEL_ADM_READER_H
#define HX_MODEL_ADM_READER_H

#include "model/adm/keywords.h"
#include "model/draft.h"

/* A checked statement. */
typedef struct hx_adm_entry {
    const hx_adm_spec *spec;
    int line;
    int id;              /* 0 for statements without one */
    hx_adm_value *values;
    char *buffer;        /* the statement's text, which the values point into */
    int unsimulated;     /* not built: a warning named it */
    double frame[12];    /* PART: its frame (p, R); MARKER: its world frame at t = 0 */
    int frame_state;     /* MARKER: 0 not placed, 1 placing, 2 placed */
    int index;           /* PART, MARKER: its index in the model's bodies or markers; -1 */
} hx_adm_entry;

typedef struct hx_adm_reader {
    hx_draft *d;
    const char *path;
    hx_adm_entry *entries;
    int nentries, capacity;
    int *slots;          /* open addressing: (statement, id) -> entry index */
    int nslots;
    unsigned char *noted; /* per statement of the table: a setting already noted */
} hx_adm_reader;

/* The entry of statement NAME (the table's spelling) with this id, or NULL. */
hx_adm_entry *hx_adm_find(const hx_adm_reader *r, const char *name, int id);

/* A keyword's values by its full name (never NULL: absent keywords read as
 * not present). */
const hx_adm_value *hx_adm_get(const hx_adm_entry *e, const char *keyword);
int hx_adm_has(const hx_adm_entry *e, const char *keyword);
double hx_adm_number(const hx_adm_entry *e, const char *keyword, int k, double fallback);
/* The first id of an ID keyword, 0 when absent. */
int hx_adm_ref(const hx_adm_entry *e, const char *keyword);
/* The (first) text of a keyword, NULL when absent. */
const char *hx_adm_text(const hx_adm_entry *e, const char *keyword);

/* "STATEMENT/ID" of an entry into out. */
const char *hx_adm_label(const hx_adm_entry *e, char *out, size_t size);
/* Fails the draft: "file:line: STATEMENT/ID: what"; returns -1. */
int hx_adm_fail(hx_adm_reader *r, const hx_adm_entry *e, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* The entry acts on the dynamics in a way the harness does not model: a
 * warning naming it, its line and why, counted in m->nunsimulated (run and
 * bench refuse, check still verifies the user elements); its expressions
 * kept (m->expressions). */
void hx_adm_unsimulated(hx_adm_reader *r, hx_adm_entry *e, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* A note on the warnings stream, not counted. */
void hx_adm_note(hx_adm_reader *r, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* 1 when the expression is USER(...). */
int hx_adm_is_user(const char *expression);
/* The type flag of a JOINT (REVOLUTE, ...), NULL when none is given. */
const char *hx_adm_joint_type(const hx_adm_entry *e);

/* The builders (build_*.c), one per statement the table builds. */
int hx_adm_build_part(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_marker(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_joint(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_jprim(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_coupler(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_motion(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_gcon(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_gforce(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_sforce(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_field(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_springdamper(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_bushing(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_beam(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_force_stateeqn(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_diff(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_variable(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_array(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_string(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_spline(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_request(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_units(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_accgrav(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_integrator(hx_adm_reader *r, hx_adm_entry *e);
int hx_adm_build_plant_port(hx_adm_reader *r, hx_adm_entry *e);

/* The markers' world frames at t = 0 into the draft, and the parts'
 * initial velocities (build_parts.c); after every statement is built. */
int hx_adm_place_markers(hx_adm_reader *r);
/* Whether each entry can be simulated: joints the model holds, and what
 * names an element that is not (an unsimulated JOINT's COUPLER, ...);
 * warnings for those that are not (simulated.c). */
int hx_adm_decide_simulated(hx_adm_reader *r);

#endif
