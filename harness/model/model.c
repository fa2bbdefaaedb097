/* Model look-ups and release (model.h). */
#include "model/model.h"

#include <stdlib.h>
#include <strings.h>

#include "model/expr/expr.h"

int hx_model_marker(const hx_model *m, int id)
{
    if (m->marker_slot_count == 0)
        return -1;
    const unsigned mask = (unsigned)m->marker_slot_count - 1u; /* a power of two */
    for (unsigned s = ((unsigned)id * 2654435761u) & mask;; s = (s + 1) & mask) {
        const int k = m->marker_slots[s];
        if (k < 0)
            return -1;
        if (m->markers[k].id == id)
            return k;
    }
}

int hx_model_body(const hx_model *m, int id)
{
    for (int k = 0; k < m->nbodies; ++k)
        if (m->bodies[k].id == id)
            return k;
    return -1;
}

static int find_joint(const hx_model *m, int id, int primitive)
{
    for (int k = 0; k < m->njoints; ++k)
        if (m->joints[k].id == id && hx_joint_type_is_primitive(m->joints[k].type) == primitive)
            return k;
    return -1;
}

int hx_model_joint(const hx_model *m, int id)
{
    return find_joint(m, id, 0);
}

int hx_model_primitive(const hx_model *m, int id)
{
    return find_joint(m, id, 1);
}

/* MotionSolve's names, in enum hx_joint_type's order; HOOKE is Adams's too;
 * the primitives' are Constraint_Jprim's types and Adams' JPRIM words */
static const char *const joint_type_names[] = {"REVOLUTE", "TRANSLATIONAL", "FIXED",
                                               "CYLINDRICAL", "SPHERICAL", "UNIVERSAL",
                                               "HOOKE", "PLANAR", "CONSTANT_VELOCITY",
                                               "RACK_PINION", "SCREW", "ATPOINT", "INLINE",
                                               "INPLANE", "ORIENTATION", "PARALLEL_AXES",
                                               "PERPENDICULAR"};

int hx_joint_type_is_primitive(enum hx_joint_type type)
{
    return type >= HX_JOINT_ATPOINT;
}

const char *hx_joint_element_name(enum hx_joint_type type)
{
    return hx_joint_type_is_primitive(type) ? "Constraint_Jprim" : "Constraint_Joint";
}

const char *hx_joint_type_name(enum hx_joint_type type)
{
    return joint_type_names[type];
}

int hx_joint_type_from_name(const char *name)
{
    /* Adams' JOINT words where they differ from MotionSolve's */
    if (strcasecmp(name, "CONVEL") == 0)
        return HX_JOINT_CONVEL;
    if (strcasecmp(name, "RACKPIN") == 0)
        return HX_JOINT_RACKPIN;
    for (int k = 0; k < (int)(sizeof joint_type_names / sizeof joint_type_names[0]); ++k)
        if (strcasecmp(name, joint_type_names[k]) == 0)
            return k;
    return -1;
}

const char *hx_model_string(const hx_model *m, int id)
{
    for (int k = 0; k < m->nstrings; ++k)
        if (m->strings[k].id == id)
            return m->strings[k].text;
    return NULL;
}

int hx_model_variable(const hx_model *m, int id)
{
    for (int k = 0; k < m->nvariables; ++k)
        if (m->variables[k].id == id)
            return k;
    return -1;
}

int hx_model_array(const hx_model *m, int id)
{
    for (int k = 0; k < m->narrays; ++k)
        if (m->arrays[k].id == id)
            return k;
    return -1;
}

int hx_model_find_stateeqn(const hx_model *m, const char *text, int *index, hx_message *msg)
{
    const char *number = strncasecmp(text, "stateeqn:", 9) == 0 ? text + 9 : text;
    char *end;
    const long id = strtol(number, &end, 10);
    if (end == number || *end != '\0')
        return hx_fail(msg, "'%s' is not a Force_StateEqn id (ID or stateeqn:ID)", text);
    for (int k = 0; k < m->nstateeqns; ++k)
        if (m->stateeqns[k].id == id) {
            *index = k;
            return 0;
        }
    return hx_fail(msg, "the model has no Force_StateEqn %ld", id);
}

int hx_force_output_axes(const hx_force *f)
{
    return f->interface == HX_FORCE_GFOSUB ? f->ref_marker : f->j_marker;
}

int hx_force_routine_values(enum hx_user_output part)
{
    return part == HX_OUTPUT_FORCE_AND_TORQUE ? 6 : part < HX_OUTPUT_SCALAR_FORCE ? 3 : 1;
}

const char *hx_force_element_name(const hx_force *f)
{
    if (f->interface == HX_FORCE_FIESUB)
        return "Force_Field";
    if (f->one_body)
        return "Force_Vector_OneBody";
    return f->part >= HX_OUTPUT_SCALAR_FORCE ? "Force_Scalar_TwoBody" : "Force_Vector_TwoBody";
}

const char *hx_load_element_name(const hx_load *l)
{
    switch (l->builtin) {
    case HX_LOAD_SPRINGDAMPER: return "Force_SpringDamper";
    case HX_LOAD_BUSHING: return "Force_Bushing";
    case HX_LOAD_BEAM: return "Force_Beam";
    case HX_LOAD_FIELD: return "Force_Field";
    case HX_LOAD_AS_WRITTEN: break;
    }
    if (l->kind != HX_LOAD_VECTOR)
        return "Force_Scalar_TwoBody";
    return l->j_marker >= 0 ? "Force_Vector_TwoBody" : "Force_Vector_OneBody";
}

