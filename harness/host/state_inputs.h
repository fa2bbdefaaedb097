/*
 * The inputs of a Force_StateEqn: its U array's Reference_Variable elements
 * evaluated by the harness itself at a state, with the measures it answers
 * c_sysfnc with (docs/interface.md §5, §7.10); a USERSUB one is its VARSUB's
 * value, which the variables' stage computed into the frames' variables.
 */
#ifndef HX_HOST_STATE_INPUTS_H
#define HX_HOST_STATE_INPUTS_H

#include "frames/frames.h"

/* The value of variable v at frames fr; 0, or -1 when a marker it names is
 * unknown (the model's resolve pass has ruled that out). */
int hx_variable_value(const hx_frames *fr, const hx_variable *v, double *value);

/* The ninput inputs of Force_StateEqn `element` at frames fr (a variable by
 * an expression evaluated there, docs/interface.md §7.10; a USERSUB one
 * from fr->variables); 0 or -1. */
int hx_stateeqn_inputs(const hx_frames *fr, int element, double *u);
/* Why hx_stateeqn_inputs failed at fr: "file:line:column: Reference_Variable
 * ID: what at t = ..." for an expression's fault, or the input that could not
 * be measured, into msg; -1. Not a hot path: called after a failure. */
int hx_stateeqn_inputs_why(const hx_frames *fr, int element, hx_message *msg);

/* 1 when variable v is an angle (AX, AY, AZ): differences of it wrap. */
int hx_variable_is_angle(const hx_variable *v);

#endif
