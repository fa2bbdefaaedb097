/*
 * The Force_StateEqn elements' share of the Newton matrix (newton_matrix.h).
 * With x an element's states, u = U(q, u_body) its inputs (the harness's own
 * measures), xdot = F(x, u) and out = G(x, u):
 *
 *   rows of x:   d xdot/d(q, u_body) = F_u dU/dy,   d xdot/dx = F_x
 *   outputs:     d out/d(q, u_body)  = G_u dU/dy,   d out/dx  = G_x
 *
 * F_x, F_u, G_x, G_u are YFOXX, YFOXU, YFOYX and YFOYU when the library
 * exports them, else central differences of YFOSUB (dflag set); dU/dy are
 * differences of the harness's measures alone (no library call). The
 * outputs enter J through the frozen right-hand side's response to a unit
 * output (B_k, newton_matrix.h), as the force elements' do.
 */
#ifndef HX_SIM_STATE_JACOBIAN_H
#define HX_SIM_STATE_JACOBIAN_H

#include "sim/dynamics/dynamics.h"

typedef struct hx_state_jacobian {
    hx_dynamics *d;
    int count;           /* elements */
    int n, m;            /* state size; positions and velocities */
    size_t *block;       /* per element: where its F_x, F_u, G_x, G_u start in partials */
    size_t *slope;       /* per element: where its dU/dy (ninput x m) starts in du */
    double *partials;
    double *du;
    double *y, *x, *u, *up, *um, *xdot, *xdotm, *out, *outm; /* scratch */
    unsigned char exported[4]; /* the library's partial routine k was used (all elements) */
    unsigned char differenced[4]; /* routine k was differenced for some element */
} hx_state_jacobian;

/* 0, or -1 with msg (out of memory). */
int hx_state_jacobian_init(hx_state_jacobian *sj, hx_dynamics *d, hx_message *msg);
void hx_state_jacobian_free(hx_state_jacobian *sj);

/* At (t, y): each element's outputs (6 per element) and partials, and the
 * inputs' slopes dU/dy. Counts its element calls into *calls. 0, or -1
 * (d->message) when an element failed. */
int hx_state_jacobian_outputs(hx_state_jacobian *sj, double t, const double *y, double *outputs,
                              long *calls);

/* J += the elements' share, given response (n x 6 per element, column by
 * column): B_k times d out/dy, and the rows of their states. */
void hx_state_jacobian_add(const hx_state_jacobian *sj, const double *response, double *J);

/* Where the partials came from, appended to text. */
void hx_state_jacobian_describe(const hx_state_jacobian *sj, char *text, size_t size);

#endif
