/*
 * Rotations (usrsub/core/rotation.h): Euler and projection angles
 * against matrices worked by hand; phi rebuilt at rest from any psi; the
 * rotation of given projection angles and its derivative; the rotation
 * vector near 0 and pi; the inverse tangent map and its derivatives; and the
 * rotation-vector measure's forces and partials against central differences
 * of the whole map.
 */
#include <math.h>
#include <string.h>

#include "test_support.h"
#include "usrsub/core/rotation.h"

static void axis_angle(const double axis[3], double angle, double R[9])
{
    const double n = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    const double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n;
    const double c = cos(angle), s = sin(angle), t = 1.0 - c;
    const double M[9] = {t * x * x + c,     t * x * y - s * z, t * x * z + s * y,
                         t * x * y + s * z, t * y * y + c,     t * y * z - s * x,
                         t * x * z - s * y, t * y * z + s * x, t * z * z + c};
    memcpy(R, M, sizeof M);
}

static void mul(const double A[9], const double B[9], double C[9])
{
    double T[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            T[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
    memcpy(C, T, sizeof T);
}

static void euler_and_angles_by_hand(void **state)
{
    (void)state;
    /* psi = pi/2, theta = pi/2, phi = 0: Rz(90) Rx(90): x -> (0,1,0), y -> (0,0,1), z -> (1,0,0) */
    double R[9];
    usrsub_euler313_rotation((const double[3]){M_PI / 2, M_PI / 2, 0.0}, R);
    const double expected[9] = {0, 0, 1, 1, 0, 0, 0, 1, 0};
    for (int k = 0; k < 9; ++k)
        assert_close(R[k], expected[k], 0, 1e-15);
    /* a general one against the product of the three elementary turns */
    const double e[3] = {0.7, -0.4, 2.1}, z[3] = {0, 0, 1}, x[3] = {1, 0, 0};
    double A[9], B[9], C[9];
    axis_angle(z, e[0], A);
    axis_angle(x, e[1], B);
    axis_angle(z, e[2], C);
    mul(A, B, A);
    mul(A, C, A);
    usrsub_euler313_rotation(e, R);
    for (int k = 0; k < 9; ++k)
        assert_close(R[k], A[k], 0, 1e-15);
    /* projection angles: a turn about one axis gives that angle alone */
    double a[3];
    axis_angle(x, 0.25, R);
    usrsub_projection_angles(R, a);
    assert_close(a[0], 0.25, 0, 1e-15);
    assert_close(a[1], 0.0, 0, 1e-15);
    assert_close(a[2], 0.0, 0, 1e-15);
    axis_angle(z, -1.1, R);
    usrsub_projection_angles(R, a);
    assert_close(a[2], -1.1, 0, 1e-15);
}

static void phi_at_rest_from_any_psi(void **state)
{
    (void)state;
    /* the twist AZ = 0.3 with a tilt from 1e-15 to 1e-3, psi anything; and I
     * flipped (theta near pi, z axes opposite), where cos(theta) is -1 */
    for (int flipped = 0; flipped < 2; ++flipped)
        for (double tilt = 1e-15; tilt <= 1e-3; tilt *= 10.0)
            for (double psi = -3.0; psi <= 3.0; psi += 0.77) {
                const double az = 0.3, theta = flipped ? M_PI - tilt : tilt;
                const double phi = usrsub_rest_phi(psi, cos(theta), az);
                double R[9], a[3];
                usrsub_euler313_rotation((const double[3]){psi, theta, phi}, R);
                usrsub_projection_angles(R, a);
                assert_close(a[2], az, 0, 2e-15);
            }
}

static void rotation_of_projection_angles_round_trip(void **state)
{
    (void)state;
    const double axes[4][3] = {{1, 2, 3}, {-0.3, 0.1, 1}, {0.2, -1, 0.4}, {1, 0, 0}};
    const double angles[4] = {0.4, 0.05, 0.9, 0.3};
    for (int c = 0; c < 4; ++c) {
        double R[9], a[3], R2[9], A[9];
        axis_angle(axes[c], angles[c], R);
        usrsub_projection_angles(R, a);
        assert_int_equal(usrsub_rotation_of_projection_angles(a, R2, A), 0);
        for (int k = 0; k < 9; ++k)
            assert_close(R2[k], R[k], 0, 1e-14);
        /* A = d theta / d a: a small change of the angles turns R by A da */
        for (int j = 0; j < 3; ++j) {
            const double h = 1e-6;
            double ap[3] = {a[0], a[1], a[2]}, am[3] = {a[0], a[1], a[2]}, Rp[9], Rm[9], D[9];
            ap[j] += h, am[j] -= h;
            assert_int_equal(usrsub_rotation_of_projection_angles(ap, Rp, NULL), 0);
            assert_int_equal(usrsub_rotation_of_projection_angles(am, Rm, NULL), 0);
            /* dR R^T = [dtheta]x */
            double dR[9], RT[9];
            for (int k = 0; k < 9; ++k)
                dR[k] = (Rp[k] - Rm[k]) / (2 * h);
            for (int i = 0; i < 3; ++i)
                for (int l = 0; l < 3; ++l)
                    RT[3 * i + l] = R[3 * l + i];
            mul(dR, RT, D);
            assert_close(A[3 * 0 + j], D[7], 1e-8, 1e-8); /* [w]x(2,1) = w0 */
            assert_close(A[3 * 1 + j], D[2], 1e-8, 1e-8); /* (0,2) = w1 */
            assert_close(A[3 * 2 + j], D[3], 1e-8, 1e-8); /* (1,0) = w2 */
        }
    }
}

static void rotation_vector_near_zero_and_pi(void **state)
{
    (void)state;
    const double axis[3] = {0.6, -0.8, 0.0};
    const double angles[] = {0.0, 1e-12, 1e-6, 0.3, 2.0, M_PI - 1e-9, M_PI};
    for (size_t k = 0; k < sizeof angles / sizeof angles[0]; ++k) {
        double R[9], r[3];
        axis_angle(axis, angles[k], R);
        usrsub_rotation_vector(R, r);
        const double len = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
        assert_close(len, angles[k], 1e-12, 1e-15);
        if (angles[k] > 0.0) { /* along the axis (either way at exactly pi) */
            const double along = (r[0] * 0.6 - r[1] * 0.8) / len;
            assert_close(fabs(along), 1.0, 0, 1e-9);
            if (angles[k] < 3.0)
                assert_true(along > 0.0);
        }
    }
}

/* exp([r]x) by Rodrigues' formula. */
static void exp_rotation(const double r[3], double R[9])
{
    const double t = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (t == 0.0) {
        const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        memcpy(R, I, sizeof I);
        return;
    }
    axis_angle(r, t, R);
}

static void tangent_map_and_its_derivatives(void **state)
{
    (void)state;
    const double rs[4][3] = {{0.3, -0.2, 0.5}, {1e-5, 2e-5, -1e-5}, {1.2, 0.9, -1.5}, {0.2, 0.1, 0.3}};
    for (int c = 0; c < 4; ++c) {
        const double *r = rs[c];
        double Jinv[9], dJ[27];
        usrsub_tangent_inverse(r, Jinv, dJ);
        /* omega of the path exp([r + s u]x) at s = 0 is J u: so J^-1 omega = u */
        const double u[3] = {0.7, -0.3, 0.2}, h = 1e-6;
        double rp[3], rm[3], Rp[9], Rm[9], R[9];
        for (int i = 0; i < 3; ++i)
            rp[i] = r[i] + h * u[i], rm[i] = r[i] - h * u[i];
        exp_rotation(rp, Rp);
        exp_rotation(rm, Rm);
        exp_rotation(r, R);
        double dR[9], RT[9], W[9];
        for (int k = 0; k < 9; ++k)
            dR[k] = (Rp[k] - Rm[k]) / (2 * h);
        for (int i = 0; i < 3; ++i)
            for (int l = 0; l < 3; ++l)
                RT[3 * i + l] = R[3 * l + i];
        mul(dR, RT, W);
        const double omega[3] = {W[7], W[2], W[3]};
        for (int i = 0; i < 3; ++i)
            assert_close(Jinv[3 * i] * omega[0] + Jinv[3 * i + 1] * omega[1] + Jinv[3 * i + 2] * omega[2],
                         u[i], 1e-8, 1e-9);
        /* the derivatives of J^-1 against central differences */
        for (int k = 0; k < 3; ++k) {
            const double hk = 1e-6;
            double a[3] = {r[0], r[1], r[2]}, b[3] = {r[0], r[1], r[2]}, Ja[9], Jb[9];
            a[k] += hk, b[k] -= hk;
            usrsub_tangent_inverse(a, Ja, NULL);
            usrsub_tangent_inverse(b, Jb, NULL);
            for (int n = 0; n < 9; ++n)
                assert_close(dJ[9 * k + n], (Ja[n] - Jb[n]) / (2 * hk), 1e-7, 1e-9);
        }
    }
}

/* A linear law on the generalized deformation: Q = -K d - C v (full K, C). */
static void linear_law(const double d[6], const double v[6], double Q[6], double K[36],
                       double C[36])
{
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            K[i + 6 * j] = -(i == j ? 100.0 * (i + 1) : 3.0 * (i - j) + 1.0);
            C[i + 6 * j] = -(i == j ? 2.0 + i : 0.1 * (i + 2 * j));
        }
    for (int i = 0; i < 6; ++i) {
        Q[i] = 7.0 * (i + 1);
        for (int j = 0; j < 6; ++j)
            Q[i] += K[i + 6 * j] * d[j] + C[i + 6 * j] * v[j];
    }
}

/* F of the map at (x, angles) and (v, omega). */
static void mapped(const double d[6], const double v[6], double F[6], double *dFdd, double *dFdv)
{
    double R[9], A[9];
    assert_int_equal(usrsub_rotation_of_projection_angles(d + 3, R, A), 0);
    usrsub_rotation_map m;
    usrsub_rotation_map_make(&m, R, v + 3, dFdd != NULL ? A : NULL);
    const double dm[6] = {d[0], d[1], d[2], m.r[0], m.r[1], m.r[2]};
    const double vm[6] = {v[0], v[1], v[2], m.rdot[0], m.rdot[1], m.rdot[2]};
    double Q[6], K[36], C[36];
    linear_law(dm, vm, Q, K, C);
    usrsub_rotation_map_forces(&m, Q, K, C, F, dFdd, dFdv);
}

static void rotation_vector_partials_against_differences(void **state)
{
    (void)state;
    const double d0[6] = {0.3, -0.2, 0.1, 0.21, -0.13, 0.37};
    const double v0[6] = {1.5, -2.0, 0.7, 0.4, 0.9, -0.6};
    double F[6], dFdd[36], dFdv[36];
    mapped(d0, v0, F, dFdd, dFdv);
    for (int j = 0; j < 12; ++j) {
        double dp[6], vp[6], dm[6], vm[6], Fp[6], Fm[6];
        memcpy(dp, d0, sizeof dp), memcpy(vp, v0, sizeof vp);
        memcpy(dm, d0, sizeof dm), memcpy(vm, v0, sizeof vm);
        const double h = 1e-6;
        (j < 6 ? dp : vp)[j % 6] += h;
        (j < 6 ? dm : vm)[j % 6] -= h;
        mapped(dp, vp, Fp, NULL, NULL);
        mapped(dm, vm, Fm, NULL, NULL);
        for (int i = 0; i < 6; ++i) {
            const double fd = (Fp[i] - Fm[i]) / (2 * h);
            const double an = j < 6 ? dFdd[i + 6 * j] : dFdv[i + 6 * (j - 6)];
            assert_close(an, fd, 1e-7, 1e-6);
        }
    }
    /* the torque does work on omega as Q_r does on rdot: T . omega = Q_r . rdot */
    double R[9];
    assert_int_equal(usrsub_rotation_of_projection_angles(d0 + 3, R, NULL), 0);
    usrsub_rotation_map m;
    usrsub_rotation_map_make(&m, R, v0 + 3, NULL);
    const double dmap[6] = {d0[0], d0[1], d0[2], m.r[0], m.r[1], m.r[2]};
    const double vmap[6] = {v0[0], v0[1], v0[2], m.rdot[0], m.rdot[1], m.rdot[2]};
    double Q[6], K[36], C[36];
    linear_law(dmap, vmap, Q, K, C);
    const double power_T = F[3] * v0[3] + F[4] * v0[4] + F[5] * v0[5];
    const double power_Q = Q[3] * m.rdot[0] + Q[4] * m.rdot[1] + Q[5] * m.rdot[2];
    assert_close(power_T, power_Q, 1e-13, 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(euler_and_angles_by_hand),
        cmocka_unit_test(phi_at_rest_from_any_psi),
        cmocka_unit_test(rotation_of_projection_angles_round_trip),
        cmocka_unit_test(rotation_vector_near_zero_and_pi),
        cmocka_unit_test(tangent_map_and_its_derivatives),
        cmocka_unit_test(rotation_vector_partials_against_differences),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
