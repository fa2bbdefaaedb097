/*
 * The user routines that are not forces (routine_elements.h). Attribute names
 * are MotionSolve's (docs/interface.md §7.12).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "model/draft.h"
#include "model/expr/expr.h"
#include "model/load_elements.h"
#include "model/request_elements.h"
#include "model/routine_elements.h"
#include "model/xml_attrs.h"

static hx_routine *push_routine(hx_draft *d, const hx_element_read *e, enum hx_routine_kind kind,
                                int user)
{
    hx_model *m = d->m;
    const int earlier = hx_model_routine(m, kind, e->id);
    if (earlier >= 0) {
        hx_draft_fail(d, e->line, "%s %d is defined twice (line %d)", e->name, e->id,
                      m->routines[earlier].line);
        return NULL;
    }
    if (hx_attr_present(e, "script_name")) {
        hx_draft_fail(d, e->line, "%s %d: script_name: the harness loads compiled libraries"
                      " (usrsub_dll_name), not scripts", e->name, e->id);
        return NULL;
    }
    hx_routine *r = hx_draft_push(d, (void **)&m->routines, &m->nroutines, &d->cap_routines,
                                  sizeof *r, NULL, 0);
    if (r == NULL)
        return NULL;
    r->id = e->id;
    r->kind = kind;
    r->slot = m->nroutines_of[kind]++;
    r->joint = -1;
    r->line = e->line;
    if (user && hx_draft_user_call(d, e, &r->user) != 0)
        return NULL;
    return r;
}

/* type="USERSUB", or no type: any other is a form the harness does not read. */
static int user_type(hx_draft *d, const hx_element_read *e)
{
    const char *type = hx_attr_text(e, "type");
    if (type == NULL || strcasecmp(type, "USERSUB") == 0)
        return 0;
    hx_draft_fail(d, e->line, "%s %d: type \"%s\" with a user routine: expected USERSUB", e->name,
                  e->id, type);
    return -1;
}

/* expr1..expr8 and the markers are read by the forms the harness answers
 * itself (request_elements.c); with a user routine they have no effect. */
const hx_attr_spec hx_request_attrs[] = {
    ID, TEXT("type"), TEXT("expr1"), TEXT("expr2"), TEXT("expr3"), TEXT("expr4"),
    TEXT("expr5"), TEXT("expr6"), TEXT("expr7"), TEXT("expr8"), INT("i_marker_id"),
    INT("j_marker_id"), INT("ref_marker_id"), IGNORED("elem_type"), IGNORED("jflag"),
    IGNORED("comment"), IGNORED("title"), USER_CALL, END};

void hx_build_request(hx_draft *d, const hx_element_read *e)
{
    if (!hx_attr_present(e, "usrsub_param_string") && !hx_attr_present(e, "usrsub_dll_name")) {
        hx_build_builtin_request(d, e);
        return;
    }
    if (user_type(d, e) == 0)
        push_routine(d, e, HX_ROUTINE_REQUEST, 1);
}

void hx_build_user_variable(hx_draft *d, const hx_element_read *e)
{
    if (hx_attr_present(e, "expr")) {
        hx_draft_fail(d, e->line, "Reference_Variable %d: type USERSUB takes no expr (VARSUB"
                      " computes the value)", e->id);
        return;
    }
    hx_routine *r = push_routine(d, e, HX_ROUTINE_VARIABLE, 1);
    if (r == NULL)
        return;
    r->ic[0] = hx_attr_number(e, "ic", 0.0);
    /* a variable too, which VARVAL and the order of the variables find by its id */
    const hx_variable v = {.id = e->id, .varsub = 1, .routine = (int)(r - d->m->routines),
                           .line = e->line};
    hx_variable *slot = hx_draft_push(d, (void **)&d->m->variables, &d->m->nvariables,
                                      &d->cap_variables, sizeof *slot, NULL, 0);
    if (slot != NULL)
        *slot = v;
}

const hx_attr_spec hx_diff_attrs[] = {
    ID, TEXT("type"), {"is_implicit", HX_ATTR_BOOL, 0}, REAL("ic"), REAL("ic_dot"),
    {"is_static_hold", HX_ATTR_BOOL, 0}, TEXT("expr"), USER_CALL, END};

