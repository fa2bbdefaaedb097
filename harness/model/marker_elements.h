/*
 * The elements that act at a marker (docs/interface.md §7.13, §8.3): which
 * force elements' forces a function of the function language reads by the
 * element's id (SFORCE, VFORCE, ...), and which elements act between two
 * markers whose forces the harness does not sum at a marker yet (FX .. TM,
 * REQUEST/FORCE refuse those).
 */
#ifndef HX_MODEL_MARKER_ELEMENTS_H
#define HX_MODEL_MARKER_ELEMENTS_H

#include <stddef.h>

#include "model/model.h"

/* Whether an element with markers a and b acts at marker i between i and j
 * (j < 0: between i and any marker): a or b is i, and the other is j. */
int hx_marker_between(int a, int b, int i, int j);

/* The force element that the element-force function `function`
 * (model/expr/functions.h: HX_FN_SFORCE, HX_FN_VFORCE, HX_FN_VTORQ,
 * HX_FN_GFORCE, HX_FN_BUSHING, HX_FN_BEAM, HX_FN_SPDP, HX_FN_FIELD) names with id: 0 with *force 0
 * and *index in m->loads (an element by expressions) or *force 1 and *index
 * in m->forces (an element by a user routine); -1 with what it names in
 * `what` ("Force_Field (FIELD) 7 in the model") when m has none. */
int hx_marker_element_find(const hx_model *m, int function, int id, int *force, int *index,
                           char *what, size_t size);

/* The first element acting at marker i between i and j (j < 0: any) whose
 * force the harness does not sum at a marker: a Force_StateEqn, or a
 * Constraint_General whose I marker is i on ground (j < 0 only). 1 with "Force_StateEqn 3 (line 12)"
 * in what, else 0. */
int hx_marker_unsummed(const hx_model *m, int i, int j, char *what, size_t size);

#endif
