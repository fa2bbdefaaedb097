/*
 * Function expressions evaluated (docs/interface.md §8.5, §8.6): a linked
 * program (model/expr/expr.h) at a context holding the frames (time, the
 * markers' frames, the Control_Diff values) and the model's variables'
 * values; the value, or the value and its exact partial derivatives in
 * each of the program's inputs. No allocation, no recursion; an evaluation
 * reads only its arguments, so one program may be evaluated on many
 * threads at once.
 */
#ifndef HX_EXPR_EVALUATE_H
#define HX_EXPR_EVALUATE_H

#include <stddef.h>

#include "frames/frames.h"
#include "model/expr/expr.h"

/* What an output time knows beyond the frames, from the right-hand side
 * evaluated at its state (a request's: docs/interface.md §7.13); a pointer
 * NULL where not known (what reads it then faults). */
typedef struct hx_expr_outputs {
    const double *reactions;     /* the joints' reactions by index (model->joints), six each:
                                  * the force and torque on I's body at I's origin, world axes
                                  * (sim/dynamics/reactions.h); JOINT and JPRIM read them */
    const double *accelerations; /* the bodies' by index (model->bodies), six each: the body
                                  * frame origin's linear and the angular one, world axes
                                  * (sim/dynamics/accelerations.h); ACCX .. WDTM read them */
    const double *loads;         /* the loads' by index (model->loads), twelve each: the force
                                  * and torque on I at I's origin, then on J at the point the
                                  * load puts its reaction (sim/dynamics/loads.h), world axes;
                                  * SFORCE, VFORCE, VTORQ, GFORCE read them */
    const double *forces;        /* the user force elements' by index (model->forces), twelve
                                  * each, the values the forces stage applied: on I at I's
                                  * origin, then on J at its origin (at I's for a
                                  * Force_Vector's floating J), world axes; zeros on J for a
                                  * Force_Vector_OneBody; SFORCE, VFORCE, ..., FIELD read them */
    const double *constraints;   /* the motions', couplers' and general constraints' forces,
                                  * twelve a slot (expr/marker_forces.h's
                                  * hx_marker_forces_slot): on I at I's origin, then on J at
                                  * J's origin, world axes (sim/dynamics/constraint_forces.h);
                                  * MOTION, COUPLER, GCON read them */
} hx_expr_outputs;

typedef struct hx_expr_context {
    const hx_frames *frames;   /* of the model the program is linked against */
    const double *variables;   /* the variables' current values by index (model->variables),
                                * which the caller keeps: VARVAL and ARYVAL of a U array read
                                * them; may be NULL when the program reads none */
    const hx_expr_outputs *outputs; /* NULL but at an output time, after the accelerations:
                                * the forces and variables evaluated within the right-hand
                                * side cannot know them */
} hx_expr_context;

/* The value at c. Returns 0, or -1 with the fault (kind, function, what, the
 * op's line and column, the time): a division by zero, an argument outside
 * a function's domain, a result or input that is not finite, a function the
 * harness does not answer, a program not linked against c's model. */
int hx_expr_eval(const hx_expr_program *p, const hx_expr_context *c, double *value,
                 hx_expr_fault *fault);

/* The doubles of scratch hx_expr_eval_partials (either method) needs for p. */
size_t hx_expr_scratch_size(const hx_expr_program *p);

/* The value and its partials in each input (partials[k] for
 * hx_expr_inputs(p)[k]), by an adjoint sweep over the ops evaluated (the
 * cheaper of the two methods on the harness's expressions: docs/performance.md).
 * At a kink the partial is the mean of the one-sided slopes, where a function
 * is flat or jumps 0; only the branch IF takes contributes. scratch holds
 * hx_expr_scratch_size(p) doubles. Returns 0, or -1 with the fault (a
 * partial that is not finite is one). */
int hx_expr_eval_partials(const hx_expr_program *p, const hx_expr_context *c, double *value,
                          double *partials, double *scratch, hx_expr_fault *fault);

/* The same by forward accumulation (each stack value carries its gradient):
 * the other method, kept for the measurement and as a check of the first. */
int hx_expr_eval_partials_forward(const hx_expr_program *p, const hx_expr_context *c,
                                  double *value, double *partials, double *scratch,
                                  hx_expr_fault *fault);

/* The value of input k at c (what the program reads there): 0, or -1 with
 * the fault. */
int hx_expr_input_value(const hx_expr_program *p, const hx_expr_context *c, int k,
                        double *value, hx_expr_fault *fault);

/* The value at c of an acceleration or a force read outside any program (a
 * user routine's query, model/loop_inputs.h), from c's outputs: 0, or -1
 * with the fault (none given). */
int hx_expr_query_value(const hx_expr_context *c, const hx_expr_input *in, double *value,
                        hx_expr_fault *fault);

#endif
