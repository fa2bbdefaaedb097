/*
 * Flexible joint (docs/interface.md §3.5): concentrated springs and
 * dampers between two bodies with fully populated 6x6 stiffness K and damping
 * D acting on (x y z ax ay az), and a preload P:
 *   F = P - K d - D ddot,   dF/dd = -K,   dF/dddot = -D.
 * The torque rows act on projection angles, so the joint is conservative
 * (for a symmetric K) in translations and in rotations about one fixed axis,
 * and to first order in the angles otherwise.
 */
#ifndef USRSUB_FLEX_JOINT_H
#define USRSUB_FLEX_JOINT_H

#include "usrsub/core/message.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct usrsub_flex_joint {
    double k[36], d[36]; /* column-major: k[i + 6*j] = K_ij, in the model's units */
    double preload[6];
    int rotation_measure;  /* enum usrsub_rotation_measure (core/bushing.h) */
    /* derived by usrsub_flex_joint_prepare */
    double minus_k[36], minus_d[36]; /* the partials */
    unsigned k_blocks, d_blocks;     /* bit 2*(i/3) + j/3: block (rows i, columns j) is not zero */
    int uses_translation, uses_rotation, uses_velocity;
    int uses_twist; /* the force depends on the rotation about z, d[5] */
} usrsub_flex_joint;

/* Force and torque on I in J axes; partials (may be NULL) column-major. */
void usrsub_flex_joint_force(const usrsub_flex_joint *j, const double d[6], const double v[6],
                             double F[6], double *dFdd, double *dFdv);

/* Derives the blocks, flags and partials; call after filling a joint by hand. */
void usrsub_flex_joint_prepare(usrsub_flex_joint *j);


/* Smallest eigenvalue of the symmetric part of the n x n matrix a (n <= 6),
 * after scaling rows and columns by 1/sqrt(|a_ii|) so that mixed units do not
 * matter (the sign pattern of the eigenvalues is kept): a negative value
 * means the matrix is not positive semi-definite. */
double usrsub_scaled_smallest_eigenvalue(const double *a, int n);

void usrsub_flex_joint_free(usrsub_flex_joint *j);

#ifdef __cplusplus
}
#endif

#endif
