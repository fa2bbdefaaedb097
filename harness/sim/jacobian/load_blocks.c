/*
 * The loads' blocks of the Jacobian (jacobian.h). A load whose expressions
 * read TIME, measures of markers, Control_Diff states (DIF) and variables
 * (VARVAL, ARYVAL of a U array: a number, one measure, or an expression
 * that reads those) is exact: its expressions' partials in their inputs
 * (expr/evaluate.h), times each measure's slope in the motion of a body's
 * column (measure_slope.h), 1 for the DIF of a state's own column, or a
 * variable's own partials times its inputs' changes, give the change of
 * its values; with the turning of its axes (a vector load's reference
 * marker, a scalar torque's z of J), the line from J to I of a scalar force
 * and the lever arms about the bodies' centres, the change of its wrenches
 * on its bodies. A load that reads any other variable (a USERSUB one: its
 * VARSUB's declared reads, sim/dynamics/varsub_reads.h) is taken by central
 * differences of that load alone, the variables recomputed at each moved
 * state, on the columns of the bodies its markers sit on and of those its
 * expressions measure (hx_load_bodies) and of the states they read.
 * docs/architecture.md, "The Jacobian".
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "expr/evaluate.h"
#include "host/variable_values.h"
#include "model/expr/program.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/loads.h"
#include "sim/jacobian/jacobian_parts.h"
#include "sim/jacobian/measure_slope.h"

/* A load's programs: a vector load's three force and three torque
 * components, then a scalar load's value. */
#define HX_LOAD_PROGRAMS 7

/* The central difference of a load's wrenches at +h and -h (side, application,
 * (F, T)) in column c, onto the bodies it is applied to. */
static void put_difference(hx_jacobian *jac, int count, const int *body,
                           double W[2][2][6], double h, int c)
{
    for (int a = 0; a < count; ++a) {
        double dW[6];
        for (int r = 0; r < 6; ++r)
            dW[r] = (W[0][a][r] - W[1][a][r]) / (2.0 * h);
        hx_jacobian_body_load(jac, body[a], c, -1, dW, dW + 3);
    }
}

/* What share puts on its i-th body: F and the torque about its centre. */
static void wrench(const hx_load_share *share, int i, const hx_frames *fr, double F[3], double T[3])
{
    double arm[3];
    v3_copy(F, share->F[i]);
    v3_sub(arm, share->point[i], fr->bodies[share->body[i]].p);
    v3_cross(T, arm, share->F[i]);
    v3_add(T, T, share->T[i]);
}

/* Load k's change in the Control_Diff states it reads by DIF (hx_load_diffs),
 * by central differences of that load alone at the moved frames; 0 or -1. */
static int diff_columns(hx_jacobian *jac, int k)
{
    const hx_dynamics *d = jac->d;
    const hx_model *m = d->m;
    int slots[HX_LOAD_BODIES_MAX];
    const int nslots = hx_load_diffs(d, k, slots);
    for (int i = 0; i < nslots; ++i) {
        const int c = d->diff_offset + slots[i];
        const double keep = jac->y[c], h = hx_jacobian_step(jac->y, c);
        hx_load_share share[2];
        double W[2][2][6]; /* side, application, (F, T) */
        int status = 0;
        hx_message msg;
        for (int side = 0; side < 2 && status == 0; ++side) {
            jac->moved.diffs[2 * slots[i]] = keep + (side == 0 ? h : -h);
            if (m->variables_read && hx_variables_values(&jac->moved, d->routine_binding,
                                                         jac->moved.variables, &msg) != 0)
                status = -1;
            if (status == 0 && hx_load_share_at(m, &jac->moved, jac->dd.turn + m->njoints, k,
                                                &share[side], &msg) != 0)
                status = -1;
            for (int a = 0; status == 0 && a < share[side].count; ++a)
                wrench(&share[side], a, &jac->moved, W[side][a], W[side][a] + 3);
        }
        jac->moved.diffs[2 * slots[i]] = keep;
        memcpy(jac->moved.variables, jac->dd.frames.variables, sizeof(double) * (size_t)m->nvariables);
        if (status != 0)
            return hx_dynamics_fail(&jac->dd, "%s", msg.text);
        put_difference(jac, share[0].count, share[0].body, W, h, c);
    }
    return 0;
}

