/*
 * Calling a bound element's functions (host/binding.h), one calling
 * convention per kind. Each call is bound to the host (host/call.h) with the
 * frames its queries are answered from; its outputs are zeroed first (check
 * fills them with NaN once: binding.h's output_fill), as a solver zeroes them.
 * `call` may be NULL (a default record is used) or a record set up by
 * hx_binding_call_init. The frames' time is the call's time.
 */
#ifndef HX_HOST_INVOKE_H
#define HX_HOST_INVOKE_H

#include "host/binding.h"

/* COUSUB (which 0), COUXX (1) or COUXX2 (2) at the joint coordinates disp. */
void hx_invoke_coupler(hx_binding *b, int which, const hx_frames *fr, const double *disp,
                       int ndisp, int iflag, double *out, hx_call *call);
/* A FORCE element's routine: values receives what the routine itself
 * returns, in the layout its entry type documents (hx_force_routine_values of
 * them: GFOSUB's force and torque, VFOSUB's force, VTOSUB's torque, SFOSUB's
 * one value). What the harness makes of them (their axes, the direction of
 * a scalar) is the dynamics' (sim/dynamics/element_forces.h); check judges
 * these values. */
void hx_invoke_force(hx_binding *b, const hx_frames *fr, int dflag, int iflag, double *values,
                     hx_call *call);
/* FIESUB at the deformation disp and rates velo of I relative to J. */
void hx_invoke_field(hx_binding *b, const hx_frames *fr, const double disp[6],
                     const double velo[6], int dflag, int iflag, double field[6], double dfddis[36],
                     double dfdvel[36], hx_call *call);
/* A routine that is not a force: REQSUB's eight values, or the one value of
 * VARSUB, DIFSUB (flag: dflag) or MOTSUB (flag: iord). */
void hx_invoke_routine(hx_binding *b, const hx_frames *fr, int flag, int iflag, double *values,
                       hx_call *call);
/* YFOSUB of a Force_StateEqn: states (nstate) and input (ninput), the
 * caller's copies, which a library may write into; stated (nstate) and
 * output (6) receive its results. */
void hx_invoke_stateeqn(hx_binding *b, const hx_frames *fr, double *states, double *input,
                        int dflag, int iflag, double *stated, double output[6], hx_call *call);
/* Partial routine `which` (0 YFOXX, 1 YFOXU, 2 YFOYX, 3 YFOYU; it must be
 * exported) at states and input, into matrix (column-major, its rows first). */
void hx_invoke_stateeqn_partial(hx_binding *b, int which, const hx_frames *fr, double *states,
                                double *input, double *matrix, hx_call *call);

/* The FIESUB twin of a FORCE element (b->twin must be set), at the
 * deformation of its I marker relative to its J marker; it may not query.
 * Its messages go to `messages` (the caller's, kept apart from the session's:
 * a twin that refuses the list disqualifies itself, it does not stop the run). */
void hx_invoke_twin(hx_binding *b, const hx_frames *fr, const double disp[6],
                    const double velo[6], double field[6], double dfddis[36], double dfdvel[36],
                    hx_messages *messages);

#endif
