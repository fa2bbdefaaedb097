/* Force elements at prescribed states (element_probe.h). */
#include "sim/element_probe.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "state/measures.h"
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

void hx_place_relative(const hx_state *base, hx_state *out, int i_marker, int j_marker,
                       const double disp[6], const double velo[6])
{
    const hx_model *m = base->model;
    hx_state_copy(out, base);
    hx_frame scratch;
    const hx_frame *J = hx_state_marker(base, j_marker, &scratch);
    double Rrel[9];
    if (hx_rotation_from_angles(disp + 3, Rrel) != 0)
        rotation_of_vector(disp + 3, Rrel);
    hx_frame I;
    m3_mul(I.R, J->R, Rrel);
    m3_apply(I.p, J->R, disp);
    v3_add(I.p, I.p, J->p);
    double w[3], v[3], r[3], wr[3];
    m3_apply(w, J->R, velo + 3);
    v3_add(I.w, J->w, w);
    m3_apply(v, J->R, velo);
    v3_sub(r, I.p, J->p);
    v3_cross(wr, J->w, r);
    v3_add(I.v, J->v, v);
    v3_add(I.v, I.v, wr);
    /* the body frame that carries the I marker there */
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
    hx_state_update(out);
}

/* GFOSUB at a placed state; result turned into J axes. */
static int gfosub_at(hx_session *s, hx_binding *b, hx_state *scratch, const hx_state *base,
                     double t, const double disp[6], const double velo[6], double F[6])
{
    const hx_force *f = &s->model->forces[b->index];
    hx_place_relative(base, scratch, f->i_marker, f->j_marker, disp, velo);
    scratch->time = t;
    double out[6];
    hx_call_gfosub(b, scratch, 1, 0, out, NULL);
    hx_frame frames[2];
    const hx_frame *J = hx_state_marker(scratch, f->j_marker, &frames[0]);
    const hx_frame *ref = hx_state_marker(scratch, f->ref_marker, &frames[1]);
    double Rjr[9];
    m3_tmul(Rjr, J->R, ref->R);
    m3_apply(F, Rjr, out);
    m3_apply(F + 3, Rjr, out + 3);
    return hx_messages_stopped(&s->messages) ? -1 : 0;
}

int hx_element_at(hx_session *s, hx_state *scratch, const hx_state *base, int force, double t,
                  const double disp[6], const double velo[6], double F[6], double *dFdd,
                  double *dFdv)
{
    hx_binding *b = hx_binding_of_force(&s->bindings, force);
    if (b->kind == HX_BIND_FIESUB) {
        double dfd[36], dfv[36];
        hx_state_copy(scratch, base);
        scratch->time = t;
        hx_call_fiesub(b, scratch, disp, velo, dFdd != NULL, 0, F, dfd, dfv, NULL);
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

double hx_element_potential(hx_session *s, hx_state *scratch, const hx_state *base, int force,
                            double t, const double disp[6])
{
    static const double node[8] = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355,
                                   0.4082826787521751, 0.5917173212478249, 0.7627662049581645,
                                   0.8983332387068134, 0.9801449282487681};
    static const double weight[8] = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436,
                                     0.1813418916891810, 0.1813418916891810, 0.1568533229389436,
                                     0.1111905172266872, 0.0506142681451881};
    const double zero[6] = {0, 0, 0, 0, 0, 0};
    double energy = 0.0;
    for (int k = 0; k < 8; ++k) {
        double d[6], F[6];
        for (int i = 0; i < 6; ++i)
            d[i] = node[k] * disp[i];
        if (hx_element_at(s, scratch, base, force, t, d, zero, F, NULL, NULL) != 0)
            return NAN;
        for (int i = 0; i < 6; ++i)
            energy -= weight[k] * F[i] * disp[i];
    }
    return energy;
}
