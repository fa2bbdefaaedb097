/*
 * A force element evaluated at a prescribed deformation of I relative to J
 * (x, y, z, ax, ay, az in J axes, with rates vx..wz): a FIESUB element takes
 * it directly; for a GFOSUB element I's body is placed, in a scratch state
 * of the caller's, so that the host answers exactly that deformation. Used
 * by the elastic energy, the rig and the checks; the state being simulated
 * is never touched.
 */
#ifndef HX_SIM_DYNAMICS_ELEMENT_AT_H
#define HX_SIM_DYNAMICS_ELEMENT_AT_H

#include "session/session.h"
#include "frames/frames.h"

/* A rotation whose projection angles (AX, AY, AZ) are a; returns 0, or -1
 * when Newton's method does not converge (angles near +-pi/2 or beyond). */
int hx_rotation_from_angles(const double a[3], double R[9]);

/* out = base with I's body moved so that the I marker sits at p with
 * orientation R and moves at v, w relative to the J marker (all in J axes;
 * markers updated). */
void hx_place_pose(const hx_frames *base, hx_frames *out, int i_marker, int j_marker,
                   const double p[3], const double R[9], const double v[3],
                   const double w[3]);

/* The same with the orientation given by projection angles disp[3..5]. */
void hx_place_relative(const hx_frames *base, hx_frames *out, int i_marker, int j_marker,
                       const double disp[6], const double velo[6]);

/* Force and torque on I in J axes at a prescribed deformation and time t;
 * dFdd and dFdv (may be NULL) receive the 6x6 partials, column-major:
 * FIESUB's own, or central differences for GFOSUB. scratch: a state of the
 * model to place bodies in. Returns 0, or -1 when the element stopped the run. */
int hx_element_at(hx_session *s, hx_frames *scratch, const hx_frames *base, int force, double t,
                  const double disp[6], const double velo[6], double F[6], double *dFdd,
                  double *dFdv);

/* Elastic energy of the element at frames base (scratch: a copy of base,
 * which it is again on return; one copy serves every element): minus the work of its force
 * and torque on I, at rest, along the path from J's pose to I's that moves
 * straight and turns about one fixed axis (I at s x and exp(s [r]x) in J, s
 * from 0 to 1; 8-point Gauss-Legendre). For a conservative element any path
 * gives the same: this is its potential, in force * length units. */
double hx_element_potential(hx_session *s, hx_frames *scratch, const hx_frames *base, int force,
                            double t);

#endif
