/*
 * The scenario of the rest-orientation tests: a bushing's I and J frames held
 * in ground as a solver holds them (J turned arbitrarily, I = J turned 0.3
 * rad about z and tilted about x by 1e-15 to 1e-3 rad), and the reference
 * torque, the bushing law at the exact projection angles of that relative
 * rotation (through the library's FIESUB form, which takes the angles as
 * they are).
 */
#ifndef REST_SCENARIO_H
#define REST_SCENARIO_H

#include <math.h>
#include <string.h>

/* A bushing stiff in the three rotations (and a little in translation). */
static const char rest_gbs[] =
    "[HEADER]\nFILE_TYPE = 'gbs'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\nFORCE = 'newton'\n"
    "MASS = 'kg'\nTIME = 'second'\n[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
    "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 1 1 1 1 1 1\n"
    "[CONSTANT_STIFFNESS_FX]\nK = 100\n[CONSTANT_STIFFNESS_FY]\nK = 100\n[CONSTANT_STIFFNESS_FZ]\nK = 100\n"
    "[CONSTANT_STIFFNESS_TX]\nK = 2e5\n[CONSTANT_STIFFNESS_TY]\nK = 3e5\n[CONSTANT_STIFFNESS_TZ]\nK = 1e5\n";

static inline void rest_axis_angle(double x, double y, double z, double angle, double R[9])
{
    const double n = sqrt(x * x + y * y + z * z);
    x /= n, y /= n, z /= n;
    const double c = cos(angle), s = sin(angle), t = 1.0 - c;
    const double M[9] = {t * x * x + c,     t * x * y - s * z, t * x * z + s * y,
                         t * x * y + s * z, t * y * y + c,     t * y * z - s * x,
                         t * x * z - s * y, t * y * z + s * x, t * z * z + c};
    memcpy(R, M, sizeof M);
}

static inline void rest_mul(const double A[9], const double B[9], double C[9])
{
    double T[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            T[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
    memcpy(C, T, sizeof T);
}

/* Case k: J's orientation in ground, and the exact relative rotation at tilt. */
static inline void rest_case(int k, double tilt, double RJ[9], double Rrel[9])
{
    static const double axes[4][3] = {{0.3, -0.8, 0.5}, {1, 1, 1}, {-0.2, 0.1, 0.97}, {0.9, -0.1, 0.2}};
    static const double angles[4] = {0.7, 2.4, -1.3, 3.0};
    rest_axis_angle(axes[k][0], axes[k][1], axes[k][2], angles[k], RJ);
    double Rz[9], Rx[9];
    rest_axis_angle(0, 0, 1, 0.3, Rz);
    rest_axis_angle(1, 0, 0, tilt, Rx);
    rest_mul(Rz, Rx, Rrel);
}

/* The exact projection angles of Rz(0.3) Rx(tilt), worked by hand:
 * R = [[c, -s ct, s st], [s, c ct, -c st], [0, st, ct]] with c, s of 0.3. */
static inline void rest_exact_angles(double tilt, double a[3])
{
    const double c = cos(0.3), s = sin(0.3), ct = cos(tilt), st = sin(tilt);
    a[0] = atan2(st, c * ct); /* R21, R11 */
    a[1] = atan2(s * st, ct); /* R02, R22 */
    a[2] = atan2(s, c);       /* R10, R00 */
}

#endif
