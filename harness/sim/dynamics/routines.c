/* The user routines that are not forces in the equations of motion (routines.h). */
#include "expr/evaluate.h"
#include "expr/time_derivative.h"
#include "host/invoke.h"
#include "host/variable_values.h"
#include "sim/dynamics/coordinate_rows.h"
#include "sim/dynamics/routines.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/implicit_diffs.h"
#include "sim/dynamics/joint_coordinate.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int hx_routines_init(hx_dynamics *d, hx_message *msg)
{
    const hx_model *m = d->m;
    d->ndiffs = m->nroutines_of[HX_ROUTINE_DIFF];
    d->diff_offset = d->stateeqn_offset + d->nstates;
    d->routine_binding = calloc((size_t)m->nroutines + 1, sizeof *d->routine_binding);
    d->driver = calloc((size_t)m->nbodies + 1, sizeof *d->driver);
    if (d->routine_binding == NULL || d->driver == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < m->nbodies; ++k)
        d->driver[k] = -1;
    for (int k = 0; k < m->nroutines; ++k) {
        const hx_routine *r = &m->routines[k];
        d->routine_binding[k] =
            r->program != NULL ? NULL : hx_bindings_find(&d->s->bindings, HX_FAMILY_ROUTINE, k);
        d->diffs_read_variables |= r->reads_variables;
        if (r->kind == HX_ROUTINE_DIFF && r->implicit && r->program == NULL)
            return hx_fail(msg, "%s:%d: Control_Diff %d: is_implicit=\"TRUE\" with DIFSUB: the"
                           " harness runs an implicit Control_Diff by expression only (how a"
                           " solver calls DIFSUB for a residual is not documented; check"
                           " verifies this one)", m->path, r->line, r->id);
        if (r->kind != HX_ROUTINE_MOTION)
            continue;
        /* the joint carries its I marker's body (model/resolve.c); any other joint's
         * motion is a row of the constraint system (constraints.c) */
        const int body = m->markers[m->joints[r->joint].i_marker].body;
        for (int c = 0; c < m->ncouplers; ++c)
            for (int j = 0; j < m->couplers[c].njoints; ++j)
                if (m->couplers[c].joint[j] == r->joint)
                    return hx_fail(msg, "%s:%d: Motion_Joint %d drives joint %d, which"
                                   " Constraint_Coupler %d couples: the harness does not run"
                                   " a motion on a coupled joint", m->path, r->line, r->id,
                                   r->joint_id, m->couplers[c].id);
        if (m->joints[r->joint].reduced)
            d->driver[body] = k;
    }
    /* an acceleration motion between bodies: its displacement and velocity are states
     * after the Control_Diff states (docs/architecture.md, the constraint system) */
    d->motion_state_offset = d->diff_offset + d->ndiffs;
    d->nmotion_states = 0;
    d->motion_state = malloc(sizeof(int) * ((size_t)d->nmotions + 1));
    if (d->motion_state == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < d->nmotions; ++k) {
        d->motion_state[k] = -1;
        if (m->routines[d->motion_routine[k]].val_type == 'A') {
            d->motion_state[k] = d->motion_state_offset + d->nmotion_states;
            d->nmotion_states += 2;
        }
    }
    return hx_implicit_diffs_init(d, msg);
}

void hx_routines_free(hx_dynamics *d)
{
    hx_implicit_diffs_free(d);
    free(d->routine_binding);
    free(d->driver);
    free(d->motion_state);
}

void hx_routines_set_state(const hx_dynamics *d, hx_dynamics_data *dd, const double *y)
{
    for (int k = 0; k < d->ndiffs; ++k)
        dd->frames.diffs[2 * k] = y[d->diff_offset + k];
}

