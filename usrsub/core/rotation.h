/*
 * Rotations of I relative to J (docs/interface.md §3.1, §3.7). A rotation is
 * a row-major 3x3 matrix R whose columns are I's axes in J's: R = R_J^T R_I.
 *  - the host's 3-1-3 Euler angles: R = Rz(psi) Rx(theta) Rz(phi);
 *  - the projection angles AX = atan2(R21, R11), AY = atan2(R02, R22),
 *    AZ = atan2(R10, R00);
 *  - the rotation vector r (axis times angle, in J): R = exp([r]x), with the
 *    tangent map of J's frame: omega = J(r) rdot, so rdot = J(r)^-1 omega.
 * At rest (sin theta ~ 0) a host may split psi and phi arbitrarily: only
 * their sum is defined. usrsub_rest_phi rebuilds phi from psi, theta and the
 * host's AZ, exactly, so that nothing depends on the host's split.
 */
#ifndef USRSUB_CORE_ROTATION_H
#define USRSUB_CORE_ROTATION_H

#ifdef __cplusplus
extern "C" {
#endif

/* How an element measures rotations (docs/interface.md §3.7): the
 * projection angles AX, AY, AZ (the default, the solver's measure), or the
 * rotation vector, whose elastic torques have a potential for any rotation. */
enum usrsub_rotation_measure { USRSUB_PROJECTION_ANGLES, USRSUB_ROTATION_VECTOR };

/* Below this |sin(theta)| the split of psi and phi is not trusted (their
 * error grows like 1e-16 / sin(theta)): phi is rebuilt from AZ. */
#define USRSUB_REST_TILT 1e-4

/* R = Rz(psi) Rx(theta) Rz(phi). */
void usrsub_euler313_rotation(const double euler[3], double R[9]);

/* AX, AY, AZ of R. */
void usrsub_projection_angles(const double R[9], double a[3]);

/* phi such that AZ of Rz(psi) Rx(theta) Rz(phi) is az: with cos(theta) = ct,
 * tan(az - psi) = ct tan(phi) (exact at every tilt, for any psi). */
double usrsub_rest_phi(double psi, double ct, double az);

/* The rotation with projection angles a (|AX|, |AY|, |AZ| < pi/2 each in the
 * intended use); A (may be NULL) receives dtheta/da, row-major: the small
 * rotation (in J) per change of the angles. Returns 0, or -1 when the angles
 * belong to no rotation near them (degenerate). */
int usrsub_rotation_of_projection_angles(const double a[3], double R[9], double *A);

/* The rotation vector of R (its angle in [0, pi]). */
void usrsub_rotation_vector(const double R[9], double r[3]);

/* J(r)^-1 = I - [r]x / 2 + c(|r|) [r]x^2, row-major; dJinv (may be NULL)
 * receives its derivatives, dJinv[9 k + 3 i + j] = d(J^-1)_ij / d r_k. */
void usrsub_tangent_inverse(const double r[3], double Jinv[9], double *dJinv);

/* The rotation-vector measure of a deformation (docs/interface.md §3.7): the
 * rotational deformation r and rate rdot for the force law, and how to turn
 * its generalized rotational forces Q into torques T = J^-T Q, which makes
 * the elastic part conservative for any rotation. */
typedef struct usrsub_rotation_map {
    double r[3], rdot[3];
    double Jinv[9];
    double dJinv[27];
    double dr_da[9];    /* d r / d angles (when A was given), row-major */
    double drdot_da[9]; /* d rdot / d angles at fixed omega */
} usrsub_rotation_map;

/* From the rotation R and the angular velocity omega (in J); A: d theta/da of
 * the projection angles the host handed over (NULL: no partials wanted). */
void usrsub_rotation_map_make(usrsub_rotation_map *m, const double R[9], const double omega[3],
                              const double *A);

/* F (6) from the generalized forces Q (6) of the law evaluated at (x, r) and
 * (v, rdot); when dQdd and dQdv (6x6 column-major, with respect to (x, r) and
 * (v, rdot)) are given, dFdd and dFdv with respect to (x, angles) and
 * (v, omega). */
void usrsub_rotation_map_forces(const usrsub_rotation_map *m, const double Q[6],
                                const double *dQdd, const double *dQdv, double F[6],
                                double *dFdd, double *dFdv);

#ifdef __cplusplus
}
#endif

#endif
