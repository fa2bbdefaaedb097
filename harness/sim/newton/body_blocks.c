/*
 * Each body's own block of the Newton matrix, analytic, with the loads on
 * the body held (newton_matrix.h), and the rows a change of those loads
 * moves. Free body: p' = v, q' = q (x) (0, omega) / 2,
 * v' = ucf F / m, omega' = I^-1 (ucf R^T T - omega x I omega) with R the
 * frame of q made unit. Jointed: s' = u, u' = ucf (a.T + a.(r x F)) / m_a
 * (revolute, r from the axis to the centre) or ucf a.F / m (slider).
 */
#include <math.h>

#include "base/vecmath.h"
#include "sim/newton/newton_parts.h"

int hx_newton_body_rows_at(const hx_newton_matrix *nm, int b, int col)
{
    const hx_dynamics *d = nm->d;
    const hx_body_dof *dof = &d->dof[b];
    if (dof->kind == HX_DOF_GROUND)
        return -1;
    return hx_newton_rows_at(nm, d->nq + dof->u, dof->kind == HX_DOF_FREE ? 6 : 1, col);
}

/* J[row .. row + count - 1, col] += v, at `at` when known. */
static void add_rows(hx_newton_matrix *nm, int at, int row, int count, int col, const double *v)
{
    if (at < 0) {
        hx_newton_add(nm, row, count, col, v);
        return;
    }
    for (int i = 0; i < count; ++i)
        nm->values[at + i] += v[i];
}

void hx_newton_body_load(hx_newton_matrix *nm, int b, int col, int at, const double dF[3],
                         const double dT[3])
{
    const hx_dynamics *d = nm->d;
    const hx_body_dof *dof = &d->dof[b];
    const hx_frame *f = &d->frames.bodies[b];
    const int row = d->nq + dof->u;
    double v[6];
    switch (dof->kind) {
    case HX_DOF_GROUND:
        return;
    case HX_DOF_FREE: {
        const double *map = nm->load_map + 12 * b; /* hx_body_blocks */
        if (at >= 0) {
            hx_newton_free_body_load(nm->values + at, map, 1.0, dF, dT);
            return;
        }
        v3_scale(v, dF, map[0]);
        m3_apply(v + 3, map + 3, dT);
        hx_newton_add(nm, row, 6, col, v);
        return;
    }
    case HX_DOF_REVOLUTE: {
        double r[3], ar[3];
        v3_sub(r, f->p, dof->origin);
        v3_cross(ar, dof->axis, r); /* a.(r x F) = (a x r).F */
        v[0] = d->ucf * (v3_dot(dof->axis, dT) + v3_dot(ar, dF)) / dof->mass;
        add_rows(nm, at, row, 1, col, v);
        return;
    }
    case HX_DOF_SLIDER:
        v[0] = d->ucf * v3_dot(dof->axis, dF) / dof->mass;
        add_rows(nm, at, row, 1, col, v);
        return;
    }
}

static void free_body(hx_newton_matrix *nm, int b, const double *y)
{
    const hx_dynamics *d = nm->d;
    const hx_body_dof *dof = &d->dof[b];
    const hx_frame *f = &d->frames.bodies[b];
    const int q = dof->q, u = d->nq + dof->u;
    const double *quat = y + q + 3, *omega = y + u + 3, *T = d->torque + 3 * b;
    const double one = 1.0;
    for (int i = 0; i < 3; ++i)
        hx_newton_add(nm, q + i, 1, u + i, &one); /* p' = v */
    /* q' = q (x) (0, omega) / 2: linear in q and in omega */
    const double w4[4] = {0, omega[0], omega[1], omega[2]};
    for (int j = 0; j < 4; ++j) {
        double e[4] = {0, 0, 0, 0}, col[4];
        e[j] = 1.0;
        quat_mul(col, e, w4);
        for (int i = 0; i < 4; ++i)
            col[i] *= 0.5;
        hx_newton_add(nm, q + 3, 4, q + 3 + j, col);
    }
    for (int j = 0; j < 3; ++j) {
        double e[4] = {0, 0, 0, 0}, col[4];
        e[j + 1] = 1.0;
        quat_mul(col, quat, e);
        for (int i = 0; i < 4; ++i)
            col[i] *= 0.5;
        hx_newton_add(nm, q + 3, 4, u + 3 + j, col);
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
        hx_newton_add(nm, u + 3, 3, u + 3 + j, col);
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
        hx_newton_add(nm, u + 3, 3, q + 3 + j, col);
    }
}

void hx_body_blocks(hx_newton_matrix *nm, const double *y)
{
    const hx_dynamics *d = nm->d;
    const double one = 1.0;
    for (int b = 0; b < d->m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        if (dof->kind == HX_DOF_GROUND)
            continue;
        if (dof->kind == HX_DOF_FREE) {
            /* what a load's change does to the accelerations, once per build */
            double *map = nm->load_map + 12 * b, IinvRt[9];
            m3_mult(IinvRt, dof->inertia_inv, d->frames.bodies[b].R);
            map[0] = d->ucf / dof->mass;
            for (int i = 0; i < 9; ++i)
                map[3 + i] = d->ucf * IinvRt[i];
            free_body(nm, b, y);
            continue;
        }
        const int q = dof->q, u = d->nq + dof->u;
        hx_newton_add(nm, q, 1, u, &one); /* s' = u */
        if (dof->kind == HX_DOF_REVOLUTE) {
            /* the centre turns about the axis: r changes by a x r */
            const hx_frame *f = &d->frames.bodies[b];
            const double *F = d->force + 3 * b;
            double r[3], ar[3], aar[3];
            v3_sub(r, f->p, dof->origin);
            v3_cross(ar, dof->axis, r);
            v3_cross(aar, dof->axis, ar);
            const double v = d->ucf * v3_dot(aar, F) / dof->mass;
            hx_newton_add(nm, u, 1, q, &v);
        }
    }
}
