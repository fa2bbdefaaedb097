/* The dynamics' model and data, and one evaluation (dynamics.h). */
#include "sim/dynamics/dynamics.h"
#include "host/variable_values.h"
#include "sim/dynamics/algebraic_loop.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraint_matrix.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/redundancy.h"
#include "sim/dynamics/element_forces.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/joint_turns.h"
#include "sim/dynamics/implicit_diffs.h"
#include "sim/dynamics/loads.h"
#include "sim/dynamics/routines.h"
#include "sim/dynamics/stateeqns.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A force element's output axes are the world's for good: on ground, unturned. */
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
    d->world_aligned = calloc((size_t)nf + 1, 1);
    d->load_off = calloc((size_t)m->nloads + 1, 1);
    d->force_off = calloc((size_t)nf + 1, 1);
    d->gravity = malloc(3 * sizeof(double));
    if (!d->dof || !d->coupler_binding || !d->force_binding || !d->world_aligned ||
        !d->load_off || !d->force_off || !d->gravity)
        return hx_fail(msg, "out of memory");
    memcpy(d->gravity, m->gravity, 3 * sizeof(double));
    if (hx_bodies_init(d, msg) != 0 || hx_constraints_init(d, msg) != 0 ||
        hx_joint_turns_init(d, msg) != 0 || hx_stateeqns_init(d, msg) != 0 ||
        hx_routines_init(d, msg) != 0)
        return -1;
    d->load_work = d->motion_state_offset + d->nmotion_states;
    d->element_work = d->load_work + 1;
    d->n = d->element_work + 1;
    for (int k = 0; k < nc; ++k)
        d->coupler_binding[k] = hx_bindings_find(&s->bindings, HX_FAMILY_COUPLER, k);
    for (int k = 0; k < nf; ++k) {
        d->force_binding[k] = hx_bindings_find(&s->bindings, HX_FAMILY_FORCE, k);
        d->world_aligned[k] = (unsigned char)world_aligned(m, &m->forces[k]);
    }
    return 0;
}

/* The redundant rows, at the model's initial configuration and again where the
 * assembly takes it (redundancy.h). */
static int find_redundant(hx_dynamics *d, hx_message *msg)
{
    hx_dynamics_data dd;
    if (hx_dynamics_data_init(&dd, d, msg) != 0)
        return -1;
    double *y = malloc(sizeof(double) * ((size_t)d->n + 1));
    int status = -1;
    if (y == NULL)
        hx_fail(msg, "out of memory");
    else if (hx_dynamics_model_state(d, &dd, y) != 0)
        hx_fail(msg, "%s", dd.message);
    else if ((status = hx_redundancy_find(d, &dd, y, msg)) == 0)
        status = hx_redundancy_reassess(d, &dd, msg);
    free(y);
    hx_dynamics_data_free(&dd);
    return status;
}

int hx_dynamics_init(hx_dynamics *d, hx_session *s, hx_message *msg)
{
    memset(d, 0, sizeof *d);
    if (init_parts(d, s, msg) == 0 &&
        (d->nrows == 0 || (find_redundant(d, msg) == 0 && hx_constraint_matrix_plan(d, msg) == 0)))
        return 0;
    hx_dynamics_free(d);
    return -1;
}

void hx_dynamics_switch(const hx_dynamics *d, const unsigned char *flags)
{
    const int nloads = d->m->nloads;
    for (int k = 0; k < nloads; ++k)
        d->load_off[k] = flags != NULL ? flags[k] : 0;
    for (int k = 0; k < d->m->nforces; ++k)
        d->force_off[k] = flags != NULL ? flags[nloads + k] : 0;
}

void hx_dynamics_free(hx_dynamics *d)
{
    free(d->dof);
    free(d->coupler_binding);
    free(d->force_binding);
    free(d->world_aligned);
    free(d->load_off);
    free(d->force_off);
    free(d->gravity);
    free(d->turn_joint);
    free(d->turn_coupler);
    hx_constraints_free(d);
    hx_stateeqns_free(d);
    hx_routines_free(d);
    memset(d, 0, sizeof *d);
}

int hx_dynamics_data_init(hx_dynamics_data *dd, const hx_dynamics *d, hx_message *msg)
{
    memset(dd, 0, sizeof *dd);
    const hx_model *m = d->m;
    const size_t nb = (size_t)m->nbodies, nf = (size_t)m->nforces, nu = (size_t)d->nu;
    dd->force = calloc(3 * nb + 1, sizeof(double));
    dd->torque = calloc(3 * nb + 1, sizeof(double));
    dd->element_outputs = calloc(6 * nf + 1, sizeof(double));
    dd->element_load = calloc(6 * nf + 1, sizeof(double));
    dd->element_partials = calloc(72 * nf + 1, sizeof(double));
    dd->stateeqn_outputs = calloc(6 * (size_t)m->nstateeqns + 1, sizeof(double));
    dd->free_accelerations = calloc(nu + 1, sizeof(double));
    dd->lambda = calloc((size_t)d->nrows + 1, sizeof(double));
    dd->gcon_twist = calloc(6 * HX_CONSTRAINT_ROW_BLOCKS * (size_t)m->ngcons + 1, sizeof(double));
    dd->turn = calloc((size_t)m->njoints + (size_t)m->nloads + 1, sizeof(double));
    dd->turn_rate = calloc((size_t)m->njoints + (size_t)m->nloads + 1, sizeof(double));
    dd->constraint_work = calloc(hx_constraints_work_size(d), sizeof(double));
    dd->stateeqn_work = malloc(sizeof(double) * (size_t)hx_stateeqns_work_size(d));
    dd->implicit_start = calloc((size_t)d->nimplicit + 1, sizeof(double));
    dd->implicit_work = calloc(hx_implicit_diffs_work_size(d), sizeof(double));
    dd->loop_work = calloc(hx_algebraic_loop_work_size(d) + 1, sizeof(double));
    if (!dd->implicit_start || !dd->implicit_work || !dd->loop_work ||
        !dd->force || !dd->torque || !dd->element_outputs || !dd->element_load ||
        !dd->element_partials || !dd->stateeqn_outputs || !dd->free_accelerations ||
        !dd->lambda || !dd->gcon_twist || !dd->turn || !dd->turn_rate || !dd->constraint_work ||
        !dd->stateeqn_work ||
        hx_frames_clone(&dd->frames, &d->s->frames) != 0 ||
        hx_frames_clone(&dd->moved, &d->s->frames) != 0) {
        hx_dynamics_data_free(dd);
        return hx_fail(msg, "out of memory");
    }
    hx_joint_turns_placed(d, dd);
    hx_implicit_diffs_restart(d, dd);
    return 0;
}

