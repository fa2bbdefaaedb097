/*
 * The bodies' accelerations (accelerations.h) from udot, by the body's
 * degrees of freedom (dynamics.h):
 *   free: u = (v of the origin, world; w in body axes), so a = vdot and
 *         alpha = d/dt (R w_b) = R (w_b x w_b) + R w_b' = R w_b';
 *   revolute: about a fixed axis through a fixed point, alpha = axis udot,
 *         a = alpha x r + w x (w x r), r from the axis's point to the origin;
 *   slider: a = axis udot, no rotation.
 */
#include "sim/dynamics/accelerations.h"

#include "base/vecmath.h"

void hx_accelerations_bodies(const hx_dynamics *d, const hx_dynamics_data *dd, const double *ydot,
                             double *out)
{
    const double *udot = ydot + d->nq;
    for (int k = 0; k < d->m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        const hx_frame *f = &dd->frames.bodies[k];
        double *a = out + 6 * k, *alpha = a + 3;
        v3_set(a, 0, 0, 0), v3_set(alpha, 0, 0, 0);
        switch (dof->kind) {
        case HX_DOF_GROUND:
            break;
        case HX_DOF_FREE:
            v3_copy(a, udot + dof->u);
            m3_apply(alpha, f->R, udot + dof->u + 3);
            break;
        case HX_DOF_REVOLUTE: {
            double r[3], t[3];
            v3_scale(alpha, dof->axis, udot[dof->u]);
            v3_sub(r, f->p, dof->origin);
            v3_cross(a, alpha, r);
            v3_cross(t, f->w, f->v); /* w x (w x r), v = w x r */
            v3_add(a, a, t);
            break;
        }
        case HX_DOF_SLIDER:
            v3_scale(a, dof->axis, udot[dof->u]);
            break;
        }
    }
}
