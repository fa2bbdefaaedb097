/* Gravity and the model's loads on the bodies (loads.h). */
#include "sim/dynamics/loads.h"

#include <math.h>
#include <stdio.h>

#include "base/vecmath.h"
#include "expr/evaluate.h"
#include "frames/measures.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/varsub_reads.h"

/* A component's value at fr: a component left out is 0. */
static int value_at(const hx_load *l, const hx_expr_program *p, const hx_frames *fr,
                    double *value, hx_message *msg)
{
    *value = 0.0;
    if (p == NULL)
        return 0;
    const hx_expr_context c = {fr, fr->variables, NULL}; /* computed before the loads */
    hx_expr_fault fault;
    if (hx_expr_eval(p, &c, value, &fault) == 0)
        return 0;
    char element[64];
    snprintf(element, sizeof element, "%s %d", hx_load_element_name(l), l->id);
    return hx_expr_fail(msg, p, &fault, element);
}

int hx_load_share_at(const hx_model *m, const hx_frames *fr, const double *turn, int k,
                     hx_load_share *share, hx_message *msg)
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
        for (int i = 0; i < 3; ++i)
            if (value_at(l, l->force[i], fr, &f[i], msg) != 0 ||
                value_at(l, l->torque[i], fr, &tq[i], msg) != 0)
                return -1;
        const hx_frame *ref = hx_frames_marker(fr, l->ref_marker, &scratch[2]);
        m3_apply(F, ref->R, f);
        m3_apply(T, ref->R, tq);
        if (l->j_marker < 0)
            return 0;
        /* a Force_Vector_TwoBody: the reaction on J's body at the same point, as a
         * user force element's (element_forces.c) */
        share->count = 2;
        share->body[1] = m->markers[l->j_marker].body;
        v3_copy(share->point[1], I->p);
        v3_scale(share->F[1], F, -1.0);
        v3_scale(share->T[1], T, -1.0);
        return 0;
    }
    const hx_frame *J = hx_frames_marker(fr, l->j_marker, &scratch[1]);
    v3_set(F, 0, 0, 0);
    v3_set(T, 0, 0, 0);
    double value;
    if (value_at(l, l->value, fr, &value, msg) != 0)
        return -1;
    if (l->kind == HX_LOAD_SCALAR_TORQUE) {
        if (l->turn_stiffness != 0.0) { /* its AZ's full turns since the angle held (§7.17) */
            double R[9];
            hx_relative_rotation(I, J, R);
            const double az = hx_projection_angle(R, 2);
            const double two_pi = 6.283185307179586;
            value -= l->turn_stiffness * (turn[k] - az - remainder(turn[k] - az, two_pi));
        }
        v3_set(T, J->R[2] * value, J->R[5] * value, J->R[8] * value);
    } else {
        double r[3];
        v3_sub(r, I->p, J->p);
        const double len = v3_norm(r);
        if (len > 0.0)
            v3_scale(F, r, value / len); /* positive pushes I away from J */
    }
    if (l->action_only)
        return 0;
    share->count = 2;
    share->body[1] = m->markers[l->j_marker].body;
    v3_copy(share->point[1], J->p);
    v3_scale(share->F[1], F, -1.0);
    v3_scale(share->T[1], T, -1.0);
    return 0;
}

/* Body b added to bodies[0 .. *n) unless there. */
static void add_body(int *bodies, int *n, int b)
{
    for (int i = 0; i < *n; ++i)
        if (bodies[i] == b)
            return;
    if (*n < HX_LOAD_BODIES_MAX)
        bodies[(*n)++] = b;
}

static void add_program_bodies(const hx_dynamics *d, const hx_expr_program *p, int *bodies,
                               int *n);

/* The bodies variable k reads, through the variables it reads in turn (they
 * form no cycle: model/variable_programs.c); a USERSUB variable's, those of
 * the markers its VARSUB declared in its dependency pass. */
static void add_variable_bodies(const hx_dynamics *d, int k, int *bodies, int *n)
{
    const hx_model *m = d->m;
    const hx_variable *v = &m->variables[k];
    if (v->varsub) {
        int markers[4 * HX_MAX_QUERIES];
        const int count = hx_varsub_reads(d, k, HX_READS_MARKERS, markers, 4 * HX_MAX_QUERIES);
        for (int i = 0; i < count; ++i)
            add_body(bodies, n, m->markers[markers[i]].body);
        for (int i = m->varsub_read_start[k]; i < m->varsub_read_start[k + 1]; ++i)
            add_variable_bodies(d, m->varsub_reads[i], bodies, n);
        return;
    }
    if (v->program != NULL) {
        add_program_bodies(d, v->program, bodies, n);
        return;
    }
    for (int i = 0; i < v->nmarkers; ++i)
        if (v->marker_ids[i] != 0)
            add_body(bodies, n, m->markers[hx_model_marker(m, v->marker_ids[i])].body);
}

static void add_program_bodies(const hx_dynamics *d, const hx_expr_program *p, int *bodies,
                               int *n)
{
    const hx_model *m = d->m;
    const hx_expr_input *in = hx_expr_inputs(p);
    for (int j = 0; j < hx_expr_input_count(p); ++j) {
        if (in[j].variable >= 0)
            add_variable_bodies(d, in[j].variable, bodies, n);
        for (int i = 0; i < in[j].nids && i < 4; ++i)
            if (in[j].kind == HX_EXPR_INPUT_MEASURE && in[j].index[i] >= 0)
                add_body(bodies, n, m->markers[in[j].index[i]].body);
    }
}

