/*
 * The inputs of a model's algebraic loop (docs/interface.md §8.8): each
 * distinct acceleration (ACCX .. WDTM), joint reaction (JOINT, JPRIM) or
 * SFORCE force that a force, a variable or a Control_Diff rate reads. They
 * are known only once the forces and the accelerations are, which they feed:
 * the dynamics solves for their values at each right-hand side
 * (sim/dynamics/algebraic_loop.h). Found once, after every program is
 * linked; the values live in the frames of whoever evaluates (frames.h's
 * loop), never in the model.
 */
#ifndef HX_MODEL_LOOP_INPUTS_H
#define HX_MODEL_LOOP_INPUTS_H

#include "model/draft.h"
#include "model/expr/expr.h"

typedef struct hx_loop_input {
    const hx_expr_program *program; /* the first program that reads it ... */
    int input;                      /* ... and its place among that program's inputs */
    char element[48];               /* that program's element: "Force_Scalar_TwoBody 1" */
} hx_loop_input;

/* Gives every loop input of the loads', variables' and Control_Diffs'
 * programs its slot (hx_expr_set_loop), the same one wherever the same
 * function of the same ids is read, and lists them in model->loop_inputs;
 * 0, or -1 with the draft failed (out of memory). */
int hx_draft_find_loop_inputs(hx_draft *d);

/* "ACCZ(10) (Force_Scalar_TwoBody 1)" for slot k into text; returns text. */
const char *hx_loop_input_text(const hx_model *m, int k, char *text, size_t size);

#endif
