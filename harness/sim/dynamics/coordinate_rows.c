/*
 * The rows written on joint coordinates (coordinate_rows.h): a coupler's
 * phi(M) of its joints' coordinates, its row sum_i dphi/dM_i G_i and its
 * gamma -(sum_i dphi/dM_i c_i + qdot^T H qdot); a coupler of reduced joints
 * alone keeps its former arithmetic (one value a joint, no convective term,
 * so the models' runs are unchanged); a motion's a - f(t).
 */
#include <math.h>
#include <string.h>

#include "host/invoke.h"
#include "sim/dynamics/coordinate_rows.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/joint_coordinate.h"
#include "sim/dynamics/routines.h"

/* The coupled joints' bodies (a reduced joint's: q and u agree). */
static int coupler_joints(const hx_dynamics *d, int k, int body[3])
{
    const hx_coupler *c = &d->m->couplers[k];
    for (int i = 0; i < c->njoints; ++i)
        body[i] = d->m->markers[d->m->joints[c->joint[i]].i_marker].body;
    return c->njoints;
}

/* A general coupler's joints at y: their coordinates, rates, rows (12 values:
 * I's body block, J's) and convective terms (joint_coordinate.h). */
typedef struct coupled_joints {
    double disp[3], rate[3], row[3][12], conv[3];
} coupled_joints;

static double block_rate(const hx_dynamics *d, int body, const double *g, const double *y)
{
    const hx_body_dof *dof = &d->dof[body];
    if (dof->kind == HX_DOF_GROUND)
        return 0.0;
    const double *u = y + d->nq + dof->u;
    double s = 0.0;
    for (int c = 0; c < (dof->kind == HX_DOF_FREE ? 6 : 1); ++c)
        s += g[c] * u[c];
    return s;
}

static void general_joints(const hx_dynamics *d, const hx_dynamics_data *dd, int k,
                           const double *y, coupled_joints *cj)
{
    const hx_model *m = d->m;
    const hx_coupler *c = &m->couplers[k];
    for (int i = 0; i < c->njoints; ++i) {
        const hx_joint *j = &m->joints[c->joint[i]];
        const int bi = m->markers[j->i_marker].body, bj = m->markers[j->j_marker].body;
        memset(cj->row[i], 0, sizeof cj->row[i]);
        /* a rotation unwrapped against the angle dd holds (joint_turns.h) */
        hx_joint_coordinate_near(d, c->joint[i], c->freedom[i], y, dd->turn[c->joint[i]],
                                 &cj->disp[i], cj->row[i], &cj->conv[i]);
        cj->rate[i] = block_rate(d, bi, cj->row[i], y);
        if (!j->reduced)
            cj->rate[i] += block_rate(d, bj, cj->row[i] + 6, y);
    }
}

/* phi, dphi/dM and the velocity term qdot^T H qdot of coupler k (cj: a
 * general coupler's joints, NULL for one of reduced joints). */
static int coupler_terms(const hx_dynamics *d, hx_dynamics_data *dd, int k, double t,
                         const double *y, double *phi, double grad[3], double *gamma,
                         const coupled_joints *cj)
{
    const hx_coupler *c = &d->m->couplers[k];
    int body[3];
    const int n = coupler_joints(d, k, body);
    double disp[3], rate[3];
    for (int i = 0; i < n; ++i) {
        disp[i] = cj != NULL ? cj->disp[i] : y[d->dof[body[i]].q];
        rate[i] = cj != NULL ? cj->rate[i] : y[d->nq + d->dof[body[i]].u];
    }
    hx_binding *b = d->coupler_binding[k];
    if (b == NULL) {
        *phi = 0.0;
        for (int i = 0; i < n; ++i) {
            *phi += c->coefficients[i] * disp[i];
            grad[i] = c->coefficients[i];
        }
        if (gamma != NULL)
            *gamma = 0.0;
        return n;
    }
    double hess[9] = {0};
    dd->frames.time = t; /* couplers get their state in disp: only the time is bound */
    hx_invoke_coupler(b, 0, &dd->frames, disp, n, 0, phi, NULL);
    hx_invoke_coupler(b, 1, &dd->frames, disp, n, 0, grad, NULL);
    if (gamma != NULL)
        hx_invoke_coupler(b, 2, &dd->frames, disp, n, 0, hess, NULL);
    if (hx_dynamics_check_call(d, dd, b, phi, 1, "value", t) != 0 ||
        hx_dynamics_check_call(d, dd, b, grad, n, "value", t) != 0 ||
        hx_dynamics_check_call(d, dd, b, hess, n * n, "value", t) != 0)
        return -1;
    if (gamma != NULL) {
        *gamma = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                *gamma += rate[i] * hess[i + n * j] * rate[j];
    }
    return n;
}

/* Motion k's row (docs/interface.md §7.12): in displacement phi = a(q) -
 * f(t), G the joint coordinate's, and G u_dot = f''(t) - c, MOTSUB's iord 0
 * and 2 at t (the rotation unwrapped against f); in velocity (val_type V)
 * the row holds G u = f(t) and G u_dot = f'(t) - c, and phi = 0: the
 * coordinate is where the integrated rates take it, which the position
 * projection leaves (its Newton step has no component along the row); in
 * acceleration (val_type A) phi = a(q) - s with s the motion's displacement
 * state (unwrapped against s), G u held to its velocity state v, and
 * G u_dot = f(t) - c, MOTSUB's iord 0: the states integrate f, the row holds
 * the joint to them. */
