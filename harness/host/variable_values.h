/*
 * The values of a model's Reference_Variable elements at frames
 * (docs/interface.md §7.10): each computed once, in the model's
 * variable_order (each after those it reads), a measure by the harness's
 * own measures, an expression by the engine reading the values already
 * computed, a USERSUB one by its VARSUB. No allocation, no string work
 * unless an expression faults.
 */
#ifndef HX_HOST_VARIABLE_VALUES_H
#define HX_HOST_VARIABLE_VALUES_H

#include "frames/frames.h"
#include "host/binding.h"

/* The nvariables values at fr into values (by index; fr->variables, or a
 * caller's own array); routines: the bindings of the model's routines (by
 * index in routines[]), which call the USERSUB variables' VARSUBs. 0, or -1
 * with "file:line:column: Reference_Variable ID: what at t = ..." in msg
 * for an expression's fault or a VARSUB's non-finite value. */
int hx_variables_values(const hx_frames *fr, hx_binding *const *routines, double *values,
                        hx_message *msg);

#endif
