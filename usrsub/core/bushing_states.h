/*
 * The bushing with its internal states (docs/interface.md §3.8), as a state
 * equation  xdot = f(x, u),  y = g(x, u):
 *   u = (d, v): the deformation and its rate, I relative to J in J axes, as
 *       FIESUB receives them (x y z ax ay az, then the six rates);
 *   y = the force and torque on I in J axes;
 *   x = [ z (3, friction's bristles) | s_k (a balanced mount, per direction
 *       FX..TZ) | s_k, sdot_k (a mount with a node inertia, per direction
 *       TX..TZ) | x_k (a rubber filter, per direction FX..TZ) ].
 * The bushing and the limits see q = d - s and qdot = v - sdot. Three kinds
 * of mount, chosen by the file (docs/interface.md §3.8):
 *   balanced: K s + C sdot = -y, solved for sdot; a mount with damping C > 0,
 *       or without (C = 0) in a direction whose own force depends on its rate
 *       (constant or rubber damping): a series spring that caps the damper;
 *   inertial: J sddot = -(K s + C sdot + y_k), a rotational mount in series
 *       with friction, whose torque can fall with the slip rate faster than
 *       the mount's damping rises, so that the balance would have several
 *       roots; J = K / (1e4 rad/s)^2 makes the answer one;
 *   following: K s = -y with C = 0 in a direction without rate terms; no
 *       state (s follows the force at once).
 * The rubber filter: xdot_k = H qdot_k - R x_k, adding
 * -V (K x_k + C xdot_k). Friction adds its torque (lugre_friction.h) with the
 * bushing's translational force (with the limits) as the normal force and
 * qdot's rotations as the slip rate. With no state active, y is exactly the
 * FIESUB form's force.
 */
#ifndef USRSUB_BUSHING_STATES_H
#define USRSUB_BUSHING_STATES_H

#include "usrsub/core/bushing.h"
#include "usrsub/core/message.h"
#include "usrsub/core/mount_limits.h"

#ifdef __cplusplus
extern "C" {
#endif

#define USRSUB_MAX_STATES 18

/* Where each state sits in x. */
typedef struct usrsub_state_layout {
    int n;                      /* states in all */
    int friction;               /* 3 bristle states from x[0], or 0 when none */
    int nmount, mount[6];       /* directions of the balanced mounts (one state each) */
    int ninertial, inertial[3]; /* directions of the inertial mounts (two states each) */
    int nfollow, follow[6];     /* directions of the following mounts (no state) */
    int nrubber, rubber[6];     /* directions with a rubber filter */
} usrsub_state_layout;

void usrsub_bushing_state_layout(const usrsub_bushing *b, usrsub_state_layout *layout);

/* The partials, column-major with the rows as leading dimension:
 * dxdot_dx[i + n j] = d xdot_i / d x_j (n x n), dxdot_du (n x 12),
 * dy_dx (6 x n), dy_du (6 x 12). */
typedef struct usrsub_state_partials {
    double dxdot_dx[USRSUB_MAX_STATES * USRSUB_MAX_STATES];
    double dxdot_du[USRSUB_MAX_STATES * 12];
    double dy_dx[6 * USRSUB_MAX_STATES];
    double dy_du[6 * 12];
} usrsub_state_partials;

/* xdot (layout.n) and y (6) at states x and inputs u; limits may be NULL;
 * partials may be NULL. Returns 0, or -1 with msg when the mounts' balance
 * has no solution near the state (a deformation far outside any sensible
 * range). */
int usrsub_bushing_states_eval(const usrsub_bushing *b, const usrsub_mount_limits *limits,
                               const usrsub_state_layout *layout, const double u[12],
                               const double *x, double *xdot, double y[6],
                               usrsub_state_partials *partials, usrsub_message *msg);

#ifdef __cplusplus
}
#endif

#endif