int hx_coordinate_rows_motion(const hx_dynamics *d, hx_dynamics_data *dd, int k, double t,
                              const double *y, double *phi, double G[12], double *gamma)
{
    const int routine = d->motion_routine[k];
    const hx_routine *rt = &d->m->routines[routine];
    double f = 0.0, accel = 0.0, value, c;
    dd->frames.time = t;
    if (rt->val_type == 'V' || rt->val_type == 'A') {
        if (gamma != NULL &&
            hx_routines_motion(d, dd, routine, rt->val_type == 'V' ? 1 : 0, &accel) != 0)
            return -1;
        const double s = rt->val_type == 'A' ? y[d->motion_state[k]] : 0.0;
        memset(G, 0, sizeof(double) * 12);
        hx_joint_coordinate_near(d, rt->joint, rt->motion_type, y, s, &value, G, &c);
        *phi = rt->val_type == 'A' ? value - s : 0.0;
        if (gamma != NULL)
            *gamma = accel - c;
        return 0;
    }
    if (hx_routines_motion(d, dd, routine, 0, &f) != 0 ||
        (gamma != NULL && hx_routines_motion(d, dd, routine, 2, &accel) != 0))
        return -1;
    memset(G, 0, sizeof(double) * 12);
    hx_joint_coordinate_near(d, rt->joint, rt->motion_type, y, f, &value, G, &c);
    *phi = value - f;
    if (gamma != NULL)
        *gamma = accel - c;
    return 0;
}

/* What G u is held to at row i: a motion's rate f'(t) (f(t) for val_type
 * V, the velocity state for A), else 0 (not called). */
int hx_coordinate_rows_rate(const hx_dynamics *d, hx_dynamics_data *dd, int i, double t,
                            const double *y, double *rate)
{
    const int k = i - d->motion_first, routine = d->motion_routine[k];
    if (d->motion_state[k] >= 0) {
        *rate = y[d->motion_state[k] + 1];
        return 0;
    }
    dd->frames.time = t;
    return hx_routines_motion(d, dd, routine, d->m->routines[routine].val_type == 'V' ? 0 : 1,
                              rate);
}

double hx_coordinate_rows_joint_rate(const hx_dynamics *d, int joint, char freedom,
                                     const double *y)
{
    const hx_model *m = d->m;
    const hx_joint *j = &m->joints[joint];
    double value, G[12] = {0};
    hx_joint_coordinate_near(d, joint, freedom, y, 0.0, &value, G, NULL);
    const double rate = block_rate(d, m->markers[j->i_marker].body, G, y);
    return j->reduced ? rate : rate + block_rate(d, m->markers[j->j_marker].body, G + 6, y);
}

/* A general coupler's row: sum_i grad_i G_i, each joint's blocks at its
 * bodies' slots. */
static void general_row(const hx_dynamics *d, int k, const double grad[3],
                        const coupled_joints *cj, double *G)
{
    const hx_model *m = d->m;
    const hx_coupler *c = &m->couplers[k];
    const hx_constraint_row *r = &d->rows[k];
    for (int i = 0; i < c->njoints; ++i) {
        const hx_joint *j = &m->joints[c->joint[i]];
        const int side[2] = {m->markers[j->i_marker].body, m->markers[j->j_marker].body};
        for (int s = 0; s < (j->reduced ? 1 : 2); ++s)
            for (int b = 0; b < r->nblocks; ++b)
                if (r->body[b] == side[s])
                    for (int v = 0; v < r->width[b]; ++v)
                        G[r->slot[b] + v] += grad[i] * cj->row[i][6 * s + v];
    }
}

int hx_coordinate_rows_coupler(const hx_dynamics *d, hx_dynamics_data *dd, int k, double t,
                               const double *y, double *phi, double *G, double *gamma)
{
    double grad[3], term = 0.0;
    if (!d->coupler_general[k]) {
        if (coupler_terms(d, dd, k, t, y, phi, grad, gamma ? &term : NULL, NULL) < 0)
            return -1;
        for (int i = 0; i < d->m->couplers[k].njoints; ++i)
            G[i] = grad[i];
        if (gamma != NULL)
            *gamma = -term; /* phi_ddot = G udot + qdot^T H qdot */
        return 0;
    }
    coupled_joints cj;
    general_joints(d, dd, k, y, &cj);
    if (coupler_terms(d, dd, k, t, y, phi, grad, gamma ? &term : NULL, &cj) < 0)
        return -1;
    general_row(d, k, grad, &cj, G);
    /* phi_ddot = sum grad_i (G_i udot + c_i) + qdot^T H qdot */
    for (int i = 0; i < d->m->couplers[k].njoints && gamma != NULL; ++i)
        term += grad[i] * cj.conv[i];
    if (gamma != NULL)
        *gamma = -term;
    return 0;
}

double hx_coordinate_rows_force(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                                const double *y, int coupler, int joint)
{
    double phi, grad[3];
    coupled_joints cj;
    const int general = d->coupler_general[coupler];
    if (general)
        general_joints(d, dd, coupler, y, &cj);
    if (coupler_terms(d, dd, coupler, t, y, &phi, grad, NULL, general ? &cj : NULL) < 0)
        return NAN;
    return grad[joint] * dd->lambda[coupler];
}
