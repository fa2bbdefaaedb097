/* Relative measures of frames (measures.h). */
#include "frames/measures.h"

#include <math.h>

#include "base/vecmath.h"

void hx_displacement(const hx_frame *I, const hx_frame *J, const hx_frame *K, double d[3])
{
    double r[3];
    v3_sub(r, I->p, J->p);
    m3_tapply(d, K->R, r);
}

void hx_relative_rotation(const hx_frame *I, const hx_frame *J, double R[9])
{
    m3_tmul(R, J->R, I->R);
}

double hx_projection_angle(const double R[9], int axis)
{
    switch (axis) {
    case 0: return atan2(R[7], R[4]); /* Y_I . Z_J, Y_I . Y_J */
    case 1: return atan2(R[2], R[8]); /* Z_I . X_J, Z_I . Z_J */
    default: return atan2(R[3], R[0]); /* X_I . Y_J, X_I . X_J */
    }
}

void hx_projection_angles(const double R[9], double a[3])
{
    for (int axis = 0; axis < 3; ++axis)
        a[axis] = hx_projection_angle(R, axis);
}

static double wrap(double angle)
{
    if (angle > M_PI)
        return angle - 2.0 * M_PI;
    if (angle <= -M_PI)
        return angle + 2.0 * M_PI;
    return angle;
}

void hx_euler313(const double R[9], double e[3])
{
    /* R = [[. . s_psi s_th], [. . -c_psi s_th], [s_th s_phi, s_th c_phi, c_th]]; and
     *   R10 - R01 = (1 + c_th) sin(psi + phi),  R00 + R11 = (1 + c_th) cos(psi + phi),
     *   R10 + R01 = (1 - c_th) sin(psi - phi),  R00 - R11 = (1 - c_th) cos(psi - phi) */
    const double s = sqrt(R[2] * R[2] + R[5] * R[5]); /* entries of at most 1: no overflow */
    e[1] = atan2(s, R[8]);
    /* psi is arbitrary where sin(theta) is rounding; where it is exactly 0, all
     * of the defined sum goes to psi */
    e[0] = s > 0.0 ? atan2(R[2], -R[5]) : R[8] >= 0.0 ? atan2(R[3] - R[1], R[0] + R[4])
                                                     : atan2(R[3] + R[1], R[0] - R[4]);
    if (R[8] >= 0.0)
        e[2] = wrap(atan2(R[3] - R[1], R[0] + R[4]) - e[0]);
    else
        e[2] = wrap(e[0] - atan2(R[3] + R[1], R[0] - R[4]));
}

void hx_euler321(const double R[9], double e[3])
{
    /* R = [[c_y c_b, ., .], [s_y c_b, ., .], [-s_b, c_b s_r, c_b c_r]]; and
     *   R01 - R12 = (1 + s_b) sin(r - y),  R11 + R02 = (1 + s_b) cos(r - y),
     *   R01 + R12 = (s_b - 1) sin(r + y),  R11 - R02 = (1 - s_b) cos(r + y) */
    const double c = sqrt(R[0] * R[0] + R[3] * R[3]);
    const int up = R[6] <= 0.0; /* b >= 0 */
    const double defined = up ? atan2(R[1] - R[5], R[4] + R[2]) /* r - y */
                              : atan2(-(R[1] + R[5]), R[4] - R[2]); /* r + y */
    e[1] = atan2(-R[6], c);
    e[0] = c > 0.0 ? atan2(R[3], R[0]) : wrap(up ? -defined : defined);
    e[2] = wrap(up ? defined + e[0] : defined - e[0]);
}