int hx_routines_motion(const hx_dynamics *d, hx_dynamics_data *dd, int k, int iord,
                       double *value)
{
    static const char *const what[3] = {"value (iord 0)", "rate (iord 1)",
                                         "acceleration (iord 2)"};
    const hx_routine *r = &d->m->routines[k];
    if (r->program != NULL) { /* by expression: f, f' exact, f'' by differences of f' */
        hx_expr_fault fault;
        if (hx_time_derivative_eval(r->program, &dd->frames, iord, value, &fault) == 0)
            return 0;
        char element[48];
        hx_message msg;
        snprintf(element, sizeof element, "Motion_Joint %d", r->id);
        hx_expr_fail(&msg, r->program, &fault, element);
        return hx_dynamics_fail(dd, "%s", msg.text);
    }
    hx_binding *b = d->routine_binding[k];
    hx_invoke_routine(b, &dd->frames, iord, 0, value, NULL);
    return hx_dynamics_check_call(d, dd, b, value, 1, what[iord], dd->frames.time);
}

int hx_routines_initial(const hx_dynamics *d, hx_dynamics_data *dd, double *y)
{
    const hx_model *m = d->m;
    for (int k = 0; k < m->nroutines; ++k) {
        const hx_routine *r = &m->routines[k];
        if (r->kind != HX_ROUTINE_DIFF)
            continue;
        y[d->diff_offset + r->slot] = r->ic[0];
        /* what DIF and DIF1 answer a MOTSUB called below, and any call before
         * the first right-hand side */
        dd->frames.diffs[2 * r->slot] = r->ic[0];
        dd->frames.diffs[2 * r->slot + 1] = r->ic[1];
    }
    hx_implicit_diffs_restart(d, dd); /* a run's start: Newton from ic_dot, or 0 */
    dd->frames.time = 0.0;
    for (int body = 0; body < m->nbodies; ++body) {
        const int k = d->driver[body];
        if (k < 0)
            continue;
        const hx_routine *r = &m->routines[k];
        double *q = &y[d->dof[body].q], *u = &y[d->nq + d->dof[body].u];
        /* an initial value not written stays the model's (hx_bodies_initial_state) */
        if (r->ic_given[0])
            *q = r->ic[0];
        if (r->ic_given[1])
            *u = r->ic[1];
        if ((r->val_type == 'D' && (hx_routines_motion(d, dd, k, 0, q) != 0 || hx_routines_motion(d, dd, k, 1, u) != 0)) ||
            (r->val_type == 'V' && hx_routines_motion(d, dd, k, 0, u) != 0))
            return -1;
    }
    /* an acceleration motion between bodies starts at ic_disp and ic_vel, or where the
     * model places its joint and at the rate the bodies' initial velocities give it */
    for (int k = 0; k < d->nmotions; ++k) {
        const int at = d->motion_state[k];
        if (at < 0)
            continue;
        const hx_routine *r = &m->routines[d->motion_routine[k]];
        double value;
        hx_joint_coordinate_near(d, r->joint, r->motion_type, y, 0.0, &value, NULL, NULL);
        y[at] = r->ic_given[0] ? r->ic[0] : value;
        y[at + 1] = r->ic_given[1] ? r->ic[1]
                                   : hx_coordinate_rows_joint_rate(d, r->joint, r->motion_type, y);
    }
    return 0;
}

int hx_routines_diff_expression(const hx_dynamics *d, hx_dynamics_data *dd, int k, double *rate)
{
    const hx_routine *r = &d->m->routines[k];
    const hx_expr_context c = {&dd->frames, dd->frames.variables, NULL};
    hx_expr_fault fault;
    if (hx_expr_eval(r->program, &c, rate, &fault) == 0)
        return 0;
    char element[48];
    hx_message msg;
    snprintf(element, sizeof element, "Control_Diff %d", r->id);
    hx_expr_fail(&msg, r->program, &fault, element);
    return hx_dynamics_fail(dd, "%s", msg.text);
}

/* The rates of the Control_Diffs by expression, after the DIFSUBs': the
 * implicit ones solved together, then the explicit ones, each after those
 * whose rate it reads (the model's diff_order). */
