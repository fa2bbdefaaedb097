/*
 * The force elements' forces as the function language reads them
 * (expr/evaluate.h's hx_expr_outputs.loads and .forces: SFORCE, VFORCE,
 * VTORQ, GFORCE, FIELD, FX .. TM), at dd's frames after an evaluation: at an
 * output time, and within the algebraic loop (algebraic_loop.h).
 */
#ifndef HX_SIM_DYNAMICS_ELEMENT_OUTPUTS_H
#define HX_SIM_DYNAMICS_ELEMENT_OUTPUTS_H

#include "base/message.h"
#include "sim/dynamics/dynamics.h"

/* The loads' forces, twelve a load of d's model: on I at I's origin, then on
 * J where the load puts its reaction (zeros for an action-only or a
 * switched-off load). 0, or -1 with an expression's fault in msg. */
int hx_element_outputs_loads(const hx_dynamics *d, const hx_dynamics_data *dd, double *out,
                             hx_message *msg);

/* The user force elements' forces, the load the forces stage applied, twelve
 * an element of d's model: on I at I's origin, then on J: -F and -T for a
 * Force_Vector's floating J (at I's origin, where it floats), moved to J's
 * origin for a Force_Field's and a Force_Scalar_TwoBody's
 * (-T - (x_I - x_J) x F); zeros for a Force_Vector_OneBody's J. */
void hx_element_outputs_forces(const hx_dynamics *d, const hx_dynamics_data *dd, double *out);

#endif
