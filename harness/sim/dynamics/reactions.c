/*
 * The joints' reactions (reactions.h, docs/interface.md §7.14).
 *
 * Rows: M udot = ucf (Q + G^T lambda) (constraints.c), so the rows put the
 * generalized force G^T lambda, in force units, on the bodies they join.
 * Written in world twists (joint_equations.h: the velocity of the body
 * frame's origin and the angular velocity, world axes), I's columns of a row
 * are a force and a torque about I's body frame origin; the torque at I's
 * origin is that less r x F, r from the frame's origin to I's. The rows are
 * evaluated again here in world twists: the solver's own G has a free body's
 * omega in body axes. A redundant row removed at the set-up has no
 * multiplier: the rows kept carry its share.
 *
 * Reduced: the body moves in its joint's coordinate alone, so what the
 * joint puts on it is what its motion needs beyond the applied loads:
 * F = m a_cm / ucf - F_applied and, about the centre of mass,
 * T = (I alpha + omega x I omega) / ucf - T_applied (world), less what the
 * general constraints acting on the body put on it (their rows hold its
 * coordinate). The joint's own axis carries no torque (revolute) or force
 * (translational): what the balance leaves along it is a coupler's or a
 * motion's, removed.
 */
#include "sim/dynamics/reactions.h"

#include "base/vecmath.h"
#include "sim/dynamics/joint_equations.h"

/* The joint's frames' positions: I's and J's origins (world). */
static void origin(const hx_dynamics_data *dd, const hx_marker *mk, double x[3])
{
    const hx_frame *f = &dd->frames.bodies[mk->body];
    m3_apply(x, f->R, mk->r_local);
    v3_add(x, x, f->p);
}

static void from_rows(const hx_dynamics *d, const hx_dynamics_data *dd, int k, double out[6])
{
    const hx_joint *j = &d->m->joints[k];
    const hx_marker *mi = &d->m->markers[j->i_marker], *mj = &d->m->markers[j->j_marker];
    const hx_frame *fi = &dd->frames.bodies[mi->body], *fj = &dd->frames.bodies[mj->body];
    double phi[HX_JOINT_MAX_EQUATIONS], G[12 * HX_JOINT_MAX_EQUATIONS];
    hx_joint_equations_of(d->m, k, fi, fj, phi, G, NULL);
    double F[3] = {0, 0, 0}, T[3] = {0, 0, 0}, r[3], rxF[3];
    const int first = d->joint_row[k], count = hx_joint_equations_count(j->type);
    for (int e = 0; e < count; ++e) {
        const double lambda = dd->lambda[first + e];
        v3_axpy(F, lambda, G + 12 * e);
        v3_axpy(T, lambda, G + 12 * e + 3);
    }
    m3_apply(r, fi->R, mi->r_local);
    v3_cross(rxF, r, F);
    v3_sub(T, T, rxF);
    v3_copy(out, F), v3_copy(out + 3, T);
}

/* Less what the general constraints put on body b (lambda times their rows'
 * world twists there, expression_rows.h), from F and T about its origin:
 * their rows hold the body's coordinate too, so the balance holds their
 * force, which is not the joint's. */
static void general_constraints_on(const hx_dynamics *d, const hx_dynamics_data *dd, int b,
                                   double F[3], double T[3])
{
    for (int k = 0; k < d->m->ngcons; ++k) {
        const hx_constraint_row *r = &d->rows[d->gcon_first + k];
        const double lambda = dd->lambda[d->gcon_first + k];
        for (int blk = 0; blk < r->nblocks; ++blk) {
            const double *tw = dd->gcon_twist + 6 * (HX_CONSTRAINT_ROW_BLOCKS * k + blk);
            if (r->body[blk] != b)
                continue;
            v3_axpy(F, -lambda, tw);
            v3_axpy(T, -lambda, tw + 3);
        }
    }
}

void hx_reactions_balance(const hx_dynamics *d, const hx_dynamics_data *dd, const double *ydot,
                          int k, double out[6])
{
    const hx_joint *j = &d->m->joints[k];
    const hx_marker *mi = &d->m->markers[j->i_marker];
    const int b = mi->body;
    const hx_body *body = &d->m->bodies[b];
    const hx_body_dof *dof = &d->dof[b];
    const hx_frame *f = &dd->frames.bodies[b];
    const double udot = ydot[d->nq + dof->u], *a = dof->axis;
    double acc[3], alpha[3] = {0, 0, 0}, F[3], T[3] = {0, 0, 0};
    if (dof->kind == HX_DOF_REVOLUTE) {
        /* a_cm = alpha x r + omega x (omega x r), v = omega x r */
        double r[3], wv[3], Iw[9], tmp[9], Ialpha[3], Iomega[3], gyro[3];
        v3_scale(alpha, a, udot);
        v3_sub(r, f->p, dof->origin);
        v3_cross(acc, alpha, r);
        v3_cross(wv, f->w, f->v);
        v3_add(acc, acc, wv);
        m3_mul(tmp, f->R, body->inertia); /* R I R^T: the inertia about the cm, world */
        m3_mult(Iw, tmp, f->R);
        m3_apply(Ialpha, Iw, alpha);
        m3_apply(Iomega, Iw, f->w);
        v3_cross(gyro, f->w, Iomega);
        v3_add(T, Ialpha, gyro);
        v3_scale(T, T, 1.0 / d->ucf);
    } else {
        v3_scale(acc, a, udot);
    }
    v3_scale(F, acc, body->mass / d->ucf);
    v3_sub(F, F, dd->force + 3 * b);
    v3_sub(T, T, dd->torque + 3 * b);
    general_constraints_on(d, dd, b, F, T);
    double x[3], r[3], rxF[3];
    origin(dd, mi, x);
    v3_sub(r, x, f->p);
    v3_cross(rxF, r, F);
    v3_sub(T, T, rxF);
    v3_copy(out, F), v3_copy(out + 3, T);
}

static void from_balance(const hx_dynamics *d, const hx_dynamics_data *dd, const double *ydot,
                         int k, double out[6])
{
    hx_reactions_balance(d, dd, ydot, k, out);
    const hx_body_dof *dof = &d->dof[d->m->markers[d->m->joints[k].i_marker].body];
    /* along the axis: a coupler's or a motion's, not the joint's */
    double *along = dof->kind == HX_DOF_REVOLUTE ? out + 3 : out;
    v3_axpy(along, -v3_dot(along, dof->axis), dof->axis);
}

void hx_reactions_joint(const hx_dynamics *d, const hx_dynamics_data *dd, const double *ydot,
                        int k, double out[6])
{
    if (d->joint_row[k] >= 0)
        from_rows(d, dd, k, out);
    else
        from_balance(d, dd, ydot, k, out);
}

void hx_reactions_all(const hx_dynamics *d, const hx_dynamics_data *dd, const double *ydot,
                      double *out)
{
    for (int k = 0; k < d->m->njoints; ++k)
        hx_reactions_joint(d, dd, ydot, k, out + 6 * k);
}
