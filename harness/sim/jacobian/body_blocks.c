/*
 * Each body's own block of the Jacobian, analytic, with the loads on the
 * body held (jacobian.h). Free body: p' = v, q' = q (x) (0, omega) / 2,
 * v' = ucf F / m, omega' = I^-1 (ucf R^T T - omega x I omega) with R the
 * frame of q made unit. Jointed: s' = u, u' = ucf (a.T + a.(r x F)) / m_a
 * (revolute, r from the axis to the centre) or ucf a.F / m (slider).
 */
#include <math.h>

#include "base/vecmath.h"
#include "sim/jacobian/jacobian_parts.h"

static void free_body(hx_jacobian *jac, int b, const double *y)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    const hx_body_dof *dof = &d->dof[b];
    const hx_frame *f = &dd->frames.bodies[b];
    const int q = dof->q, u = d->nq + dof->u;
    const double *quat = y + q + 3, *omega = y + u + 3, *T = dd->torque + 3 * b;
    const double one = 1.0;
    for (int i = 0; i < 3; ++i)
        hx_jacobian_add(jac, q + i, 1, u + i, &one); /* p' = v */
    /* q' = q (x) (0, omega) / 2: linear in q and in omega */
    const double w4[4] = {0, omega[0], omega[1], omega[2]};
    for (int j = 0; j < 4; ++j) {
        double e[4] = {0, 0, 0, 0}, col[4];
        e[j] = 1.0;
        quat_mul(col, e, w4);
        for (int i = 0; i < 4; ++i)
            col[i] *= 0.5;
        hx_jacobian_add(jac, q + 3, 4, q + 3 + j, col);
    }
    for (int j = 0; j < 3; ++j) {
        double e[4] = {0, 0, 0, 0}, col[4];
        e[j + 1] = 1.0;
        quat_mul(col, quat, e);
        for (int i = 0; i < 4; ++i)
            col[i] *= 0.5;
        hx_jacobian_add(jac, q + 3, 4, u + 3 + j, col);
    }
    /* omega' by omega: -I^-1 ([omega]x I - [I omega]x) */
    double Iw[3];
    m3_apply(Iw, dof->inertia, omega);
    for (int j = 0; j < 3; ++j) {
        double e[3] = {0, 0, 0}, Ie[3], a[3], c[3], col[3];
        e[j] = 1.0;
        m3_apply(Ie, dof->inertia, e);
        v3_cross(a, omega, Ie);
        v3_cross(c, e, Iw);
        v3_add(a, a, c);
        m3_apply(col, dof->inertia_inv, a);
        v3_scale(col, col, -1.0);
        hx_jacobian_add(jac, u + 3, 3, u + 3 + j, col);
    }
    /* omega' by the quaternion: R^T T changes by R^T (T x dth) */
    for (int j = 0; j < 4; ++j) {
        hx_motion mo;
        hx_body_column_motion(d, b, 3 + j, y, f, &mo);
        double txd[3], tb[3], col[3];
        v3_cross(txd, T, mo.dth);
        m3_tapply(tb, f->R, txd);
        m3_apply(col, dof->inertia_inv, tb);
        v3_scale(col, col, d->ucf);
        hx_jacobian_add(jac, u + 3, 3, q + 3 + j, col);
    }
}

void hx_body_blocks(hx_jacobian *jac, const double *y)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    const double one = 1.0;
    for (int b = 0; b < d->m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        if (dof->kind == HX_DOF_GROUND)
            continue;
        if (dof->kind == HX_DOF_FREE) {
            /* what a load's change does to the accelerations, once per build */
            double *map = jac->load_map + 12 * b, IinvRt[9];
            m3_mult(IinvRt, dof->inertia_inv, dd->frames.bodies[b].R);
            map[0] = d->ucf / dof->mass;
            for (int i = 0; i < 9; ++i)
                map[3 + i] = d->ucf * IinvRt[i];
            free_body(jac, b, y);
            continue;
        }
        const int q = dof->q, u = d->nq + dof->u;
        hx_jacobian_add(jac, q, 1, u, &one); /* s' = u */
        if (dof->kind == HX_DOF_REVOLUTE) {
            /* the centre turns about the axis: r changes by a x r */
            const hx_frame *f = &dd->frames.bodies[b];
            const double *F = dd->force + 3 * b;
            double r[3], ar[3], aar[3];
            v3_sub(r, f->p, dof->origin);
            v3_cross(ar, dof->axis, r);
            v3_cross(aar, dof->axis, ar);
            const double v = d->ucf * v3_dot(aar, F) / dof->mass;
            hx_jacobian_add(jac, u, 1, q, &v);
        }
    }
}
