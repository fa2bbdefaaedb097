/*
 * Static equilibrium (docs/harness.md, run --static; docs/interface.md §9.9,
 * SIMULATE/STATIC): the positions where the loads balance with the
 * constraints held and every velocity zero, by damped Newton on the bodies'
 * unbalanced generalized forces at u = 0.
 */
#ifndef HX_SIM_SIMULATION_EQUILIBRIUM_H
#define HX_SIM_SIMULATION_EQUILIBRIUM_H

#include "sim/jacobian/jacobian.h"

/* Converged when every component of the parts' unbalanced loads is within
 * this of the model's force (the largest of the parts' weights, the loads and
 * the force elements' loads, each alone, at the start; a couple over the
 * model's length) or, for a turn, of that force times the model's length. */
#define HX_EQUILIBRIUM_TOLERANCE 1e-10
#define HX_EQUILIBRIUM_ITERATIONS 50

typedef struct hx_equilibrium_result {
    int iterations;     /* Newton iterations taken */
    double residual;    /* the largest unbalanced load left, relative as above */
    double force_scale; /* the model's force the tolerance is relative to */
    int analytic;       /* K from the Jacobian (else by differences of h) */
    long evaluations;   /* right-hand sides, the Jacobian's builds' among them */
    double seconds;     /* wall time of the solve */
} hx_equilibrium_result;

/* Moves y (d->n values, at time t) to the static equilibrium nearest it on
 * the constraints: positions of the parts solved, velocities zero (a part a
 * Motion_Joint drives keeps its position and velocity), the Force_StateEqn
 * and Control_Diff states and the work accumulators held. On dd (its
 * evaluations). The Newton matrix from jac's builds (equilibrium_matrix.h;
 * jac a Jacobian of d, its counts left as they were) or, jac NULL, by
 * central differences of the unbalanced loads. 0, or -1 with msg: no
 * equilibrium (a part with nothing balancing its load, named), no
 * convergence (the parts with the largest unbalanced loads named), or an
 * evaluation's failure (the Jacobian's build's among them). */
int hx_equilibrium_solve(const hx_dynamics *d, hx_dynamics_data *dd, hx_jacobian *jac,
                         double t, double *y, hx_equilibrium_result *result, hx_message *msg);

#endif
