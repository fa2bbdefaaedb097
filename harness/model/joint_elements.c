/*
 * Constraint_Joint and Constraint_Jprim (docs/interface.md §7.14): a joint's
 * type, its markers and, for a RACK_PINION or a SCREW, its pitch_diameter or
 * pitch; the markers are resolved once the model is whole (resolve.c).
 */
#include <math.h>

#include "model/draft.h"
#include "model/joint_elements.h"
#include "model/xml_attrs.h"

const hx_attr_spec hx_joint_attrs[] = {
    ID, REQUIRED("type", HX_ATTR_TEXT), REQUIRED("i_marker_id", HX_ATTR_INT),
    REQUIRED("j_marker_id", HX_ATTR_INT), REAL("pitch_diameter"), REAL("pitch"),
    IGNORED("is_virtual"), END};

/* A RACK_PINION's pitch_diameter (> 0) and a SCREW's pitch (not 0): required. */
static int gearing_values(hx_draft *d, const hx_element_read *e, hx_joint *j)
{
    const char *name = j->type == HX_JOINT_RACKPIN ? "pitch_diameter" : "pitch";
    if (j->type != HX_JOINT_RACKPIN && j->type != HX_JOINT_SCREW)
        return 0;
    const double value = hx_attr_number(e, name, 0.0);
    if (!hx_attr_present(e, name)) {
        hx_draft_fail(d, e->line, "Constraint_Joint %d: a %s joint needs %s", e->id,
                      hx_joint_type_name(j->type), name);
        return -1;
    }
    if (j->type == HX_JOINT_RACKPIN ? !(value > 0.0) : !(value != 0.0 && isfinite(value))) {
        hx_draft_fail(d, e->line, "Constraint_Joint %d: %s = %g: expected %s", e->id, name,
                      value, j->type == HX_JOINT_RACKPIN ? "a diameter > 0" : "a pitch not 0");
        return -1;
    }
    j->pitch_diameter = j->type == HX_JOINT_RACKPIN ? value : 0.0;
    j->pitch = j->type == HX_JOINT_SCREW ? value : 0.0;
    return 0;
}

/* A Constraint_Joint or, primitive, a Constraint_Jprim: its own types, its own ids. */
static void build_any_joint(hx_draft *d, const hx_element_read *e, int primitive)
{
    hx_model *m = d->m;
    const char *element = primitive ? "Constraint_Jprim" : "Constraint_Joint";
    if ((primitive ? hx_model_primitive(m, e->id) : hx_model_joint(m, e->id)) >= 0) {
        hx_draft_fail(d, e->line, "%s %d is defined twice", element, e->id);
        return;
    }
    const int jt = hx_joint_type_from_name(hx_attr_text(e, "type"));
    if (jt < 0 || hx_joint_type_is_primitive((enum hx_joint_type)jt) != primitive) {
        hx_draft_fail(d, e->line, "%s %d: type \"%s\" is not one the harness simulates (%s)",
                      element, e->id, hx_attr_text(e, "type"),
                      primitive ? "ATPOINT, INLINE, INPLANE, ORIENTATION, PARALLEL_AXES or"
                                  " PERPENDICULAR"
                                : "FIXED, REVOLUTE, TRANSLATIONAL, CYLINDRICAL, SPHERICAL,"
                                  " UNIVERSAL, HOOKE, PLANAR, CONSTANT_VELOCITY, RACK_PINION"
                                  " or SCREW");
        return;
    }
    hx_joint *j = hx_draft_push(d, (void **)&m->joints, &m->njoints, &d->cap_joints, sizeof *j,
                                (void **)&d->rjoints, sizeof(raw_refs));
    if (j == NULL)
        return;
    j->id = e->id, j->type = (enum hx_joint_type)jt, j->line = e->line;
    j->pitch_diameter = j->pitch = 0.0;
    if (gearing_values(d, e, j) != 0)
        return;
    int *ids = d->rjoints[m->njoints - 1].ids;
    ids[0] = hx_attr_int(e, "i_marker_id", 0), ids[1] = hx_attr_int(e, "j_marker_id", 0);
}

void hx_build_joint(hx_draft *d, const hx_element_read *e)
{
    build_any_joint(d, e, 0);
}

void hx_build_jprim(hx_draft *d, const hx_element_read *e)
{
    build_any_joint(d, e, 1);
}

