/* The algebraic loop solved at a right-hand side (algebraic_loop.h). */
#include "sim/dynamics/algebraic_loop.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/difference_step.h"
#include "base/linalg.h"
#include "expr/evaluate.h"
#include "model/expr/functions.h"
#include "model/loop_inputs.h"
#include "sim/dynamics/accelerations.h"
#include "sim/dynamics/constraint_forces.h"
#include "sim/dynamics/element_outputs.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/loads.h"
#include "sim/dynamics/reactions.h"
#include "sim/dynamics/routines.h"

/* Forward differences of g: sqrt(DBL_EPSILON) of a value, absolute below 1. */
#define LOOP_STEP 1.5e-8

size_t hx_algebraic_loop_work_size(const hx_dynamics *d)
{
    const hx_model *m = d->m;
    const size_t nz = (size_t)m->nloop_inputs;
    if (nz == 0)
        return 0;
    /* z, g(z), g moved, the step; I - dg/dz and its copy the solve takes; the
     * outputs g reads z back from and the driven bodies' free accelerations */
    return 4 * nz + 2 * nz * nz + 6 * (size_t)m->nbodies + 6 * (size_t)m->njoints +
           12 * (size_t)m->nloads + 12 * (size_t)m->nforces + hx_constraint_forces_size(d) +
           (size_t)m->nbodies;
}

/* Which outputs the loop's inputs read beyond the accelerations: every one
 * for a force at a marker (it sums them all), else those their functions
 * name (a joint's reaction and an expression load each alone, below). */
typedef struct loop_reads {
    int all, users, constraints;
} loop_reads;

/* What loop input li reads: its program's input, or a user routine's query. */
static const hx_expr_input *input_of(const hx_loop_input *li)
{
    return li->program != NULL ? &hx_expr_inputs(li->program)[li->input] : &li->query;
}

static loop_reads reads_of(const hx_model *m)
{
    loop_reads r = {0, 0, 0};
    for (int i = 0; i < m->nloop_inputs; ++i) {
        const hx_expr_input *in = input_of(&m->loop_inputs[i]);
        r.all |= in->kind == HX_EXPR_INPUT_MARKER_FORCE;
        r.users |= in->kind == HX_EXPR_INPUT_LOAD && in->index[1];
        r.constraints |= in->kind == HX_EXPR_INPUT_REACTION && in->function != HX_FN_JOINT &&
                         in->function != HX_FN_JPRIM;
    }
    return r;
}

/* The driven bodies' accelerations into ydot, their free ones kept in
 * free_udot (restore = 0), or put back (restore = 1): the routines stage
 * sets the drives' after the loop (routines.h) and takes the drive's power
 * from the free one, but what the loop reads (a driven body's acceleration,
 * its joint's reaction, the motion's force) is at the drive's. 0 or -1. */
static int driven(const hx_dynamics *d, hx_dynamics_data *dd, double *ydot, double *free_udot,
                  int restore)
{
    for (int body = 0; body < d->m->nbodies; ++body) {
        const int k = d->driver[body];
        if (k < 0)
            continue;
        double *udot = &ydot[d->nq + d->dof[body].u];
        if (restore) {
            *udot = free_udot[body];
            continue;
        }
        free_udot[body] = *udot;
        const char type = d->m->routines[k].val_type; /* the iord of the acceleration */
        if (hx_routines_motion(d, dd, k, type == 'D' ? 2 : type == 'V' ? 1 : 0, udot) != 0)
            return -1;
    }
    return 0;
}

/* g(z) from the stages' evaluation: the outputs the inputs read, and each
 * input's value. */
static int loop_values(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                       const double *ydot, double *accelerations, double *gz)
{
    const hx_model *m = d->m;
    const int nz = m->nloop_inputs;
    double *reactions = accelerations + 6 * m->nbodies, *loads = reactions + 6 * m->njoints;
    double *forces = loads + 12 * m->nloads, *constraints = forces + 12 * m->nforces;
    hx_accelerations_bodies(d, dd, ydot, accelerations);
    const loop_reads r = reads_of(m);
    hx_message msg;
    if (r.all) {
        hx_reactions_all(d, dd, ydot, reactions);
        if (hx_element_outputs_loads(d, dd, loads, &msg) != 0)
            return hx_dynamics_fail(dd, "%s", msg.text);
    }
    if (r.all || r.users)
        hx_element_outputs_forces(d, dd, forces);
    if ((r.all || r.constraints) &&
        hx_constraint_forces_all(d, dd, t, y, ydot, constraints) != 0)
        return -1;
    const hx_expr_outputs outputs = {reactions, accelerations, loads, forces, constraints};
    const hx_expr_context c = {&dd->frames, dd->frames.variables, &outputs};
    for (int i = 0; i < nz; ++i) {
        const hx_loop_input *li = &m->loop_inputs[i];
        hx_expr_fault fault;
        const hx_expr_input *in = input_of(li);
        const int joint = in->function == HX_FN_JOINT || in->function == HX_FN_JPRIM;
        if (!r.all && in->kind == HX_EXPR_INPUT_REACTION && joint)
            hx_reactions_joint(d, dd, ydot, in->index[0], reactions + 6 * in->index[0]);
        else if (!r.all && in->kind == HX_EXPR_INPUT_LOAD && !in->index[1] &&
                 hx_loads_output(d, dd, in->index[0], loads + 12 * in->index[0], &msg) != 0)
            return hx_dynamics_fail(dd, "%s", msg.text);
        if (li->program == NULL) { /* a user routine's query (host/loop_queries.h) */
            if (hx_expr_query_value(&c, in, &gz[i], &fault) != 0)
                return hx_dynamics_fail(dd, "%s of %s: %s", li->text, li->element, fault.what);
            continue;
        }
        if (hx_expr_input_value(li->program, &c, li->input, &gz[i], &fault) != 0) {
            hx_expr_fail(&msg, li->program, &fault, li->element);
            return hx_dynamics_fail(dd, "%s", msg.text);
        }
    }
    return 0;
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
    double *free_udot = accelerations + 6 * m->nbodies + 6 * m->njoints + 12 * m->nloads +
                        12 * m->nforces + hx_constraint_forces_size(d);
    if (driven(d, dd, ydot, free_udot, 0) != 0)
        return -1;
    const int status = loop_values(d, dd, t, y, ydot, accelerations, gz);
    driven(d, dd, ydot, free_udot, 1);
    return status;
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