/* type="EXPRESSION" (or no type and no user routine): a Control_Diff's
 * rate is expr (docs/interface.md §7.10), parsed here, linked once the model
 * is whole (hx_draft_resolve_routines); a Motion_Joint's the same. */
static int expression_form(const hx_element_read *e)
{
    const char *type = hx_attr_text(e, "type");
    if (type != NULL)
        return strcasecmp(type, "EXPRESSION") == 0;
    return !hx_attr_present(e, "usrsub_param_string") && !hx_attr_present(e, "usrsub_dll_name") &&
           !hx_attr_present(e, "script_name");
}

void hx_build_diff(hx_draft *d, const hx_element_read *e)
{
    const int expression = expression_form(e);
    if (expression) {
        if (!hx_attr_present(e, "expr")) {
            hx_draft_fail(d, e->line, "Control_Diff %d: attribute expr is missing (type"
                          " EXPRESSION: the state's rate)", e->id);
            return;
        }
        if (hx_attr_present(e, "usrsub_param_string") || hx_attr_present(e, "usrsub_dll_name")) {
            hx_draft_fail(d, e->line, "Control_Diff %d: type EXPRESSION takes no user routine"
                          " (usrsub_*)", e->id);
            return;
        }
    } else if (user_type(d, e) != 0) {
        return;
    } else if (hx_attr_present(e, "expr")) {
        hx_draft_fail(d, e->line, "Control_Diff %d: type USERSUB takes no expr (DIFSUB computes"
                      " the rate)", e->id);
        return;
    }
    hx_routine *r = push_routine(d, e, HX_ROUTINE_DIFF, !expression);
    if (r == NULL)
        return;
    r->ic[0] = hx_attr_number(e, "ic", 0.0);
    r->ic[1] = hx_attr_number(e, "ic_dot", 0.0);
    r->ic_given[1] = hx_attr_present(e, "ic_dot");
    r->implicit = hx_attr_number(e, "is_implicit", 0.0) != 0.0;
    r->static_hold = hx_attr_number(e, "is_static_hold", 0.0) != 0.0;
    if (expression)
        hx_draft_parse_expression(d, e, "expr", &r->program);
}

const hx_attr_spec hx_motion_attrs[] = {
    ID, TEXT("type"), REQUIRED("joint_id", HX_ATTR_INT), TEXT("joint_type"),
    TEXT("motion_type"), TEXT("val_type"), REAL("ic_disp"), REAL("ic_vel"), TEXT("expr"),
    USER_CALL, END};

/* type="EXPRESSION" (or no type and no user routine): the motion is expr, a
 * function of TIME (docs/interface.md §7.12), parsed here, linked once the
 * model is whole (hx_draft_resolve_routines); else MOTSUB's. */
static int expression_motion(hx_draft *d, const hx_element_read *e)
{
    if (!expression_form(e))
        return user_type(d, e) != 0 ? -1 : 0;
    if (!hx_attr_present(e, "expr")) {
        hx_draft_fail(d, e->line, "Motion_Joint %d: attribute expr is missing (type EXPRESSION:"
                      " the motion as a function of TIME)", e->id);
        return -1;
    }
    if (hx_attr_present(e, "usrsub_param_string") || hx_attr_present(e, "usrsub_dll_name")) {
        hx_draft_fail(d, e->line, "Motion_Joint %d: type EXPRESSION takes no user routine"
                      " (usrsub_*)", e->id);
        return -1;
    }
    return 1;
}

