/*
 * The Altair-style bushing (docs/interface.md §3.2 and §3.3): per direction
 * k in (x, y, z, ax, ay, az), with q = H d - Q and qdot = H ddot,
 *   G(q, qdot) = -(g(q) + c qdot),   F = -P + V G,
 * g a constant, spline or cubic characteristic; CYLINDRICAL coupling joins the
 * x,y translations and the x,y rotations, SPHERICAL all three of each, so that
 * the force opposes the overall deformation (the vendor's coupling page, signs made consistent; docs/sources.md),
 * blended into the uncoupled force below the radius EPSILON.
 */
#ifndef USRSUB_BUSHING_H
#define USRSUB_BUSHING_H

#include "usrsub/core/lugre_friction.h"
#include "usrsub/core/message.h"
#include "usrsub/core/spline.h"

#ifdef __cplusplus
extern "C" {
#endif

enum usrsub_coupling { USRSUB_UNCOUPLED, USRSUB_CYLINDRICAL, USRSUB_SPHERICAL };
enum usrsub_stiffness_kind {
    USRSUB_STIFFNESS_NONE,
    USRSUB_STIFFNESS_CONSTANT,
    USRSUB_STIFFNESS_SPLINE,
    USRSUB_STIFFNESS_CUBIC
};

/* Cubic characteristic: right of O, with u = q - O,
 * OF + OS u + c2p u^2 + c3p u^3 through (RP, RPF) with slope EPS at EP, linear
 * with slope EPS beyond EP; the mirror image with RN, RNF, EN, ENS on the left. */
typedef struct usrsub_cubic_characteristic {
    double o, of, os, rp, rpf, ep, eps, rn, rnf, en, ens;
    double c2p, c3p, c2n, c3n; /* fitted */
    double at_ep, at_en;       /* values at EP and EN */
} usrsub_cubic_characteristic;

typedef struct usrsub_bushing_direction {
    int active;
    int stiffness;   /* enum usrsub_stiffness_kind */
    double k;        /* constant stiffness */
    usrsub_spline spline;
    usrsub_cubic_characteristic cubic;
    int damped;
    double c;        /* constant damping */
    double preload, offset, disp_scale, force_scale; /* P, Q, H, V */
    double g_at_zero; /* g(0), set by usrsub_bushing_prepare */
    /* internal states (docs/interface.md §3.8), read only by the
     * state-carrying entry: the rubber filter's cut-off R and the dynamic
     * part's K and C; the mount's series stiffness and damping */
    int rubber;
    double rubber_r, rubber_k, rubber_c;
    int mount;
    double mount_k, mount_c;
    double mount_inertia; /* of the node between mount and bushing: K / (1e4 rad/s)^2 */
} usrsub_bushing_direction;

typedef struct usrsub_bushing {
    usrsub_bushing_direction dir[6];
    usrsub_friction friction; /* its torque needs the state-carrying entry */
    int coupling;          /* enum usrsub_coupling */
    int rotation_measure;  /* enum usrsub_rotation_measure (core/rotation.h) */
    double group_epsilon[2]; /* blend radius of the translational and rotational groups */
    /* derived by usrsub_bushing_prepare: the coupled groups of active
     * directions, the directions evaluated alone, the inactive ones */
    int ngroups;
    int group[2][3];
    int group_size[2];
    double epsilon[2];     /* each coupled group's blend radius */
    int nsingle, single[6];
    int ninactive, inactive[6];
    int uses_translation, uses_rotation, uses_velocity;
    int uses_twist; /* the force depends on the rotation about z, d[5] */
    int has_states; /* friction, a mount or a rubber filter is active */
} usrsub_bushing;

/* Fits c2 and c3 of both sides; -1 with a message when the points cannot
 * define them (they must satisfy EN < RN < O < RP < EP). */
int usrsub_cubic_fit(usrsub_cubic_characteristic *c, usrsub_message *msg);

/* The characteristic g(q) of a direction, and g'(q) in *slope (may be NULL
 * when only the value is wanted). */
double usrsub_characteristic(const usrsub_bushing_direction *d, double q, double *slope);

/* Derives what evaluation reads (active flags, coupled groups of the active
 * directions, g(0), what is measured) from the directions and the coupling;
 * call once after filling a bushing by hand. */
void usrsub_bushing_prepare(usrsub_bushing *b);

/* Force and torque on I (x, y, z, ax, ay, az order) for the deformation d and
 * its rate v; dFdd and dFdv (may be NULL) receive the 6x6 partials,
 * column-major: [i + 6*j] = dF_i / dx_j. */
void usrsub_bushing_force(const usrsub_bushing *b, const double d[6], const double v[6],
                          double F[6], double *dFdd, double *dFdv);

/* Force of a coupled group of m (2 or 3) directions at q, qdot (after offset
 * and scale), before preload and force scale, with its m x m partials
 * (column-major [i + m*j] = dF_i/dq_j; may be NULL). */
void usrsub_bushing_coupling_force(const usrsub_bushing_direction *const dirs[], int m,
                                   double epsilon, const double *q, const double *qd, double *F,
                                   double *dFdq, double *dFdqd);


void usrsub_bushing_free(usrsub_bushing *b);

#ifdef __cplusplus
}
#endif

#endif
