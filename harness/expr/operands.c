/* What an evaluation takes from its context and the model (operands.h). */
#include "expr/operands.h"

#include <math.h>

#include "base/vecmath.h"
#include "frames/acceleration_measures.h"
#include "expr/marker_forces.h"
#include "frames/measure_functions.h"
#include "model/curve.h"
#include "model/expr/functions.h"
#include "model/spline_surface.h"

static int fault_of(hx_expr_fault *f, hx_expr_fault_kind kind, const char *function,
                    const char *what, int has_argument, double argument)
{
    f->kind = kind, f->function = function, f->what = what;
    f->has_argument = has_argument, f->argument = argument;
    return -1;
}

int hx_expr_operands_ready(const hx_expr_program *p, const hx_expr_context *c,
                           hx_expr_fault *fault)
{
    if (p->model != NULL && c != NULL && c->frames != NULL && c->frames->model == p->model)
        return 1;
    fault_of(fault, HX_EXPR_FAULT_NOT_LINKED, "", p->model == NULL
             ? "the expression is not linked against a model (hx_expr_link)"
             : "the frames are not of the model the expression is linked against", 0, 0.0);
    fault->line = p->nops > 0 ? p->places[0].line : 0;
    fault->column = p->nops > 0 ? p->places[0].column : 0;
    fault->time = c != NULL && c->frames != NULL ? c->frames->time : 0.0;
    return 0;
}

/* A variable's value, from the caller's array. */
static int variable(const hx_expr_context *c, const hx_expr_input *in, double *value,
                    hx_expr_fault *fault)
{
    const char *name = hx_expr_function_at(in->function)->name;
    if (c->variables == NULL)
        return fault_of(fault, HX_EXPR_FAULT_INPUT, name, "no variables' values were given to"
                        " read it from", 0, 0.0);
    *value = c->variables[in->variable];
    return 0;
}

/* comp 1..8 of a force F and torque T: FM, FX, FY, FZ, TM, TX, TY, TZ, the
 * components in rm's axes. */
static double component(const hx_expr_context *c, int comp, int rm, const double F[3],
                        const double T[3])
{
    const int torque = comp > 4;
    const double *v = torque ? T : F;
    if (comp == 1 || comp == 5)
        return v3_norm(v);
    hx_frame scratch;
    double in_rm[3];
    m3_tapply(in_rm, hx_frames_marker(c->frames, rm, &scratch)->R, v);
    return in_rm[comp - (torque ? 6 : 2)];
}

/* SFORCE, VFORCE, VTORQ, GFORCE, FIELD (id, jflag, comp, rm; docs/interface.md
 * §8.3): jflag 0 on I at I, 1 on J where the element puts it; from the
 * loads' values (an element by expressions) or the force elements' (by a
 * user routine). */
static int load(const hx_expr_context *c, const hx_expr_input *in, double *value,
                hx_expr_fault *fault)
{
    const char *name = hx_expr_function_at(in->function)->name;
    const int force = in->index[1] == 1;
    const double *all = c->outputs == NULL ? NULL : force ? c->outputs->forces
                                                          : c->outputs->loads;
    if (all == NULL)
        return fault_of(fault, HX_EXPR_FAULT_INPUT, name, "no element forces were given to read"
                        " it from (they are known at output times only)", 0, 0.0);
    const double *at = all + 12 * in->index[0] + 6 * (in->ids[1] == 1);
    *value = component(c, in->ids[2], in->index[3], at, at + 3);
    return 0;
}

/* JOINT(id, jflag, comp, rm), JPRIM(...) (docs/interface.md §7.14): jflag 0 the
 * reaction on I at I, 1 the one on J at J (-F, and -(T + (x_I - x_J) x F));
 * comp 1..8 FM, FX, FY, FZ, TM, TX, TY, TZ, the components in rm's axes.
 * MOTION, COUPLER (jflag 2k, 2k + 1 at its joint k + 1's I and J) and GCON
 * (§8.3) the same, from the slots an output time keeps. */