void hx_build_motion(hx_draft *d, const hx_element_read *e)
{
    const int expression = expression_motion(d, e);
    if (expression < 0)
        return;
    if (!expression && hx_attr_present(e, "expr")) {
        hx_draft_fail(d, e->line, "Motion_Joint %d: type USERSUB takes no expr (MOTSUB computes"
                      " the motion)", e->id);
        return;
    }
    const char *val_type = hx_attr_text(e, "val_type");
    if (val_type == NULL)
        val_type = "D";
    if (strlen(val_type) != 1 || strchr("DVAdva", val_type[0]) == NULL) {
        hx_draft_fail(d, e->line, "Motion_Joint %d: val_type \"%s\": expected D, V or A", e->id,
                      val_type);
        return;
    }
    const char *motion_type = hx_attr_text(e, "motion_type");
    if (motion_type != NULL && strcasecmp(motion_type, "R") != 0 &&
        strcasecmp(motion_type, "T") != 0) {
        hx_draft_fail(d, e->line, "Motion_Joint %d: motion_type \"%s\": expected R or T", e->id,
                      motion_type);
        return;
    }
    hx_routine *r = push_routine(d, e, HX_ROUTINE_MOTION, !expression);
    if (r == NULL)
        return;
    if (expression && hx_draft_parse_expression(d, e, "expr", &r->program) != 0)
        return;
    r->val_type = (char)(val_type[0] & ~0x20); /* upper case */
    r->ic[0] = hx_attr_number(e, "ic_disp", 0.0);
    r->ic[1] = hx_attr_number(e, "ic_vel", 0.0);
    r->ic_given[0] = hx_attr_present(e, "ic_disp");
    r->ic_given[1] = hx_attr_present(e, "ic_vel");
    r->joint_id = hx_attr_int(e, "joint_id", 0);
    r->motion_type = motion_type == NULL ? 0 : (char)(motion_type[0] & ~0x20);
}

/* The routine index of the Control_Diff in slot, or -1. */
static int diff_of_slot(const hx_model *m, int slot)
{
    for (int k = 0; k < m->nroutines; ++k)
        if (m->routines[k].kind == HX_ROUTINE_DIFF && m->routines[k].slot == slot)
            return k;
    return -1;
}

/* The expression Control_Diff whose rate (DIF1) routine k's program reads
 * through input j, when that one is computed after the DIFSUBs too; else -1. */
static int rate_read(const hx_model *m, int k, int j)
{
    const hx_expr_input *in = &hx_expr_inputs(m->routines[k].program)[j];
    if (in->kind != HX_EXPR_INPUT_DIF1)
        return -1;
    const int r = diff_of_slot(m, in->index[0]);
    return r >= 0 && m->routines[r].program != NULL && !m->routines[r].implicit ? r : -1;
}

/* An implicit Control_Diff's residual (docs/interface.md §7.10) reads its own
 * rate, and the rates of no explicit Control_Diff by expression (those are
 * computed after the implicit ones are solved). */
static int check_implicit(hx_draft *d, int k)
{
    hx_model *m = d->m;
    const hx_routine *r = &m->routines[k];
    const hx_expr_input *in = hx_expr_inputs(r->program);
    int own = 0;
    for (int j = 0; j < hx_expr_input_count(r->program); ++j) {
        if (in[j].kind != HX_EXPR_INPUT_DIF1)
            continue;
        own |= in[j].index[0] == r->slot;
        const int q = rate_read(m, k, j);
        if (q >= 0) {
            char name[64], what[HX_MESSAGE_MAX];
            snprintf(what, sizeof what, "%s:%d:%d: %s: an implicit Control_Diff's residual reads"
                     " the rate of Control_Diff %d (line %d), an explicit one by expression,"
                     " which is computed after the implicit ones are solved", d->path,
                     in[j].line, in[j].column, hx_expr_input_text(&in[j], name, sizeof name),
                     m->routines[q].id, m->routines[q].line);
            hx_draft_fail_expression(d, "Control_Diff", r->id, "expr", what);
            return -1;
        }
    }
    if (own)
        return 0;
    hx_draft_fail(d, r->line, "Control_Diff %d: is_implicit=\"TRUE\": expr does not read"
                  " DIF1(%d), the element's own rate: such a residual is an algebraic"
                  " constraint on the state, not a differential equation, which the harness"
                  " does not solve", r->id, r->id);
    return -1;
}

