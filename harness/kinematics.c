/* Relative measures of frames (kinematics.h). */
#include "kinematics.h"

#include <math.h>

#include "usrsub/trig.h"
#include "vecmath.h"

static const hx_frame world = {{0, 0, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0}};

void hx_marker_frame(const hx_model *m, const hx_frame *bodies, int marker, hx_frame *out)
{
    if (marker < 0) {
        *out = world;
        return;
    }
    const hx_marker *mk = &m->markers[marker];
    const hx_frame *b = &bodies[mk->body];
    if (mk->local_axes)
        m3_copy(out->R, b->R);
    else
        m3_mul(out->R, b->R, mk->R_local);
    v3_copy(out->w, b->w);
    if (mk->at_body_origin) {
        v3_copy(out->p, b->p);
        v3_copy(out->v, b->v);
        return;
    }
    double r[3], wr[3];
    m3_apply(r, b->R, mk->r_local);
    v3_add(out->p, b->p, r);
    v3_cross(wr, b->w, r);
    v3_add(out->v, b->v, wr);
}

void hx_initial_frames(const hx_model *m, hx_frame *bodies)
{
    for (int k = 0; k < m->nbodies; ++k) {
        const hx_body *b = &m->bodies[k];
        hx_frame *f = &bodies[k];
        v3_copy(f->p, b->p0);
        m3_copy(f->R, b->R0);
        v3_copy(f->v, b->v0);
        v3_copy(f->w, b->w0);
    }
}

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

void hx_projection_angles(const double R[9], double a[3])
{
    a[0] = usrsub_atan2(R[7], R[4]); /* Y_I . Z_J, Y_I . Y_J */
    a[1] = usrsub_atan2(R[2], R[8]); /* Z_I . X_J, Z_I . Z_J */
    a[2] = usrsub_atan2(R[3], R[0]); /* X_I . Y_J, X_I . X_J */
}

void hx_euler313(const double R[9], double e[3])
{
    const double s = sqrt(R[2] * R[2] + R[5] * R[5]); /* entries of a rotation: no overflow */
    e[1] = usrsub_atan2(s, R[8]);
    if (s > 1e-12) {
        e[0] = usrsub_atan2(R[2], -R[5]);
        e[2] = usrsub_atan2(R[6], R[7]);
    } else { /* theta = 0 or pi: only psi +- phi is defined; put it all in psi */
        e[0] = usrsub_atan2(R[3], R[0]);
        e[2] = 0.0;
    }
}

void hx_relative_euler313(const hx_frame *I, const hx_frame *J, double e[3])
{
    /* only the entries the angles use of R = R_J^T R_I: R[a][b] = (J axis a) . (I axis b) */
    const double *ri = I->R, *rj = J->R;
#define ENTRY(a, b) (rj[a] * ri[b] + rj[3 + a] * ri[3 + b] + rj[6 + a] * ri[6 + b])
    double R[9];
    R[2] = ENTRY(0, 2), R[5] = ENTRY(1, 2), R[8] = ENTRY(2, 2);
    R[6] = ENTRY(2, 0), R[7] = ENTRY(2, 1);
    R[0] = ENTRY(0, 0), R[3] = ENTRY(1, 0);
#undef ENTRY
    R[1] = R[4] = 0.0;
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

double hx_joint_coordinate(const hx_model *m, const hx_frame *bodies, int joint)
{
    const hx_joint *j = &m->joints[joint];
    hx_frame I, J;
    hx_marker_frame(m, bodies, j->i_marker, &I);
    hx_marker_frame(m, bodies, j->j_marker, &J);
    if (j->type == HX_JOINT_REVOLUTE) {
        double R[9], a[3];
        hx_relative_rotation(&I, &J, R);
        hx_projection_angles(R, a);
        return a[2];
    }
    double d[3];
    hx_displacement(&I, &J, &J, d);
    return d[2];
}
