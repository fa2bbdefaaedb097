/*
 * A force element evaluated at a prescribed deformation of I relative to J
 * (x, y, z, ax, ay, az in J axes, with rates vx..wz): a FIESUB element takes
 * it directly; for a GFOSUB element the body of I is placed so that the host
 * answers exactly that state, and put back afterwards. Used by the rig, the
 * checks and the elastic energy.
 */
#ifndef HX_ELEMENT_PROBE_H
#define HX_ELEMENT_PROBE_H

#include "session.h"

/* A rotation whose projection angles (AX, AY, AZ) are a; returns 0, or -1
 * when Newton's method does not converge (angles near +-pi/2 or beyond). */
int hx_rotation_from_angles(const double a[3], double R[9]);

/* Copies frames to out, with I's body moved so that the I marker sits at disp
 * and moves at velo relative to the J marker. */
void hx_place_relative(const hx_model *m, const hx_frame *frames, hx_frame *out, int i_marker,
                       int j_marker, const double disp[6], const double velo[6]);

/* The deformation and rate of a force element at the session's frames. */
void hx_element_state(const hx_session *s, int force, double disp[6], double velo[6]);

/* Force and torque on I in J axes at a prescribed state; dFdd and dFdv (may
 * be NULL) receive the 6x6 partials, column-major: FIESUB's own, or central
 * differences for GFOSUB. Returns 0, or -1 when the element stopped the run or
 * the rotation cannot be placed. */
int hx_element_at(hx_session *s, int force, double t, const double disp[6],
                  const double velo[6], double F[6], double *dFdd, double *dFdv);

/* Elastic energy -integral_0^1 F(s disp, 0) . disp ds (8-point Gauss-Legendre):
 * the potential of a conservative element, in force * length units. */
double hx_element_potential(hx_session *s, int force, double t, const double disp[6]);

#endif