void hx_dynamics_data_free(hx_dynamics_data *dd)
{
    free(dd->force);
    free(dd->torque);
    free(dd->element_outputs);
    free(dd->element_load);
    free(dd->element_partials);
    free(dd->stateeqn_outputs);
    free(dd->free_accelerations);
    free(dd->lambda);
    free(dd->gcon_twist);
    free(dd->turn);
    free(dd->turn_rate);
    free(dd->constraint_work);
    free(dd->stateeqn_work);
    free(dd->implicit_start);
    free(dd->implicit_work);
    free(dd->loop_work);
    hx_frames_free(&dd->frames);
    hx_frames_free(&dd->moved);
    memset(dd, 0, sizeof *dd);
}

void hx_dynamics_kinematics(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                            const double *y)
{
    dd->frames.time = t;
    hx_bodies_set_frames(d, dd, y);
    hx_routines_set_state(d, dd, y);
    hx_frames_update(&dd->frames);
}

int hx_dynamics_stages(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                       double *ydot, unsigned ask)
{
    const int nb = d->m->nbodies;
    if (d->m->variables_read) { /* the variables the loads read, each once */
        hx_message msg;
        if (hx_variables_values(&dd->frames, d->routine_binding, dd->frames.variables, &msg) != 0)
            return hx_dynamics_fail(dd, "%s", msg.text);
    }
    memset(dd->force, 0, sizeof(double) * 3 * (size_t)nb);
    memset(dd->torque, 0, sizeof(double) * 3 * (size_t)nb);
    if (hx_loads_apply(d, dd, &ydot[d->load_work]) != 0 ||
        hx_element_forces_apply(d, dd, (ask & HX_EVALUATE_PARTIALS) != 0,
                                &ydot[d->element_work]) != 0 ||
        hx_stateeqns_apply(d, dd, y, ydot) != 0)
        return -1;
    hx_bodies_accelerations(d, dd, y, ydot);
    if (d->nrows > 0) {
        memcpy(dd->free_accelerations, ydot + d->nq, sizeof(double) * (size_t)d->nu);
        if (hx_constraints_apply(d, dd, t, y, ydot + d->nq, &ydot[d->load_work]) != 0)
            return -1;
    }
    return 0;
}

int hx_dynamics_evaluate(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                         double *ydot, unsigned ask)
{
    hx_dynamics_kinematics(d, dd, t, y);
    if (d->m->nloop_inputs > 0 ? hx_algebraic_loop_solve(d, dd, t, y, ydot, ask) != 0
                               : hx_dynamics_stages(d, dd, t, y, ydot, ask) != 0)
        return -1;
    if (d->m->nroutines > 0 && hx_routines_apply(d, dd, y, ydot) != 0)
        return -1;
    return 0;
}

int hx_dynamics_rhs(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                    double *ydot)
{
    return hx_dynamics_evaluate(d, dd, t, y, ydot, 0);
}

int hx_dynamics_model_state(const hx_dynamics *d, hx_dynamics_data *dd, double *y)
{
    memset(y, 0, sizeof(double) * (size_t)d->n);
    hx_bodies_initial_state(d, y);
    hx_stateeqns_initial(d, y);
    return hx_routines_initial(d, dd, y);
}

int hx_dynamics_initial_state(const hx_dynamics *d, hx_dynamics_data *dd, double *y)
{
    if (hx_dynamics_model_state(d, dd, y) != 0)
        return -1;
    if (d->assembled_q != NULL) /* where the set-up found the redundant rows it keeps */
        memcpy(y, d->assembled_q, sizeof(double) * (size_t)d->nq);
    dd->max_phi = dd->max_phidot = 0.0;
    return hx_constraints_project(d, dd, 0.0, y);
}

int hx_dynamics_initial_y(const hx_dynamics *d, double *y, hx_message *msg)
{
    hx_dynamics_data dd;
    if (hx_dynamics_data_init(&dd, d, msg) != 0)
        return -1;
    const int status = hx_dynamics_initial_state(d, &dd, y);
    if (status != 0)
        hx_fail(msg, "%s", dd.message);
    hx_dynamics_data_free(&dd);
    return status;
}

void hx_constraint_row_sort(hx_constraint_row *r)
{
    for (int a = 1; a < r->nblocks; ++a)
        for (int b = a; b > 0 && r->u[b - 1] > r->u[b]; --b) {
            int t;
            t = r->u[b], r->u[b] = r->u[b - 1], r->u[b - 1] = t;
            t = r->width[b], r->width[b] = r->width[b - 1], r->width[b - 1] = t;
            t = r->slot[b], r->slot[b] = r->slot[b - 1], r->slot[b - 1] = t;
            t = r->body[b], r->body[b] = r->body[b - 1], r->body[b - 1] = t;
        }
}
