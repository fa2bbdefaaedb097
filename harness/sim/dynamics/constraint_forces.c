/*
 * The motions', couplers' and general constraints' forces
 * (constraint_forces.h, docs/interface.md §8.3).
 *
 * A row with multiplier lambda puts lambda G on the bodies it joins
 * (reactions.c). A motion's row and a coupler's share of its row are a
 * joint's coordinate a (joint_coordinate.h): written in world twists, G's
 * I block is the force on I's body at its frame's origin and the torque
 * about it, moved here to I's origin; J's side is its opposite at J
 * (expr/marker_forces.h), as a joint's reaction's. A coupler's share on its
 * joint n is the generalized force dphi/da_n lambda along a_n's G. A
 * motion on a reduced joint has no row: its share of the body's balance
 * along the axis is what the couplers and general constraints on that body
 * leave. A general constraint's force is lambda times its row's world twist
 * on its I marker's body (expression_rows.h), moved to I.
 */
#include "sim/dynamics/constraint_forces.h"

#include <math.h>
#include <string.h>

#include "base/vecmath.h"
#include "expr/marker_forces.h"
#include "model/expr/functions.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/joint_coordinate.h"
#include "sim/dynamics/reactions.h"

size_t hx_constraint_forces_size(const hx_dynamics *d)
{
    return 12 * (size_t)hx_marker_forces_slots(d->m);
}

/* F and T on marker mk's body, at its frame's origin: moved to mk's origin. */
static void at_marker(const hx_dynamics_data *dd, const hx_marker *mk, const double F[3],
                      const double T[3], double out[6])
{
    double r[3], rxF[3];
    m3_apply(r, dd->frames.bodies[mk->body].R, mk->r_local);
    v3_cross(rxF, r, F);
    v3_copy(out, F);
    v3_sub(out + 3, T, rxF);
}

/* scale times joint k's coordinate's I block (world twists), at I; J's side. */
static void along_coordinate(const hx_dynamics *d, const hx_dynamics_data *dd, int k,
                             char freedom, double scale, double out[12])
{
    const hx_model *m = d->m;
    const hx_marker *mi = &m->markers[m->joints[k].i_marker];
    const hx_marker *mj = &m->markers[m->joints[k].j_marker];
    const hx_joint_side si = {&dd->frames.bodies[mi->body], mi->r_local, mi->R_local};
    const hx_joint_side sj = {&dd->frames.bodies[mj->body], mj->r_local, mj->R_local};
    double value, G[12], F[3], T[3];
    hx_joint_coordinate_sides(freedom, &si, &sj, &value, G, NULL);
    v3_scale(F, G, scale), v3_scale(T, G + 3, scale);
    at_marker(dd, mi, F, T, out);
    hx_marker_forces_joint_on_j(&dd->frames, k, out, out + 6);
}

/* Coupler c's generalized force on each of its joints into out (three); 0 or -1. */
static int coupler_forces(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                          int c, double out[3])
{
    for (int n = 0; n < d->m->couplers[c].njoints; ++n) {
        out[n] = hx_constraints_coupler_force(d, dd, t, y, c, n);
        if (!isfinite(out[n]))
            return hx_dynamics_fail(dd, "COUPLER: Constraint_Coupler %d's force on its joint %d"
                                    " is not finite", d->m->couplers[c].id, n + 1);
    }
    return 0;
}

/* A motion on reduced joint k: the balance along the axis, less the couplers'. */
static void reduced_motion(const hx_dynamics *d, const hx_dynamics_data *dd, const double *ydot,
                           int k, const double *coupler_slots, double out[12])
{
    const hx_model *m = d->m;
    double balance[6];
    hx_reactions_balance(d, dd, ydot, k, balance);
    const hx_body_dof *dof = &d->dof[m->markers[m->joints[k].i_marker].body];
    const int torque = dof->kind == HX_DOF_REVOLUTE;
    double along = v3_dot(balance + 3 * torque, dof->axis);
    for (int c = 0; c < m->ncouplers; ++c)
        for (int n = 0; n < m->couplers[c].njoints; ++n)
            if (m->couplers[c].joint[n] == k)
                along -= v3_dot(coupler_slots + 12 * (3 * c + n) + 3 * torque, dof->axis);
    memset(out, 0, 6 * sizeof(double));
    v3_scale(out + 3 * torque, dof->axis, along);
    hx_marker_forces_joint_on_j(&dd->frames, k, out, out + 6);
}

/* General constraint k's force on its I marker's body, at I: lambda times its
 * row's world twist there (expression_rows.h), whatever the body's
 * coordinates (a free body's six, a hinged or slid body's one). */
static void gcon_force(const hx_dynamics *d, const hx_dynamics_data *dd, int k, double out[12])
{
    const hx_model *m = d->m;
    memset(out, 0, 12 * sizeof(double));
    const int i = m->gcons[k].i_marker;
    if (i < 0)
        return; /* not read: model/expr/link.c refuses it */
    const hx_constraint_row *r = &d->rows[d->gcon_first + k];
    const double lambda = dd->lambda[d->gcon_first + k];
    for (int b = 0; b < r->nblocks; ++b)
        if (r->body[b] == m->markers[i].body) {
            const double *tw = dd->gcon_twist + 6 * (HX_CONSTRAINT_ROW_BLOCKS * k + b);
            double F[3], T[3];
            v3_scale(F, tw, lambda);
            v3_scale(T, tw + 3, lambda);
            at_marker(dd, &m->markers[i], F, T, out);
        }
}

int hx_constraint_forces_all(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                             const double *y, const double *ydot, double *out)
{
    const hx_model *m = d->m;
    memset(out, 0, hx_constraint_forces_size(d) * sizeof(double));
    double *couplers = out + 12 * hx_marker_forces_slot(m, HX_FN_COUPLER, 0, 0);
    for (int c = 0; c < m->ncouplers; ++c) {
        double Q[3];
        if (coupler_forces(d, dd, t, y, c, Q) != 0)
            return -1;
        for (int n = 0; n < m->couplers[c].njoints; ++n)
            along_coordinate(d, dd, m->couplers[c].joint[n], m->couplers[c].freedom[n], Q[n],
                             couplers + 12 * (3 * c + n));
    }
    for (int k = 0; k < d->nmotions; ++k) {
        const hx_routine *rt = &m->routines[d->motion_routine[k]];
        along_coordinate(d, dd, rt->joint, rt->motion_type, dd->lambda[d->motion_first + k],
                         out + 12 * hx_marker_forces_slot(m, HX_FN_MOTION,
                                                          d->motion_routine[k], 0));
    }
    for (int k = 0; k < m->nroutines; ++k) {
        const hx_routine *rt = &m->routines[k];
        if (rt->kind == HX_ROUTINE_MOTION && rt->joint >= 0 && m->joints[rt->joint].reduced)
            reduced_motion(d, dd, ydot, rt->joint, couplers,
                           out + 12 * hx_marker_forces_slot(m, HX_FN_MOTION, k, 0));
    }
    for (int k = 0; k < m->ngcons; ++k)
        gcon_force(d, dd, k, out + 12 * hx_marker_forces_slot(m, HX_FN_GCON, k, 0));
    return 0;
}
