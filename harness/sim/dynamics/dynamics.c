/* The right-hand side and its set-up (dynamics.h). */
#include "sim/dynamics/dynamics.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/element_forces.h"
#include "sim/dynamics/loads.h"
#include "sim/dynamics/routines.h"
#include "sim/dynamics/stateeqns.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A force element's result axes are the world's for good: on ground, unturned. */
static int world_aligned(const hx_model *m, const hx_force *f)
{
    const int axes = hx_force_output_axes(f);
    if (axes < 0)
        return 1;
    if (!m->bodies[m->markers[axes].body].is_ground)
        return 0;
    for (int i = 0; i < 9; ++i)
        if (m->markers[axes].R0[i] != (i % 4 == 0 ? 1.0 : 0.0))
            return 0;
    return 1;
}

/* hx_dynamics_init's work; on failure what it took is left for the caller. */
static int init_parts(hx_dynamics *d, hx_session *s, hx_message *msg)
{
    d->s = s;
    d->m = s->model;
    const hx_model *m = d->m;
    if (m->nunsimulated > 0)
        return hx_fail(msg, "the model has %d element%s the harness does not simulate (the first:"
                       " %s): its dynamics would not be the model's; check can still verify its"
                       " user elements", m->nunsimulated, m->nunsimulated == 1 ? "" : "s",
                       m->unsimulated);
    const double *u = m->unit_scales;
    d->ucf = m->has_units ? u[HX_UNIT_TIME] * u[HX_UNIT_TIME] * u[HX_UNIT_FORCE] /
                                (u[HX_UNIT_MASS] * u[HX_UNIT_LENGTH])
                          : 1.0;
    const int nb = m->nbodies, nc = m->ncouplers, nf = m->nforces;
    d->dof = calloc((size_t)nb + 1, sizeof *d->dof);
    d->coupler_binding = calloc((size_t)nc + 1, sizeof *d->coupler_binding);
    d->force_binding = calloc((size_t)nf + 1, sizeof *d->force_binding);
    d->lambda = calloc((size_t)nc + 1, sizeof *d->lambda);
    d->element_load = calloc(6 * (size_t)nf + 1, sizeof *d->element_load);
    d->world_aligned = calloc((size_t)nf + 1, 1);
    d->force = calloc(3 * (size_t)nb + 1, sizeof *d->force);
    d->torque = calloc(3 * (size_t)nb + 1, sizeof *d->torque);
    d->element_outputs = calloc(6 * (size_t)nf + 1, sizeof(double));
    d->element_partials = calloc(72 * (size_t)nf + 1, sizeof(double));
    if (!d->dof || !d->coupler_binding || !d->force_binding || !d->lambda || !d->element_load ||
        !d->world_aligned || !d->force || !d->torque || !d->element_outputs ||
        !d->element_partials || hx_frames_clone(&d->frames, &s->frames) != 0 ||
        hx_frames_clone(&d->probe, &s->frames) != 0)
        return hx_fail(msg, "out of memory");
    if (hx_bodies_init(d, msg) != 0 || hx_stateeqns_init(d, msg) != 0 ||
        hx_routines_init(d, msg) != 0)
        return -1;
    d->load_work = d->diffs + d->ndiffs;
    d->element_work = d->load_work + 1;
    d->n = d->element_work + 1;
    d->free_accelerations = calloc((size_t)d->nu + 1, sizeof(double));
    d->evaluated_y = calloc((size_t)d->n, sizeof(double));
    if (d->free_accelerations == NULL || d->evaluated_y == NULL)
        return hx_fail(msg, "out of memory");
    /* scratch: G (nc x nu), A (nc x nc), several vectors of nu and nc */
    d->scratch = calloc((size_t)(nc * d->nu + nc * nc + 6 * (d->nu + nc) + 16), sizeof(double));
    if (d->scratch == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < nc; ++k)
        d->coupler_binding[k] = hx_binding_of_coupler(&s->bindings, k);
    for (int k = 0; k < nf; ++k) {
        d->force_binding[k] = hx_binding_of_force(&s->bindings, k);
        d->world_aligned[k] = (unsigned char)world_aligned(m, &m->forces[k]);
    }
    return 0;
}

int hx_dynamics_init(hx_dynamics *d, hx_session *s, hx_message *msg)
{
    memset(d, 0, sizeof *d);
    if (init_parts(d, s, msg) == 0)
        return 0;
    hx_dynamics_free(d);
    return -1;
}

void hx_dynamics_free(hx_dynamics *d)
{
    free(d->dof);
    free(d->coupler_binding);
    free(d->force_binding);
    free(d->lambda);
    free(d->element_load);
    free(d->world_aligned);
    free(d->force);
    free(d->torque);
    free(d->scratch);
    free(d->element_outputs);
    free(d->element_partials);
    free(d->free_accelerations);
    free(d->evaluated_y);
    hx_stateeqns_free(d);
    hx_routines_free(d);
    hx_frames_free(&d->frames);
    hx_frames_free(&d->probe);
    memset(d, 0, sizeof *d);
}

void hx_dynamics_set_state(hx_dynamics *d, double t, const double *y)
{
    d->evaluated = 0;
    d->frames.time = t;
    hx_bodies_set_frames(d, y);
    hx_routines_set_state(d, y);
    hx_frames_update(&d->frames);
}

int hx_dynamics_rhs(hx_dynamics *d, double t, const double *y, double *ydot)
{
    const int nb = d->m->nbodies;
    hx_dynamics_set_state(d, t, y);
    memset(d->force, 0, sizeof(double) * 3 * (size_t)nb);
    memset(d->torque, 0, sizeof(double) * 3 * (size_t)nb);
    ydot[d->load_work] = hx_loads_apply(d, t);
    if (hx_element_forces_apply(d, &ydot[d->element_work]) != 0 ||
        hx_stateeqns_apply(d, y, ydot) != 0)
        return -1;
    hx_bodies_accelerations(d, y, ydot);
    if (d->m->ncouplers > 0) {
        memcpy(d->free_accelerations, ydot + d->nq, sizeof(double) * (size_t)d->nu);
        if (hx_constraints_apply(d, t, y, ydot + d->nq) != 0)
            return -1;
    }
    if (d->m->nroutines > 0 && hx_routines_apply(d, y, ydot) != 0)
        return -1;
    memcpy(d->evaluated_y, y, sizeof(double) * (size_t)d->n);
    d->evaluated_t = t;
    d->evaluated = 1;
    return 0;
}

int hx_dynamics_initial_state(hx_dynamics *d, double *y)
{
    memset(y, 0, sizeof(double) * (size_t)d->n);
    hx_bodies_initial_state(d, y);
    hx_stateeqns_initial(d, y);
    if (hx_routines_initial(d, y) != 0)
        return -1;
    d->max_phi = d->max_phidot = 0.0;
    return hx_constraints_project(d, 0.0, y);
}
