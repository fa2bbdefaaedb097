/* The Force_StateEqn elements' share of the Newton matrix (state_jacobian.h). */
#include "sim/newton/state_jacobian.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/finite.h"
#include "host/state_inputs.h"
#include "sim/dynamics/state_elements.h"

static const char *const routine_names[4] = {"YFOXX", "YFOXU", "YFOYX", "YFOYU"};

int hx_state_jacobian_init(hx_state_jacobian *sj, hx_dynamics *d, hx_message *msg)
{
    memset(sj, 0, sizeof *sj);
    const hx_model *m = d->m;
    sj->d = d;
    sj->count = m->nstate_eqns;
    sj->n = d->n;
    sj->m = d->nq + d->nu;
    const size_t c1 = (size_t)sj->count + 1;
    sj->block = calloc(c1, sizeof *sj->block);
    sj->slope = calloc(c1, sizeof *sj->slope);
    if (sj->block == NULL || sj->slope == NULL)
        return hx_fail(msg, "out of memory");
    size_t partials = 0, slopes = 0, inputs = 0;
    int widest = 1;
    for (int k = 0; k < sj->count; ++k) {
        const hx_state_eqn *f = &m->state_eqns[k];
        const size_t ns = (size_t)f->nstate, ni = (size_t)f->ninput;
        sj->block[k] = partials;
        sj->slope[k] = slopes;
        partials += (ns + 6) * (ns + ni);
        slopes += ni * (size_t)sj->m;
        inputs += ni;
        if (f->nstate + f->ninput + 6 > widest)
            widest = f->nstate + f->ninput + 6;
    }
    sj->partials = calloc(partials + 1, sizeof(double));
    sj->du = calloc(slopes + 1, sizeof(double));
    /* y; x, u, xdot, xdotm, out, outm: one element at a time; up, um: the
     * inputs of every element */
    sj->y = calloc((size_t)sj->n + 6 * (size_t)widest + 2 * inputs + 1, sizeof(double));
    if (sj->partials == NULL || sj->du == NULL || sj->y == NULL) {
        hx_state_jacobian_free(sj);
        return hx_fail(msg, "out of memory");
    }
    sj->x = sj->y + sj->n;
    sj->u = sj->x + widest;
    sj->xdot = sj->u + widest;
    sj->xdotm = sj->xdot + widest;
    sj->out = sj->xdotm + widest;
    sj->outm = sj->out + widest;
    sj->up = sj->outm + widest;
    sj->um = sj->up + inputs;
    return 0;
}

void hx_state_jacobian_free(hx_state_jacobian *sj)
{
    free(sj->block);
    free(sj->slope);
    free(sj->partials);
    free(sj->du);
    free(sj->y);
    memset(sj, 0, sizeof *sj);
}

/* The step of a difference in value v: relative above 1e-3, absolute below
 * (states and inputs are lengths, angles and their rates in model units). */
static double step_of(double v)
{
    return 1e-6 * fmax(fabs(v), 1e-3);
}

/* The four blocks of element k by the library's partial routines where it
 * exports them; which[r] is set for the routines that must be differenced. */
static int library_partials(hx_state_jacobian *sj, int k, double *blocks[4], int which[4],
                            long *calls)
{
    hx_dynamics *d = sj->d;
    const hx_state_eqn *f = &d->m->state_eqns[k];
    hx_binding *b = d->stateful->binding[k];
    const int size[4] = {f->nstate * f->nstate, f->nstate * f->ninput, 6 * f->nstate,
                         6 * f->ninput};
    for (int r = 0; r < 4; ++r) {
        which[r] = b->state_partial[r] == NULL;
        if (which[r]) {
            sj->differenced[r] = 1;
            continue;
        }
        sj->exported[r] = 1;
        memcpy(sj->xdot, sj->x, sizeof(double) * (size_t)f->nstate); /* copies it may write */
        memcpy(sj->xdotm, sj->u, sizeof(double) * (size_t)f->ninput);
        hx_call_state_partial(b, r, &d->state, sj->xdot, sj->xdotm, blocks[r], NULL);
        ++*calls;
        if (hx_dynamics_check_stop(d, b) != 0)
            return -1;
        if (!hx_all_finite(blocks[r], size[r]))
            return hx_dynamics_fail(d, "Force_StateEqn %d: %s returned non-finite partials at t ="
                                    " %g", f->id, b->names[1 + r], d->state.time);
    }
    return 0;
}

/* Central differences of YFOSUB for the blocks the library does not give:
 * states perturbed for F_x and G_x, inputs for F_u and G_u. */
static int differenced_partials(hx_state_jacobian *sj, int k, double *blocks[4],
                                const int which[4], long *calls)
{
    hx_dynamics *d = sj->d;
    const hx_state_eqn *f = &d->m->state_eqns[k];
    const int ns = f->nstate, ni = f->ninput;
    for (int group = 0; group < 2; ++group) {
        if (!which[group] && !which[group + 2])
            continue;
        double *v = group == 0 ? sj->x : sj->u;
        const int columns = group == 0 ? ns : ni;
        for (int j = 0; j < columns; ++j) {
            const double keep = v[j], h = step_of(keep);
            v[j] = keep + h;
            int status = hx_state_element_evaluate(d, k, sj->x, sj->u, 1, sj->xdot, sj->out);
            v[j] = keep - h;
            if (status == 0)
                status = hx_state_element_evaluate(d, k, sj->x, sj->u, 1, sj->xdotm, sj->outm);
            v[j] = keep;
            *calls += 2;
            if (status != 0)
                return -1;
            for (int i = 0; i < ns && which[group]; ++i)
                blocks[group][i + ns * j] = (sj->xdot[i] - sj->xdotm[i]) / (2.0 * h);
            for (int i = 0; i < 6 && which[group + 2]; ++i)
                blocks[group + 2][i + 6 * j] = (sj->out[i] - sj->outm[i]) / (2.0 * h);
        }
    }
    return 0;
}

