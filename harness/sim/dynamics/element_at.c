/* Force elements at prescribed states (element_at.h). */
#include "host/invoke.h"
#include "sim/dynamics/element_at.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "frames/measures.h"
#include "sim/dynamics/element_forces.h"
#include "base/linalg.h"
#include "base/vecmath.h"

static void rotation_of_vector(const double th[3], double R[9])
{
    const double angle = v3_norm(th);
    if (angle == 0.0) {
        m3_identity(R);
        return;
    }
    const double axis[3] = {th[0] / angle, th[1] / angle, th[2] / angle};
    m3_axis_angle(R, axis, angle);
}

int hx_rotation_from_angles(const double a[3], double R[9])
{
    double th[3] = {a[0], a[1], a[2]};
    for (int it = 0; it < 50; ++it) {
        double angles[3], f[3];
        rotation_of_vector(th, R);
        hx_projection_angles(R, angles);
        v3_sub(f, angles, a);
        if (hx_max_abs(f, 3) < 1e-15)
            return 0;
        double J[9], Rp[9], ap[3];
        for (int k = 0; k < 3; ++k) {
            double tp[3] = {th[0], th[1], th[2]};
            tp[k] += 1e-7;
            rotation_of_vector(tp, Rp);
            hx_projection_angles(Rp, ap);
            for (int i = 0; i < 3; ++i)
                J[3 * i + k] = (ap[i] - angles[i]) / 1e-7;
        }
        if (hx_solve(3, J, f) != 0)
            return -1;
        v3_sub(th, th, f);
    }
    double angles[3], f[3];
    rotation_of_vector(th, R);
    hx_projection_angles(R, angles);
    v3_sub(f, angles, a);
    return hx_max_abs(f, 3) < 1e-12 ? 0 : -1;
}

/* Moves the body that carries i_marker in out so that the I marker sits at
 * (p, Rrel) and moves at (v, w) relative to the J marker as base has it;
 * returns that body. Only its frame is written, not its markers'. */
static int place_body(const hx_frames *base, hx_frames *out, int i_marker, int j_marker,
                      const double p[3], const double Rrel[9], const double v[3],
                      const double w[3])
{
    const hx_model *m = base->model;
    hx_frame scratch;
    const hx_frame *J = hx_frames_marker(base, j_marker, &scratch);
    hx_frame I;
    m3_mul(I.R, J->R, Rrel);
    m3_apply(I.p, J->R, p);
    v3_add(I.p, I.p, J->p);
    double wg[3], vg[3], r[3], wr[3];
    m3_apply(wg, J->R, w);
    v3_add(I.w, J->w, wg);
    m3_apply(vg, J->R, v);
    v3_sub(r, I.p, J->p);
    v3_cross(wr, J->w, r);
    v3_add(I.v, J->v, vg);
    v3_add(I.v, I.v, wr);
    const hx_marker *mk = &m->markers[i_marker];
    hx_frame *b = &out->bodies[mk->body];
    m3_mult(b->R, I.R, mk->R_local);
    double rb[3];
    m3_apply(rb, b->R, mk->r_local);
    v3_sub(b->p, I.p, rb);
    v3_copy(b->w, I.w);
    double wrb[3];
    v3_cross(wrb, b->w, rb);
    v3_sub(b->v, I.v, wrb);
    return mk->body;
}

void hx_place_pose(const hx_frames *base, hx_frames *out, int i_marker, int j_marker,
                   const double p[3], const double Rrel[9], const double v[3],
                   const double w[3])
{
    hx_frames_copy(out, base);
    const int body = place_body(base, out, i_marker, j_marker, p, Rrel, v, w);
    hx_frames_update(out);
    /* the body's markers follow it on ground too, which the kinematics stage
     * leaves: an element's I on ground moves with ground's frame */
    hx_frames_update_body(out, body);
}

void hx_place_relative(const hx_frames *base, hx_frames *out, int i_marker, int j_marker,
                       const double disp[6], const double velo[6])
{
    double Rrel[9];
    if (hx_rotation_from_angles(disp + 3, Rrel) != 0)
        rotation_of_vector(disp + 3, Rrel);
    hx_place_pose(base, out, i_marker, j_marker, disp, Rrel, velo, velo + 3);
}

/* GFOSUB at the state placed in scratch; result turned into J axes. */
static int gfosub_placed(hx_session *s, hx_binding *b, hx_frames *scratch, double t, double F[6])
{
    const hx_force *f = &s->model->forces[b->index];
    scratch->time = t;
    double out[6];
    hx_force_routine_call(b, scratch, 1, out);
    hx_frame frames[2];
    const hx_frame *J = hx_frames_marker(scratch, f->j_marker, &frames[0]);
    const hx_frame *ref = hx_frames_marker(scratch, f->ref_marker, &frames[1]);
    double Rjr[9];
    m3_tmul(Rjr, J->R, ref->R);
    m3_apply(F, Rjr, out);
    m3_apply(F + 3, Rjr, out + 3);
    return hx_messages_stopped(&s->messages) ? -1 : 0;
}

