/*
 * A joint's coordinate between any two bodies (joint_coordinate.h). With
 * x, y, z a marker's axes, omega x a an axis's rate, and dw = omega_I - omega_J:
 *   rotation     a = atan2(s, c), s = x_I . y_J, c = x_I . x_J;
 *                s_dot = dw . (x_I x y_J), c_dot = dw . (x_I x x_J), so
 *                a_dot = g . dw with g = (c (x_I x y_J) - s (x_I x x_J)) / (s^2 + c^2)
 *                (= z_J when the z axes are aligned) and c = g_dot . dw;
 *   translation  a = (x_I - x_J) . z_J, d = x_I - x_J, r the markers' levers from
 *                their bodies' centres: a_dot = z_J . (v_I + omega_I x r_I)
 *                - z_J . (v_J + omega_J x (r_J + d)), and
 *                c = z_J . (omega_I x (omega_I x r_I) - omega_J x (omega_J x r_J))
 *                    + 2 d_dot . (omega_J x z_J) + d . (omega_J x (omega_J x z_J)).
 */
#include <math.h>
#include <string.h>

#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/joint_coordinate.h"

#define TWO_PI 6.283185307179586476925

char hx_joint_coordinate_default(enum hx_joint_type type)
{
    return type == HX_JOINT_REVOLUTE ? 'R' : type == HX_JOINT_TRANSLATIONAL ? 'T' : 0;
}

int hx_joint_coordinate_allowed(enum hx_joint_type type, char freedom)
{
    if (type == HX_JOINT_CYLINDRICAL)
        return freedom == 'R' || freedom == 'T';
    const char own = hx_joint_coordinate_default(type);
    return own != 0 && freedom == own;
}

static void column(double a[3], const double R[9], int k)
{
    v3_set(a, R[k], R[3 + k], R[6 + k]);
}

static void rotation(const hx_frame *fi, const hx_frame *fj, const double Ai[9],
                     const double Aj[9], double *value, double G[12], double *conv)
{
    double xi[3], xj[3], yj[3], a[3], b[3], dw[3];
    column(xi, Ai, 0), column(xj, Aj, 0), column(yj, Aj, 1);
    const double s = v3_dot(xi, yj), c = v3_dot(xi, xj), n = s * s + c * c;
    *value = atan2(s, c);
    v3_cross(a, xi, yj);
    v3_cross(b, xi, xj);
    double g[3];
    for (int k = 0; k < 3; ++k)
        g[k] = (c * a[k] - s * b[k]) / n;
    if (G != NULL) {
        memset(G, 0, sizeof(double) * 12);
        v3_copy(G + 3, g);
        v3_scale(G + 9, g, -1.0);
    }
    if (conv == NULL)
        return;
    v3_sub(dw, fi->w, fj->w);
    double xi_dot[3], xj_dot[3], yj_dot[3], t1[3], t2[3], a_dot[3], b_dot[3];
    v3_cross(xi_dot, fi->w, xi);
    v3_cross(xj_dot, fj->w, xj);
    v3_cross(yj_dot, fj->w, yj);
    v3_cross(t1, xi_dot, yj), v3_cross(t2, xi, yj_dot), v3_add(a_dot, t1, t2);
    v3_cross(t1, xi_dot, xj), v3_cross(t2, xi, xj_dot), v3_add(b_dot, t1, t2);
    const double s_dot = v3_dot(dw, a), c_dot = v3_dot(dw, b);
    const double n_dot = 2.0 * (s * s_dot + c * c_dot);
    double g_dot[3];
    for (int k = 0; k < 3; ++k)
        g_dot[k] = (c_dot * a[k] + c * a_dot[k] - s_dot * b[k] - s * b_dot[k] - g[k] * n_dot) / n;
    *conv = v3_dot(g_dot, dw);
}