/* Links routine k's program; refuses a rate that reads itself. */
static int link_diff(hx_draft *d, int k)
{
    hx_model *m = d->m;
    hx_routine *r = &m->routines[k];
    hx_message why;
    if (hx_expr_link_loop(r->program, m, &why) != 0) {
        hx_draft_fail_expression(d, "Control_Diff", r->id, "expr", why.text);
        return -1;
    }
    const hx_expr_input *in = hx_expr_inputs(r->program);
    for (int j = 0; j < hx_expr_input_count(r->program); ++j) {
        if (in[j].variable >= 0)
            r->reads_variables = 1;
        if (in[j].kind == HX_EXPR_INPUT_MEASURE)
            for (int i = 0; i < in[j].nids && i < 4; ++i)
                if (in[j].index[i] >= 0)
                    m->markers[in[j].index[i]].tracked = 1;
        if (!r->implicit && rate_read(m, k, j) == k) {
            char name[64], what[HX_MESSAGE_MAX];
            snprintf(what, sizeof what, "%s:%d:%d: %s: a Control_Diff's rate reads its own rate"
                     " (an algebraic loop, which the harness does not solve)", d->path,
                     in[j].line, in[j].column, hx_expr_input_text(&in[j], name, sizeof name));
            hx_draft_fail_expression(d, "Control_Diff", r->id, "expr", what);
            return -1;
        }
    }
    return 0;
}

/* Links a Motion_Joint's expression: TIME is all it may read (its rate and
 * acceleration are taken in time, expr/time_derivative.h); any other input
 * is refused at its file:line:column. */
static int link_motion(hx_draft *d, hx_routine *r)
{
    hx_message why;
    if (hx_expr_link(r->program, d->m, &why) != 0) {
        hx_draft_fail_expression(d, "Motion_Joint", r->id, "expr", why.text);
        return -1;
    }
    const hx_expr_input *in = hx_expr_inputs(r->program);
    const int n = hx_expr_input_count(r->program);
    while (in < hx_expr_inputs(r->program) + n && in->kind == HX_EXPR_INPUT_TIME)
        ++in;
    if (in == hx_expr_inputs(r->program) + n)
        return 0;
    char name[64], what[HX_MESSAGE_MAX];
    snprintf(what, sizeof what, "%s:%d:%d: %s: a motion's expression reads TIME alone (the"
             " harness takes its rate and acceleration in time; a motion of the state is not"
             " simulated)", d->path, in->line, in->column,
             hx_expr_input_text(in, name, sizeof name));
    hx_draft_fail_expression(d, "Motion_Joint", r->id, "expr", what);
    return -1;
}

/* The expression Control_Diffs linked and ordered, each after those whose
 * rate it reads (passes until none is added: they are few, this runs once);
 * a cycle of DIF1 is refused naming each element of it with its line. */
static int order_diffs(hx_draft *d)
{
    hx_model *m = d->m;
    m->diff_order = malloc(sizeof(int) * (size_t)(m->nroutines + 1));
    unsigned char *ordered = calloc((size_t)m->nroutines + 1, 1);
    if (m->diff_order == NULL || ordered == NULL) {
        free(ordered);
        hx_draft_fail(d, 0, "out of memory");
        return -1;
    }
    int total = 0;
    for (int k = 0; k < m->nroutines; ++k)
        if (m->routines[k].program != NULL && m->routines[k].kind == HX_ROUTINE_DIFF) {
            if (link_diff(d, k) != 0) {
                free(ordered);
                return -1;
            }
            total += !m->routines[k].implicit;
        }
    for (int k = 0; k < m->nroutines; ++k)
        if (m->routines[k].program != NULL && m->routines[k].kind == HX_ROUTINE_DIFF &&
            m->routines[k].implicit && check_implicit(d, k) != 0) {
            free(ordered);
            return -1;
        }
    int count = 0;
    for (int added = 1; added && count < total;) {
        added = 0;
        for (int k = 0; k < m->nroutines; ++k) {
            if (m->routines[k].program == NULL || m->routines[k].kind != HX_ROUTINE_DIFF ||
                m->routines[k].implicit || ordered[k])
                continue;
            int ready = 1;
            for (int j = 0; j < hx_expr_input_count(m->routines[k].program) && ready; ++j) {
                const int r = rate_read(m, k, j);
                ready = r < 0 || ordered[r];
            }
            if (ready)
                ordered[k] = 1, m->diff_order[count++] = k, added = 1;
        }
    }
    m->ndiff_programs = count;
    if (count < total) {
        char text[HX_MESSAGE_MAX] = "";
        size_t used = 0;
        int first = -1;
        for (int k = 0; k < m->nroutines; ++k) {
            const hx_routine *r = &m->routines[k];
            if (r->program == NULL || r->kind != HX_ROUTINE_DIFF || r->implicit || ordered[k])
                continue;
            first = first < 0 ? k : first;
            for (int j = 0; j < hx_expr_input_count(r->program); ++j) {
                const int q = rate_read(m, k, j);
                if (q >= 0 && !ordered[q] && used < sizeof text)
                    used += (size_t)snprintf(text + used, sizeof text - used,
                                             "%s%s:%d: Control_Diff %d reads DIF1(%d)",
                                             used == 0 ? "" : ", ", d->path, r->line, r->id,
                                             m->routines[q].id);
            }
        }
        hx_draft_fail(d, m->routines[first].line, "a cycle of Control_Diff rates (an algebraic"
                      " loop, which the harness does not solve): %s", text);
    }
    free(ordered);
    return d->failed ? -1 : 0;
}

