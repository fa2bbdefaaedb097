/* The user force elements in the equations of motion (dynamics.h): each is
 * called with the dynamics' state bound, its
 * result turned into world axes and applied at I, its reaction on J's body at
 * the same point; one switched off (d->force_off) is not called and gives
 * nothing. */
#include <math.h>
#include <string.h>

#include "host/invoke.h"
#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/element_forces.h"
#include "sim/dynamics/failure.h"
#include "frames/measures.h"

void hx_force_routine_load(const hx_model *m, const hx_frames *fr, int force,
                           const double *values, double load[6])
{
    const hx_force *f = &m->forces[force];
    for (int k = 0; k < 6; ++k)
        load[k] = 0.0;
    switch (f->part) {
    case HX_OUTPUT_FORCE_AND_TORQUE:
        for (int k = 0; k < 6; ++k)
            load[k] = values[k];
        return;
    case HX_OUTPUT_FORCE:
        v3_copy(load, values);
        return;
    case HX_OUTPUT_TORQUE:
        v3_copy(load + 3, values);
        return;
    case HX_OUTPUT_SCALAR_FORCE:
    case HX_OUTPUT_SCALAR_TORQUE:
        break;
    }
    const double value = values[0];
    if (isnan(value)) {
        load[0] = value;
        return;
    }
    hx_frame scratch[2];
    const hx_frame *I = hx_frames_marker(fr, f->i_marker, &scratch[0]);
    const hx_frame *J = hx_frames_marker(fr, f->j_marker, &scratch[1]);
    if (f->part == HX_OUTPUT_SCALAR_TORQUE) {
        for (int k = 0; k < 3; ++k)
            load[3 + k] = value * J->R[3 * k + 2];
        return;
    }
    double r[3] = {I->p[0] - J->p[0], I->p[1] - J->p[1], I->p[2] - J->p[2]};
    const double length = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (length > 0.0)
        for (int k = 0; k < 3; ++k)
            load[k] = value * r[k] / length;
}

void hx_force_routine_call(hx_binding *b, const hx_frames *fr, int dflag, double load[6])
{
    double values[6];
    hx_invoke_force(b, fr, dflag, 0, values, NULL);
    hx_force_routine_load(b->model, fr, b->index, values, load);
}

int hx_element_forces_apply(const hx_dynamics *d, hx_dynamics_data *dd, int partials,
                            double *power)
{
    const hx_model *m = d->m;
    const hx_frames *fr = &dd->frames;
    *power = 0.0;
    for (int k = 0; k < m->nforces; ++k) {
        const hx_force *f = &m->forces[k];
        hx_binding *b = d->force_binding[k];
        const hx_frame *I = &fr->markers[f->i_marker], *J = &fr->markers[f->j_marker];
        double *out = dd->element_outputs + 6 * k;
        double *F = dd->element_load + 6 * k, *T = F + 3;
        if (d->force_off[k]) { /* switched off: not called, nothing on the bodies */
            for (int j = 0; j < 6; ++j)
                out[j] = F[j] = 0.0;
            if (partials && f->interface == HX_FORCE_FIESUB)
                memset(dd->element_partials + 72 * k, 0, 72 * sizeof(double));
            continue;
        }
        const int axes_marker = hx_force_output_axes(f);
        const double *axes = axes_marker >= 0 ? fr->markers[axes_marker].R : hx_world_frame.R;
        if (f->interface == HX_FORCE_GFOSUB) {
            hx_force_routine_call(b, fr, 0, out);
        } else {
            double disp[6], velo[6], *dfd = dd->element_partials + 72 * k;
            hx_field_state(I, J, disp, velo);
            hx_invoke_field(b, fr, disp, velo, partials, 0, out, dfd, dfd + 36, NULL);
        }
        if (hx_dynamics_check_call(d, dd, b, out, 6, "force", fr->time) != 0)
            return -1;
        if (d->world_aligned[k]) {
            v3_copy(F, out);
            v3_copy(T, out + 3);
        } else {
            m3_apply(F, axes, out);
            m3_apply(T, axes, out + 3);
        }
        *power += hx_bodies_apply_load(d, dd, m->markers[f->i_marker].body, I->p, F, T, 1.0);
        *power += hx_bodies_apply_load(d, dd, m->markers[f->j_marker].body, I->p, F, T, -1.0);
    }
    return 0;
}