/* Load k by central differences of that load alone; 0 or -1. */
static int differences(hx_jacobian *jac, int k)
{
    const hx_dynamics *d = jac->d;
    if (diff_columns(jac, k) != 0)
        return -1;
    int bodies[HX_LOAD_BODIES_MAX];
    const int nbodies = hx_load_bodies(d, k, bodies);
    for (int i = 0; i < nbodies; ++i) {
        const int b = bodies[i];
        if (d->dof[b].kind == HX_DOF_GROUND)
            continue;
        int columns[13];
        const int count = hx_jacobian_body_columns(d, b, columns);
        for (int j = 0; j < count; ++j) {
            const int c = columns[j];
            const double keep = jac->y[c], h = hx_jacobian_step(jac->y, c);
            hx_load_share share[2];
            double W[2][2][6]; /* side, application, (F, T) */
            for (int side = 0; side < 2; ++side) {
                jac->y[c] = keep + (side == 0 ? h : -h);
                hx_jacobian_move_body(jac, b, jac->y);
                hx_message msg;
                if (hx_load_share_at(d->m, &jac->moved, jac->dd.turn + d->m->njoints, k,
                                     &share[side], &msg) != 0) {
                    jac->y[c] = keep;
                    hx_jacobian_restore_body(jac, b);
                    return hx_dynamics_fail(&jac->dd, "%s", msg.text);
                }
                for (int a = 0; a < share[side].count; ++a)
                    wrench(&share[side], a, &jac->moved, W[side][a], W[side][a] + 3);
            }
            jac->y[c] = keep;
            hx_jacobian_restore_body(jac, b);
            put_difference(jac, share[0].count, share[0].body, W, h, c);
        }
    }
    return 0;
}

/* ---- exact blocks ------------------------------------------------------------------ */

/* Load l's programs: the force's and torque's components of a vector load,
 * then a scalar load's value (NULL: a component left out, 0). */
static void programs_of(const hx_load *l, const hx_expr_program *p[HX_LOAD_PROGRAMS])
{
    const hx_expr_program *all[HX_LOAD_PROGRAMS] = {l->force[0],  l->force[1],  l->force[2],
                                                    l->torque[0], l->torque[1], l->torque[2],
                                                    l->value};
    memcpy(p, all, sizeof all);
}

/* Whether program p reads only inputs with exact partials here: TIME,
 * measures, DIF, and the variables (VARVAL, ARYVAL of a U array) that are
 * a number, one measure, or expressions that read those in turn (they form
 * no cycle: model/variable_programs.c). */
static int program_exact(const hx_model *m, const hx_expr_program *p)
{
    const hx_expr_input *in = hx_expr_inputs(p);
    for (int j = 0; j < hx_expr_input_count(p); ++j) {
        if (in[j].variable >= 0) {
            const hx_variable *v = &m->variables[in[j].variable];
            if (v->varsub) /* a VARSUB's: by differences on what it declared */
                return 0;
            if (v->program == NULL ? v->function[0] != '\0' && hx_measure_find(v->function) < 0
                                   : !program_exact(m, v->program))
                return 0;
        } else if (in[j].kind != HX_EXPR_INPUT_TIME && in[j].kind != HX_EXPR_INPUT_MEASURE &&
                   in[j].kind != HX_EXPR_INPUT_DIF) {
            return 0;
        }
    }
    return 1;
}

static int reads_exactly(const hx_model *m, const hx_load *l)
{
    const hx_expr_program *p[HX_LOAD_PROGRAMS];
    programs_of(l, p);
    for (int i = 0; i < HX_LOAD_PROGRAMS; ++i)
        if (p[i] != NULL && !program_exact(m, p[i]))
            return 0;
    return 1;
}

int hx_load_blocks_init(hx_jacobian *jac, hx_message *msg)
{
    const hx_model *m = jac->d->m;
    size_t scratch = 1;
    for (int k = 0; k < m->nloads; ++k) {
        const hx_expr_program *p[HX_LOAD_PROGRAMS];
        programs_of(&m->loads[k], p);
        for (int i = 0; i < HX_LOAD_PROGRAMS; ++i)
            if (p[i] != NULL && hx_expr_scratch_size(p[i]) > scratch)
                scratch = hx_expr_scratch_size(p[i]);
    }
    for (int k = 0; k < m->nvariables; ++k) /* the variables' partials, one at a time */
        if (m->variables[k].program != NULL &&
            hx_expr_scratch_size(m->variables[k].program) > scratch)
            scratch = hx_expr_scratch_size(m->variables[k].program);
    if (jac->load_scratch != NULL && scratch <= jac->load_scratch_size)
        return 0;
    double *grown = realloc(jac->load_scratch, sizeof(double) * scratch);
    if (grown == NULL)
        return hx_fail(msg, "out of memory");
    jac->load_scratch = grown;
    jac->load_scratch_size = scratch;
    return 0;
}

