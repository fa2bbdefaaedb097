/* The implicit Control_Diff elements by expression (implicit_diffs.h). */
#include "sim/dynamics/implicit_diffs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/linalg.h"
#include "expr/evaluate.h"
#include "model/expr/program.h"
#include "sim/dynamics/failure.h"

/* Newton's iterations before it is given up, and its step small enough to
 * stop at (relative to 1 + |rate|): past quadratic convergence, the rates
 * are then exact to rounding. */
#define NEWTON_ITERATIONS 50
#define NEWTON_STEP 1e-10

int hx_implicit_diffs_init(hx_dynamics *d, hx_message *msg)
{
    const hx_model *m = d->m;
    d->nimplicit = 0;
    d->implicit = malloc(sizeof(int) * ((size_t)m->nroutines + 1));
    d->implicit_of_slot = malloc(sizeof(int) * ((size_t)d->ndiffs + 1));
    if (d->implicit == NULL || d->implicit_of_slot == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < d->ndiffs; ++k)
        d->implicit_of_slot[k] = -1;
    size_t scratch = 1;
    for (int k = 0; k < m->nroutines; ++k) {
        const hx_routine *r = &m->routines[k];
        if (r->kind != HX_ROUTINE_DIFF || !r->implicit || r->program == NULL)
            continue;
        d->implicit_of_slot[r->slot] = d->nimplicit;
        d->implicit[d->nimplicit++] = k;
        if (hx_expr_scratch_size(r->program) > scratch)
            scratch = hx_expr_scratch_size(r->program);
    }
    const size_t n = (size_t)d->nimplicit;
    d->implicit_work = n == 0 ? 0 : 3 * n + n * n + HX_EXPR_MAX_INPUTS + scratch;
    return 0;
}

void hx_implicit_diffs_free(hx_dynamics *d)
{
    free(d->implicit);
    free(d->implicit_of_slot);
}

size_t hx_implicit_diffs_work_size(const hx_dynamics *d)
{
    return d->implicit_work + 1;
}

void hx_implicit_diffs_restart(const hx_dynamics *d, hx_dynamics_data *dd)
{
    for (int i = 0; i < d->nimplicit; ++i) {
        const hx_routine *r = &d->m->routines[d->implicit[i]];
        dd->implicit_start[i] = r->ic_given[1] ? r->ic[1] : 0.0;
    }
}

/* The rates of dd->frames into to. */
static void rates_into(const hx_dynamics *d, const hx_dynamics_data *dd, double *to)
{
    for (int i = 0; i < d->nimplicit; ++i)
        to[i] = dd->frames.diffs[2 * d->m->routines[d->implicit[i]].slot + 1];
}

void hx_implicit_diffs_keep(const hx_dynamics *d, hx_dynamics_data *dd)
{
    rates_into(d, dd, dd->implicit_start);
}

/* The residuals F at the rates x (set into dd->frames) and their partials J
 * in the rates (row i: residual i; column j: the rate of d->implicit[j]). */
static int residuals(const hx_dynamics *d, hx_dynamics_data *dd, const double *x, double *F,
                     double *J, double *partials, double *scratch)
{
    const int n = d->nimplicit;
    for (int i = 0; i < n; ++i)
        dd->frames.diffs[2 * d->m->routines[d->implicit[i]].slot + 1] = x[i];
    const hx_expr_context c = {&dd->frames, dd->frames.variables, NULL};
    for (int i = 0; i < n; ++i) {
        const hx_routine *r = &d->m->routines[d->implicit[i]];
        hx_expr_fault fault;
        if (hx_expr_eval_partials(r->program, &c, &F[i], partials, scratch, &fault) != 0) {
            char element[48];
            hx_message msg;
            snprintf(element, sizeof element, "Control_Diff %d", r->id);
            hx_expr_fail(&msg, r->program, &fault, element);
            return hx_dynamics_fail(dd, "%s", msg.text);
        }
        for (int j = 0; j < n; ++j)
            J[i * n + j] = 0.0;
        const hx_expr_input *in = hx_expr_inputs(r->program);
        for (int j = 0; j < hx_expr_input_count(r->program); ++j)
            if (in[j].kind == HX_EXPR_INPUT_DIF1 && d->implicit_of_slot[in[j].index[0]] >= 0)
                J[i * n + d->implicit_of_slot[in[j].index[0]]] += partials[j];
    }
    return 0;
}

/* The implicit element whose residual is the largest at F. */
static int worst(const double *F, int n)
{
    int w = 0;
    for (int i = 1; i < n; ++i)
        if (!(fabs(F[i]) <= fabs(F[w])))
            w = i;
    return w;
}

int hx_implicit_diffs_solve(const hx_dynamics *d, hx_dynamics_data *dd, double *ydot)
{
    const int n = d->nimplicit;
    if (n == 0)
        return 0;
    const hx_model *m = d->m;
    double *x = dd->implicit_work, *F = x + n, *step = F + n, *J = step + n,
           *partials = J + n * n, *scratch = partials + HX_EXPR_MAX_INPUTS;
    for (int i = 0; i < n; ++i)
        x[i] = dd->implicit_start[i];
    for (int it = 0; it < NEWTON_ITERATIONS; ++it) {
        if (residuals(d, dd, x, F, J, partials, scratch) != 0)
            return -1;
        for (int i = 0; i < n; ++i)
            step[i] = -F[i];
        if (hx_solve(n, J, step) != 0) {
            const hx_routine *r = &m->routines[d->implicit[worst(F, n)]];
            return hx_dynamics_fail(dd, "%s:%d: Control_Diff %d: is_implicit: dF/dDIF1, the"
                                    " residual's partials in the implicit rates, is singular at"
                                    " t = %.9g (residual %.6g at DIF1(%d) = %.9g): the rate is"
                                    " not defined by the residual there", m->path, r->line,
                                    r->id, dd->frames.time, F[worst(F, n)], r->id,
                                    x[worst(F, n)]);
        }
        int small = 1;
        for (int i = 0; i < n; ++i) {
            x[i] += step[i];
            small &= isfinite(x[i]) && fabs(step[i]) <= NEWTON_STEP * (1.0 + fabs(x[i]));
        }
        if (small) {
            for (int i = 0; i < n; ++i) {
                const int slot = m->routines[d->implicit[i]].slot;
                dd->frames.diffs[2 * slot + 1] = x[i];
                if (ydot != NULL)
                    ydot[d->diff_offset + slot] = x[i];
            }
            return 0;
        }
    }
    const int w = worst(F, n);
    const hx_routine *r = &m->routines[d->implicit[w]];
    return hx_dynamics_fail(dd, "%s:%d: Control_Diff %d: is_implicit: Newton's method on the"
                            " residual did not converge in %d iterations at t = %.9g (residual"
                            " %.6g at DIF1(%d) = %.9g)", m->path, r->line, r->id,
                            NEWTON_ITERATIONS, dd->frames.time, F[w], r->id, x[w]);
}