static int diff_expressions(const hx_dynamics *d, hx_dynamics_data *dd, double *ydot)
{
    const hx_model *m = d->m;
    if (!m->variables_read && d->diffs_read_variables) {
        /* the variables the rates read, unless the loads' computed them already */
        hx_message msg;
        if (hx_variables_values(&dd->frames, d->routine_binding, dd->frames.variables, &msg) != 0)
            return hx_dynamics_fail(dd, "%s", msg.text);
    }
    /* the implicit rates first: the explicit ones may read them (DIF1) */
    if (hx_implicit_diffs_solve(d, dd, ydot) != 0)
        return -1;
    for (int i = 0; i < m->ndiff_programs; ++i) {
        const int k = m->diff_order[i];
        const int slot = m->routines[k].slot;
        double rate;
        if (hx_routines_diff_expression(d, dd, k, &rate) != 0)
            return -1;
        ydot[d->diff_offset + slot] = rate;
        dd->frames.diffs[2 * slot + 1] = rate;
    }
    return 0;
}

int hx_routines_apply(const hx_dynamics *d, hx_dynamics_data *dd, const double *y, double *ydot)
{
    const hx_model *m = d->m;
    for (int k = 0; k < m->nroutines; ++k) {
        const hx_routine *r = &m->routines[k];
        if (r->kind != HX_ROUTINE_DIFF || r->program != NULL)
            continue;
        hx_binding *b = d->routine_binding[k];
        double rate;
        hx_invoke_routine(b, &dd->frames, 0, 0, &rate, NULL);
        if (hx_dynamics_check_call(d, dd, b, &rate, 1, "value", dd->frames.time) != 0)
            return -1;
        ydot[d->diff_offset + r->slot] = rate;
        dd->frames.diffs[2 * r->slot + 1] = rate;
    }
    if ((m->ndiff_programs > 0 || d->nimplicit > 0) && diff_expressions(d, dd, ydot) != 0)
        return -1;
    for (int body = 0; body < m->nbodies; ++body) {
        const int k = d->driver[body];
        if (k < 0)
            continue;
        const char val_type = m->routines[k].val_type;
        double *qdot = &ydot[d->dof[body].q], *udot = &ydot[d->nq + d->dof[body].u];
        const double rate = y[d->nq + d->dof[body].u], free_udot = *udot;
        *qdot = rate;
        if ((val_type == 'D' &&
             (hx_routines_motion(d, dd, k, 1, qdot) != 0 || hx_routines_motion(d, dd, k, 2, udot) != 0)) ||
            (val_type == 'V' &&
             (hx_routines_motion(d, dd, k, 0, qdot) != 0 || hx_routines_motion(d, dd, k, 1, udot) != 0)) ||
            (val_type == 'A' && hx_routines_motion(d, dd, k, 0, udot) != 0))
            return -1;
        /* the drive's power: the generalized force that turns the loads' udot into the
         * motion's, m (udot - udot_free) / ucf, times the joint rate (docs/architecture.md,
         * the energy balance) */
        ydot[d->load_work] += d->dof[body].mass * (*udot - free_udot) / d->ucf * rate;
    }
    /* an acceleration motion between bodies: its displacement's rate is its velocity, its
     * velocity's the motion (its row holds the joint to both, coordinate_rows.h) */
    for (int k = 0; k < d->nmotions; ++k) {
        const int at = d->motion_state[k];
        if (at < 0)
            continue;
        ydot[at] = y[at + 1];
        if (hx_routines_motion(d, dd, d->motion_routine[k], 0, &ydot[at + 1]) != 0)
            return -1;
    }
    return 0;
}

int hx_routines_driven_rows(const hx_dynamics *d, int *rows)
{
    int n = 0;
    for (int body = 0; body < d->m->nbodies; ++body) {
        const int k = d->driver[body];
        if (k < 0)
            continue;
        if (d->m->routines[k].val_type != 'A') /* an acceleration motion keeps qdot = u */
            rows[n++] = d->dof[body].q;
        rows[n++] = d->nq + d->dof[body].u;
    }
    return n;
}

