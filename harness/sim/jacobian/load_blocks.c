/*
 * The loads' blocks of the Jacobian (jacobian.h): each load by central
 * differences of that load alone, on the columns of the bodies its markers
 * sit on and of those its expressions measure (hx_load_bodies).
 */
#include <string.h>

#include "base/vecmath.h"
#include "host/variable_values.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/loads.h"
#include "sim/jacobian/jacobian_parts.h"

/* What share puts on its i-th body: F and the torque about its centre. */
/* The central difference of a load's wrenches at +h and -h (side, application,
 * (F, T)) in column c, onto the bodies it is applied to. */
static void put_difference(hx_jacobian *jac, int count, const int *body,
                           double W[2][2][6], double h, int c)
{
    for (int a = 0; a < count; ++a) {
        double dW[6];
        for (int r = 0; r < 6; ++r)
            dW[r] = (W[0][a][r] - W[1][a][r]) / (2.0 * h);
        hx_jacobian_body_load(jac, body[a], c, -1, dW, dW + 3);
    }
}

static void wrench(const hx_load_share *share, int i, const hx_frames *fr, double F[3], double T[3])
{
    double arm[3];
    v3_copy(F, share->F[i]);
    v3_sub(arm, share->point[i], fr->bodies[share->body[i]].p);
    v3_cross(T, arm, share->F[i]);
    v3_add(T, T, share->T[i]);
}

/* Load k's change in the Control_Diff states it reads by DIF (hx_load_diffs),
 * by central differences of that load alone at the moved frames; 0 or -1. */
static int diff_columns(hx_jacobian *jac, int k)
{
    const hx_dynamics *d = jac->d;
    const hx_model *m = d->m;
    int slots[HX_LOAD_BODIES_MAX];
    const int nslots = hx_load_diffs(m, k, slots);
    for (int i = 0; i < nslots; ++i) {
        const int c = d->diff_offset + slots[i];
        const double keep = jac->y[c], h = hx_jacobian_step(jac->y, c);
        hx_load_share share[2];
        double W[2][2][6]; /* side, application, (F, T) */
        int status = 0;
        hx_message msg;
        for (int side = 0; side < 2 && status == 0; ++side) {
            jac->moved.diffs[2 * slots[i]] = keep + (side == 0 ? h : -h);
            if (m->variables_read && hx_variables_values(&jac->moved, jac->moved.variables,
                                                         &msg) != 0)
                status = -1;
            if (status == 0 && hx_load_share_at(m, &jac->moved, k, &share[side], &msg) != 0)
                status = -1;
            for (int a = 0; status == 0 && a < share[side].count; ++a)
                wrench(&share[side], a, &jac->moved, W[side][a], W[side][a] + 3);
        }
        jac->moved.diffs[2 * slots[i]] = keep;
        memcpy(jac->moved.variables, jac->dd.frames.variables, sizeof(double) * (size_t)m->nvariables);
        if (status != 0)
            return hx_dynamics_fail(&jac->dd, "%s", msg.text);
        put_difference(jac, share[0].count, share[0].body, W, h, c);
    }
    return 0;
}

int hx_load_blocks(hx_jacobian *jac, double t, const double *y)
{
    (void)t, (void)y; /* the moved frames hold the time */
    const hx_dynamics *d = jac->d;
    const hx_model *m = d->m;
    for (int k = 0; k < m->nloads; ++k) {
        if (d->load_off[k])
            continue; /* switched off: nothing on the bodies, nothing here */
        if (diff_columns(jac, k) != 0)
            return -1;
        int bodies[HX_LOAD_BODIES_MAX];
        const int nbodies = hx_load_bodies(m, k, bodies);
        for (int i = 0; i < nbodies; ++i) {
            const int b = bodies[i];
            if (d->dof[b].kind == HX_DOF_GROUND)
                continue;
            int columns[13];
            const int count = hx_jacobian_body_columns(d, b, columns);
            for (int j = 0; j < count; ++j) {
                const int c = columns[j];
                const double keep = jac->y[c], h = hx_jacobian_step(jac->y, c);
                hx_load_share share[2];
                double W[2][2][6]; /* side, application, (F, T) */
                for (int side = 0; side < 2; ++side) {
                    jac->y[c] = keep + (side == 0 ? h : -h);
                    hx_jacobian_move_body(jac, b, jac->y);
                    hx_message msg;
                    if (hx_load_share_at(d->m, &jac->moved, k, &share[side], &msg) != 0) {
                        jac->y[c] = keep;
                        hx_jacobian_restore_body(jac, b);
                        return hx_dynamics_fail(&jac->dd, "%s", msg.text);
                    }
                    for (int a = 0; a < share[side].count; ++a)
                        wrench(&share[side], a, &jac->moved, W[side][a], W[side][a] + 3);
                }
                jac->y[c] = keep;
                hx_jacobian_restore_body(jac, b);
                put_difference(jac, share[0].count, share[0].body, W, h, c);
            }
        }
    }
    return 0;
}
