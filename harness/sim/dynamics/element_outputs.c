/*
 * The force elements' forces as the function language reads them
 * (element_outputs.h).
 */
#include "sim/dynamics/element_outputs.h"

#include "base/vecmath.h"
#include "sim/dynamics/loads.h"

int hx_element_outputs_loads(const hx_dynamics *d, const hx_dynamics_data *dd, double *out,
                             hx_message *msg)
{
    for (int k = 0; k < d->m->nloads; ++k)
        if (hx_loads_output(d, dd, k, out + 12 * k, msg) != 0)
            return -1;
    return 0;
}

void hx_element_outputs_forces(const hx_dynamics *d, const hx_dynamics_data *dd, double *out)
{
    const hx_model *m = d->m;
    for (int k = 0; k < m->nforces; ++k) {
        const hx_force *f = &m->forces[k];
        const double *on_i = dd->element_load + 6 * k;
        double *at = out + 12 * k;
        for (int j = 0; j < 6; ++j)
            at[j] = on_i[j], at[6 + j] = 0.0;
        if (f->one_body)
            continue; /* the ground takes it: no J side (a Force_Vector_OneBody) */
        /* the forces stage puts -F, -T on J's body at I's origin (element_forces.c):
         * a floating J is there; a Force_Field's or Force_Scalar's J has it moved to J */
        v3_scale(at + 6, on_i, -1.0), v3_scale(at + 9, on_i + 3, -1.0);
        const int floating = f->interface == HX_FORCE_GFOSUB &&
                             f->part != HX_OUTPUT_SCALAR_FORCE && f->part != HX_OUTPUT_SCALAR_TORQUE;
        if (floating)
            continue;
        hx_frame scratch[2];
        const hx_frame *i = hx_frames_marker(&dd->frames, f->i_marker, &scratch[0]);
        const hx_frame *j = hx_frames_marker(&dd->frames, f->j_marker, &scratch[1]);
        double r[3], rxF[3];
        v3_sub(r, i->p, j->p);
        v3_cross(rxF, r, at + 6); /* the torque of -F at I about J's origin */
        v3_add(at + 9, at + 9, rxF);
    }
}
