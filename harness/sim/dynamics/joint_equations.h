/*
 * The equations of a joint between two bodies in Cartesian coordinates
 * (docs/architecture.md, the constraint system): phi(q) = 0 written between
 * its I and J markers, their Jacobian G in the bodies' velocities and the
 * velocity-squared term gamma.
 *
 * Sign convention: phi_ddot = G w_dot - gamma, so the accelerations satisfy
 * G w_dot = gamma (gamma = -(d/dt G) w, Haug's). Here G is written in the
 * world twists w = [v_I, omega_I, v_J, omega_J] (velocities of the bodies'
 * centres and their angular velocities, all in world axes): 12 columns a
 * row; constraints.c turns omega's columns into body axes.
 */
#ifndef HX_SIM_DYNAMICS_JOINT_EQUATIONS_H
#define HX_SIM_DYNAMICS_JOINT_EQUATIONS_H

#include <stddef.h>

#include "frames/frames.h"

#define HX_JOINT_MAX_EQUATIONS 6

/* The number of equations of a joint type (6 FIXED ... 1 INPLANE, PERPENDICULAR,
 * RACKPIN, SCREW). */
int hx_joint_equations_count(enum hx_joint_type type);

/* 1 when equation e (0 <= e < count) of the type is a length (a point or a
 * point-in-plane row, scaled by the model's length in constraints.c), 0 when
 * it is a product of two unit axes. */
int hx_joint_equation_is_length(enum hx_joint_type type, int e);

/* Equation e of the type in words, into text: "x_I - x_J along x" (the
 * origins, world axes), "z_I . y_J" (the markers' axes), "x_J . (x_I - x_J)". */
const char *hx_joint_equation_name(enum hx_joint_type type, int e, char *text, size_t size);

/* One side of a joint: its body's frame (world) and the marker's place and
 * axes in the body (hx_marker's r_local, R_local). */
typedef struct hx_joint_side {
    const hx_frame *body;
    const double *r_local, *R_local;
} hx_joint_side;

/* A RACKPIN's or SCREW's law: s - s0 = ratio (theta - theta0), the travel s
 * and the turn theta measured from their values at t = 0 (ratio PD/2 or
 * PITCH/(2 pi), docs/interface.md §7.14); all zero for the other types. */
typedef struct hx_joint_law {
    double ratio, s0, theta0;
} hx_joint_law;

/* The joint's law from its PD or PITCH and its markers' poses at t = 0. */
void hx_joint_equations_law(const hx_joint *joint, const hx_marker *mi, const hx_marker *mj,
                            hx_joint_law *law);

/* phi (count values), G (count x 12, row-major; may be NULL) and gamma
 * (count; may be NULL) of a joint of this type at I's and J's frames; law is
 * read by RACKPIN and SCREW only (may be NULL for the others). */
void hx_joint_equations_eval(enum hx_joint_type type, const hx_joint_law *law,
                             const hx_joint_side *i, const hx_joint_side *j, double *phi,
                             double *G, double *gamma);

/* The same for joint `joint` of m, its I and J markers' bodies at frames fi
 * and fj (world), its law from the model. */
void hx_joint_equations_of(const hx_model *m, int joint, const hx_frame *fi, const hx_frame *fj,
                           double *phi, double *G, double *gamma);

#endif
