/*
 * Mount limits (docs/interface.md §3.4): contact between the bodies a
 * bushing connects once the deflection q closes the gap L, per direction and
 * side, on the raw deformation and rate (never offset, scaled or coupled):
 *   positive side, q > L:  F = min(0, -K (q - L)^E - C qdot STEP(q - L, 0, 0, D, 1))
 *   negative side, q < -L: F = -min(0, -K (-q - L)^E + C qdot STEP(-q - L, 0, 0, D, 1))
 *   otherwise 0.
 * The min() keeps a fast-separating contact from pulling; with D = 0 the
 * damping is fully on at contact.
 */
#ifndef USRSUB_MOUNT_LIMITS_H
#define USRSUB_MOUNT_LIMITS_H

#include "usrsub/core/message.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct usrsub_limit_side {
    int direction; /* 0..5: x y z ax ay az */
    int sign;      /* +1 positive side, -1 negative side */
    double k, e, c, d, l;
    /* derived by usrsub_mount_limits_prepare */
    int power;     /* how p^E is computed: enum usrsub_limit_power */
    double inv_d;  /* 1/D (0 when D = 0: no ramp) */
} usrsub_limit_side;

enum usrsub_limit_power {
    USRSUB_POWER_GENERAL, USRSUB_POWER_1, USRSUB_POWER_3_2, USRSUB_POWER_2, USRSUB_POWER_3
};

typedef struct usrsub_mount_limits {
    int nsides;                  /* active sides only (K > 0 or C > 0) */
    usrsub_limit_side side[12];
    int uses_translation, uses_rotation, uses_velocity;
    int uses_twist; /* the force depends on the rotation about z, d[5] */
    /* derived by usrsub_mount_limits_prepare: the sides by [direction][0
     * positive, 1 negative], an absent side with an infinite gap */
    usrsub_limit_side by_direction[6][2];
    unsigned directions;         /* bit k: direction k has an active side */
} usrsub_mount_limits;

/* Adds the limit forces to F (6), and their partials to dFdd, dFdv (6x6
 * column-major; may be NULL) at the raw deformation d and rate v. */
void usrsub_mount_limits_add(const usrsub_mount_limits *m, const double d[6], const double v[6],
                             double F[6], double *dFdd, double *dFdv);

/* One side's force at deflection q and rate qdot, and its partials (the side
 * need not be prepared). */
double usrsub_limit_side_force(const usrsub_limit_side *s, double q, double qdot, double *dq,
                               double *dqdot);

/* Derives the flags, the look-up by direction and each side's derived data;
 * call after filling a limits model by hand. */
void usrsub_mount_limits_prepare(usrsub_mount_limits *m);


void usrsub_mount_limits_free(usrsub_mount_limits *m);

#ifdef __cplusplus
}
#endif

#endif
