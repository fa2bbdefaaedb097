/*
 * The loads' blocks of the Newton matrix (newton_matrix.h): each load by
 * central differences of that load alone, on the columns of the bodies its
 * markers sit on (loads are few; their time functions need no partials).
 */
#include "base/vecmath.h"
#include "sim/dynamics/loads.h"
#include "sim/jacobian/jacobian_parts.h"

/* What share puts on its i-th body: F and the torque about its centre. */
static void wrench(const hx_load_share *share, int i, const hx_frames *fr, double F[3], double T[3])
{
    double arm[3];
    v3_copy(F, share->F[i]);
    v3_sub(arm, share->point[i], fr->bodies[share->body[i]].p);
    v3_cross(T, arm, share->F[i]);
    v3_add(T, T, share->T[i]);
}

int hx_load_blocks(hx_jacobian *jac, double t, const double *y)
{
    (void)y;
    const hx_dynamics *d = jac->d;
    const hx_model *m = d->m;
    for (int k = 0; k < m->nloads; ++k) {
        const hx_load *l = &m->loads[k];
        const int other = l->kind == HX_LOAD_VECTOR ? l->ref_marker : l->j_marker;
        const int bodies[2] = {m->markers[l->i_marker].body,
                               other >= 0 ? m->markers[other].body : -1};
        for (int i = 0; i < 2; ++i) {
            const int b = bodies[i];
            if (b < 0 || d->dof[b].kind == HX_DOF_GROUND || (i == 1 && b == bodies[0]))
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
                    hx_load_share_at(d->m, &jac->moved, t, k, &share[side]);
                    for (int a = 0; a < share[side].count; ++a)
                        wrench(&share[side], a, &jac->moved, W[side][a], W[side][a] + 3);
                }
                jac->y[c] = keep;
                hx_jacobian_restore_body(jac, b);
                for (int a = 0; a < share[0].count; ++a) {
                    double dW[6];
                    for (int r = 0; r < 6; ++r)
                        dW[r] = (W[0][a][r] - W[1][a][r]) / (2.0 * h);
                    hx_jacobian_body_load(jac, share[0].body[a], c, -1, dW, dW + 3);
                }
            }
        }
    }
    return 0;
}