int hx_draft_resolve_routines(hx_draft *d)
{
    hx_model *m = d->m;
    if (order_diffs(d) != 0)
        return -1;
    for (int k = 0; k < m->nroutines; ++k) {
        hx_routine *r = &m->routines[k];
        if (r->kind != HX_ROUTINE_MOTION)
            continue;
        const int joint = hx_model_joint(m, r->joint_id);
        if (joint < 0) {
            hx_draft_fail(d, r->line, "Motion_Joint %d: joint_id %d is not a Constraint_Joint the"
                          " harness reads (REVOLUTE or TRANSLATIONAL)", r->id, r->joint_id);
            return -1;
        }
        /* a body's one joint to ground moves the body; any other revolute, translational
         * or cylindrical joint is a row of the constraint system, driven in displacement,
         * velocity or acceleration (docs/interface.md §7.12) */
        const enum hx_joint_type type = m->joints[joint].type;
        if (!m->joints[joint].reduced && type != HX_JOINT_REVOLUTE &&
            type != HX_JOINT_TRANSLATIONAL && type != HX_JOINT_CYLINDRICAL) {
            hx_draft_fail(d, r->line, "Motion_Joint %d: joint %d is %s, which has no coordinate"
                          " to drive (REVOLUTE, TRANSLATIONAL or CYLINDRICAL joints only)",
                          r->id, r->joint_id, hx_joint_type_name(type));
            return -1;
        }
        if (type == HX_JOINT_CYLINDRICAL && r->motion_type == 0) {
            hx_draft_fail(d, r->line, "Motion_Joint %d: joint %d is cylindrical: motion_type"
                          " must say which of its coordinates is driven (R its rotation, T its"
                          " translation)", r->id, r->joint_id);
            return -1;
        }
        if (!m->joints[joint].reduced && r->val_type == 'V' && r->ic_given[0]) {
            hx_draft_fail(d, r->line, "Motion_Joint %d: ic_disp on joint %d, which is not a"
                          " body's only joint to ground: a velocity motion there starts from"
                          " the coordinate where the model places the joint (leave ic_disp"
                          " out)", r->id, r->joint_id);
            return -1;
        }
        const char freedom = type == HX_JOINT_CYLINDRICAL ? r->motion_type
                             : type == HX_JOINT_TRANSLATIONAL ? 'T'
                                                              : 'R';
        if (r->motion_type != 0 && r->motion_type != freedom) {
            hx_draft_fail(d, r->line, "Motion_Joint %d: motion_type %c on joint %d, a %s joint",
                          r->id, r->motion_type, r->joint_id,
                          freedom == 'T' ? "translational" : "revolute");
            return -1;
        }
        for (int i = 0; i < k; ++i)
            if (m->routines[i].kind == HX_ROUTINE_MOTION && m->routines[i].joint == joint) {
                hx_draft_fail(d, r->line, "Motion_Joint %d: joint %d is driven by Motion_Joint %d"
                              " too (line %d)", r->id, r->joint_id, m->routines[i].id,
                              m->routines[i].line);
                return -1;
            }
        r->joint = joint;
        r->motion_type = freedom;
        if (r->program != NULL && link_motion(d, r) != 0)
            return -1;
    }
    return 0;
}
