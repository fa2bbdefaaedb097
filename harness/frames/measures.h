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
/* Body 3-2-1 angles (yaw, b, roll) with R = Rz(yaw) Ry(b) Rx(roll), b in
 * [-pi/2, pi/2], yaw and roll in (-pi, pi]. Where cos(b) is small only
 * roll - yaw (b > 0) or roll + yaw (b < 0) is defined: it is taken from the
 * entries that stay well conditioned there, as hx_euler313 takes psi + phi,
 * and where cos(b) is exactly 0 all of it goes to yaw (roll 0). */
void hx_euler321(const double R[9], double e[3]);
/* A body-fixed sequence a-b-c (axes[k] 0 x, 1 y, 2 z) turned into one of the
 * two above: C = Q R Q^T with Q a rotation taking a to z and b to x for a
 * proper sequence (a = c; C is then the 3-1-3 sequence of the same three
 * angles), a to z, b to y and c to sign times x for a Tait-Bryan one (C the
 * 3-2-1 sequence of t1, t2, sign t3). Linear in R, so a change of R turns
 * into C's change the same way. Returns 1 for a proper sequence, else 0. */
int hx_euler_canonical(const int axes[3], const double R[9], double C[9], double *sign);
/* The body-fixed a-b-c angles of R = R_a(t1) R_b(t2) R_c(t3): the middle one
 * in [0, pi] (proper) or [-pi/2, pi/2] (Tait-Bryan), the others in (-pi, pi],
 * with the rule of hx_euler313 or hx_euler321 where the outer axes line up. */
void hx_euler_sequence(const int axes[3], const double R[9], double e[3]);
/* The Euler parameters of R (e0 the scalar part, e1..e3 the axis times
 * sin(angle / 2)), the angle in [0, pi]: e0 >= 0, and at a half turn
 * (e0 = 0) the first nonzero of e1..e3 positive. */
void hx_euler_parameters(const double R[9], double e[4]);
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
