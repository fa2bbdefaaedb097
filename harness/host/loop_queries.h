/*
 * The accelerations and forces user routines ask (docs/interface.md §5.1): a
 * routine that declares c_sysfnc's ACCX .. WDTM or c_sysary's ACC TACC RACC,
 * or c_sysfnc's JOINT .. SPDP (id, jflag, comp, rm) or FX .. TM (I[, J[,
 * K]]; FM, TM I[, J]), in its dependency pass reads inputs of the model's algebraic loop, as
 * an expression's ACCZ or JOINT does (model/loop_inputs.h): each value gets its slot,
 * and the routine's calls are answered from the frames' loop values, which
 * the dynamics solves at each right-hand side (sim/dynamics/algebraic_loop.h),
 * for a force, a variable or a Control_Diff routine. A request's REQSUB runs
 * at output times, once the forces and accelerations are known: what it
 * declares is one of the model's output queries, answered then from the
 * outputs of that time (sim/dynamics/routines.h), and closes no loop.
 */
#ifndef HX_HOST_LOOP_QUERIES_H
#define HX_HOST_LOOP_QUERIES_H

#include "host/binding.h"

/* After the dependency passes: every declared acceleration and force of
 * bs's elements a slot of m's loop (hx_model_loop_query), a REQSUB's of m's
 * output queries (hx_model_output_query), kept in its binding's loop_slot.
 * 0, or -1 with msg ("model.xml:12: Post_Request 3 (REQSUB) declares
 * JOINT(9,0,4,0) in its dependency pass: no Constraint_Joint (JOINT) 9 in the
 * model"; out of memory). */
int hx_bind_loop_queries(hx_model *m, hx_bindings *bs, hx_message *msg);

#endif