/* dU/dy over positions and velocities, every element at once: differences of
 * the harness's measures (angles wrapped), no element called. */
static void input_slopes(hx_state_jacobian *sj, double t)
{
    hx_dynamics *d = sj->d;
    const hx_model *m = d->m;
    for (int c = 0; c < sj->m; ++c) {
        const double keep = sj->y[c], h = 1e-5 * fmax(1.0, fabs(keep));
        double *at[2] = {sj->up, sj->um};
        for (int side = 0; side < 2; ++side) {
            sj->y[c] = keep + (side == 0 ? h : -h);
            hx_dynamics_set_state(d, t, sj->y);
            for (int k = 0, i0 = 0; k < sj->count; i0 += m->state_eqns[k++].ninput)
                hx_state_eqn_inputs(&d->state, k, at[side] + i0);
        }
        sj->y[c] = keep;
        for (int k = 0, i0 = 0; k < sj->count; i0 += m->state_eqns[k++].ninput) {
            const hx_state_eqn *f = &m->state_eqns[k];
            double *column = sj->du + sj->slope[k] + (size_t)f->ninput * (size_t)c;
            for (int i = 0; i < f->ninput; ++i) {
                double delta = sj->up[i0 + i] - sj->um[i0 + i];
                if (hx_variable_is_angle(&m->variables[f->inputs[i]]))
                    delta = remainder(delta, 2.0 * M_PI);
                column[i] = delta / (2.0 * h);
            }
        }
    }
}

int hx_state_jacobian_outputs(hx_state_jacobian *sj, double t, const double *y, double *outputs,
                              long *calls)
{
    hx_dynamics *d = sj->d;
    memcpy(sj->y, y, sizeof(double) * (size_t)sj->n);
    hx_dynamics_set_state(d, t, y); /* the element calls below take it read-only */
    for (int k = 0; k < sj->count; ++k) {
        const hx_state_eqn *f = &d->m->state_eqns[k];
        memcpy(sj->x, y + d->stateful->offset[k], sizeof(double) * (size_t)f->nstate);
        hx_state_eqn_inputs(&d->state, k, sj->u);
        ++*calls;
        if (hx_state_element_evaluate(d, k, sj->x, sj->u, 0, sj->xdot, outputs + 6 * k) != 0)
            return -1;
        double *xx = sj->partials + sj->block[k];
        double *blocks[4] = {xx, xx + f->nstate * f->nstate,
                             xx + f->nstate * (f->nstate + f->ninput),
                             xx + f->nstate * (f->nstate + f->ninput) + 6 * f->nstate};
        int which[4];
        if (library_partials(sj, k, blocks, which, calls) != 0 ||
            differenced_partials(sj, k, blocks, which, calls) != 0)
            return -1;
    }
    input_slopes(sj, t);
    return 0;
}

void hx_state_jacobian_add(const hx_state_jacobian *sj, const double *response, double *J)
{
    const hx_dynamics *d = sj->d;
    const size_t n = (size_t)sj->n;
    for (int k = 0; k < sj->count; ++k) {
        const hx_state_eqn *f = &d->m->state_eqns[k];
        const int ns = f->nstate, ni = f->ninput, x0 = d->stateful->offset[k];
        const double *xx = sj->partials + sj->block[k], *xu = xx + ns * ns;
        const double *yx = xu + ns * ni, *yu = yx + 6 * ns;
        const double *B = response + n * 6 * (size_t)k;
        for (int c = 0; c < sj->m + ns; ++c) {
            /* column c of d out/dy and of d xdot/dy: through the inputs for the
             * bodies' positions and velocities, directly for the states */
            const int is_state = c >= sj->m, col = is_state ? x0 + c - sj->m : c;
            const double *slope = is_state ? NULL : sj->du + sj->slope[k] + (size_t)ni * (size_t)c;
            double g[6], *Jc = J + n * (size_t)col;
            for (int r = 0; r < 6; ++r) {
                g[r] = 0.0;
                if (is_state)
                    g[r] = yx[r + 6 * (c - sj->m)];
                else
                    for (int l = 0; l < ni; ++l)
                        g[r] += yu[r + 6 * l] * slope[l];
            }
            for (int r = 0; r < 6; ++r)
                if (g[r] != 0.0)
                    for (size_t i = 0; i < n; ++i)
                        Jc[i] += B[n * (size_t)r + i] * g[r];
            for (int i = 0; i < ns; ++i) {
                double s = 0.0;
                if (is_state)
                    s = xx[i + ns * (c - sj->m)];
                else
                    for (int l = 0; l < ni; ++l)
                        s += xu[i + ns * l] * slope[l];
                Jc[x0 + i] += s;
            }
        }
    }
}

void hx_state_jacobian_describe(const hx_state_jacobian *sj, char *text, size_t size)
{
    if (sj->count == 0)
        return;
    size_t len = strlen(text);
    for (int r = 0; r < 4 && len < size; ++r)
        len += (size_t)snprintf(text + len, size - len, "%s%s %s", r == 0 ? "\n    Force_StateEqn"
                                " partials: " : "; ", routine_names[r],
                                sj->exported[r] && sj->differenced[r] ? "the library's and by"
                                " differences of YFOSUB" : sj->exported[r] ? "the library's"
                                : "by differences of YFOSUB (not exported)");
}
