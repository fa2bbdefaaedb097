/*
 * One way to call a bound element (docs/interface.md §5.1): its inputs, its
 * outputs, and one call of its routine, whatever its kind. Inputs: a
 * coupler's joint coordinates (n); none for a Force_Vector_TwoBody's routine,
 * which asks the host for the state; a field's deformation and rates (12);
 * a state equation's states, then its inputs; none for the routines that are
 * not forces. Outputs: a coupler's phi, its n first and n*n second
 * derivatives; what a Force_Vector's or Force_Scalar's routine returns (its
 * force and torque, its force or torque alone, or its one value); a field's six, then
 * dfddis and dfdvel (72); a state equation's rates, then its six outputs;
 * REQSUB's eight values; VARSUB's and DIFSUB's one; MOTSUB's value at iord
 * 0, 1 and 2.
 */
#ifndef HX_HOST_EVALUATE_H
#define HX_HOST_EVALUATE_H

#include "host/binding.h"

int hx_binding_input_count(const hx_binding *b);
int hx_binding_output_count(const hx_binding *b);

/* Its inputs at state s; a state equation's states from states (NULL: its
 * initial states). */
void hx_binding_inputs(const hx_binding *b, const hx_frames *s, const double *states, double *in);

/* One call at state s (its time is the call's) and inputs in, which a
 * library may write into (state equations): the number of outputs. */
int hx_binding_evaluate(hx_binding *b, const hx_frames *s, double *in, int iflag, int dflag,
                        double *out);

#endif
