/* Gravity and the model's loads on the bodies (dynamics.h). */
#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/loads.h"

static double value_at(const hx_time_function *f, double t)
{
    /* components left out are constant zeros: skip them */
    return f->kind == 0 ? f->a[0] : hx_time_function_at(f, t);
}

double hx_loads_apply(hx_dynamics *d, double t)
{
    const hx_model *m = d->m;
    for (int k = 0; k < m->nbodies; ++k)
        if (d->dof[k].kind != HX_DOF_GROUND)
            v3_axpy(d->force + 3 * k, m->bodies[k].mass / d->ucf, m->gravity);
    double power = 0.0;
    for (int k = 0; k < m->nloads; ++k) {
        const hx_load *l = &m->loads[k];
        hx_frame scratch[3];
        const hx_frame *I = hx_state_marker(&d->state, l->i_marker, &scratch[0]);
        const int bi = m->markers[l->i_marker].body;
        if (l->kind == HX_LOAD_VECTOR) {
            double F[3], T[3], f[3], tq[3];
            for (int i = 0; i < 3; ++i) {
                f[i] = value_at(&l->force[i], t);
                tq[i] = value_at(&l->torque[i], t);
            }
            const hx_frame *ref = hx_state_marker(&d->state, l->ref_marker, &scratch[2]);
            m3_apply(F, ref->R, f);
            m3_apply(T, ref->R, tq);
            power += hx_bodies_apply_load(d, bi, I->p, F, T, 1.0);
            continue;
        }
        const hx_frame *J = hx_state_marker(&d->state, l->j_marker, &scratch[1]);
        const int bj = m->markers[l->j_marker].body;
        double F[3] = {0, 0, 0}, T[3] = {0, 0, 0};
        const double value = hx_time_function_at(&l->value, t);
        if (l->kind == HX_LOAD_SCALAR_TORQUE) {
            v3_set(T, J->R[2] * value, J->R[5] * value, J->R[8] * value);
        } else {
            double r[3];
            v3_sub(r, I->p, J->p);
            const double len = v3_norm(r);
            if (len > 0.0)
                v3_scale(F, r, value / len); /* positive pushes I away from J */
        }
        power += hx_bodies_apply_load(d, bi, I->p, F, T, 1.0);
        if (!l->action_only)
            power += hx_bodies_apply_load(d, bj, J->p, F, T, -1.0);
    }
    return power;
}
