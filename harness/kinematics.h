/*
 * Frames and the relative measures a MotionSolve-style host answers with:
 * DX/DY/DZ(I,J,K), AX/AY/AZ(I,J), the 3-1-3 Euler angles of DISP, VX..(I,J,K,L)
 * and WX..(I,J,K). A marker index of -1 is the world frame.
 */
#ifndef HX_KINEMATICS_H
#define HX_KINEMATICS_H

#include "model.h"

/* Pose and velocity of a frame in world coordinates: origin p, orientation R
 * (columns = axes), velocity of the origin v, angular velocity w. */
typedef struct hx_frame {
    double p[3], R[9], v[3], w[3];
} hx_frame;

/* World frame of a marker given the frames of all bodies. */
void hx_marker_frame(const hx_model *m, const hx_frame *bodies, int marker, hx_frame *out);

/* Bodies at their initial pose and velocity. */
void hx_initial_frames(const hx_model *m, hx_frame *bodies);

/* R_K^T (p_I - p_J) */
void hx_displacement(const hx_frame *I, const hx_frame *J, const hx_frame *K, double d[3]);
/* Orientation of I relative to J: R_J^T R_I */
void hx_relative_rotation(const hx_frame *I, const hx_frame *J, double R[9]);
/* AX, AY, AZ: projection angles of a relative rotation. */
void hx_projection_angles(const double R[9], double a[3]);
/* Body 3-1-3 Euler angles (psi, theta, phi) with R = Rz(psi) Rx(theta) Rz(phi). */
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

/* Joint coordinate: AZ(I,J) of a revolute or DZ(I,J,J) of a translational joint. */
double hx_joint_coordinate(const hx_model *m, const hx_frame *bodies, int joint);

#endif
