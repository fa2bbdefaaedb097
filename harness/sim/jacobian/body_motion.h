/*
 * How a body and the points fixed to it move when one of the body's
 * coordinates in y changes: the first-order change of its pose (dp of its
 * centre, dth a small rotation, world axes) and of its velocities (dv, dw,
 * world axes) per unit of that coordinate. Positions' columns move the
 * pose (and the world velocities that depend on it); velocities' columns
 * move the velocities only. A free body's frame is that of its quaternion
 * made unit (bodies.h), so a change of the quaternion along itself is no
 * motion at all.
 */
#ifndef HX_SIM_JACOBIAN_BODY_MOTION_H
#define HX_SIM_JACOBIAN_BODY_MOTION_H

#include "sim/dynamics/dynamics.h"

typedef struct hx_motion {
    double dp[3], dth[3], dv[3], dw[3];
} hx_motion;

/* The motion of body b (frame f at y) per unit of its column `which`
 * (0 .. count - 1 in hx_jacobian_body_columns' order). */
void hx_body_column_motion(const hx_dynamics *d, int b, int which, const double *y,
                           const hx_frame *f, hx_motion *mo);

/* The motion of a marker frame M fixed to a body of frame f that moves by mo. */
void hx_point_motion(const hx_frame *f, const hx_motion *mo, const hx_frame *M, hx_motion *out);

#endif
