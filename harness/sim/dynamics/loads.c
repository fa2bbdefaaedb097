/* Gravity and the model's loads on the bodies (loads.h). */
#include "sim/dynamics/loads.h"

#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"

static double value_at(const hx_time_function *f, double t)
{
    /* components left out are constant zeros: skip them */
    return f->kind == 0 ? f->a[0] : hx_time_function_at(f, t);
}

void hx_load_share_at(const hx_model *m, const hx_frames *fr, double t, int k,
                      hx_load_share *share)
{
    const hx_load *l = &m->loads[k];
    hx_frame scratch[3];
    const hx_frame *I = hx_frames_marker(fr, l->i_marker, &scratch[0]);
    share->count = 1;
    share->body[0] = m->markers[l->i_marker].body;
    v3_copy(share->point[0], I->p);
    double *F = share->F[0], *T = share->T[0];
    if (l->kind == HX_LOAD_VECTOR) {
        double f[3], tq[3];
        for (int i = 0; i < 3; ++i) {
            f[i] = value_at(&l->force[i], t);
            tq[i] = value_at(&l->torque[i], t);
        }
        const hx_frame *ref = hx_frames_marker(fr, l->ref_marker, &scratch[2]);
        m3_apply(F, ref->R, f);
        m3_apply(T, ref->R, tq);
        return;
    }
    const hx_frame *J = hx_frames_marker(fr, l->j_marker, &scratch[1]);
    v3_set(F, 0, 0, 0);
    v3_set(T, 0, 0, 0);
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
    if (l->action_only)
        return;
    share->count = 2;
    share->body[1] = m->markers[l->j_marker].body;
    v3_copy(share->point[1], J->p);
    v3_scale(share->F[1], F, -1.0);
    v3_scale(share->T[1], T, -1.0);
}

double hx_loads_apply(const hx_dynamics *d, hx_dynamics_data *dd, double t)
{
    const hx_model *m = d->m;
    for (int k = 0; k < m->nbodies; ++k)
        if (d->dof[k].kind != HX_DOF_GROUND)
            v3_axpy(dd->force + 3 * k, m->bodies[k].mass / d->ucf, m->gravity);
    double power = 0.0;
    for (int k = 0; k < m->nloads; ++k) {
        hx_load_share share;
        hx_load_share_at(m, &dd->frames, t, k, &share);
        for (int i = 0; i < share.count; ++i)
            power += hx_bodies_apply_load(d, dd, share.body[i], share.point[i], share.F[i],
                                          share.T[i], 1.0);
    }
    return power;
}
