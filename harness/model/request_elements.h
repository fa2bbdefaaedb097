/*
 * The requests the harness answers itself (docs/interface.md §7.13): the
 * one builder both readers call (a Post_Request of type MARKER_DISPLACEMENT,
 * MARKER_VELOCITY or EXPRESSION; an Adams REQUEST with DISPLACEMENT,
 * VELOCITY or F1..F8), each expression parsed where it is written. Private
 * to the model layer.
 */
#ifndef HX_MODEL_REQUEST_ELEMENTS_H
#define HX_MODEL_REQUEST_ELEMENTS_H

#include "model/draft.h"
#include "model/expr/expr.h"
#include "model/xml_schema.h"

/* A new request of a kind with markers I, J, RM as written (0: the world),
 * or NULL with the draft failed (a second request of the id, out of
 * memory). label names it in messages ("Post_Request 5", "REQUEST/5"). */
hx_request *hx_draft_request(hx_draft *d, int id, enum hx_request_kind kind,
                             const int marker_ids[3], int line, const char *label);

/* Component k (0 .. 7) of an expression request: text parsed as written at
 * where; "NULL" or blank is 0 (no program). 0, or -1 with the draft failed
 * ("file:line:column: what", label and the component in front). */
int hx_draft_request_expression(hx_draft *d, hx_request *q, int k, const char *text,
                                const hx_expr_source *where, const char *label);

/* A Post_Request in a form the harness answers (not a REQSUB). */
void hx_build_builtin_request(hx_draft *d, const hx_element_read *e);

#endif