static int gfosub_at(hx_session *s, hx_binding *b, hx_frames *scratch, const hx_frames *base,
                     double t, const double disp[6], const double velo[6], double F[6])
{
    const hx_force *f = &s->model->forces[b->index];
    hx_place_relative(base, scratch, f->i_marker, f->j_marker, disp, velo);
    return gfosub_placed(s, b, scratch, t, F);
}

int hx_element_at(hx_session *s, hx_frames *scratch, const hx_frames *base, int force, double t,
                  const double disp[6], const double velo[6], double F[6], double *dFdd,
                  double *dFdv)
{
    hx_binding *b = hx_bindings_find(&s->bindings, HX_FAMILY_FORCE, force);
    if (b->kind == HX_BIND_FIELD) {
        double dfd[36], dfv[36];
        hx_frames_copy(scratch, base);
        scratch->time = t;
        hx_invoke_field(b, scratch, disp, velo, dFdd != NULL, 0, F, dfd, dfv, NULL);
        if (dFdd != NULL) {
            memcpy(dFdd, dfd, sizeof dfd);
            memcpy(dFdv, dfv, sizeof dfv);
        }
        return hx_messages_stopped(&s->messages) ? -1 : 0;
    }
    int status = gfosub_at(s, b, scratch, base, t, disp, velo, F);
    for (int j = 0; j < 12 && dFdd != NULL && status == 0; ++j) {
        double dp[6], vp[6], Fp[6], Fm[6];
        memcpy(dp, disp, sizeof dp);
        memcpy(vp, velo, sizeof vp);
        double *x = j < 6 ? &dp[j] : &vp[j - 6];
        const double h = 1e-6 * fmax(1.0, fabs(*x)), x0 = *x;
        *x = x0 + h;
        status |= gfosub_at(s, b, scratch, base, t, dp, vp, Fp);
        *x = x0 - h;
        status |= gfosub_at(s, b, scratch, base, t, dp, vp, Fm);
        double *col = j < 6 ? dFdd + 6 * j : dFdv + 6 * (j - 6);
        for (int i = 0; i < 6; ++i)
            col[i] = (Fp[i] - Fm[i]) / (2.0 * h);
    }
    return status;
}

/* Force and torque on I in J axes with I at rest at pose (p, R) relative to
 * J. scratch equals base on entry and on return: a FIESUB reads its
 * deformation as arguments and the frames only through its queries; a
 * GFOSUB's I body is moved and put back, its markers with it. */
static int element_at_pose(hx_session *s, hx_frames *scratch, const hx_frames *base, int force,
                           double t, const double p[3], const double R[9], double F[6])
{
    static const double zero[6] = {0, 0, 0, 0, 0, 0};
    hx_binding *b = hx_bindings_find(&s->bindings, HX_FAMILY_FORCE, force);
    scratch->time = t;
    if (b->kind == HX_BIND_FIELD) {
        double disp[6], dfd[36], dfv[36];
        v3_copy(disp, p);
        hx_projection_angles(R, disp + 3);
        hx_invoke_field(b, scratch, disp, zero, 0, 0, F, dfd, dfv, NULL);
        scratch->time = base->time;
        return hx_messages_stopped(&s->messages) ? -1 : 0;
    }
    const hx_force *f = &s->model->forces[b->index];
    const int body = place_body(base, scratch, f->i_marker, f->j_marker, p, R, zero, zero);
    hx_frames_update_body(scratch, body);
    const int status = gfosub_placed(s, b, scratch, t, F);
    hx_frames_copy_body(scratch, base, body);
    scratch->time = base->time;
    return status;
}

double hx_element_potential(hx_session *s, hx_frames *scratch, const hx_frames *base, int force,
                            double t)
{
    static const double node[8] = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355,
                                   0.4082826787521751, 0.5917173212478249, 0.7627662049581645,
                                   0.8983332387068134, 0.9801449282487681};
    static const double weight[8] = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436,
                                     0.1813418916891810, 0.1813418916891810, 0.1568533229389436,
                                     0.1111905172266872, 0.0506142681451881};
    /* the pose of I in J: position x, rotation vector r */
    const hx_force *f = &s->model->forces[force];
    hx_frame frames[2];
    const hx_frame *I = hx_frames_marker(base, f->i_marker, &frames[0]);
    const hx_frame *J = hx_frames_marker(base, f->j_marker, &frames[1]);
    double x[3], R[9], r[3];
    hx_displacement(I, J, J, x);
    hx_relative_rotation(I, J, R);
    hx_rotation_vector(R, r);
    const double angle = v3_norm(r);
    double energy = 0.0;
    for (int k = 0; k < 8; ++k) {
        /* along the path, I moves at x and turns at r (in J axes): the power of
         * the force and torque on it is F . x + T . r */
        double p[3], Rk[9], F[6];
        v3_scale(p, x, node[k]);
        if (angle > 0.0) {
            const double axis[3] = {r[0] / angle, r[1] / angle, r[2] / angle};
            m3_axis_angle(Rk, axis, node[k] * angle);
        } else {
            m3_identity(Rk);
        }
        if (element_at_pose(s, scratch, base, force, t, p, Rk, F) != 0)
            return NAN;
        energy -= weight[k] * (v3_dot(F, x) + v3_dot(F + 3, r));
    }
    return energy;
}
