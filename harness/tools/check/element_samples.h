/*
 * The states a check evaluates a force element at: sample 0 is its
 * deformation at the model's initial state; samples 1.. add deterministic
 * offsets growing from 0.5 to 10 typical steps (1 mm, 0.02 rad, and those
 * over 10 ms for the rates, in the model's units), so that every term of an
 * element (a contact beyond its gap, a spline's far end) wakes in some;
 * sample 1 is a twist at rest (no tilt), where hosts' Euler angles are
 * ill-defined and elements may ask for more; and
 * each sample has its own time, so that what an element does at t > 0 is
 * seen too.
 */
#ifndef HX_TOOLS_CHECK_ELEMENT_SAMPLES_H
#define HX_TOOLS_CHECK_ELEMENT_SAMPLES_H

#include "session/session.h"

#define HX_FORCE_SAMPLES 12

/* Deformation and rate of sample k of force element `force`; scale receives
 * the typical step of each of the twelve. */
void hx_sample_force_deformation(const hx_session *s, int force, int k, double disp[6],
                             double velo[6], double scale[12]);

/* Sample k of Force_StateEqn `element`: its states (IC at sample 0) and its
 * inputs (at the model's initial state at sample 0), each moved on its own by
 * 0.5 to 10 typical steps at the later samples; scale receives the typical
 * step of each (states then inputs): the inputs' by their measure (a length,
 * an angle, their rates over 10 ms, 1 for a number), the states' 0.01 mm
 * (or 1e-5 of the model's length unit without units), as the harness does
 * not know what a state is. */
void hx_sample_stateeqn_states(const hx_session *s, int element, int k, double *states,
                             double *inputs, double *scale);

/* Sample k of the whole model, for the routines that ask the host for any
 * state (REQSUB, VARSUB, DIFSUB): from the model's initial state, every
 * moving body's position, orientation, velocity and angular velocity moved
 * by 0.5 to 10 typical steps, and every Control_Diff state by as many
 * hundredths of 1 + |ic|; scale receives the typical steps of a body's twelve
 * states (as hx_sample_force_deformation's). The state's time is left as it is. */
void hx_sample_model_frames(const hx_session *s, int k, hx_frames *out, double scale[12]);

/* One second in the model's time unit. */
double hx_model_second(const hx_model *m);
/* The time of sample k: 0, then spread over the model's first second. */
double hx_sample_time(const hx_model *m, int k);

/* Deterministic numbers in [-1, 1] (a linear congruential sequence). */
double hx_jitter(unsigned *seed);

#endif
