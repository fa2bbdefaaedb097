/*
 * A joint's coordinate as the couplers take it (docs/interface.md §2,
 * docs/architecture.md, the constraint system): the rotation AZ(I,J) of a
 * REVOLUTE joint or the 'R' freedom of a CYLINDRICAL one, the translation
 * DZ(I,J,J) of a TRANSLATIONAL joint or the 'T' freedom of a CYLINDRICAL one,
 * between any two bodies, either on ground. Its value, its velocity row (the
 * blocks of I's and J's bodies) and its convective term:
 *   a_dot = G u,   a_ddot = G u_dot + c.
 */
#ifndef HX_SIM_DYNAMICS_JOINT_COORDINATE_H
#define HX_SIM_DYNAMICS_JOINT_COORDINATE_H

#include "sim/dynamics/dynamics.h"
#include "sim/dynamics/joint_equations.h"

/* The freedom a joint type's coordinate is taken in when none is given:
 * 'R' (REVOLUTE), 'T' (TRANSLATIONAL); 0 when the type needs one given
 * (CYLINDRICAL) or has no coordinate (every other type). */
char hx_joint_coordinate_default(enum hx_joint_type type);
/* 1 when the type has a coordinate in freedom ('R' or 'T'), else 0. */
int hx_joint_coordinate_allowed(enum hx_joint_type type, char freedom);

/* The coordinate between two markers in freedom 'R' or 'T', in the world
 * twists w = [v_I, omega_I, v_J, omega_J] (joint_equations.h's sides: the
 * velocities of the bodies' centres and their angular velocities, world
 * axes): the value (an angle in (-pi, pi]: atan2(x_I . y_J, x_I . x_J)),
 * G (12 values; may be NULL) and c (may be NULL). */
void hx_joint_coordinate_sides(char freedom, const hx_joint_side *i, const hx_joint_side *j,
                               double *value, double G[12], double *c);

/* The rotation AZ(I,J) of joint `joint` where the model places it (in
 * (-pi, pi]); 0 for a joint type without a rotation. */
double hx_joint_coordinate_placed(const hx_dynamics *d, int joint);

/* Joint `joint`'s coordinate at y in freedom: a reduced joint's is y's
 * coordinate (G = {1} on its body's velocity, c = 0); any other's from its
 * markers, G in the bodies' velocities (a free body's omega in body axes:
 * I's at G[0..5], J's at G[6..11], a ground side's zero), a rotation
 * unwrapped against `near` (within pi of it: a motion's value, or the angle
 * an evaluation's data holds for the joint, joint_turns.h); returns 0. */
int hx_joint_coordinate_near(const hx_dynamics *d, int joint, char freedom, const double *y,
                             double near, double *value, double G[12], double *c);
/* The same with a rotation unwrapped against where the model places the
 * joint (hx_joint_coordinate_placed). */
void hx_joint_coordinate_at(const hx_dynamics *d, int joint, char freedom, const double *y,
                            double *value, double G[12], double *c);

#endif
