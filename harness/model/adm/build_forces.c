/*
 * The force statements (docs/interface.md §9.5): GFORCE, VFORCE and VTORQUE
 * into Force_Vector_TwoBody (ForceAndTorque, ForceOnly, TorqueOnly) with a
 * user routine, or, given by components (function expressions), into
 * Force_Vector_TwoBody by expressions, or, with JFLOAT on ground, into the
 * one-body load that is the same force; SFORCE into Force_Scalar_TwoBody; FIELD into
 * Force_Field; FORCE_STATEEQN (this harness's statement for MotionSolve's
 * Force_StateEqn) into Force_StateEqn.
 */
#include <string.h>

#include "model/adm/translate.h"

static const char *const components[6] = {"FX", "FY", "FZ", "TX", "TY", "TZ"};
static const char *const component_attrs[6] = {"fx_expression", "fy_expression",
                                               "fz_expression", "tx_expression",
                                               "ty_expression", "tz_expression"};

int hx_adm_build_gforce(hx_adm_reader *r, hx_adm_entry *e)
{
    const char *name = e->spec->name;
    const int part = strcmp(name, "GFORCE") == 0 ? 0 : strcmp(name, "VFORCE") == 0 ? 1 : 2;
    static const char *const xml_types[3] = {"ForceAndTorque", "ForceOnly", "TorqueOnly"};
    static const char *const load_types[3] = {"FORCEANDTORQUE", "FORCEONLY", "TORQUEONLY"};
    int ncomponents = 0;
    for (int k = 0; k < 6; ++k)
        ncomponents += hx_adm_has(e, components[k]);
    const char *function = hx_adm_text(e, "FUNCTION");
    hx_adm_element el;
    if (function != NULL) {
        if (!hx_adm_is_user(function))
            return hx_adm_fail(r, e, hx_adm_get(e, "FUNCTION")->line, "FUNCTION=%s: a %s's"
                               " FUNCTION is USER(...); its components are FX=..\\FY=..",
                               function, name);
        if (ncomponents > 0)
            return hx_adm_fail(r, e, e->line, "FUNCTION=USER(...) and components (FX=..\\FY=..):"
                               " give one of them");
        hx_adm_element_init(&el, "Force_Vector_TwoBody");
        hx_adm_element_text(&el, "type", xml_types[part]);
        hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
        hx_adm_element_number(&el, "j_floating_marker_id", hx_adm_ref(e, "JFLOAT"));
        if (hx_adm_has(e, "RM"))
            hx_adm_element_number(&el, "ref_marker_id", hx_adm_ref(e, "RM"));
        if (hx_adm_element_user(r, e, &el, NULL) != 0)
            return -1;
        return hx_adm_element_build(r, e, &el, NULL);
    }
    if (ncomponents == 0)
        return hx_adm_fail(r, e, e->line, "no force: give FUNCTION=USER(...) or its components");
    /* components: the reaction on JFLOAT's part, or lost to ground */
    const hx_adm_entry *jfloat = hx_adm_find(r, "MARKER", hx_adm_ref(e, "JFLOAT"));
    const hx_adm_entry *jpart = jfloat != NULL ? hx_adm_find(r, "PART", hx_adm_ref(jfloat, "PART"))
                                               : NULL;
    if (jpart != NULL && hx_adm_has(jpart, "GROUND")) {
        hx_adm_element_init(&el, "Force_Vector_OneBody");
        hx_adm_element_text(&el, "type", load_types[part]);
        hx_adm_element_number(&el, "marker_id", hx_adm_ref(e, "I"));
    } else {
        hx_adm_element_init(&el, "Force_Vector_TwoBody");
        hx_adm_element_text(&el, "type", xml_types[part]);
        hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
        hx_adm_element_number(&el, "j_floating_marker_id", hx_adm_ref(e, "JFLOAT"));
    }
    if (hx_adm_has(e, "RM"))
        hx_adm_element_number(&el, "ref_marker_id", hx_adm_ref(e, "RM"));
    for (int k = 0; k < 6; ++k)
        hx_adm_element_expression(&el, component_attrs[k], e, components[k]);
    return hx_adm_element_build(r, e, &el, NULL);
}

int hx_adm_build_sforce(hx_adm_reader *r, hx_adm_entry *e)
{
    const int translation = hx_adm_has(e, "TRANSLATION"), rotation = hx_adm_has(e, "ROTATION");
    if (translation == rotation)
        return hx_adm_fail(r, e, e->line, "give TRANSLATION (a force along the line from J to I)"
                           " or ROTATION (a torque about J's z axis)");
    hx_adm_element el;
    hx_adm_element_init(&el, "Force_Scalar_TwoBody");
    hx_adm_element_text(&el, "type", translation ? "FORCE" : "TORQUE");
    hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
    hx_adm_element_number(&el, "j_marker_id", hx_adm_ref(e, "J"));
    if (hx_adm_has(e, "ACTIONONLY"))
        hx_adm_element_text(&el, "is_action_only", "TRUE");
    const char *function = hx_adm_text(e, "FUNCTION");
    if (hx_adm_is_user(function)) {
        if (hx_adm_element_user(r, e, &el, NULL) != 0)
            return -1;
    } else {
        if (hx_adm_no_routine(r, e) != 0)
            return -1;
        hx_adm_element_expression(&el, "val_expression", e, "FUNCTION");
    }
    return hx_adm_element_build(r, e, &el, NULL);
}

/* MotionSolve's names of a linear field's matrix entries, Krc row r column c,
 * in the order Adams' KMATRIX and CMATRIX list them: by columns. */
