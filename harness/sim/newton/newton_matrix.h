/*
 * The Jacobian J = df/dy of the dynamics (dynamics.h) for the Newton
 * iterations of the implicit integrator, from the force elements' own
 * partials rather than from differences of the whole right-hand side:
 *
 *   J = J_frozen + sum over force elements k of B_k dOut_k/dy
 *
 * J_frozen: central differences of the right-hand side with every force
 *   element's outputs frozen at their values at y: the elements are not
 *   called, their outputs are re-applied in their own axes at the perturbed
 *   frames. It holds the turning axes and lever arms, the rigid-body terms,
 *   gravity and loads, and the couplers (whose COUSUB, COUXX and COUXX2 the
 *   constraint solve still calls: their partials enter through it).
 * B_k (n x 6): d(ydot)/d(outputs of element k), exact: the frozen right-hand
 *   side is affine in the outputs, so its response to a unit output is it.
 * dOut_k/dy (6 x n): for a Force_Field, FIESUB's dfddis and dfdvel times the
 *   derivatives of its six deformations and rates with respect to y, taken
 *   by differences of the harness's kinematics alone (no element call); for a
 *   Force_Vector_TwoBody (GFOSUB), the same with the partials of its FIESUB
 *   twin (docs/interface.md §3.0) when the library exports one whose field
 *   equals the GFOSUB result (to 1e-9, checked at every build), otherwise
 *   central differences of that element alone at perturbed states (§5).
 *
 * Force_StateEqn elements (state_jacobian.h): their outputs enter like the
 * force elements' (B_k from the frozen right-hand side, which holds their
 * states' rates at zero), with d out/dy from their partials; the rows of
 * their states are their partials alone.
 *
 * The columns of the work accumulators are zero (nothing depends on them);
 * their rows are the powers, differentiated like the rest.
 */
#ifndef HX_SIM_NEWTON_MATRIX_H
#define HX_SIM_NEWTON_MATRIX_H

#include "sim/dynamics/dynamics.h"
#include "sim/newton/state_jacobian.h"

typedef enum hx_partials_source {
    HX_PARTIALS_FIESUB,     /* a Force_Field's own dfddis and dfdvel */
    HX_PARTIALS_TWIN,       /* a GFOSUB element's FIESUB twin */
    HX_PARTIALS_DIFFERENCES /* differences of that GFOSUB element alone */
} hx_partials_source;

#define HX_NEWTON_WHY 160

typedef struct hx_newton_matrix {
    hx_dynamics *d;
    int n, m;                  /* state size; positions and velocities */
    int nf;                    /* force elements */
    int ne;                    /* Force_StateEqn elements: outputs, unit and response hold
                                * theirs after the force elements' */
    hx_state_jacobian states;  /* their partials */
    hx_partials_source *source; /* per force element */
    char *why;                 /* per element, HX_NEWTON_WHY: why differences */
    int *column_body;          /* per column < m: the body it moves */
    unsigned char *touches;    /* nf x nbodies: element k acts on (or is measured on) body b */
    double *outputs;           /* 6 per element, at the state of the build */
    double *partials;          /* 72 per element: dfddis then dfdvel (column-major 6 x 6) */
    double *dout;              /* 6 x m per element: dOut_k/dy, column by column */
    double *response;          /* n x 6 per element: B_k, column by column */
    double *unit;              /* 6 per element: outputs of the response evaluations */
    double *y, *fp, *fm, *plus, *minus; /* scratch: n each; plus/minus 12 per element */
    hx_messages twin_messages; /* the twins' own messages, apart from the session's */
    long frozen_evaluations;   /* right-hand sides with outputs frozen (harness only) */
    long partial_calls;        /* element calls made for partials and outputs */
} hx_newton_matrix;

/* Returns 0, or -1 with msg (out of memory). */
int hx_newton_matrix_init(hx_newton_matrix *nm, hx_dynamics *d, hx_message *msg);
void hx_newton_matrix_free(hx_newton_matrix *nm);

/* J (column-major n x n) at (t, y). Returns 0, or -1 (d->message) when an
 * element or the constraints failed. */
int hx_newton_matrix_build(hx_newton_matrix *nm, double t, const double *y, double *J);

/* Where each element's partials come from, in a line or two. */
void hx_newton_matrix_describe(const hx_newton_matrix *nm, char *text, size_t size);

#endif
