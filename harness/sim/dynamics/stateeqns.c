/* The Force_StateEqn elements in the equations of motion (stateeqns.h). */
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/stateeqns.h"

#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "host/invoke.h"
#include "host/state_inputs.h"

int hx_stateeqns_init(hx_dynamics *d, hx_message *msg)
{
    const hx_model *m = d->m;
    hx_stateeqns *se = calloc(1, sizeof *se);
    if (se == NULL)
        return hx_fail(msg, "out of memory");
    d->stateeqns = se;
    se->count = m->nstateeqns;
    const size_t n1 = (size_t)se->count + 1;
    d->stateeqn_offset = d->nq + d->nu;
    d->nstates = 0;
    se->binding = calloc(n1, sizeof *se->binding);
    se->offset = calloc(n1, sizeof *se->offset);
    if (se->binding == NULL || se->offset == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < se->count; ++k) {
        se->binding[k] = hx_bindings_find(&d->s->bindings, HX_FAMILY_STATEEQN, k);
        se->offset[k] = d->stateeqn_offset + d->nstates;
        d->nstates += m->stateeqns[k].nstate;
    }
    return 0;
}

int hx_stateeqns_work_size(const hx_dynamics *d)
{
    int work = 6;
    for (int k = 0; k < d->m->nstateeqns; ++k) {
        const hx_stateeqn *f = &d->m->stateeqns[k];
        if (f->nstate + 2 * f->ninput > work)
            work = f->nstate + 2 * f->ninput;
    }
    return work;
}

void hx_stateeqns_free(hx_dynamics *d)
{
    hx_stateeqns *se = d->stateeqns;
    if (se == NULL)
        return;
    free(se->binding);
    free(se->offset);
    free(se);
    d->stateeqns = NULL;
}

void hx_stateeqns_initial(const hx_dynamics *d, double *y)
{
    const hx_stateeqns *se = d->stateeqns;
    for (int k = 0; k < se->count; ++k) {
        const hx_stateeqn *f = &d->m->stateeqns[k];
        for (int i = 0; i < f->nstate; ++i)
            y[se->offset[k] + i] = f->initial[i];
    }
}

int hx_stateeqn_call(const hx_dynamics *d, hx_dynamics_data *dd, int k, const double *x,
                     const double *u, int dflag, double *xdot, double out[6])
{
    const hx_stateeqn *f = &d->m->stateeqns[k];
    hx_binding *b = d->stateeqns->binding[k];
    /* copies (past the inputs of hx_stateeqns_apply): a library may
     * write into its arguments, never into y */
    double *states = dd->stateeqn_work + f->ninput, *input = states + f->nstate;
    memcpy(states, x, sizeof(double) * (size_t)f->nstate);
    memcpy(input, u, sizeof(double) * (size_t)f->ninput);
    hx_invoke_stateeqn(b, &dd->frames, states, input, dflag, 0, xdot, out, NULL);
    const double t = dd->frames.time;
    if (hx_dynamics_check_call(d, dd, b, out, 6, "force", t) != 0 ||
        hx_dynamics_check_call(d, dd, b, xdot, f->nstate, "state rate", t) != 0)
        return -1;
    return 0;
}

/* The outputs on I (ref_marker axes) applied to I's body at the I marker and,
 * reversed, to the J marker's body at the same point; their power. */
static double apply_outputs(const hx_dynamics *d, hx_dynamics_data *dd, const hx_stateeqn *f,
                            const double out[6])
{
    const hx_model *m = d->m;
    hx_frame scratch[2];
    const hx_frame *I = hx_frames_marker(&dd->frames, f->i_marker, &scratch[0]);
    const hx_frame *ref = hx_frames_marker(&dd->frames, f->ref_marker, &scratch[1]);
    double F[3], T[3];
    m3_apply(F, ref->R, out);
    m3_apply(T, ref->R, out + 3);
    return hx_bodies_apply_load(d, dd, m->markers[f->i_marker].body, I->p, F, T, 1.0) +
           hx_bodies_apply_load(d, dd, m->markers[f->j_marker].body, I->p, F, T, -1.0);
}

int hx_stateeqns_apply(const hx_dynamics *d, hx_dynamics_data *dd, const double *y,
                       double *ydot)
{
    const hx_stateeqns *se = d->stateeqns;
    for (int k = 0; k < se->count; ++k) {
        const hx_stateeqn *f = &d->m->stateeqns[k];
        double *out = dd->stateeqn_outputs + 6 * k, *xdot = ydot + se->offset[k];
        double *u = dd->stateeqn_work; /* the call's own copies come after them */
        if (hx_stateeqn_inputs(&dd->frames, k, u) != 0) {
            hx_message why;
            hx_stateeqn_inputs_why(&dd->frames, k, &why);
            return hx_dynamics_fail(dd, "Force_StateEqn %d: its input %s", f->id, why.text);
        }
        if (hx_stateeqn_call(d, dd, k, y + se->offset[k], u, 0, xdot, out) != 0)
            return -1;
        ydot[d->element_work] += apply_outputs(d, dd, f, out);
    }
    return 0;
}

void hx_stateeqns_csv_header(FILE *f, const hx_dynamics *d)
{
    static const char *const loads[6] = {"fx", "fy", "fz", "tx", "ty", "tz"};
    for (int k = 0; k < d->m->nstateeqns; ++k) {
        const hx_stateeqn *e = &d->m->stateeqns[k];
        for (int i = 0; i < e->nstate; ++i)
            fprintf(f, ",stateeqn%d.x%d", e->id, i + 1);
        for (int i = 0; i < e->ninput; ++i)
            fprintf(f, ",stateeqn%d.u%d", e->id, i + 1);
        for (int j = 0; j < 6; ++j)
            fprintf(f, ",stateeqn%d.%s", e->id, loads[j]);
    }
}

void hx_stateeqns_csv_row(FILE *f, const hx_dynamics *d, hx_dynamics_data *dd, const double *y)
{
    const hx_stateeqns *se = d->stateeqns;
    for (int k = 0; k < se->count; ++k) {
        const hx_stateeqn *e = &d->m->stateeqns[k];
        for (int i = 0; i < e->nstate; ++i)
            fprintf(f, ",%.12g", y[se->offset[k] + i]);
        hx_stateeqn_inputs(&dd->frames, k, dd->stateeqn_work);
        for (int i = 0; i < e->ninput; ++i)
            fprintf(f, ",%.12g", dd->stateeqn_work[i]);
        for (int j = 0; j < 6; ++j)
            fprintf(f, ",%.12g", dd->stateeqn_outputs[6 * k + j]);
    }
}