/* A load's values and their partials in its inputs at the build's state. */
typedef struct load_values {
    const hx_expr_program *p[HX_LOAD_PROGRAMS];
    double value[HX_LOAD_PROGRAMS];
    double partials[HX_LOAD_PROGRAMS][HX_EXPR_MAX_INPUTS];
} load_values;

static int evaluate(hx_jacobian *jac, const hx_load *l, load_values *lv)
{
    const hx_expr_context c = {&jac->dd.frames, jac->dd.frames.variables, NULL};
    programs_of(l, lv->p);
    for (int i = 0; i < HX_LOAD_PROGRAMS; ++i) {
        lv->value[i] = 0.0;
        if (lv->p[i] == NULL)
            continue;
        hx_expr_fault fault;
        if (hx_expr_eval_partials(lv->p[i], &c, &lv->value[i], lv->partials[i], jac->load_scratch,
                                  &fault) != 0) {
            char element[64];
            hx_message msg;
            snprintf(element, sizeof element, "%s %d", hx_load_element_name(l), l->id);
            hx_expr_fail(&msg, lv->p[i], &fault, element);
            return hx_dynamics_fail(&jac->dd, "%s", msg.text);
        }
    }
    return 0;
}

/* The motion of marker `marker` (-1: the world's) when body b moves by mo
 * (b = -1: none); NULL when it does not move. */
static const hx_motion *marker_motion(const hx_jacobian *jac, int marker, const hx_frame *M,
                                      int b, const hx_motion *mo, hx_motion *out)
{
    if (b < 0 || marker < 0 || jac->d->m->markers[marker].body != b)
        return NULL;
    hx_point_motion(&jac->dd.frames.bodies[b], mo, M, out);
    return out;
}

static double program_change(hx_jacobian *jac, const hx_expr_program *p,
                             const double *partials, int b, const hx_motion *mo, int slot);

/* The change of variable k's value (an expression's) when body b moves by
 * mo, or per unit of Control_Diff state `slot` (b = -1): its partials at
 * the build's state times its inputs' changes. A fault of its partials (one
 * not finite: SQRT at 0) fails the build (jac->dd) and counts 0 here. */
static double variable_change(hx_jacobian *jac, int k, int b, const hx_motion *mo, int slot)
{
    const hx_model *m = jac->d->m;
    const hx_variable *v = &m->variables[k];
    if (v->program == NULL) { /* a number, or sign times one measure (state_inputs.c) */
        if (v->function[0] == '\0' || b < 0)
            return 0.0;
        hx_frame scratch[4];
        hx_motion motion[4];
        const hx_frame *f[4];
        const hx_motion *mm[4];
        for (int a = 0; a < 4; ++a) {
            const int marker = a < v->nmarkers && v->marker_ids[a] != 0
                                   ? hx_model_marker(m, v->marker_ids[a]) : -1;
            f[a] = hx_frames_marker(&jac->dd.frames, marker, &scratch[a]);
            mm[a] = marker_motion(jac, marker, f[a], b, mo, &motion[a]);
        }
        return v->sign * hx_measure_slope((hx_measure)hx_measure_find(v->function), f, mm);
    }
    const hx_expr_context c = {&jac->dd.frames, jac->dd.frames.variables, NULL};
    double value, partials[HX_EXPR_MAX_INPUTS];
    hx_expr_fault fault;
    if (hx_expr_eval_partials(v->program, &c, &value, partials, jac->load_scratch, &fault) != 0) {
        char element[48];
        hx_message msg;
        snprintf(element, sizeof element, "Reference_Variable %d", v->id);
        hx_expr_fail(&msg, v->program, &fault, element);
        hx_dynamics_fail(&jac->dd, "%s", msg.text);
        return 0.0;
    }
    return program_change(jac, v->program, partials, b, mo, slot);
}

/* The change of program p's value (partials its partials in its inputs)
 * when body b moves by mo (b = -1: none), or per unit of Control_Diff
 * state `slot` (-1: none): each measure's slope, 1 for DIF of that state,
 * a variable's change, times its partial. */