static void add_program_diffs(const hx_dynamics *d, const hx_expr_program *p, int *slots, int *n);

/* The Control_Diff slots variable k reads: its program's by DIF, its
 * VARSUB's declared DIF, through the variables they read (no cycle). */
static void add_variable_diffs(const hx_dynamics *d, int k, int *slots, int *n)
{
    const hx_model *m = d->m;
    const hx_variable *v = &m->variables[k];
    if (v->program != NULL)
        add_program_diffs(d, v->program, slots, n);
    if (!v->varsub)
        return;
    int read[HX_MAX_QUERIES];
    const int count = hx_varsub_reads(d, k, HX_READS_DIFF, read, HX_MAX_QUERIES);
    for (int i = 0; i < count; ++i)
        add_body(slots, n, read[i]);
    for (int i = m->varsub_read_start[k]; i < m->varsub_read_start[k + 1]; ++i)
        add_variable_diffs(d, m->varsub_reads[i], slots, n);
}

/* The Control_Diff slots program p reads by DIF, through the variables it
 * reads too. */
static void add_program_diffs(const hx_dynamics *d, const hx_expr_program *p, int *slots, int *n)
{
    const hx_expr_input *in = hx_expr_inputs(p);
    for (int j = 0; j < hx_expr_input_count(p); ++j) {
        if (in[j].kind == HX_EXPR_INPUT_DIF)
            add_body(slots, n, in[j].index[0]); /* distinct, as the bodies */
        if (in[j].variable >= 0)
            add_variable_diffs(d, in[j].variable, slots, n);
    }
}

int hx_load_diffs(const hx_dynamics *d, int k, int *slots)
{
    const hx_load *l = &d->m->loads[k];
    int n = 0;
    const hx_expr_program *programs[7] = {l->force[0],  l->force[1],  l->force[2], l->torque[0],
                                          l->torque[1], l->torque[2], l->value};
    for (int p = 0; p < 7; ++p)
        if (programs[p] != NULL)
            add_program_diffs(d, programs[p], slots, &n);
    return n;
}

int hx_variable_bodies(const hx_dynamics *d, int k, int *bodies)
{
    int n = 0;
    add_variable_bodies(d, k, bodies, &n);
    return n;
}

int hx_load_bodies(const hx_dynamics *d, int k, int *bodies)
{
    const hx_model *m = d->m;
    const hx_load *l = &m->loads[k];
    int n = 0; /* distinct, in the order first named */
    const int other = l->kind == HX_LOAD_VECTOR ? l->ref_marker : l->j_marker;
    const int named[3] = {l->i_marker, other, l->kind == HX_LOAD_VECTOR ? l->j_marker : -1};
    for (int i = 0; i < 3; ++i)
        if (named[i] >= 0)
            add_body(bodies, &n, m->markers[named[i]].body);
    const hx_expr_program *programs[7] = {l->force[0],  l->force[1],  l->force[2], l->torque[0],
                                          l->torque[1], l->torque[2], l->value};
    for (int p = 0; p < 7; ++p)
        if (programs[p] != NULL)
            add_program_bodies(d, programs[p], bodies, &n);
    return n;
}

int hx_loads_output(const hx_dynamics *d, const hx_dynamics_data *dd, int k, double out[12],
                    hx_message *msg)
{
    for (int j = 0; j < 12; ++j)
        out[j] = 0.0;
    if (d->load_off[k])
        return 0; /* switched off: it puts nothing on the bodies */
    hx_load_share share;
    if (hx_load_share_at(d->m, &dd->frames, dd->turn + d->m->njoints, k, &share, msg) != 0)
        return -1;
    for (int s = 0; s < share.count; ++s)
        for (int j = 0; j < 3; ++j)
            out[6 * s + j] = share.F[s][j], out[6 * s + 3 + j] = share.T[s][j];
    const hx_load *l = &d->m->loads[k];
    if ((l->builtin == HX_LOAD_BUSHING || l->builtin == HX_LOAD_BEAM ||
         l->builtin == HX_LOAD_FIELD) && share.count == 2) {
        /* a bushing's, a beam's or a linear field's J side at J's origin: the moment of the offset added
         * (§7.17) */
        hx_frame scratch;
        const hx_frame *J = hx_frames_marker(&dd->frames, l->j_marker, &scratch);
        double offset[3], moment[3];
        v3_sub(offset, share.point[1], J->p);
        v3_cross(moment, offset, share.F[1]);
        v3_add(out + 9, out + 9, moment);
    }
    return 0;
}

int hx_loads_apply(const hx_dynamics *d, hx_dynamics_data *dd, double *power)
{
    const hx_model *m = d->m;
    for (int k = 0; k < m->nbodies; ++k)
        if (d->dof[k].kind != HX_DOF_GROUND)
            v3_axpy(dd->force + 3 * k, m->bodies[k].mass / d->ucf, d->gravity);
    *power = 0.0;
    for (int k = 0; k < m->nloads; ++k) {
        if (d->load_off[k])
            continue;
        hx_load_share share;
        hx_message msg;
        if (hx_load_share_at(m, &dd->frames, dd->turn + m->njoints, k, &share, &msg) != 0)
            return hx_dynamics_fail(dd, "%s", msg.text);
        for (int i = 0; i < share.count; ++i)
            *power += hx_bodies_apply_load(d, dd, share.body[i], share.point[i], share.F[i],
                                           share.T[i], 1.0);
    }
    return 0;
}
