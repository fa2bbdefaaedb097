/*
 * JOINT, JPRIM, COUPLER, MOTION and GCON (docs/interface.md §9.4) into
 * Constraint_Joint, Constraint_Jprim, Constraint_Coupler, Motion_Joint and
 * Constraint_General. Which joints the harness simulates
 * is decided before (simulated.c): here every entry built is one it holds.
 */
#include <stdio.h>
#include <string.h>

#include "model/adm/translate.h"
#include "model/model.h"

/* The joint types of the JOINT table, in its order. */
static const char *const joint_types[] = {"REVOLUTE", "TRANSLATIONAL", "CYLINDRICAL", "SPHERICAL",
                                          "UNIVERSAL", "HOOKE", "CONVEL", "FIXED", "PLANAR",
                                          "RACKPIN", "SCREW", "PARALLEL_AXES", "PERPENDICULAR",
                                          "INLINE", "INPLANE", "ORIENTATION"};

const char *hx_adm_joint_type(const hx_adm_entry *e)
{
    for (size_t k = 0; k < sizeof joint_types / sizeof joint_types[0]; ++k)
        if (hx_adm_has(e, joint_types[k]))
            return joint_types[k];
    return NULL;
}

int hx_adm_build_joint(hx_adm_reader *r, hx_adm_entry *e)
{
    int ntypes = 0;
    for (size_t k = 0; k < sizeof joint_types / sizeof joint_types[0]; ++k)
        ntypes += hx_adm_has(e, joint_types[k]);
    if (ntypes != 1)
        return hx_adm_fail(r, e, e->line, "give the joint's type, one of REVOLUTE, TRANSLATIONAL,"
                           " CYLINDRICAL, SPHERICAL, ... (%d given)", ntypes);
    const char *type = hx_adm_joint_type(e);
    const int jt = hx_joint_type_from_name(type);
    hx_adm_element el;
    hx_adm_element_init(&el, "Constraint_Joint");
    /* MotionSolve's word (CONVEL is CONSTANT_VELOCITY, RACKPIN RACK_PINION) */
    hx_adm_element_text(&el, "type", jt >= 0 ? hx_joint_type_name((enum hx_joint_type)jt) : type);
    hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
    hx_adm_element_number(&el, "j_marker_id", hx_adm_ref(e, "J"));
    /* RACKPIN's PD= and SCREW's PITCH= (docs/interface.md §9.4) */
    const int rackpin = jt == HX_JOINT_RACKPIN, screw = jt == HX_JOINT_SCREW;
    if (rackpin || screw) {
        const char *key = rackpin ? "PD" : "PITCH";
        const hx_adm_value *v = hx_adm_get(e, key);
        if (!v->present)
            return hx_adm_fail(r, e, e->line, "a %s joint needs %s= (%s)", type, key,
                               rackpin ? "the pinion's pitch diameter"
                                       : "the travel per turn of the screw");
        const double value = hx_adm_number(e, key, 0, 0.0);
        if (rackpin ? !(value > 0.0) : !(value != 0.0))
            return hx_adm_fail(r, e, v->line, "%s=%g: expected %s", key, value,
                               rackpin ? "a diameter > 0" : "a pitch not 0");
        hx_adm_element_number(&el, rackpin ? "pitch_diameter" : "pitch", value);
    }
    return hx_adm_element_build(r, e, &el, NULL);
}

/* The primitives of JPRIM: the words are Constraint_Jprim's types. */
static const char *const primitive_types[] = {"ATPOINT", "INLINE", "INPLANE", "ORIENTATION",
                                              "PARALLEL_AXES", "PERPENDICULAR"};

int hx_adm_build_jprim(hx_adm_reader *r, hx_adm_entry *e)
{
    const char *type = NULL;
    int ntypes = 0;
    for (size_t k = 0; k < sizeof primitive_types / sizeof primitive_types[0]; ++k)
        if (hx_adm_has(e, primitive_types[k]))
            type = primitive_types[k], ++ntypes;
    if (ntypes != 1)
        return hx_adm_fail(r, e, e->line, "give the primitive, one of ATPOINT, INLINE, INPLANE,"
                           " ORIENTATION, PARALLEL_AXES, PERPENDICULAR (%d given)", ntypes);
    hx_adm_element el;
    hx_adm_element_init(&el, "Constraint_Jprim");
    hx_adm_element_text(&el, "type", type);
    hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
    hx_adm_element_number(&el, "j_marker_id", hx_adm_ref(e, "J"));
    return hx_adm_element_build(r, e, &el, NULL);
}

