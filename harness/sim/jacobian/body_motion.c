/* How bodies move with their coordinates (body_motion.h). */
#include "sim/jacobian/body_motion.h"

#include <math.h>
#include <string.h>

#include "base/vecmath.h"

void hx_body_column_motion(const hx_dynamics *d, int b, int which, const double *y,
                           const hx_frame *f, hx_motion *mo)
{
    const hx_body_dof *dof = &d->dof[b];
    memset(mo, 0, sizeof *mo);
    if (dof->kind == HX_DOF_FREE) {
        if (which < 3) {
            mo->dp[which] = 1.0;
        } else if (which < 7) {
            /* q' = q + e_i turns the frame by 2 vec(e_i (x) conj(q)) / |q|^2 (world axes) */
            const double *q = y + dof->q + 3;
            const double conj[4] = {q[0], -q[1], -q[2], -q[3]};
            double e[4] = {0, 0, 0, 0}, prod[4];
            e[which - 3] = 1.0;
            quat_mul(prod, e, conj);
            const double scale = 2.0 / (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            v3_set(mo->dth, scale * prod[1], scale * prod[2], scale * prod[3]);
            v3_cross(mo->dw, mo->dth, f->w); /* w = R omega turns with the frame */
        } else if (which < 10) {
            mo->dv[which - 7] = 1.0;
        } else {
            const int j = which - 10; /* omega is in body axes: w = R omega */
            v3_set(mo->dw, f->R[j], f->R[3 + j], f->R[6 + j]);
        }
        return;
    }
    if (dof->kind == HX_DOF_REVOLUTE) {
        double r[3];
        v3_sub(r, f->p, dof->origin);
        if (which == 0) {
            v3_copy(mo->dth, dof->axis);
            v3_cross(mo->dp, dof->axis, r);
            v3_cross(mo->dv, f->w, mo->dp); /* v = w x r turns with r */
        } else {
            v3_copy(mo->dw, dof->axis);
            v3_cross(mo->dv, dof->axis, r);
        }
        return;
    }
    if (dof->kind == HX_DOF_SLIDER) {
        if (which == 0)
            v3_copy(mo->dp, dof->axis);
        else
            v3_copy(mo->dv, dof->axis);
    }
}

void hx_point_motion(const hx_frame *f, const hx_motion *mo, const hx_frame *M, hx_motion *out)
{
    double r[3], tr[3], wtr[3], dwr[3];
    v3_sub(r, M->p, f->p);
    v3_cross(tr, mo->dth, r);
    v3_add(out->dp, mo->dp, tr);
    v3_copy(out->dth, mo->dth);
    v3_cross(wtr, f->w, tr);
    v3_cross(dwr, mo->dw, r);
    v3_add(out->dv, mo->dv, dwr);
    v3_add(out->dv, out->dv, wtr);
    v3_copy(out->dw, mo->dw);
}
