/* The user force elements in the equations of motion (dynamics.h): each is
 * called with the dynamics' state bound, its
 * result turned into world axes and applied at I, its reaction on J's body at
 * the same point. */
#include "base/finite.h"
#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/element_forces.h"
#include "sim/dynamics/stage_failure.h"
#include "frames/measures.h"

int hx_element_forces_apply(hx_dynamics *d, double *power)
{
    const hx_model *m = d->m;
    const hx_frames *s = &d->frames;
    *power = 0.0;
    for (int k = 0; k < m->nforces; ++k) {
        const hx_force *f = &m->forces[k];
        hx_binding *b = d->force_binding[k];
        const hx_frame *I = &s->markers[f->i_marker], *J = &s->markers[f->j_marker];
        double *out = d->element_outputs + 6 * k;
        /* the result's axes: the reference marker's (GFOSUB), or J's (FIESUB) */
        const double *axes = f->interface == HX_FORCE_GFOSUB
                                 ? (f->ref_marker >= 0 ? s->markers[f->ref_marker].R
                                                       : hx_world_frame.R)
                                 : J->R;
        if (f->interface == HX_FORCE_GFOSUB) {
            hx_invoke_gfosub(b, s, 0, 0, out, NULL);
        } else {
            /* the partials come with the force, when asked for (dflag): kept
             * for the Newton matrix */
            double disp[6], velo[6], *dfd = d->element_partials + 72 * k;
            hx_field_state(I, J, disp, velo);
            hx_invoke_fiesub(b, s, disp, velo, d->field_partials, 0, out, dfd, dfd + 36, NULL);
        }
        if (hx_dynamics_check_stop(d, b) != 0)
            return -1;
        if (!hx_all_finite(out, 6))
            return hx_dynamics_fail(d, "%s %d returned a non-finite force at t = %g", b->element,
                                    b->id, s->time);
        double *F = d->element_load + 6 * k, *T = F + 3;
        if (d->world_aligned[k]) {
            v3_copy(F, out);
            v3_copy(T, out + 3);
        } else {
            m3_apply(F, axes, out);
            m3_apply(T, axes, out + 3);
        }
        *power += hx_bodies_apply_load(d, m->markers[f->i_marker].body, I->p, F, T, 1.0);
        *power += hx_bodies_apply_load(d, m->markers[f->j_marker].body, I->p, F, T, -1.0);
    }
    return 0;
}
