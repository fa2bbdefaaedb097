/*
 * A Reference_Marker's orientation from the forms MotionSolve XML allows
 * (docs/interface.md §7): direction cosines a00..a22 (column j = the marker's
 * j-th axis), body-fixed 3-1-3 Euler angles psi, theta, phi in radians
 * (R = Rz(psi) Rx(theta) Rz(phi)), or Euler parameters e0..e3 (e0 the scalar
 * part). yaw/pitch/roll is refused: the sign of its pitch axis is not
 * documented for the XML form, and a guess could turn a marker the wrong way.
 */
#ifndef HX_MODEL_ORIENTATION_H
#define HX_MODEL_ORIENTATION_H

#include "base/message.h"
#include "model/xml_schema.h"

/* R (row-major; its columns the marker's axes in the reference frame) from
 * the element's attributes; the identity when it gives none. Returns 0, or
 * -1 with why (mixed forms, a form refused, numbers that are not a rotation). */
int hx_marker_orientation(const hx_element_read *e, double R[9], hx_message *why);

/* The axes of an x direction and a direction in the x-y plane on its
 * positive y side: x made unit, z = x cross y made unit, y = z cross x, as
 * the direction cosines are made orthonormal (the dataset's ZP/XP markers
 * end the same way, so that the same axes give the same bits). */
void hx_axes_from_xy(const double x[3], const double y[3], double R[9]);

/* R = Rz(psi) Rx(theta) Rz(phi). */
void hx_rotation_313(double psi, double theta, double phi, double R[9]);

#endif