int hx_euler_canonical(const int axes[3], const double R[9], double C[9], double *sign)
{
    const int proper = axes[0] == axes[2];
    int p[3];
    double s[3] = {1.0, 1.0, 1.0};
    if (proper) /* Q's rows: b, then the third axis, then a */
        p[0] = axes[1], p[1] = 3 - axes[0] - axes[1], p[2] = axes[0];
    else /* c, b, a */
        p[0] = axes[2], p[1] = axes[1], p[2] = axes[0];
    /* Q's row i is s[i] e_p[i]: its determinant, the permutation's parity
     * times the signs, made +1 by the one free sign */
    const int inversions = (p[0] > p[1]) + (p[0] > p[2]) + (p[1] > p[2]);
    const double parity = inversions % 2 ? -1.0 : 1.0;
    s[proper ? 1 : 0] = parity;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            C[3 * i + j] = s[i] * s[j] * R[3 * p[i] + p[j]];
    *sign = proper ? 1.0 : parity;
    return proper;
}

void hx_euler_sequence(const int axes[3], const double R[9], double e[3])
{
    double C[9], sign;
    if (hx_euler_canonical(axes, R, C, &sign)) {
        hx_euler313(C, e);
    } else {
        hx_euler321(C, e);
        e[2] = wrap(sign * e[2]);
    }
}

void hx_euler_parameters(const double R[9], double e[4])
{
    quat_from_matrix(e, R);
    int k = 0; /* the first nonzero of e0, e1, e2, e3 made positive */
    while (k < 3 && e[k] == 0.0)
        ++k;
    if (e[k] < 0.0)
        for (int i = 0; i < 4; ++i)
            e[i] = -e[i];
}

void hx_rotation_vector(const double R[9], double r[3])
{
    double q[4];
    hx_euler_parameters(R, q); /* the shorter way round: angle in [0, pi] */
    const double s = sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    /* angle / sin(angle / 2), which tends to 2 at rest */
    const double scale = s > 1e-8 ? 2.0 * atan2(s, q[0]) / s : 2.0 / q[0];
    v3_scale(r, q + 1, scale);
}

void hx_relative_euler313(const hx_frame *I, const hx_frame *J, double e[3])
{
    double R[9];
    hx_relative_rotation(I, J, R);
    hx_euler313(R, e);
}

void hx_relative_velocity(const hx_frame *I, const hx_frame *J, const hx_frame *K,
                          const hx_frame *L, double v[3])
{
    double r[3], dv[3], wr[3];
    v3_sub(r, I->p, J->p);
    v3_sub(dv, I->v, J->v);
    v3_cross(wr, L->w, r);
    v3_sub(dv, dv, wr);
    m3_tapply(v, K->R, dv);
}

void hx_relative_angular_velocity(const hx_frame *I, const hx_frame *J, const hx_frame *K,
                                  double w[3])
{
    double dw[3];
    v3_sub(dw, I->w, J->w);
    m3_tapply(w, K->R, dw);
}

void hx_field_state(const hx_frame *I, const hx_frame *J, double disp[6], double velo[6])
{
    double R[9];
    hx_displacement(I, J, J, disp);
    hx_relative_rotation(I, J, R);
    hx_projection_angles(R, disp + 3);
    hx_relative_velocity(I, J, J, J, velo);
    hx_relative_angular_velocity(I, J, J, velo + 3);
}

void hx_force_deformation(const hx_frames *fr, int force, double disp[6], double velo[6])
{
    const hx_force *f = &fr->model->forces[force];
    hx_frame scratch[2];
    hx_field_state(hx_frames_marker(fr, f->i_marker, &scratch[0]),
                   hx_frames_marker(fr, f->j_marker, &scratch[1]), disp, velo);
}

double hx_joint_coordinate(const hx_frames *fr, int joint, char freedom)
{
    const hx_joint *j = &fr->model->joints[joint];
    hx_frame scratch[2];
    const hx_frame *I = hx_frames_marker(fr, j->i_marker, &scratch[0]);
    const hx_frame *J = hx_frames_marker(fr, j->j_marker, &scratch[1]);
    if (freedom == 'R' || (freedom == 0 && j->type == HX_JOINT_REVOLUTE)) {
        double R[9], a[3];
        hx_relative_rotation(I, J, R);
        hx_projection_angles(R, a);
        return a[2];
    }
    double d[3];
    hx_displacement(I, J, J, d);
    return d[2];
}
