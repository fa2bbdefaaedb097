/* The energy of a state and its balance (dynamics.h). */
#include "base/vecmath.h"
#include "sim/dynamics/energy.h"
#include "sim/dynamics/element_at.h"
#include "frames/measures.h"

hx_energy hx_energy_of(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y)
{
    const hx_model *m = d->m;
    hx_dynamics_kinematics(d, dd, t, y);
    double kinetic = 0.0, potential = 0.0;
    for (int k = 0; k < m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        const hx_frame *f = &dd->frames.bodies[k];
        const double *u = y + d->nq + dof->u;
        if (dof->kind == HX_DOF_GROUND)
            continue;
        if (dof->kind == HX_DOF_FREE) {
            double Iw[3];
            m3_apply(Iw, dof->inertia, u + 3);
            kinetic += 0.5 * dof->mass * v3_dot(u, u) + 0.5 * v3_dot(u + 3, Iw);
        } else {
            kinetic += 0.5 * dof->mass * u[0] * u[0];
        }
        potential -= m->bodies[k].mass * v3_dot(d->gravity, f->p);
    }
    double elastic = 0.0;
    hx_frames_copy(&dd->moved, &dd->frames);
    for (int k = 0; k < m->nforces; ++k)
        if (!d->force_off[k]) /* one switched off stores nothing */
            elastic += hx_element_potential(d->s, &dd->moved, &dd->frames, k, t);
    hx_energy e;
    e.kinetic = kinetic / d->ucf;
    e.elastic = elastic;
    e.total = (kinetic + potential) / d->ucf + elastic - y[d->load_work];
    e.balance = (kinetic + potential) / d->ucf - y[d->load_work] - y[d->element_work];
    return e;
}

double hx_dissipated(const hx_energy *e, const hx_energy *e0)
{
    return (e0->total - e0->balance) - (e->total - e->balance);
}