int hx_model_routine(const hx_model *m, enum hx_routine_kind kind, int id)
{
    for (int k = 0; k < m->nroutines; ++k)
        if (m->routines[k].kind == kind && m->routines[k].id == id)
            return k;
    return -1;
}

const char *hx_routine_element_name(enum hx_routine_kind kind)
{
    static const char *const names[HX_ROUTINE_KINDS] = {"Post_Request", "Reference_Variable",
                                                        "Control_Diff", "Motion_Joint"};
    return names[kind];
}

int hx_model_find_force(const hx_model *m, const char *text, int *index, hx_message *msg)
{
    int want = -1; /* -1 any, else the interface */
    const char *number = text;
    if (strncasecmp(text, "vector:", 7) == 0)
        want = HX_FORCE_GFOSUB, number = text + 7;
    else if (strncasecmp(text, "field:", 6) == 0)
        want = HX_FORCE_FIESUB, number = text + 6;
    char *end;
    const long id = strtol(number, &end, 10);
    if (end == number || *end != '\0')
        return hx_fail(msg, "'%s' is not a force element id (ID, vector:ID or field:ID)", text);
    int found = 0;
    for (int k = 0; k < m->nforces; ++k)
        if (m->forces[k].id == id && (want < 0 || (int)m->forces[k].interface == want)) {
            *index = k;
            ++found;
        }
    if (found == 1)
        return 0;
    if (found > 1)
        return hx_fail(msg, "element %ld is both a Force_Vector_TwoBody and a Force_Field: write"
                       " vector:%ld or field:%ld", id, id, id);
    return hx_fail(msg, "the model has no %s %ld", want == HX_FORCE_GFOSUB ? "Force_Vector_TwoBody"
                   : want == HX_FORCE_FIESUB ? "Force_Field" : "Force_Vector_TwoBody or Force_Field",
                   id);
}

int hx_model_spline(const hx_model *m, int id)
{
    for (int k = 0; k < m->nsplines; ++k)
        if (m->splines[k].id == id)
            return k;
    return -1;
}

int hx_model_curve(const hx_model *m, int id)
{
    for (int k = 0; k < m->ncurves; ++k)
        if (m->curves[k].id == id)
            return k;
    return -1;
}

static void free_user_call(hx_user_call *u)
{
    free(u->dll_name);
    free(u->fnc_name);
    free(u->der1_name);
    free(u->der2_name);
    free(u->der3_name);
    free(u->der4_name);
    free(u->par);
}

void hx_model_free(hx_model *m)
{
    if (m == NULL)
        return;
    for (int k = 0; k < m->ncouplers; ++k)
        free_user_call(&m->couplers[k].user);
    for (int k = 0; k < m->nforces; ++k)
        free_user_call(&m->forces[k].user);
    for (int k = 0; k < m->nstrings; ++k)
        free(m->strings[k].text);
    for (int k = 0; k < m->narrays; ++k) {
        free(m->arrays[k].numbers);
        free(m->arrays[k].variable_ids);
        free(m->arrays[k].variables);
    }
    for (int k = 0; k < m->nstateeqns; ++k) {
        free_user_call(&m->stateeqns[k].user);
        free(m->stateeqns[k].inputs);
        free(m->stateeqns[k].initial);
    }
    for (int k = 0; k < m->nroutines; ++k) {
        free_user_call(&m->routines[k].user);
        hx_expr_free(m->routines[k].program);
    }
    free(m->routines);
    free(m->diff_order);
    for (int k = 0; k < m->nsplines; ++k) {
        free(m->splines[k].x);
        free(m->splines[k].z);
        free(m->splines[k].y);
        free(m->splines[k].akima_slope);
        free(m->splines[k].cubic_slope);
    }
    free(m->splines);
    for (int k = 0; k < m->ncurves; ++k)
        free(m->curves[k].points);
    free(m->curves);
    for (int k = 0; k < m->npinputs; ++k)
        free(m->pinputs[k].variable_ids);
    for (int k = 0; k < m->npoutputs; ++k)
        free(m->poutputs[k].variable_ids);
    free(m->pinputs);
    free(m->poutputs);
    for (int k = 0; k < m->nexpressions; ++k)
        free(m->expressions[k].text);
    free(m->expressions);
    for (int k = 0; k < m->nrequests; ++k)
        for (int j = 0; j < 8; ++j)
            hx_expr_free(m->requests[k].f[j]);
    free(m->requests);
    for (int k = 0; k < m->ngcons; ++k)
        hx_expr_free(m->gcons[k].program);
    free(m->gcons);
    for (int k = 0; k < m->nvariables; ++k)
        hx_expr_free(m->variables[k].program);
    free(m->variables);
    free(m->variable_order);
    free(m->varsub_read_start);
    free(m->varsub_reads);
    free(m->loop_inputs);
    free(m->output_queries);
    free(m->arrays);
    free(m->stateeqns);
    free(m->bodies);
    free(m->markers);
    free(m->joints);
    free(m->couplers);
    free(m->forces);
    for (int k = 0; k < m->nloads; ++k) {
        hx_load *l = &m->loads[k];
        for (int i = 0; i < 3; ++i) {
            hx_expr_free(l->force[i]);
            hx_expr_free(l->torque[i]);
        }
        hx_expr_free(l->value);
    }
    free(m->loads);
    free(m->strings);
    free(m->marker_slots);
    free(m->path);
    free(m->dir);
    free(m);
}