static void translation(const hx_frame *fi, const hx_frame *fj, const double ri[3],
                        const double rj[3], const double Aj[9], double *value, double G[12],
                        double *conv)
{
    double zj[3], xi[3], xj[3], d[3], lever[3];
    column(zj, Aj, 2);
    v3_add(xi, fi->p, ri), v3_add(xj, fj->p, rj);
    v3_sub(d, xi, xj);
    *value = v3_dot(d, zj);
    if (G != NULL) {
        v3_copy(G, zj);
        v3_cross(G + 3, ri, zj);
        v3_scale(G + 6, zj, -1.0);
        v3_add(lever, rj, d);
        v3_cross(G + 9, zj, lever);
    }
    if (conv == NULL)
        return;
    double wri[3], wrj[3], wwri[3], wwrj[3], vi[3], vj[3], d_dot[3], zj_dot[3], wwz[3], t[3];
    v3_cross(wri, fi->w, ri), v3_cross(wwri, fi->w, wri);
    v3_cross(wrj, fj->w, rj), v3_cross(wwrj, fj->w, wrj);
    v3_add(vi, fi->v, wri), v3_add(vj, fj->v, wrj);
    v3_sub(d_dot, vi, vj);
    v3_cross(zj_dot, fj->w, zj);
    v3_cross(wwz, fj->w, zj_dot);
    v3_sub(t, wwri, wwrj);
    *conv = v3_dot(zj, t) + 2.0 * v3_dot(d_dot, zj_dot) + v3_dot(d, wwz);
}

void hx_joint_coordinate_sides(char freedom, const hx_joint_side *i, const hx_joint_side *j,
                               double *value, double G[12], double *c)
{
    double Ai[9], Aj[9], ri[3], rj[3];
    m3_mul(Ai, i->body->R, i->R_local);
    m3_mul(Aj, j->body->R, j->R_local);
    if (freedom == 'R') {
        rotation(i->body, j->body, Ai, Aj, value, G, c);
        return;
    }
    m3_apply(ri, i->body->R, i->r_local);
    m3_apply(rj, j->body->R, j->r_local);
    translation(i->body, j->body, ri, rj, Aj, value, G, c);
}

/* The coordinate as it comes (a rotation in (-pi, pi]); 1 when it is reduced. */
static int raw_coordinate(const hx_dynamics *d, int joint, char freedom, const double *y,
                          double *value, double G[12], double *c)
{
    const hx_model *m = d->m;
    const hx_joint *j = &m->joints[joint];
    const hx_marker *mi = &m->markers[j->i_marker], *mj = &m->markers[j->j_marker];
    if (j->reduced) {
        const hx_body_dof *dof = &d->dof[mi->body];
        *value = y[dof->q];
        if (G != NULL)
            G[0] = 1.0;
        if (c != NULL)
            *c = 0.0;
        return 1;
    }
    hx_frame fi, fj;
    hx_bodies_frame(d, mi->body, y, &fi);
    hx_bodies_frame(d, mj->body, y, &fj);
    const hx_joint_side si = {&fi, mi->r_local, mi->R_local}, sj = {&fj, mj->r_local, mj->R_local};
    hx_joint_coordinate_sides(freedom, &si, &sj, value, G, c);
    if (G != NULL) { /* omega into body axes; a ground side's block is not a velocity */
        double body[3];
        m3_tapply(body, fi.R, G + 3);
        v3_copy(G + 3, body);
        m3_tapply(body, fj.R, G + 9);
        v3_copy(G + 9, body);
    }
    return 0;
}

int hx_joint_coordinate_near(const hx_dynamics *d, int joint, char freedom, const double *y,
                             double near, double *value, double G[12], double *c)
{
    if (raw_coordinate(d, joint, freedom, y, value, G, c) == 0 && freedom == 'R')
        *value = near + remainder(*value - near, TWO_PI);
    return 0;
}

double hx_joint_coordinate_placed(const hx_dynamics *d, int joint)
{
    const hx_model *m = d->m;
    const hx_joint *j = &m->joints[joint];
    if (j->type != HX_JOINT_REVOLUTE && j->type != HX_JOINT_CYLINDRICAL)
        return 0.0;
    const hx_marker *mi = &m->markers[j->i_marker], *mj = &m->markers[j->j_marker];
    double xi[3], xj[3], yj[3];
    column(xi, mi->R0, 0), column(xj, mj->R0, 0), column(yj, mj->R0, 1);
    return atan2(v3_dot(xi, yj), v3_dot(xi, xj));
}

void hx_joint_coordinate_at(const hx_dynamics *d, int joint, char freedom, const double *y,
                            double *value, double G[12], double *c)
{
    hx_joint_coordinate_near(d, joint, freedom, y, hx_joint_coordinate_placed(d, joint), value,
                             G, c);
}
