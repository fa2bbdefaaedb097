/*
 * One way to call a bound element, whatever its kind (docs/interface.md
 * §5.1): its inputs, its outputs, and one call of its routines. Inputs: a
 * coupler's joint coordinates (n); none for a FORCE element's routine, which
 * asks the host for the state; a field's deformation and rates (12); a state
 * equation's states, then its inputs; none for the routines that are not
 * forces. Outputs: a coupler's phi, its n first and n*n second derivatives;
 * what a FORCE element's routine returns (its force and torque, its force or
 * torque alone, or its one value); a field's six, then dfddis and dfdvel (72);
 * a state equation's rates, then its six outputs; REQSUB's eight values;
 * VARSUB's and DIFSUB's one; MOTSUB's value at iord 0, 1 and 2.
 */
#ifndef HX_HOST_ELEMENT_CALL_H
#define HX_HOST_ELEMENT_CALL_H

#include "host/binding.h"

int hx_element_call_input_count(const hx_binding *b);
int hx_element_call_output_count(const hx_binding *b);

/* Its inputs at frames fr; a state equation's states from states (NULL: its
 * initial states). */
void hx_element_call_inputs(const hx_binding *b, const hx_frames *fr, const double *states,
                            double *in);

/* One call at frames fr (their time is the call's) and inputs in, which a
 * library may write into (state equations): the number of outputs. */
int hx_element_call(hx_binding *b, const hx_frames *fr, double *in, int iflag, int dflag,
                    double *out);

#endif
