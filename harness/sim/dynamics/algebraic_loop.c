/* The algebraic loop solved at a right-hand side (algebraic_loop.h). */
#include "sim/dynamics/algebraic_loop.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/difference_step.h"
#include "base/linalg.h"
#include "expr/evaluate.h"
#include "model/loop_inputs.h"
#include "sim/dynamics/accelerations.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/loads.h"
#include "sim/dynamics/reactions.h"

/* Forward differences of g: sqrt(DBL_EPSILON) of a value, absolute below 1. */
#define LOOP_STEP 1.5e-8

size_t hx_algebraic_loop_work_size(const hx_dynamics *d)
{
    const hx_model *m = d->m;
    const size_t nz = (size_t)m->nloop_inputs;
    if (nz == 0)
        return 0;
    /* z, g(z), g moved, the step; I - dg/dz and its copy the solve takes; the
     * outputs g reads z back from */
    return 4 * nz + 2 * nz * nz + 6 * (size_t)m->nbodies + 6 * (size_t)m->njoints +
           12 * (size_t)m->nloads;
}

/* g(z) into gz: the stages with the loads reading z, then z read back. */
static int loop_g(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                  double *ydot, unsigned ask, const double *z, double *gz)
{
    const hx_model *m = d->m;
    const int nz = m->nloop_inputs;
    memcpy(dd->frames.loop, z, sizeof(double) * (size_t)nz);
    if (hx_dynamics_stages(d, dd, t, y, ydot, ask) != 0)
        return -1;
    double *accelerations = dd->loop_work + 4 * nz + 2 * nz * nz;
    double *reactions = accelerations + 6 * m->nbodies, *loads = reactions + 6 * m->njoints;
    hx_accelerations_bodies(d, dd, ydot, accelerations);
    /* a loop reads an SFORCE by expression alone (model/expr/link.c): no user forces */
    const hx_expr_outputs outputs = {reactions, accelerations, loads, NULL, NULL};
    const hx_expr_context c = {&dd->frames, dd->frames.variables, &outputs};
    for (int i = 0; i < nz; ++i) {
        const hx_loop_input *li = &m->loop_inputs[i];
        hx_expr_fault fault;
        if (li->program == NULL) { /* a user routine's acceleration (host/loop_queries.h) */
            if (hx_expr_acceleration_value(&c, &li->query, &gz[i], &fault) != 0)
                return hx_dynamics_fail(dd, "%s of %s: %s", li->text, li->element, fault.what);
            continue;
        }
        const hx_expr_input *in = &hx_expr_inputs(li->program)[li->input];
        hx_message msg;
        if (in->kind == HX_EXPR_INPUT_REACTION)
            hx_reactions_joint(d, dd, ydot, in->index[0], reactions + 6 * in->index[0]);
        else if (in->kind == HX_EXPR_INPUT_LOAD &&
                 hx_loads_output(d, dd, in->index[0], loads + 12 * in->index[0], &msg) != 0)
            return hx_dynamics_fail(dd, "%s", msg.text);
        if (hx_expr_input_value(li->program, &c, li->input, &gz[i], &fault) != 0) {
            hx_expr_fail(&msg, li->program, &fault, li->element);
            return hx_dynamics_fail(dd, "%s", msg.text);
        }
    }
    return 0;
}

/* The loop's failure: its inputs named, why, and the residual left. */
static int loop_fail(const hx_dynamics *d, hx_dynamics_data *dd, double t, const char *why,
                     double residual)
{
    const hx_model *m = d->m;
    char names[600];
    size_t len = 0;
    names[0] = '\0';
    for (int i = 0; i < m->nloop_inputs && len + 1 < sizeof names; ++i) {
        char one[160];
        const int n = snprintf(names + len, sizeof names - len, "%s%s", i ? ", " : "",
                               hx_loop_input_text(m, i, one, sizeof one));
        len += n > 0 ? (size_t)n : 0;
    }
    return hx_dynamics_fail(dd, "the algebraic loop of %s at t = %.6g: %s (residual %.3g)",
                            names, t, why, residual);
}

int hx_algebraic_loop_solve(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                            const double *y, double *ydot, unsigned ask)
{
    const int nz = d->m->nloop_inputs;
    double *z = dd->loop_work, *gz = z + nz, *moved = gz + nz, *step = moved + nz;
    double *matrix = step + nz, *solved = matrix + nz * nz;
    for (int i = 0; i < nz; ++i)
        z[i] = 0.0;
    double previous = 0.0;
    for (int iteration = 0;; ++iteration) {
        if (loop_g(d, dd, t, y, ydot, ask, z, gz) != 0)
            return -1;
        double residual = 0.0;
        for (int i = 0; i < nz; ++i) {
            step[i] = gz[i] - z[i]; /* -(z - g(z)) */
            residual = fmax(residual, fabs(step[i]));
        }
        if (residual <= HX_LOOP_RTOL * fmax(hx_max_abs(z, nz), 1.0))
            return 0; /* dd and ydot are the stages' at z */
        if (!(residual < 1e300) || iteration == HX_LOOP_ITERATIONS)
            return loop_fail(d, dd, t, "Newton's method does not converge", residual);
        /* the matrix at the first iterate, and again only when a step with it
         * did not take the residual below a tenth (a loop linear in z keeps it) */
        if (iteration == 0 || residual > 0.1 * previous)
            for (int j = 0; j < nz; ++j) {
                const double zj = z[j], h = hx_difference_step(zj, LOOP_STEP, 1.0);
                z[j] = zj + h;
                const int status = loop_g(d, dd, t, y, ydot, ask, z, moved);
                z[j] = zj;
                if (status != 0)
                    return -1;
                for (int i = 0; i < nz; ++i)
                    matrix[i * nz + j] = (i == j) - (moved[i] - gz[i]) / h;
            }
        previous = residual;
        memcpy(solved, matrix, sizeof(double) * (size_t)nz * (size_t)nz);
        if (hx_solve_pivot(nz, solved, step, HX_LOOP_MIN_PIVOT) != 0)
            return loop_fail(d, dd, t, "it has no solution (its matrix I - dg/dz is singular:"
                             " the stages' answer does not fix the values the loads read)",
                             residual);
        for (int i = 0; i < nz; ++i)
            z[i] += step[i];
    }
}
