/*
 * A program's ids resolved against a model (expr.h): markers, variables,
 * Control_Diffs, arrays, splines and curves by id to their indices, each id
 * the model does not define named with its place in the text; a constraint
 * element's force, a marker's acceleration, a force element's force and the
 * forces at a marker are refused anywhere but in an output expression or one
 * linked as a loop's (a force's, a variable's, a Control_Diff's:
 * hx_expr_link_loop).
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "model/curve.h"
#include "model/marker_elements.h"
#include "model/expr/functions.h"
#include "model/expr/program.h"

/* Where a program is evaluated: what it may read beyond the state (a
 * request's and a loop's read the same: the loop solves for what it reads). */
enum { LINK_STATE, LINK_OUTPUT };

static int fail_at(hx_expr_program *p, hx_message *msg, int line, int column, const char *fmt,
                   ...) __attribute__((format(printf, 5, 6)));

static int fail_at(hx_expr_program *p, hx_message *msg, int line, int column, const char *fmt,
                   ...)
{
    char what[HX_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    p->model = NULL;
    return hx_fail(msg, "%s:%d:%d: %s", p->file, line, column, what);
}

/* The element a constraint function names: 0 with its index in in->index[0]
 * and the markers its jflag reads at in index[1] (I) and index[2] (J, -1:
 * none), or -1 with what the model lacks in `what`. */
static int constraint_element(hx_expr_input *in, const hx_model *m, char *what, size_t size)
{
    const int id = in->ids[0];
    int k = -1, joint = -1;
    switch (in->function) {
    case HX_FN_JOINT:
    case HX_FN_JPRIM:
        k = joint = in->function == HX_FN_JPRIM ? hx_model_primitive(m, id) : hx_model_joint(m, id);
        snprintf(what, size, "no %s %d in the model", in->function == HX_FN_JPRIM
                 ? "Constraint_Jprim (JPRIM)" : "Constraint_Joint (JOINT)", id);
        break;
    case HX_FN_MOTION:
        k = hx_model_routine(m, HX_ROUTINE_MOTION, id);
        joint = k >= 0 ? m->routines[k].joint : -1;
        snprintf(what, size, "no Motion_Joint (MOTION) %d in the model", id);
        break;
    case HX_FN_COUPLER:
        for (int c = 0; c < m->ncouplers && k < 0; ++c)
            if (m->couplers[c].id == id)
                k = c;
        snprintf(what, size, "no Constraint_Coupler (COUPLER) %d in the model", id);
        if (k >= 0 && in->ids[1] / 2 >= m->couplers[k].njoints) {
            snprintf(what, size, "jflag (argument 2) is %d: Constraint_Coupler %d couples %d"
                     " joints (jflag 0 to %d)", in->ids[1], id, m->couplers[k].njoints,
                     2 * m->couplers[k].njoints - 1);
            return -1;
        }
        joint = k >= 0 ? m->couplers[k].joint[in->ids[1] / 2] : -1;
        break;
    default: /* HX_FN_GCON: its force on its I marker's body, a moving body's */
        for (int g = 0; g < m->ngcons && k < 0; ++g)
            if (m->gcons[g].id == id)
                k = g;
        snprintf(what, size, "no Constraint_General (GCON) %d in the model", id);
        if (k < 0)
            return -1;
        in->index[0] = k, in->index[1] = m->gcons[k].i_marker, in->index[2] = -1;
        const int body = in->index[1] < 0 ? -1 : m->markers[in->index[1]].body;
        if (body < 0 || m->bodies[body].is_ground) {
            snprintf(what, size, "Constraint_General %d (line %d) %s: its force is read on its"
                     " I marker's body, a moving body (docs/interface.md §7.16)", id,
                     m->gcons[k].line, body < 0 ? "names no I marker"
                     : "has its I marker on ground");
            return -1;
        }
        return 0;
    }
    if (k < 0)
        return -1;
    in->index[0] = k;
    in->index[1] = m->joints[joint].i_marker, in->index[2] = m->joints[joint].j_marker;
    return 0;
}

/* rm (argument 4) into in->index[3]; 0, or -1 with why. */
static int link_rm(hx_expr_input *in, const hx_model *m, char *why, size_t size)
{
    in->index[3] = in->ids[3] == 0 ? -1 : hx_model_marker(m, in->ids[3]);
    if (in->ids[3] != 0 && in->index[3] < 0) {
        snprintf(why, size, "rm (argument 4): no Reference_Marker %d in the model", in->ids[3]);
        return -1;
    }
    return 0;
}

int hx_expr_link_force(hx_expr_input *in, const hx_model *m, char *why, size_t size)
{
    const char *name = hx_expr_function_at(in->function)->name;
    const int jflags = in->function == HX_FN_COUPLER ? 5 : in->function == HX_FN_GCON ? 0 : 1;
    if ((in->kind == HX_EXPR_INPUT_REACTION || in->kind == HX_EXPR_INPUT_LOAD) &&
        (in->ids[1] < 0 || in->ids[1] > jflags)) { /* the parser's checks, for a query's */
        snprintf(why, size, "%s: jflag (argument 2) is %d: 0 to %d", name, in->ids[1], jflags);
        return -1;
    }
    if ((in->kind == HX_EXPR_INPUT_REACTION || in->kind == HX_EXPR_INPUT_LOAD) &&
        (in->ids[2] < 1 || in->ids[2] > 8)) {
        snprintf(why, size, "%s: comp (argument 3) is %d: 1 to 8 (FM, FX, FY, FZ, TM, TX, TY,"
                 " TZ)", name, in->ids[2]);
        return -1;
    }
    switch (in->kind) {
    case HX_EXPR_INPUT_REACTION: /* JOINT .. GCON (id, jflag, comp, rm): the element, its
                                  * markers, rm */
        if (constraint_element(in, m, why, size) != 0)
            return -1;
        return link_rm(in, m, why, size);
    case HX_EXPR_INPUT_LOAD: { /* SFORCE .. SPDP (id, jflag, comp, rm): the force element
                                * (model/marker_elements.h), rm */
        char what[200];
        int force;
        if (hx_marker_element_find(m, in->function, in->ids[0], &force, &in->index[0], what,
                                   sizeof what) != 0) {
            snprintf(why, size, "no %s", what);
            return -1;
        }
        in->index[1] = force;
        return link_rm(in, m, why, size);
    }
    case HX_EXPR_INPUT_MARKER_FORCE: { /* FX .. TM (I[, J[, K]]): the markers, and no element
                                        * acting between I and J whose force is not summed */
        for (int k = 0; k < 3; ++k) {
            in->index[k] = in->ids[k] == 0 ? -1 : hx_model_marker(m, in->ids[k]);
            if (in->ids[k] != 0 && in->index[k] < 0) {
                snprintf(why, size, "no Reference_Marker %d in the model", in->ids[k]);
                return -1;
            }
        }
        char what[128];
        if (hx_marker_unsummed(m, in->index[0], in->index[1], what, sizeof what)) {
            snprintf(why, size, "%s acts at marker %d%s, and the harness does not sum its force"
                     " at a marker yet", what, in->ids[0],
                     in->index[1] >= 0 ? " (between it and J)" : "");
            return -1;
        }
        return 0;
    }
    default: snprintf(why, size, "not a force"); return -1;
    }
}

/* A constraint element's (JOINT .. GCON), a force element's (SFORCE .. SPDP)
 * or the net force at a marker (FX .. TM): refused where the state alone is
 * known, else linked (hx_expr_link_force). */
static int link_force(hx_expr_program *p, hx_expr_input *in, const hx_model *m,
                      const char *text, int where, hx_message *msg)
{
    if (where == LINK_STATE)
        return fail_at(p, msg, in->line, in->column, "%s: %s, which the harness solves for"
                       " forces, variables and Control_Diff rates only (REQUEST and Post_Request"
                       " expressions may read %s)", text,
                       in->kind == HX_EXPR_INPUT_REACTION
                       ? "a constraint element's force is known only once the accelerations"
                         " are: here it would close an algebraic loop"
                       : in->kind == HX_EXPR_INPUT_LOAD
                       ? "another element's force: here it would close an algebraic loop"
                       : "the forces at a marker are known only once the accelerations are:"
                         " here they would close an algebraic loop",
                       in->kind == HX_EXPR_INPUT_MARKER_FORCE ? "them" : "it");
    char why[320];
    if (hx_expr_link_force(in, m, why, sizeof why) != 0)
        return fail_at(p, msg, in->line, in->column, "%s: %s", text, why);
    return 0;
}

static int link_input(hx_expr_program *p, hx_expr_input *in, const hx_model *m, int where,
                      hx_message *msg)
{
    char text[96];
    hx_expr_input_text(in, text, sizeof text);
    const int id = in->ids[0];
    in->variable = -1;
    in->loop = -1;
    switch (in->kind) {
    case HX_EXPR_INPUT_TIME: return 0;
    case HX_EXPR_INPUT_REACTION:
    case HX_EXPR_INPUT_LOAD:
    case HX_EXPR_INPUT_MARKER_FORCE: return link_force(p, in, m, text, where, msg);
    case HX_EXPR_INPUT_ACCELERATION:
        if (where == LINK_STATE)
            return fail_at(p, msg, in->line, in->column, "%s: an acceleration is known only once"
                           " the forces are: here it would close an algebraic loop, which the"
                           " harness solves for forces, variables and Control_Diff rates only"
                           " (REQUEST and Post_Request expressions may read it)", text);
        /* its markers are linked as a measure's */
        /* fall through */
    case HX_EXPR_INPUT_MEASURE: {
        /* ORIENT(system, component, I[, J]): its markers I and J, as the others' */
        const int *markers = in->function == HX_FN_ORIENT ? in->ids + 2 : in->ids;
        const int count = in->function == HX_FN_ORIENT ? 2 : 4;
        for (int k = 0; k < 4; ++k) {
            const int marker = k < count ? markers[k] : 0;
            in->index[k] = marker == 0 ? -1 : hx_model_marker(m, marker);
            if (marker != 0 && in->index[k] < 0)
                return fail_at(p, msg, in->line, in->column, "%s: no Reference_Marker %d in the"
                               " model", text, marker);
        }
        return 0;
    }
    case HX_EXPR_INPUT_VARVAL:
        if ((in->index[0] = in->variable = hx_model_variable(m, id)) >= 0)
            return 0;
        return fail_at(p, msg, in->line, in->column, "%s: no Reference_Variable %d in the model",
                       text, id);
    case HX_EXPR_INPUT_DIF:
    case HX_EXPR_INPUT_DIF1: {
        const int k = hx_model_routine(m, HX_ROUTINE_DIFF, id);
        if (k < 0)
            return fail_at(p, msg, in->line, in->column, "%s: no Control_Diff %d in the model",
                           text, id);
        in->index[0] = m->routines[k].slot;
        return 0;
    }
    default: { /* HX_EXPR_INPUT_ARYVAL */
        const int k = hx_model_array(m, id), component = in->ids[1];
        if (k < 0)
            return fail_at(p, msg, in->line, in->column, "%s: no Reference_Array %d in the"
                           " model", text, id);
        const hx_array *a = &m->arrays[k];
        if (component > a->count)
            return fail_at(p, msg, in->line, in->column, "%s: Reference_Array %d has %d"
                           " component%s", text, id, a->count, a->count == 1 ? "" : "s");
        if (a->type == HX_ARRAY_U) {
            in->variable = a->variables[component - 1];
        } else if (a->type != HX_ARRAY_IC) {
            return fail_at(p, msg, in->line, in->column, "%s: Reference_Array %d is of type %s,"
                           " whose values expressions cannot read yet (IC and U arrays only)",
                           text, id, a->type == HX_ARRAY_X ? "X" : "Y");
        }
        in->index[0] = k;
        return 0;
    }
    }
}

static int link_program(hx_expr_program *p, const hx_model *m, int where, hx_message *msg)
{
    p->model = NULL;
    for (int k = 0; k < p->nops; ++k) {
        const hx_expr_op *op = &p->ops[k];
        const hx_expr_place *at = &p->places[k];
        const hx_expr_function *f = hx_expr_function_at(op->function);
        if (op->code != HX_OP_SPLINE && op->code != HX_OP_CURVE)
            continue;
        hx_expr_model_call *c = &p->calls[op->a];
        if (op->code == HX_OP_SPLINE) {
            c->index = hx_model_spline(m, c->id);
            if (c->index < 0)
                return fail_at(p, msg, at->line, at->column, "%s: no Reference_Spline %d in the"
                               " model", f->name, c->id);
        } else {
            c->index = hx_model_curve(m, c->id);
            if (c->index < 0)
                return fail_at(p, msg, at->line, at->column, "CURVE: no curve %d in the model",
                               c->id);
            hx_message why;
            if (hx_curve_check(&m->curves[c->index], &why) != 0)
                return fail_at(p, msg, at->line, at->column, "CURVE: %s", why.text);
        }
    }
    for (int k = 0; k < p->ninputs; ++k)
        if (link_input(p, &p->inputs[k], m, where, msg) != 0)
            return -1;
    p->model = m;
    return 0;
}

int hx_expr_link(hx_expr_program *p, const hx_model *m, hx_message *msg)
{
    return link_program(p, m, LINK_STATE, msg);
}

int hx_expr_link_loop(hx_expr_program *p, const hx_model *m, hx_message *msg)
{
    return link_program(p, m, LINK_OUTPUT, msg);
}

int hx_expr_link_output(hx_expr_program *p, const hx_model *m, hx_message *msg)
{
    return link_program(p, m, LINK_OUTPUT, msg);
}

void hx_expr_set_loop(hx_expr_program *p, int k, int slot)
{
    p->inputs[k].loop = slot;
}
