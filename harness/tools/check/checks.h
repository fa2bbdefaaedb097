/*
 * The checks `usrsub-harness check` runs on each user element; each prints
 * its findings, naming the routine, the output and input at fault and the
 * point of the worst error, and returns the number of failures.
 *  - couplers: COUXX against differences of COUSUB and COUXX2 against
 *    differences of COUXX, at points that vary each joint on its own;
 *  - FIESUB: dfddis and dfdvel against differences of the field;
 *  - Force_StateEqn: YFOXX, YFOXU, YFOYX and YFOYU against differences of
 *    YFOSUB in each state and input;
 *  - GFOSUB (VFOSUB, VTOSUB, SFOSUB), REQSUB, VARSUB, DIFSUB: the dependency
 *    audit (every body or Control_Diff state the outputs depend on is
 *    reached by a declared query, every declared query is used, nothing is
 *    read outside them), at states and times spread over the first second;
 *  - MOTSUB: its rate (iord 1) against differences in time of its value
 *    (iord 0), and its acceleration (iord 2) against those of its rate;
 *  - every element: the history audit (the same inputs give bit-identical
 *    outputs whatever was called before, and dflag calls change nothing).
 * Reads outside the declared dependencies and queries the host refused, at
 * any call of the check, fail it too (hx_check_queries).
 */
#ifndef HX_TOOLS_CHECK_CHECKS_H
#define HX_TOOLS_CHECK_CHECKS_H

#include <stdio.h>

#include "session/session.h"

#define HX_DERIVATIVE_TOLERANCE_TEXT "1e-6"

int hx_check_coupler(hx_session *s, hx_binding *b, FILE *out);
int hx_check_field_partials(hx_session *s, hx_binding *b, FILE *out);
/* Force_StateEqn: YFOXX, YFOXU, YFOYX, YFOYU against differences of YFOSUB. */
int hx_check_state_partials(hx_session *s, hx_binding *b, FILE *out);
int hx_audit_dependencies(hx_session *s, hx_binding *b, FILE *out);
/* MOTSUB: iord 1 and 2 against differences in time of iord 0 and 1. */
int hx_check_motion(hx_session *s, hx_binding *b, FILE *out);
int hx_audit_history(hx_session *s, hx_binding *b, FILE *out);
/* What the host noted of the element over every call so far. */
int hx_check_queries(const hx_binding *b, FILE *out);

#endif
