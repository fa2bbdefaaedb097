/*
 * The accelerations of markers (docs/interface.md §8.5): a marker's from its
 * body's, and the functions ACCX ACCY ACCZ ACCM WDTX WDTY WDTZ WDTM of up to
 * four markers' frames and accelerations. The frames hold positions and
 * velocities only; the accelerations are the caller's (known at output
 * times, after the right-hand side: sim/dynamics/accelerations.h).
 */
#ifndef HX_FRAMES_ACCELERATION_MEASURES_H
#define HX_FRAMES_ACCELERATION_MEASURES_H

#include "frames/frames.h"

typedef enum hx_acceleration_measure {
    HX_ACC_X, HX_ACC_Y, HX_ACC_Z, /* (I[, J[, K[, L]]]) */
    HX_ACC_M,                     /* (I[, J[, L]]) */
    HX_WDT_X, HX_WDT_Y, HX_WDT_Z, /* (I[, J[, K[, L]]]) */
    HX_WDT_M                      /* (I[, J[, L]]) */
} hx_acceleration_measure;

/* The acceleration of a point of a body (world axes: the point's linear one,
 * then the body's angular one) from the body's frame and its acceleration
 * (body_acc: its frame origin's linear, its angular; world axes) and the
 * point's world position. */
void hx_point_acceleration(const hx_frame *body, const double body_acc[6], const double p[3],
                           double out[6]);

/* The measure of the frames f and accelerations a (each six: linear, angular,
 * world axes) given in the order of its arguments: I, J, then K and L (or L
 * alone for ACCM and WDTM); the world frame, at rest, for those left out.
 * The time derivatives are taken in L:
 *   ACC: R_K^T (a_I - a_J - alpha_L x r - 2 w_L x r' + w_L x (w_L x r)),
 *        r = p_I - p_J, r' = v_I - v_J;
 *   WDT: R_K^T (alpha_I - alpha_J - w_L x (w_I - w_J));
 * the magnitudes the norms of the same vectors. */
double hx_acceleration_value(hx_acceleration_measure m, const hx_frame *const f[4],
                             const double *const a[4]);

#endif