static double program_change(hx_jacobian *jac, const hx_expr_program *p,
                             const double *partials, int b, const hx_motion *mo, int slot)
{
    const hx_expr_input *in = hx_expr_inputs(p);
    const hx_frames *fr = &jac->dd.frames;
    double change = 0.0;
    for (int j = 0; j < hx_expr_input_count(p); ++j) {
        if (partials[j] == 0.0)
            continue;
        if (in[j].variable >= 0) {
            change += partials[j] * variable_change(jac, in[j].variable, b, mo, slot);
            continue;
        }
        if (in[j].kind == HX_EXPR_INPUT_DIF) {
            if (slot >= 0 && in[j].index[0] == slot)
                change += partials[j];
            continue;
        }
        if (in[j].kind != HX_EXPR_INPUT_MEASURE || b < 0)
            continue;
        hx_frame scratch[4];
        hx_motion motion[4];
        const hx_frame *f[4];
        const hx_motion *m[4];
        int moves = 0;
        for (int a = 0; a < 4; ++a) {
            f[a] = hx_frames_marker(fr, in[j].index[a], &scratch[a]);
            m[a] = marker_motion(jac, in[j].index[a], f[a], b, mo, &motion[a]);
            moves |= m[a] != NULL;
        }
        if (moves)
            change += partials[j] * hx_measure_slope((hx_measure)in[j].measure, f, m);
    }
    return change;
}

/* Puts on body `body` (its centre moving by dc) the change of a force F at a
 * point (moving by dpoint), of dF, and of a couple by dT: dF, and about the
 * centre (dpoint - dc) x F + (point - c) x dF + dT, times sign. */
static void put_change(hx_jacobian *jac, int body, int col, double sign, const double point[3],
                       const double dpoint[3], const double dc[3], const double F[3],
                       const double dF[3], const double dT[3])
{
    double arm[3], darm[3], torque[3], t[3], force[3];
    v3_sub(arm, point, jac->dd.frames.bodies[body].p);
    v3_sub(darm, dpoint, dc);
    v3_cross(torque, darm, F);
    v3_cross(t, arm, dF);
    v3_add(torque, torque, t);
    v3_add(torque, torque, dT);
    v3_scale(torque, torque, sign);
    v3_scale(force, dF, sign);
    hx_jacobian_body_load(jac, body, col, -1, force, torque);
}

/* Load k's wrenches changed by dvalue (its programs' values' changes) and by
 * body b moving by mo (b = -1: none), into column col (loads.c's
 * hx_load_share_at, differentiated). */
static void put_load_change(hx_jacobian *jac, int k, const load_values *lv,
                            const double dvalue[HX_LOAD_PROGRAMS], int b, const hx_motion *mo,
                            int col)
{
    const hx_model *m = jac->d->m;
    const hx_load *l = &m->loads[k];
    const hx_frames *fr = &jac->dd.frames;
    static const double zero[3] = {0, 0, 0};
    hx_frame scratch[3];
    hx_motion motion[3];
    const hx_frame *I = hx_frames_marker(fr, l->i_marker, &scratch[0]);
    const hx_motion *mI = marker_motion(jac, l->i_marker, I, b, mo, &motion[0]);
    const double *dpI = mI != NULL ? mI->dp : zero;
    const int bi = m->markers[l->i_marker].body;
    const double *dci = b == bi ? mo->dp : zero;
    double F[3], dF[3], T[3], dT[3], t[3];
    if (l->kind == HX_LOAD_VECTOR) { /* F = R_ref f, T = R_ref tq, on I's body at I */
        const hx_frame *ref = hx_frames_marker(fr, l->ref_marker, &scratch[2]);
        const hx_motion *mr = marker_motion(jac, l->ref_marker, ref, b, mo, &motion[2]);
        m3_apply(F, ref->R, lv->value);
        m3_apply(T, ref->R, lv->value + 3);
        m3_apply(dF, ref->R, dvalue);
        m3_apply(dT, ref->R, dvalue + 3);
        if (mr != NULL) {
            v3_cross(t, mr->dth, F);
            v3_add(dF, dF, t);
            v3_cross(t, mr->dth, T);
            v3_add(dT, dT, t);
        }
        put_change(jac, bi, col, 1.0, I->p, dpI, dci, F, dF, dT);
        if (l->j_marker >= 0) { /* the reaction on J's body at the same point */
            const int bj = m->markers[l->j_marker].body;
            put_change(jac, bj, col, -1.0, I->p, dpI, b == bj ? mo->dp : zero, F, dF, dT);
        }
        return;
    }
    const hx_frame *J = hx_frames_marker(fr, l->j_marker, &scratch[1]);
    const hx_motion *mJ = marker_motion(jac, l->j_marker, J, b, mo, &motion[1]);
    const double *dpJ = mJ != NULL ? mJ->dp : zero;
    const int bj = m->markers[l->j_marker].body;
    const double value = lv->value[6], dv = dvalue[6];
    v3_set(F, 0, 0, 0), v3_set(dF, 0, 0, 0), v3_set(T, 0, 0, 0), v3_set(dT, 0, 0, 0);
    if (l->kind == HX_LOAD_SCALAR_TORQUE) { /* T = value z_J */
        const double z[3] = {J->R[2], J->R[5], J->R[8]};
        v3_scale(dT, z, dv);
        if (mJ != NULL) {
            v3_cross(t, mJ->dth, z);
            v3_axpy(dT, value, t);
        }
    } else { /* F = value u, u = r / |r|, r = p_I - p_J: du = (dr - u (u . dr)) / |r| */
        double r[3], dr[3];
        v3_sub(r, I->p, J->p);
        v3_sub(dr, dpI, dpJ);
        const double len = v3_norm(r);
        if (len > 0.0) {
            double u[3], du[3];
            v3_scale(u, r, 1.0 / len);
            v3_copy(du, dr);
            v3_axpy(du, -v3_dot(u, dr), u);
            v3_scale(du, du, 1.0 / len);
            v3_scale(F, u, value);
            v3_scale(dF, u, dv);
            v3_axpy(dF, value, du);
        }
    }
    put_change(jac, bi, col, 1.0, I->p, dpI, dci, F, dF, dT);
    if (!l->action_only) /* -F at J's point, -T */
        put_change(jac, bj, col, -1.0, J->p, dpJ, b == bj ? mo->dp : zero, F, dF, dT);
}

