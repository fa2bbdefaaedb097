/* The elements that act at a marker (marker_elements.h). */
#include "model/marker_elements.h"

#include <stdio.h>

#include "model/expr/functions.h"

int hx_marker_between(int a, int b, int i, int j)
{
    return (a == i && (j < 0 || b == j)) || (b == i && (j < 0 || a == j));
}

/* What each function reads (docs/interface.md §8.3): a Force_Scalar_TwoBody
 * (SFORCE; a Force_SpringDamper, when no Force_Scalar_TwoBody has its id),
 * any Force_Vector element (VFORCE, VTORQ and GFORCE alike, as MotionSolve's
 * pages define them), a Force_Bushing (BUSHING), a Force_Beam (BEAM), a
 * Force_SpringDamper (SPDP), a Force_Field (FIELD: a linear one, or one calling
 * FIESUB). */
static int reads_load(int function, const hx_load *l, enum hx_load_builtin builtin)
{
    if (l->builtin != builtin)
        return 0;
    if (function == HX_FN_SFORCE)
        return l->kind != HX_LOAD_VECTOR;
    if (function == HX_FN_VFORCE || function == HX_FN_VTORQ || function == HX_FN_GFORCE)
        return l->kind == HX_LOAD_VECTOR;
    return builtin != HX_LOAD_AS_WRITTEN; /* the built-in element of its own function */
}

/* The built-in element a function names first (SFORCE: one as written). */
static enum hx_load_builtin builtin_of(int function)
{
    switch (function) {
    case HX_FN_BUSHING: return HX_LOAD_BUSHING;
    case HX_FN_BEAM: return HX_LOAD_BEAM;
    case HX_FN_FIELD: return HX_LOAD_FIELD;
    case HX_FN_SPDP: return HX_LOAD_SPRINGDAMPER;
    default: return HX_LOAD_AS_WRITTEN;
    }
}

static int reads_force(int function, const hx_force *f)
{
    const int scalar = f->part == HX_OUTPUT_SCALAR_FORCE || f->part == HX_OUTPUT_SCALAR_TORQUE;
    if (function == HX_FN_SFORCE)
        return f->interface == HX_FORCE_GFOSUB && scalar;
    if (function == HX_FN_FIELD)
        return f->interface == HX_FORCE_FIESUB;
    return (function == HX_FN_VFORCE || function == HX_FN_VTORQ || function == HX_FN_GFORCE) &&
           f->interface == HX_FORCE_GFOSUB && !scalar;
}

int hx_marker_element_find(const hx_model *m, int function, int id, int *force, int *index,
                           char *what, size_t size)
{
    const enum hx_load_builtin builtin = builtin_of(function);
    for (int k = 0; k < m->nloads; ++k)
        if (m->loads[k].id == id && reads_load(function, &m->loads[k], builtin)) {
            *force = 0, *index = k;
            return 0;
        }
    for (int k = 0; k < m->nforces; ++k)
        if (m->forces[k].id == id && reads_force(function, &m->forces[k])) {
            *force = 1, *index = k;
            return 0;
        }
    for (int k = 0; k < m->nloads && function == HX_FN_SFORCE; ++k)
        if (m->loads[k].id == id && reads_load(function, &m->loads[k], HX_LOAD_SPRINGDAMPER)) {
            *force = 0, *index = k;
            return 0;
        }
    switch (function) {
    case HX_FN_SFORCE:
        snprintf(what, size, "Force_Scalar_TwoBody or Force_SpringDamper (SFORCE) %d in the model",
                 id);
        break;
    case HX_FN_FIELD: snprintf(what, size, "Force_Field (FIELD) %d in the model", id); break;
    case HX_FN_BUSHING: snprintf(what, size, "Force_Bushing (BUSHING) %d in the model", id); break;
    case HX_FN_BEAM: snprintf(what, size, "Force_Beam (BEAM) %d in the model", id); break;
    case HX_FN_SPDP: snprintf(what, size, "Force_SpringDamper (SPDP) %d in the model", id); break;
    default:
        snprintf(what, size, "Force_Vector_TwoBody or Force_Vector_OneBody (VFORCE, VTORQUE,"
                 " GFORCE) %d in the model", id);
        break;
    }
    return -1;
}

int hx_marker_unsummed(const hx_model *m, int i, int j, char *what, size_t size)
{
    for (int k = 0; k < m->nstateeqns; ++k) {
        const hx_stateeqn *s = &m->stateeqns[k];
        if (hx_marker_between(s->i_marker, s->j_marker, i, j)) {
            snprintf(what, size, "Force_StateEqn %d (line %d)", s->id, s->line);
            return 1;
        }
    }
    /* a general constraint's force is read on a moving body alone (model/expr/link.c) */
    for (int k = 0; k < m->ngcons && j < 0; ++k) {
        const int body = m->gcons[k].i_marker == i ? m->markers[i].body : -1;
        if (body >= 0 && m->bodies[body].is_ground) {
            snprintf(what, size, "Constraint_General %d (line %d)", m->gcons[k].id,
                     m->gcons[k].line);
            return 1;
        }
    }
    return 0;
}