#define COLUMN(m, c) m "1" #c, m "2" #c, m "3" #c, m "4" #c, m "5" #c, m "6" #c
static const char *const field_k[36] = {COLUMN("K", 1), COLUMN("K", 2), COLUMN("K", 3),
                                        COLUMN("K", 4), COLUMN("K", 5), COLUMN("K", 6)};
static const char *const field_c[36] = {COLUMN("C", 1), COLUMN("C", 2), COLUMN("C", 3),
                                        COLUMN("C", 4), COLUMN("C", 5), COLUMN("C", 6)};
static const char *const field_length[6] = {"length_x",  "length_y",  "length_z",
                                            "length_tx", "length_ty", "length_tz"};
static const char *const field_preload[6] = {"preload_x",  "preload_y",  "preload_z",
                                             "preload_tx", "preload_ty", "preload_tz"};

/* FIELD: FUNCTION=USER(...) calls FIESUB; without FUNCTION it is linear:
 * KMATRIX, CMATRIX (36 values by columns) or CRATIO, LENGTH and FORCE. */
int hx_adm_build_field(hx_adm_reader *r, hx_adm_entry *e)
{
    static const char *const linear[5] = {"KMATRIX", "CMATRIX", "CRATIO", "LENGTH", "FORCE"};
    hx_adm_element el;
    hx_adm_element_init(&el, "Force_Field");
    hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
    hx_adm_element_number(&el, "j_marker_id", hx_adm_ref(e, "J"));
    if (hx_adm_has(e, "FUNCTION")) {
        for (int k = 0; k < 5; ++k)
            if (hx_adm_has(e, linear[k]))
                return hx_adm_fail(r, e, hx_adm_get(e, linear[k])->line, "%s is a linear"
                                   " FIELD's, and FUNCTION=USER(...) calls FIESUB: give one of"
                                   " them", linear[k]);
        if (hx_adm_element_user(r, e, &el, NULL) != 0)
            return -1;
        return hx_adm_element_build(r, e, &el, NULL);
    }
    if (hx_adm_no_routine(r, e) != 0)
        return -1;
    if (hx_adm_has(e, "CRATIO") && !hx_adm_has(e, "KMATRIX"))
        return hx_adm_fail(r, e, hx_adm_get(e, "CRATIO")->line, "CRATIO without KMATRIX:"
                           " CRATIO scales the stiffness matrix");
    if (hx_adm_has(e, "CRATIO") && hx_adm_has(e, "CMATRIX"))
        return hx_adm_fail(r, e, hx_adm_get(e, "CRATIO")->line, "give CMATRIX or CRATIO, not"
                           " both");
    for (int k = 0; k < 36; ++k) {
        if (hx_adm_has(e, "KMATRIX"))
            hx_adm_element_number(&el, field_k[k], hx_adm_number(e, "KMATRIX", k, 0.0));
        if (hx_adm_has(e, "CMATRIX"))
            hx_adm_element_number(&el, field_c[k], hx_adm_number(e, "CMATRIX", k, 0.0));
    }
    if (hx_adm_has(e, "CRATIO"))
        hx_adm_element_number(&el, "CRATIO", hx_adm_number(e, "CRATIO", 0, 0.0));
    for (int k = 0; k < 6; ++k) {
        if (hx_adm_has(e, "LENGTH"))
            hx_adm_element_number(&el, field_length[k], hx_adm_number(e, "LENGTH", k, 0.0));
        if (hx_adm_has(e, "FORCE"))
            hx_adm_element_number(&el, field_preload[k], hx_adm_number(e, "FORCE", k, 0.0));
    }
    return hx_adm_element_build(r, e, &el, NULL);
}

int hx_adm_build_force_stateeqn(hx_adm_reader *r, hx_adm_entry *e)
{
    const char *function = hx_adm_text(e, "FUNCTION");
    if (!hx_adm_is_user(function))
        return hx_adm_fail(r, e, hx_adm_get(e, "FUNCTION")->line, "FUNCTION=%s: expected"
                           " USER(...) (YFOSUB)", function);
    hx_adm_element el;
    hx_adm_element_init(&el, "Force_StateEqn");
    hx_adm_element_text(&el, "type", "USERSUB");
    const hx_adm_entry *x = hx_adm_find(r, "ARRAY", hx_adm_ref(e, "X"));
    if (!hx_adm_has(x, "X"))
        return hx_adm_fail(r, e, hx_adm_get(e, "X")->line, "X=%d is not an X ARRAY", x->id);
    hx_adm_element_number(&el, "x_array_id", x->id);
    hx_adm_element_number(&el, "num_state", hx_adm_number(x, "SIZE", 0, 0.0));
    if (hx_adm_has(e, "U"))
        hx_adm_element_number(&el, "u_array_id", hx_adm_ref(e, "U"));
    if (hx_adm_has(e, "IC"))
        hx_adm_element_number(&el, "ic_array_id", hx_adm_ref(e, "IC"));
    hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
    hx_adm_element_number(&el, "j_floating_marker_id", hx_adm_ref(e, "JFLOAT"));
    hx_adm_element_number(&el, "ref_marker_id", hx_adm_ref(e, "RM"));
    if (hx_adm_has(e, "STATIC_HOLD"))
        hx_adm_element_text(&el, "is_static_hold", "TRUE");
    static const char *const der[] = {"usrsub_der1_name", "usrsub_der2_name", "usrsub_der3_name",
                                      "usrsub_der4_name", NULL};
    if (hx_adm_element_user(r, e, &el, der) != 0)
        return -1;
    return hx_adm_element_build(r, e, &el, NULL);
}
