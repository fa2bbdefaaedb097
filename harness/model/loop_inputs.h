/*
 * The inputs of a model's algebraic loop (docs/interface.md §8.8): each
 * distinct acceleration (ACCX .. WDTM), constraint element's force (JOINT,
 * JPRIM, MOTION, COUPLER, GCON), force element's force (SFORCE .. FIELD) or
 * force at a marker (FX .. TM) that a force, a variable or a Control_Diff
 * rate reads. They
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
    const hx_expr_program *program; /* the first program that reads it (NULL: a user
                                     * routine's query, below) ... */
    int input;                      /* ... and its place among that program's inputs */
    char element[64];               /* that program's element: "Force_Scalar_TwoBody 1";
                                     * a routine's: "GFOSUB of Force_Vector_OneBody 5" */
    /* program NULL: the acceleration or force a user routine asks (c_sysfnc
     * ACCZ or JOINT, one value of c_sysary ACC: host/loop_queries.h) as an
     * expression's input would read it, linked (its markers' or element's
     * indices), and as asked: "ACC(20)[3]", "JOINT(9,0,4,0)" */
    hx_expr_input query;
    char text[40];
} hx_loop_input;

/* Gives every loop input of the loads', variables' and Control_Diffs'
 * programs its slot (hx_expr_set_loop), the same one wherever the same
 * function of the same ids is read, and lists them in model->loop_inputs;
 * 0, or -1 with the draft failed (out of memory). */
int hx_draft_find_loop_inputs(hx_draft *d);

/* The slot of acceleration or force `in` (linked) that a user routine's query reads,
 * the one an expression's same acceleration has, or a new one (with text
 * and element); -1 out of memory. After hx_draft_find_loop_inputs, by
 * whoever knows the routines' queries (host/loop_queries.h). */
int hx_model_loop_query(hx_model *m, const hx_expr_input *in, const char *text,
                        const char *element);

/* The slot among m->output_queries of acceleration or force `in` (linked)
 * that a REQSUB's query reads: it runs at output times, once the forces and
 * accelerations are known, and closes no loop (the same slot wherever the
 * same function of the same ids is asked, a new one else); -1 out of
 * memory. */
int hx_model_output_query(hx_model *m, const hx_expr_input *in);

/* "ACCZ(10) (Force_Scalar_TwoBody 1)" for slot k into text; returns text. */
const char *hx_loop_input_text(const hx_model *m, int k, char *text, size_t size);

#endif