static int reaction(const hx_expr_context *c, const hx_expr_input *in, double *value,
                    hx_expr_fault *fault)
{
    const char *name = hx_expr_function_at(in->function)->name;
    if (in->function == HX_FN_MOTION || in->function == HX_FN_COUPLER ||
        in->function == HX_FN_GCON) {
        if (c->outputs == NULL || c->outputs->constraints == NULL)
            return fault_of(fault, HX_EXPR_FAULT_INPUT, name, "no constraint forces were given"
                            " to read it from (they are known at output times only)", 0, 0.0);
        const int joint = in->function == HX_FN_COUPLER ? in->ids[1] / 2 : 0;
        const double *at = c->outputs->constraints + 6 * (in->ids[1] % 2) +
                           12 * hx_marker_forces_slot(c->frames->model, in->function,
                                                      in->index[0], joint);
        *value = component(c, in->ids[2], in->index[3], at, at + 3);
        return 0;
    }
    if (c->outputs == NULL || c->outputs->reactions == NULL)
        return fault_of(fault, HX_EXPR_FAULT_INPUT, name, "no joint reactions were given to read"
                        " it from (they are known at output times only)", 0, 0.0);
    const double *on_i = c->outputs->reactions + 6 * in->index[0];
    double on_j[6];
    if (in->ids[1] == 1)
        hx_marker_forces_joint_on_j(c->frames, in->index[0], on_i, on_j);
    const double *at = in->ids[1] == 1 ? on_j : on_i;
    *value = component(c, in->ids[2], in->index[3], at, at + 3);
    return 0;
}

/* FX .. TM (I[, J[, K]]; docs/interface.md §8.3): the net force or torque at
 * I from the elements between I and J, in K's axes. */
static int marker_force(const hx_expr_context *c, const hx_expr_input *in, double *value,
                        hx_expr_fault *fault)
{
    /* FX FY FZ FM TX TY TZ TM as the element functions' comp */
    static const int comp[8] = {2, 3, 4, 1, 6, 7, 8, 5};
    double F[3], T[3];
    if (hx_marker_forces_sum(c->frames, c->outputs, in->index[0], in->index[1], 0, F, T,
                             fault) != 0) {
        fault->function = hx_expr_function_at(in->function)->name;
        return -1;
    }
    const int k = in->function - HX_FN_FX;
    *value = component(c, comp[k], k == 3 || k == 7 ? -1 : in->index[2], F, T);
    return 0;
}

/* ACCX .. WDTM (docs/interface.md §8.5): each marker's acceleration from its
 * body's (the world's, and a marker left out, at rest). */
static int acceleration(const hx_expr_context *c, const hx_expr_input *in, double *value,
                        hx_expr_fault *fault)
{
    const char *name = hx_expr_function_at(in->function)->name;
    if (c->outputs == NULL || c->outputs->accelerations == NULL)
        return fault_of(fault, HX_EXPR_FAULT_INPUT, name, "no accelerations were given to read"
                        " it from (they are known at output times only)", 0, 0.0);
    static const double rest[6] = {0, 0, 0, 0, 0, 0};
    hx_frame scratch[4];
    const hx_frame *f[4];
    double acc[4][6];
    const double *a[4];
    for (int j = 0; j < 4; ++j) {
        f[j] = hx_frames_marker(c->frames, in->index[j], &scratch[j]);
        a[j] = rest;
        if (in->index[j] < 0)
            continue;
        const int b = c->frames->model->markers[in->index[j]].body;
        hx_point_acceleration(&c->frames->bodies[b], c->outputs->accelerations + 6 * b, f[j]->p, acc[j]);
        a[j] = acc[j];
    }
    *value = hx_acceleration_value((hx_acceleration_measure)in->measure, f, a);
    return 0;
}

int hx_expr_query_value(const hx_expr_context *c, const hx_expr_input *in, double *value,
                        hx_expr_fault *fault)
{
    switch (in->kind) {
    case HX_EXPR_INPUT_REACTION: return reaction(c, in, value, fault);
    case HX_EXPR_INPUT_LOAD: return load(c, in, value, fault);
    case HX_EXPR_INPUT_MARKER_FORCE: return marker_force(c, in, value, fault);
    default: return acceleration(c, in, value, fault);
    }
}

