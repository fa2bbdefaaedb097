/* The rigid bodies of the dynamics (bodies.h). */
#include <math.h>
#include <string.h>

#include "base/linalg.h"
#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"
#include "frames/measures.h"

int hx_bodies_init(hx_dynamics *d, hx_message *msg)
{
    const hx_model *m = d->m;
    int nq = 0, nu = 0;
    for (int k = 0; k < m->nbodies; ++k) {
        const hx_body *b = &m->bodies[k];
        hx_body_dof *dof = &d->dof[k];
        if (b->is_ground) {
            dof->kind = HX_DOF_GROUND;
            continue;
        }
        if (b->joint < 0) {
            dof->kind = HX_DOF_FREE;
            dof->mass = b->mass;
            m3_copy(dof->inertia, b->inertia);
            for (int c = 0; c < 3; ++c) { /* the inverse, column by column */
                double A[9], e[3] = {0, 0, 0};
                m3_copy(A, b->inertia);
                e[c] = 1.0;
                if (hx_solve(3, A, e) != 0)
                    return hx_fail(msg, "Body_Rigid %d: singular inertia", b->id);
                dof->inertia_inv[c] = e[0], dof->inertia_inv[3 + c] = e[1],
                dof->inertia_inv[6 + c] = e[2];
            }
            dof->q = nq, dof->u = nu;
            nq += 7, nu += 6;
            continue;
        }
        const hx_joint *j = &m->joints[b->joint];
        const hx_marker *mj = &m->markers[j->j_marker];
        v3_set(dof->axis, mj->R0[2], mj->R0[5], mj->R0[8]);
        v3_copy(dof->origin, mj->pos0);
        dof->coord0 = hx_joint_coordinate(&d->s->frames, b->joint, 0);
        if (j->type == HX_JOINT_REVOLUTE) {
            dof->kind = HX_DOF_REVOLUTE;
            double Iw[9], tmp[9], Ia[3], r[3], axr[3];
            m3_mul(tmp, b->R0, b->inertia);
            m3_mult(Iw, tmp, b->R0);
            m3_apply(Ia, Iw, dof->axis);
            v3_sub(r, b->p0, dof->origin);
            v3_cross(axr, dof->axis, r);
            dof->mass = v3_dot(dof->axis, Ia) + b->mass * v3_dot(axr, axr);
        } else {
            dof->kind = HX_DOF_SLIDER;
            dof->mass = b->mass;
        }
        dof->q = nq++, dof->u = nu++;
    }
    d->nq = nq;
    d->nu = nu;
    return 0;
}

void hx_bodies_frame(const hx_dynamics *d, int k, const double *y, hx_frame *f)
{
    const double *q = y, *u = y + d->nq;
    const hx_body_dof *dof = &d->dof[k];
    const hx_body *b = &d->m->bodies[k];
    switch (dof->kind) {
    case HX_DOF_GROUND: /* where the model puts it, at rest */
        v3_copy(f->p, b->p0), m3_copy(f->R, b->R0);
        v3_set(f->v, 0, 0, 0), v3_set(f->w, 0, 0, 0);
        break;
    case HX_DOF_FREE: {
        /* the orientation of the unit quaternion: a trial state off unit
         * length (a Newton iterate, a difference) still has a rigid body */
        double unit[4] = {q[dof->q + 3], q[dof->q + 4], q[dof->q + 5], q[dof->q + 6]};
        quat_normalize(unit);
        v3_copy(f->p, q + dof->q);
        quat_to_matrix(f->R, unit);
        v3_copy(f->v, u + dof->u);
        m3_apply(f->w, f->R, u + dof->u + 3);
        break;
    }
    case HX_DOF_REVOLUTE: {
        double Rot[9], r0[3], r[3];
        m3_axis_angle(Rot, dof->axis, q[dof->q] - dof->coord0);
        m3_mul(f->R, Rot, b->R0);
        v3_sub(r0, b->p0, dof->origin);
        m3_apply(r, Rot, r0);
        v3_add(f->p, dof->origin, r);
        v3_scale(f->w, dof->axis, u[dof->u]);
        v3_cross(f->v, f->w, r);
        break;
    }
    case HX_DOF_SLIDER:
        m3_copy(f->R, b->R0);
        v3_copy(f->p, b->p0);
        v3_axpy(f->p, q[dof->q] - dof->coord0, dof->axis);
        v3_scale(f->v, dof->axis, u[dof->u]);
        v3_set(f->w, 0, 0, 0);
        break;
    }
}

void hx_bodies_set_frames(const hx_dynamics *d, hx_dynamics_data *dd, const double *y)
{
    for (int k = 0; k < d->m->nbodies; ++k)
        hx_bodies_frame(d, k, y, &dd->frames.bodies[k]);
}

