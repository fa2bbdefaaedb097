/*
 * The requests the harness answers itself (docs/interface.md §7.13): their
 * eight values at the frames of an output time, and their CSV columns,
 * requestID.1 .. requestID.8 in Adams' order.
 */
#ifndef HX_SIM_SIMULATION_REQUESTS_H
#define HX_SIM_SIMULATION_REQUESTS_H

#include <stdio.h>

#include "base/message.h"
#include "expr/evaluate.h"
#include "frames/frames.h"
#include "sim/dynamics/dynamics.h"

/* The eight values of request k of fr's model at fr (current for the
 * request's markers: tracked ones updated, the others computed here).
 * variables holds the model's variables' values (NULL when it has none), s
 * the reactions and accelerations (expr/evaluate.h; NULL: neither known).
 * 0, or -1 with "file:line:column: REQUEST/5 F2: what at t = ..." in msg
 * (a fault of an expression, or an ACCELERATION or FORCE request without
 * what it reads in s). */
int hx_requests_values(const hx_frames *fr, int k, const double *variables,
                       const hx_expr_outputs *s, double out[8], hx_message *msg);

/* ",request5.1,...,request5.8" for each request, in the order read. */
void hx_requests_csv_header(FILE *f, const hx_model *m);

/* Their values at fr, each with 15 significant digits (routines: the
 * dynamics' routine bindings, for the USERSUB variables they read); 0, or -1
 * with msg (nothing written for the request at fault and after it). */
int hx_requests_csv_row(FILE *f, const hx_frames *fr, hx_binding *const *routines,
                        const hx_expr_outputs *s, hx_message *msg);

#endif
