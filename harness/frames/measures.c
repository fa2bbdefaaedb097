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

void hx_rotation_vector(const double R[9], double r[3])
{
    double q[4];
    quat_from_matrix(q, R);
    if (q[0] < 0.0) /* the shorter way round: angle in [0, pi] */
        for (int k = 0; k < 4; ++k)
            q[k] = -q[k];
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