void hx_routines_csv_header(FILE *f, const hx_dynamics *d)
{
    const hx_model *m = d->m;
    for (int k = 0; k < m->nroutines; ++k) {
        const hx_routine *r = &m->routines[k];
        switch (r->kind) {
        case HX_ROUTINE_DIFF: fprintf(f, ",diff%d", r->id); break;
        case HX_ROUTINE_MOTION:
            if (r->val_type != 'A')
                fprintf(f, ",motion%d.error", r->id);
            break;
        case HX_ROUTINE_REQUEST:
            for (int j = 1; j <= 8; ++j)
                fprintf(f, ",request%d.%d", r->id, j);
            break;
        case HX_ROUTINE_VARIABLE: fprintf(f, ",variable%d", r->id); break;
        }
    }
}

/* The model's output queries (the accelerations and forces REQSUBs ask,
 * host/loop_queries.h) at this output time, from its outputs s: malloc'ed,
 * NULL when there are none; 0, or -1 (dd's message). */
static int output_answers(const hx_dynamics *d, hx_dynamics_data *dd, const hx_expr_outputs *s,
                          double **answers)
{
    const hx_model *m = d->m;
    *answers = NULL;
    if (m->noutput_queries == 0)
        return 0;
    if ((*answers = malloc(sizeof(double) * (size_t)m->noutput_queries)) == NULL)
        return hx_dynamics_fail(dd, "out of memory");
    const hx_expr_context c = {&dd->frames, dd->frames.variables, s};
    for (int k = 0; k < m->noutput_queries; ++k) {
        hx_expr_fault fault;
        if (hx_expr_query_value(&c, &m->output_queries[k], &(*answers)[k], &fault) != 0) {
            char text[96];
            hx_expr_input_text(&m->output_queries[k], text, sizeof text);
            free(*answers);
            *answers = NULL;
            return hx_dynamics_fail(dd, "%s: %s at t = %g, which a REQSUB asks: %s", m->path,
                                    text, dd->frames.time, fault.what);
        }
    }
    return 0;
}

int hx_routines_csv_row(FILE *f, const hx_dynamics *d, hx_dynamics_data *dd, const double *y,
                        const hx_expr_outputs *s)
{
    const hx_model *m = d->m;
    double *answers;
    if (output_answers(d, dd, s, &answers) != 0)
        return -1;
    for (int k = 0; k < m->nroutines; ++k) {
        const hx_routine *r = &m->routines[k];
        hx_binding *b = d->routine_binding[k];
        double values[8];
        if (r->kind == HX_ROUTINE_DIFF) {
            fprintf(f, ",%.15g", y[d->diff_offset + r->slot]);
        } else if (r->kind == HX_ROUTINE_MOTION) {
            if (r->val_type == 'A')
                continue;
            const int body = m->markers[m->joints[r->joint].i_marker].body;
            if (hx_routines_motion(d, dd, k, 0, &values[0]) != 0) {
                free(answers);
                return -1;
            }
            if (!m->joints[r->joint].reduced) { /* a row: its coordinate near f, or its rate */
                double value;
                if (r->val_type == 'V')
                    value = hx_coordinate_rows_joint_rate(d, r->joint, r->motion_type, y);
                else
                    hx_joint_coordinate_near(d, r->joint, r->motion_type, y, values[0], &value,
                                             NULL, NULL);
                fprintf(f, ",%.6g", value - values[0]);
                continue;
            }
            const int driven = r->val_type == 'D' ? d->dof[body].q : d->nq + d->dof[body].u;
            fprintf(f, ",%.6g", y[driven] - values[0]);
        } else {
            hx_call call; /* a REQSUB's accelerations and forces: this time's answers */
            hx_binding_call_init(b, &call, 0, &dd->frames, 0);
            call.answers = answers;
            hx_invoke_routine(b, &dd->frames, 0, 0, values, &call);
            if (hx_dynamics_check_call(d, dd, b, NULL, 0, "", dd->frames.time) != 0) {
                free(answers);
                return -1;
            }
            const int n = r->kind == HX_ROUTINE_REQUEST ? 8 : 1;
            for (int j = 0; j < n; ++j)
                fprintf(f, ",%.15g", values[j]);
        }
    }
    free(answers);
    return 0;
}