void hx_bodies_initial_state(const hx_dynamics *d, double *y)
{
    const hx_model *m = d->m;
    double *u = y + d->nq;
    for (int k = 0; k < m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        const hx_body *b = &m->bodies[k];
        switch (dof->kind) {
        case HX_DOF_GROUND:
            break;
        case HX_DOF_FREE:
            v3_copy(y + dof->q, b->p0);
            quat_from_matrix(y + dof->q + 3, b->R0);
            v3_copy(u + dof->u, b->v0);
            m3_tapply(u + dof->u + 3, b->R0, b->w0);
            break;
        case HX_DOF_REVOLUTE:
            y[dof->q] = dof->coord0;
            u[dof->u] = v3_dot(dof->axis, b->w0);
            break;
        case HX_DOF_SLIDER:
            y[dof->q] = dof->coord0;
            u[dof->u] = v3_dot(dof->axis, b->v0);
            break;
        }
    }
}

double hx_bodies_apply_load(const hx_dynamics *d, hx_dynamics_data *dd, int body,
                            const double point[3], const double F[3], const double T[3],
                            double sign)
{
    if (d->dof[body].kind == HX_DOF_GROUND)
        return 0.0;
    const hx_frame *f = &dd->frames.bodies[body];
    double r[3], moment[3], vp[3];
    v3_sub(r, point, f->p);
    v3_cross(moment, r, F);
    double power = 0.0;
    if (T != NULL) {
        v3_add(moment, moment, T); /* one update of the torque, not two */
        power = v3_dot(T, f->w);
    }
    v3_axpy(dd->force + 3 * body, sign, F);
    v3_axpy(dd->torque + 3 * body, sign, moment);
    v3_cross(vp, f->w, r);
    v3_add(vp, vp, f->v);
    return sign * (v3_dot(F, vp) + power);
}

void hx_bodies_accelerations(const hx_dynamics *d, const hx_dynamics_data *dd, const double *y,
                             double *ydot)
{
    const double *u = y + d->nq;
    double *qdot = ydot, *udot = ydot + d->nq;
    for (int k = 0; k < d->m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        const hx_frame *f = &dd->frames.bodies[k];
        const double *F = dd->force + 3 * k, *T = dd->torque + 3 * k;
        switch (dof->kind) {
        case HX_DOF_GROUND:
            break;
        case HX_DOF_FREE: {
            const double *w = u + dof->u + 3, *quat = y + dof->q + 3;
            v3_copy(qdot + dof->q, u + dof->u);
            const double wq[4] = {0, w[0], w[1], w[2]};
            double dq[4];
            quat_mul(dq, quat, wq);
            for (int i = 0; i < 4; ++i)
                qdot[dof->q + 3 + i] = 0.5 * dq[i];
            v3_scale(udot + dof->u, F, d->ucf / dof->mass);
            double tb[3], Iw[3], gyro[3];
            m3_tapply(tb, f->R, T);
            m3_apply(Iw, dof->inertia, w);
            v3_cross(gyro, w, Iw);
            v3_scale(tb, tb, d->ucf);
            v3_sub(tb, tb, gyro);
            m3_apply(udot + dof->u + 3, dof->inertia_inv, tb);
            break;
        }
        case HX_DOF_REVOLUTE: {
            double r[3], rxF[3];
            v3_sub(r, f->p, dof->origin);
            v3_cross(rxF, r, F);
            qdot[dof->q] = u[dof->u];
            udot[dof->u] = d->ucf * (v3_dot(dof->axis, T) + v3_dot(dof->axis, rxF)) / dof->mass;
            break;
        }
        case HX_DOF_SLIDER:
            qdot[dof->q] = u[dof->u];
            udot[dof->u] = d->ucf * v3_dot(dof->axis, F) / dof->mass;
            break;
        }
    }
}

void hx_bodies_advance_positions(const hx_dynamics *d, double *y, double h)
{
    const double *u = y + d->nq;
    for (int k = 0; k < d->m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        if (dof->kind == HX_DOF_GROUND)
            continue;
        if (dof->kind != HX_DOF_FREE) {
            y[dof->q] += h * u[dof->u];
            continue;
        }
        v3_axpy(y + dof->q, h, u + dof->u);
        /* q <- q (x) exp(h w / 2), w in body axes */
        const double *w = u + dof->u + 3;
        const double angle = h * v3_norm(w);
        double inc[4] = {1, 0, 0, 0};
        if (angle > 0.0) {
            const double s = sin(0.5 * angle) / v3_norm(w);
            inc[0] = cos(0.5 * angle);
            inc[1] = s * w[0], inc[2] = s * w[1], inc[3] = s * w[2];
        }
        double *quat = y + dof->q + 3, next[4];
        quat_mul(next, quat, inc);
        memcpy(quat, next, sizeof next);
        quat_normalize(quat);
    }
}