int hx_expr_operand_input(const hx_expr_program *p, const hx_expr_context *c, int k,
                          double *value, hx_expr_fault *fault)
{
    const hx_expr_input *in = &p->inputs[k];
    const hx_frames *fr = c->frames;
    switch (in->kind) {
    case HX_EXPR_INPUT_TIME: *value = fr->time; break;
    case HX_EXPR_INPUT_MEASURE: {
        hx_frame scratch[4];
        const hx_frame *f[4];
        for (int j = 0; j < 4; ++j)
            f[j] = hx_frames_marker(fr, in->index[j], &scratch[j]);
        *value = hx_measure_value((hx_measure)in->measure, f);
        if (in->function == HX_FN_ORIENT && !isfinite(*value)) /* system 28, a half turn */
            return fault_of(fault, HX_EXPR_FAULT_DOMAIN, "ORIENT", "I is turned half a turn"
                            " from J, where the Rodrigues parameters are not defined", 0, 0.0);
        break;
    }
    case HX_EXPR_INPUT_VARVAL:
        if (variable(c, in, value, fault) != 0)
            return -1;
        break;
    case HX_EXPR_INPUT_REACTION:
    case HX_EXPR_INPUT_ACCELERATION:
    case HX_EXPR_INPUT_LOAD:
        if (c->outputs == NULL && in->loop >= 0) {
            /* within a right-hand side: the algebraic loop's current iterate
             * (sim/dynamics/algebraic_loop.h) */
            *value = fr->loop[in->loop];
            break;
        }
        if (in->kind == HX_EXPR_INPUT_ACCELERATION) {
            if (acceleration(c, in, value, fault) != 0)
                return -1;
            break;
        }
        if (in->kind == HX_EXPR_INPUT_LOAD) {
            if (load(c, in, value, fault) != 0)
                return -1;
            break;
        }
        if (reaction(c, in, value, fault) != 0)
            return -1;
        break;
    case HX_EXPR_INPUT_MARKER_FORCE:
        if (c->outputs == NULL && in->loop >= 0) {
            *value = fr->loop[in->loop]; /* as above */
            break;
        }
        if (marker_force(c, in, value, fault) != 0)
            return -1;
        break;
    case HX_EXPR_INPUT_DIF:
    case HX_EXPR_INPUT_DIF1:
        *value = fr->diffs[2 * in->index[0] + (in->kind == HX_EXPR_INPUT_DIF1)];
        break;
    default: { /* HX_EXPR_INPUT_ARYVAL: an IC array's number, or a U array's variable */
        if (in->variable >= 0) {
            if (variable(c, in, value, fault) != 0)
                return -1;
        } else {
            *value = p->model->arrays[in->index[0]].numbers[in->ids[1] - 1];
        }
        break;
    }
    }
    if (!isfinite(*value))
        return fault_of(fault, HX_EXPR_FAULT_INPUT,
                        in->kind == HX_EXPR_INPUT_TIME ? "TIME"
                                                       : hx_expr_function_at(in->function)->name,
                        "its value is not finite", 1, *value);
    return 0;
}

int hx_expr_operand_model(const hx_expr_program *p, const hx_expr_op *op, const double *args,
                          double *value, double *partials, hx_expr_fault *fault)
{
    const hx_expr_model_call *call = &p->calls[op->a];
    const char *name = hx_expr_function_at(call->function)->name;
    double v;
    if (op->code == HX_OP_SPLINE) {
        const hx_spline *s = &p->model->splines[call->index];
        const hx_spline_method method = call->function == HX_FN_AKISPL ? HX_SPLINE_AKIMA
                                                                        : HX_SPLINE_CUBIC;
        double d[6];
        hx_spline_surface(s, method, args[0], args[1], d);
        /* the value, f_x or f_xx, and its partials in x and z */
        static const int at[3][3] = {{0, 1, 2}, {1, 3, 4}, {3, -1, -1}};
        v = d[at[call->order][0]];
        if (partials != NULL) {
            if (call->order < 2) {
                partials[0] = d[at[call->order][1]], partials[1] = d[at[call->order][2]];
            } else {
                double third[2];
                hx_spline_surface_third(s, method, args[0], args[1], third);
                partials[0] = third[0], partials[1] = third[1];
            }
        }
    } else {
        const hx_curve *curve = &p->model->curves[call->index];
        if (!curve->closed && !(args[0] >= -1.0 && args[0] <= 1.0))
            return fault_of(fault, HX_EXPR_FAULT_DOMAIN, name, "its alpha is outside [-1, 1]",
                            1, args[0]);
        double d[4];
        hx_curve_at(curve, args[0], call->component, d);
        v = d[call->order];
        if (partials != NULL)
            partials[0] = d[call->order + 1];
    }
    if (!isfinite(v))
        return fault_of(fault, HX_EXPR_FAULT_NOT_FINITE, name, "its result is not finite", 0,
                        0.0);
    *value = v;
    return 0;
}

int hx_expr_operand_fault(const hx_expr_program *p, const hx_expr_context *c, int pc,
                          hx_expr_fault *fault)
{
    fault->line = p->places[pc].line, fault->column = p->places[pc].column;
    fault->time = c->frames->time;
    return -1;
}
