/*
 * Closed-form reference solutions for linear models: free bodies that only
 * translate (on linear bushings, from rest in rotation), or a chain of
 * jointed bodies with one degree of freedom left by linear couplers. Along
 * each free direction z the model is measured through its own right-hand
 * side, z'' = f - k z - c z' (exact for linear elements), checked to be
 * decoupled and linear, and solved in closed form. Anything else is not
 * such a model, and the caller falls back to a numerical reference.
 */
#ifndef HX_TOOLS_BENCH_LINEAR_REFERENCE_H
#define HX_TOOLS_BENCH_LINEAR_REFERENCE_H

#include "sim/dynamics/dynamics.h"

#define HX_REFERENCE_MODES 24

typedef struct hx_linear_reference {
    int modes;
    double *y0;                           /* the initial state (d->n values) */
    double *direction;                    /* modes x (nq + nu): position then velocity parts */
    double k[HX_REFERENCE_MODES], c[HX_REFERENCE_MODES], f[HX_REFERENCE_MODES];
    double rate0[HX_REFERENCE_MODES];     /* z'(0); z(0) = 0 */
    int n, nq, nu;
} hx_linear_reference;

/* Builds the reference of d's model from its initial state. Returns 0, or -1
 * with msg saying why the model has no closed form here. */
int hx_linear_reference_build(const hx_dynamics *d, hx_linear_reference *r, hx_message *msg);
void hx_linear_reference_free(hx_linear_reference *r);

/* The reference state at t: positions and velocities (the other components
 * of y are left as they are). */
void hx_linear_reference_state(const hx_linear_reference *r, double t, double *y);

/* z and z' of z'' = f - k z - c z', z(0) = 0, z'(0) = v0, at t. */
void hx_damped_oscillator(double k, double c, double f, double v0, double t, double *z,
                          double *rate);

#endif