/* Load k's exact blocks: its columns of the Control_Diff states it reads
 * and of the bodies it depends on (hx_load_bodies). 0 or -1. */
static int exact(hx_jacobian *jac, int k)
{
    const hx_dynamics *d = jac->d;
    const hx_model *m = d->m;
    load_values lv;
    if (evaluate(jac, &m->loads[k], &lv) != 0)
        return -1;
    double dvalue[HX_LOAD_PROGRAMS];
    int slots[HX_LOAD_BODIES_MAX];
    const int nslots = hx_load_diffs(d, k, slots);
    for (int s = 0; s < nslots; ++s) { /* d/dDIF: the partials in that input */
        for (int i = 0; i < HX_LOAD_PROGRAMS; ++i)
            dvalue[i] = lv.p[i] != NULL
                            ? program_change(jac, lv.p[i], lv.partials[i], -1, NULL, slots[s])
                            : 0.0;
        put_load_change(jac, k, &lv, dvalue, -1, NULL, d->diff_offset + slots[s]);
    }
    int bodies[HX_LOAD_BODIES_MAX];
    const int nbodies = hx_load_bodies(d, k, bodies);
    for (int n = 0; n < nbodies; ++n) {
        const int b = bodies[n];
        if (d->dof[b].kind == HX_DOF_GROUND)
            continue;
        int columns[13];
        const int count = hx_jacobian_body_columns(d, b, columns);
        for (int c = 0; c < count; ++c) {
            hx_motion mo;
            hx_body_column_motion(d, b, c, jac->y, &jac->dd.frames.bodies[b], &mo);
            for (int i = 0; i < HX_LOAD_PROGRAMS; ++i)
                dvalue[i] = lv.p[i] != NULL
                                ? program_change(jac, lv.p[i], lv.partials[i], b, &mo, -1)
                                : 0.0;
            put_load_change(jac, k, &lv, dvalue, b, &mo, columns[c]);
        }
    }
    return jac->dd.failed ? -1 : 0; /* a variable's partials faulted */
}

int hx_load_blocks(hx_jacobian *jac, double t, const double *y)
{
    (void)t, (void)y; /* the build's frames hold the time; jac->y the state */
    const hx_dynamics *d = jac->d;
    const hx_model *m = d->m;
    for (int k = 0; k < m->nloads; ++k) {
        if (d->load_off[k])
            continue; /* switched off: nothing on the bodies, nothing here */
        const int status = reads_exactly(m, &m->loads[k]) ? exact(jac, k) : differences(jac, k);
        if (status != 0)
            return -1;
    }
    return 0;
}