int hx_adm_build_coupler(hx_adm_reader *r, hx_adm_entry *e)
{
    const hx_adm_value *joints = hx_adm_get(e, "JOINTS");
    hx_adm_element el;
    hx_adm_element_init(&el, "Constraint_Coupler");
    static const char *const joint_attrs[] = {"joint1_id", "joint2_id", "joint3_id"};
    static const char *const freedom_attrs[] = {"freedom_1", "freedom_2", "freedom_3"};
    for (int k = 0; k < joints->count; ++k)
        hx_adm_element_number(&el, joint_attrs[k], joints->numbers[k]);
    /* TYPE=T:R[:R]: each joint's freedom */
    const char *type = hx_adm_text(e, "TYPE");
    static const char *const letters[] = {"T", "R"};
    if (type != NULL) {
        int k = 0;
        for (const char *p = type; *p != '\0'; ++k) {
            const size_t n = strcspn(p, ":");
            const int t = n == 1 && (*p == 'T' || *p == 't') ? 0
                          : n == 1 && (*p == 'R' || *p == 'r') ? 1 : -1;
            if (t < 0 || k >= joints->count)
                return hx_adm_fail(r, e, hx_adm_get(e, "TYPE")->line, "TYPE=%s: expected T or R"
                                   " for each of its %d joints (TYPE=T:R)", type, joints->count);
            hx_adm_element_text(&el, freedom_attrs[k], letters[t]);
            p += n + (p[n] == ':');
        }
        if (k != joints->count)
            return hx_adm_fail(r, e, hx_adm_get(e, "TYPE")->line, "TYPE=%s names %d freedoms for"
                               " %d joints", type, k, joints->count);
    }
    const hx_adm_value *scales = hx_adm_get(e, "SCALES");
    const int user = hx_adm_has(e, "FUNCTION");
    if (user == scales->present)
        return hx_adm_fail(r, e, e->line, "give SCALES or FUNCTION=USER(...) (one of them)");
    char coefficients[160] = "";
    if (scales->present) {
        if (scales->count != joints->count)
            return hx_adm_fail(r, e, scales->line, "SCALES gives %d numbers for %d joints",
                               scales->count, joints->count);
        size_t used = 0;
        for (int k = 0; k < scales->count; ++k)
            used += (size_t)snprintf(coefficients + used, sizeof coefficients - used, "%s%.17g",
                                     k ? ", " : "", scales->numbers[k]);
        hx_adm_element_text(&el, "coefficients", coefficients);
    } else {
        if (!hx_adm_is_user(hx_adm_text(e, "FUNCTION")))
            return hx_adm_fail(r, e, hx_adm_get(e, "FUNCTION")->line, "FUNCTION=%s: expected"
                               " USER(...) (COUSUB)", hx_adm_text(e, "FUNCTION"));
        static const char *const der[] = {"usrsub_der1_name", "usrsub_der2_name", NULL};
        if (hx_adm_element_user(r, e, &el, der) != 0)
            return -1;
    }
    return hx_adm_element_build(r, e, &el, NULL);
}

int hx_adm_build_motion(hx_adm_reader *r, hx_adm_entry *e)
{
    hx_adm_element el;
    hx_adm_element_init(&el, "Motion_Joint");
    const int user = hx_adm_is_user(hx_adm_text(e, "FUNCTION"));
    if (!user && hx_adm_no_routine(r, e) != 0)
        return -1;
    hx_adm_element_text(&el, "type", user ? "USERSUB" : "EXPRESSION");
    hx_adm_element_number(&el, "joint_id", hx_adm_ref(e, "JOINT"));
    if (hx_adm_has(e, "TRANSLATION") && hx_adm_has(e, "ROTATION"))
        return hx_adm_fail(r, e, e->line, "TRANSLATION and ROTATION: give one");
    if (hx_adm_has(e, "TRANSLATION"))
        hx_adm_element_text(&el, "motion_type", "T");
    if (hx_adm_has(e, "ROTATION"))
        hx_adm_element_text(&el, "motion_type", "R");
    const int d = hx_adm_has(e, "DISPLACEMENT"), v = hx_adm_has(e, "VELOCITY"),
              a = hx_adm_has(e, "ACCELERATION");
    if (d + v + a > 1)
        return hx_adm_fail(r, e, e->line, "DISPLACEMENT, VELOCITY and ACCELERATION: give one");
    hx_adm_element_text(&el, "val_type", v ? "V" : a ? "A" : "D");
    if (hx_adm_has(e, "ICDISP"))
        hx_adm_element_number(&el, "ic_disp", hx_adm_number(e, "ICDISP", 0, 0.0));
    if (hx_adm_has(e, "ICVEL"))
        hx_adm_element_number(&el, "ic_vel", hx_adm_number(e, "ICVEL", 0, 0.0));
    if (!user)
        hx_adm_element_expression(&el, "expr", e, "FUNCTION");
    else if (hx_adm_element_user(r, e, &el, NULL) != 0)
        return -1;
    return hx_adm_element_build(r, e, &el, NULL);
}

/* GCON/id, I=marker, FUNCTION=expression into a Constraint_General (a
 * FUNCTION=USER(...) goes on to its builder, which refuses a GCOSUB). */
int hx_adm_build_gcon(hx_adm_reader *r, hx_adm_entry *e)
{
    hx_adm_element el;
    hx_adm_element_init(&el, "Constraint_General");
    if (hx_adm_has(e, "I"))
        hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
    if (hx_adm_is_user(hx_adm_text(e, "FUNCTION"))) {
        if (hx_adm_element_user(r, e, &el, NULL) != 0)
            return -1;
    } else {
        if (hx_adm_no_routine(r, e) != 0)
            return -1;
        hx_adm_element_expression(&el, "expr", e, "FUNCTION");
    }
    return hx_adm_element_build(r, e, &el, NULL);
}
