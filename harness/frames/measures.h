/*
 * The relative measures of two frames a MotionSolve-style host answers with
 * (docs/interface.md §3.1, §5): DX/DY/DZ(I,J,K), the projection angles
 * AX/AY/AZ(I,J), the 3-1-3 Euler angles of DISP, VX..(I,J,K,L) and
 * WX..(I,J,K). Computed with the C library only.
 */
#ifndef HX_FRAMES_MEASURES_H
#define HX_FRAMES_MEASURES_H

#include "frames/frames.h"

/* R_K^T (p_I - p_J) */
void hx_displacement(const hx_frame *I, const hx_frame *J, const hx_frame *K, double d[3]);
/* Orientation of I relative to J: R_J^T R_I */
void hx_relative_rotation(const hx_frame *I, const hx_frame *J, double R[9]);
/* AX, AY, AZ: projection angles of a relative rotation (one: axis 0, 1, 2). */
void hx_projection_angles(const double R[9], double a[3]);
double hx_projection_angle(const double R[9], int axis);
/* The rotation vector r (axis times angle, angle in [0, pi]) with R = exp([r]x). */
void hx_rotation_vector(const double R[9], double r[3]);
/* Body 3-1-3 Euler angles (psi, theta, phi) with R = Rz(psi) Rx(theta) Rz(phi).
 * Where sin(theta) is small only psi + phi (or psi - phi near theta = pi) is
 * defined: it is taken from the entries that stay well conditioned there, so
 * that psi + phi is exact at every tilt whatever psi comes out as. */
void hx_euler313(const double R[9], double e[3]);
/* The same for the rotation of I relative to J, from the frames. */
void hx_relative_euler313(const hx_frame *I, const hx_frame *J, double e[3]);
/* Velocity of I relative to J, differentiated in L, expressed in K. */
void hx_relative_velocity(const hx_frame *I, const hx_frame *J, const hx_frame *K,
                          const hx_frame *L, double v[3]);
/* Angular velocity of I relative to J, expressed in K. */
void hx_relative_angular_velocity(const hx_frame *I, const hx_frame *J, const hx_frame *K,
                                  double w[3]);

/* The FIESUB inputs: disp = (DX,DY,DZ)(I,J,J), (AX,AY,AZ)(I,J);
 * velo = (VX,VY,VZ)(I,J,J,J), (WX,WY,WZ)(I,J,J). */
void hx_field_state(const hx_frame *I, const hx_frame *J, double disp[6], double velo[6]);

/* The deformation of a force element of the model at a state. */
void hx_force_deformation(const hx_frames *fr, int force, double disp[6], double velo[6]);

/* Joint coordinate at a state: AZ(I,J) for freedom 'R' (a revolute's, or a
 * cylindrical's rotation), DZ(I,J,J) for 'T' (a translational's, or a
 * cylindrical's translation); freedom 0 takes the joint type's own. */
double hx_joint_coordinate(const hx_frames *fr, int joint, char freedom);

#endif
