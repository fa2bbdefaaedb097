/*
 * The exact first-order change of a measure of markers (frames/measure_functions.h,
 * docs/interface.md §8.5) when its markers move: the chain rule's last link
 * from an expression's partials in its measures (expr/evaluate.h) to the
 * bodies' columns of the Jacobian (load_blocks.c). Each marker's motion is
 * an hx_motion (body_motion.h): dp, a small rotation dth, dv and dw, world
 * axes, per unit of one column.
 */
#ifndef HX_SIM_JACOBIAN_MEASURE_SLOPE_H
#define HX_SIM_JACOBIAN_MEASURE_SLOPE_H

#include "frames/measure_functions.h"
#include "sim/jacobian/body_motion.h"

/* d(measure)/d(column) of measure m of the frames f (in the order of its
 * arguments, as hx_measure_value takes them) moving by mo (NULL: still).
 * Where the value's direction is undefined (DM, VR of coincident markers,
 * INCANG with J on I or K, VM or WM at rest) the slope is 0, as the value
 * there is. */
double hx_measure_slope(hx_measure m, const hx_frame *const f[4], const hx_motion *const mo[4]);

#endif
