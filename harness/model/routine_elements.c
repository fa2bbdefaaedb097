/*
 * The user routines that are not forces (routine_elements.h). Attribute names
 * are MotionSolve's (docs/interface.md §7.12).
 */
#include <string.h>
#include <strings.h>

#include "model/draft.h"
#include "model/request_elements.h"
#include "model/routine_elements.h"
#include "model/xml_attrs.h"

static hx_routine *push_routine(hx_draft *d, const hx_element_read *e, enum hx_routine_kind kind)
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
    if (hx_draft_user_call(d, e, &r->user) != 0)
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
        push_routine(d, e, HX_ROUTINE_REQUEST);
}

void hx_build_user_variable(hx_draft *d, const hx_element_read *e)
{
    if (hx_attr_present(e, "expr")) {
        hx_draft_fail(d, e->line, "Reference_Variable %d: type USERSUB takes no expr (VARSUB"
                      " computes the value)", e->id);
        return;
    }
    hx_routine *r = push_routine(d, e, HX_ROUTINE_VARIABLE);
    if (r != NULL)
        r->ic[0] = hx_attr_number(e, "ic", 0.0);
}

const hx_attr_spec hx_diff_attrs[] = {
    ID, TEXT("type"), {"is_implicit", HX_ATTR_BOOL, 0}, REAL("ic"), REAL("ic_dot"),
    {"is_static_hold", HX_ATTR_BOOL, 0}, IGNORED("expr"), USER_CALL, END};

void hx_build_diff(hx_draft *d, const hx_element_read *e)
{
    if (user_type(d, e) != 0)
        return;
    hx_routine *r = push_routine(d, e, HX_ROUTINE_DIFF);
    if (r == NULL)
        return;
    r->ic[0] = hx_attr_number(e, "ic", 0.0);
    r->ic[1] = hx_attr_number(e, "ic_dot", 0.0);
    r->implicit = hx_attr_number(e, "is_implicit", 0.0) != 0.0;
    r->static_hold = hx_attr_number(e, "is_static_hold", 0.0) != 0.0;
}

const hx_attr_spec hx_motion_attrs[] = {
    ID, TEXT("type"), REQUIRED("joint_id", HX_ATTR_INT), TEXT("joint_type"),
    TEXT("motion_type"), TEXT("val_type"), REAL("ic_disp"), REAL("ic_vel"), IGNORED("expr"),
    USER_CALL, END};

void hx_build_motion(hx_draft *d, const hx_element_read *e)
{
    if (user_type(d, e) != 0)
        return;
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
    hx_routine *r = push_routine(d, e, HX_ROUTINE_MOTION);
    if (r == NULL)
        return;
    r->val_type = (char)(val_type[0] & ~0x20); /* upper case */
    r->ic[0] = hx_attr_number(e, "ic_disp", 0.0);
    r->ic[1] = hx_attr_number(e, "ic_vel", 0.0);
    r->ic_given[0] = hx_attr_present(e, "ic_disp");
    r->ic_given[1] = hx_attr_present(e, "ic_vel");
    r->joint_id = hx_attr_int(e, "joint_id", 0);
    r->motion_type = motion_type == NULL ? 0 : (char)(motion_type[0] & ~0x20);
}

int hx_draft_resolve_routines(hx_draft *d)
{
    hx_model *m = d->m;
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
         * or cylindrical joint is a row of the constraint system, driven in displacement
         * (docs/interface.md §7.14) */
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
        if (!m->joints[joint].reduced && r->val_type != 'D') {
            hx_draft_fail(d, r->line, "Motion_Joint %d: val_type %c on joint %d, which is not a"
                          " body's only joint to ground: the harness drives such a joint in"
                          " displacement (val_type D) only", r->id, r->val_type, r->joint_id);
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
    }
    return 0;
}
