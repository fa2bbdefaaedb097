/*
 * The table of the XML elements the harness reads (xml_schema.h): one row
 * per element, with its attributes, and the step that builds it into the
 * draft model. References between elements are resolved afterwards
 * (resolve.c), so elements may come in any order.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/vecmath.h"
#include "model/joint_elements.h"
#include "model/builtin_forces.h"
#include "model/gcon_elements.h"
#include "model/load_elements.h"
#include "model/orientation.h"
#include "model/units.h"
#include "model/routine_elements.h"
#include "model/stateeqn_elements.h"
#include "model/spline_elements.h"
#include "model/user_list.h"
#include "model/xml_attrs.h"
#include "model/xml_schema.h"

/* usrsub_dll_name and usrsub_fnc_name: "NULL" means absent. */
static char *optional_name(const hx_element_read *e, const char *name)
{
    const char *text = hx_attr_text(e, name);
    if (text == NULL || *text == '\0' || strcasecmp(text, "NULL") == 0)
        return NULL;
    return strdup(text);
}

int hx_draft_user_call(hx_draft *d, const hx_element_read *e, hx_user_call *u)
{
    if (hx_attr_present(e, "script_name") || hx_attr_present(e, "interpreter")) {
        hx_draft_fail(d, e->line, "%s %d: script_name/interpreter user subroutines are not"
                      " supported by the harness (compiled libraries only)", e->name, e->id);
        return -1;
    }
    const char *params = hx_attr_text(e, "usrsub_param_string");
    if (params == NULL) {
        hx_draft_fail(d, e->line, "%s %d: a user-subroutine element needs usrsub_param_string",
                      e->name, e->id);
        return -1;
    }
    hx_message why;
    if (hx_parse_user_list(params, &u->par, &u->npar, &why) != 0) {
        hx_draft_fail(d, e->line, "%s %d: usrsub_param_string: %s", e->name, e->id, why.text);
        return -1;
    }
    u->dll_name = optional_name(e, "usrsub_dll_name");
    u->fnc_name = optional_name(e, "usrsub_fnc_name");
    u->der1_name = optional_name(e, "usrsub_der1_name");
    u->der2_name = optional_name(e, "usrsub_der2_name");
    u->der3_name = optional_name(e, "usrsub_der3_name");
    u->der4_name = optional_name(e, "usrsub_der4_name");
    return 0;
}

/* ---- model settings ----------------------------------------------------------------- */

static const hx_attr_spec param_unit_attrs[] = {
    TEXT("force_unit"), TEXT("mass_unit"), TEXT("length_unit"), TEXT("time_unit"),
    REAL("mass_mult_factor"), IGNORED("label"), END};

static void build_param_unit(hx_draft *d, const hx_element_read *e)
{
    static const struct {
        const char *attribute;
        enum hx_unit_kind kind;
    } units[] = {{"length_unit", HX_UNIT_LENGTH},
                 {"force_unit", HX_UNIT_FORCE},
                 {"mass_unit", HX_UNIT_MASS},
                 {"time_unit", HX_UNIT_TIME}};
    hx_model *m = d->m;
    for (size_t k = 0; k < sizeof units / sizeof units[0]; ++k) {
        const char *name = hx_attr_text(e, units[k].attribute);
        m->unit_scales[units[k].kind] = 1.0;
        if (name != NULL && hx_unit_size(units[k].kind, name, &m->unit_scales[units[k].kind]) != 0) {
            hx_draft_fail(d, e->line, "Param_Unit: %s = \"%s\" is not a unit the harness knows"
                          " (%s)", units[k].attribute, name, hx_unit_names(units[k].kind));
            return;
        }
    }
    m->unit_scales[HX_UNIT_ANGLE] = 1.0;
    const double factor = hx_attr_number(e, "mass_mult_factor", 1.0);
    if (factor != 1.0) {
        hx_draft_fail(d, e->line, "Param_Unit: mass_mult_factor %g is not supported by the"
                      " harness (only 1)", factor);
        return;
    }
    m->has_units = 1;
}

static const hx_attr_spec gravity_attrs[] = {REAL("grav_x"), REAL("grav_y"), REAL("grav_z"),
                                             IGNORED("id"), IGNORED("label"), END};

static void build_gravity(hx_draft *d, const hx_element_read *e)
{
    double *g = d->m->gravity;
    g[0] = hx_attr_number(e, "grav_x", 0.0);
    g[1] = hx_attr_number(e, "grav_y", 0.0);
    g[2] = hx_attr_number(e, "grav_z", 0.0);
}

static const hx_attr_spec string_attrs[] = {ID, TEXT("string"), END};

static void build_string(hx_draft *d, const hx_element_read *e)
{
    const char *text = hx_attr_text(e, "string");
    if (text == NULL) {
        hx_draft_fail(d, e->line, "Reference_String %d: attribute string is missing (strings"
                      " from a user subroutine are not supported)", e->id);
        return;
    }
    hx_model *m = d->m;
    if (hx_model_string(m, e->id) != NULL) {
        hx_draft_fail(d, e->line, "Reference_String %d is defined twice", e->id);
        return;
    }
    hx_string *s = hx_draft_push(d, (void **)&m->strings, &m->nstrings, &d->cap_strings,
                                 sizeof *s, NULL, 0);
    if (s != NULL && (s->text = strdup(text)) != NULL)
        s->id = e->id;
    else if (s != NULL)
        hx_draft_fail(d, e->line, "out of memory");
}

/* ---- bodies and markers ---------------------------------------------------------------- */

static hx_body *push_body(hx_draft *d, const hx_element_read *e)
{
    hx_model *m = d->m;
    if (hx_draft_find_body(d, e->id) >= 0) {
        hx_draft_fail(d, e->line, "%s %d: a body with this id is already defined", e->name, e->id);
        return NULL;
    }
    hx_body *b = hx_draft_push(d, (void **)&m->bodies, &m->nbodies, &d->cap_bodies, sizeof *b,
                               (void **)&d->rbodies, sizeof(raw_body));
    if (b == NULL)
        return NULL;
    b->id = e->id;
    if (hx_draft_enter_body(d) != 0)
        return NULL;
    b->joint = -1;
    b->cg_marker = -1;
    b->line = e->line;
    m3_identity(b->R0);
    m3_identity(b->inertia);
    return b;
}

static void make_ground(hx_draft *d, const hx_element_read *e, hx_body *b)
{
    if (d->m->ground >= 0) {
        hx_draft_fail(d, e->line, "%s %d: the model already has a ground body (line %d)",
                      e->name, e->id, d->ground_line);
        return;
    }
    b->is_ground = 1;
    d->m->ground = d->m->nbodies - 1;
    d->ground_line = e->line;
}

static const hx_attr_spec ground_attrs[] = {ID, END};

static void build_ground(hx_draft *d, const hx_element_read *e)
{
    hx_body *b = push_body(d, e);
    if (b != NULL)
        make_ground(d, e, b);
}

static const hx_attr_spec body_attrs[] = {
    ID, INT("cg_id"), INT("im_id"), INT("lprf_id"), {"isground", HX_ATTR_BOOL, 0},
    REAL("mass"), REAL("inertia_xx"), REAL("inertia_yy"), REAL("inertia_zz"), REAL("inertia_xy"),
    REAL("inertia_yz"), REAL("inertia_xz"), REAL("v_ic_x"), REAL("v_ic_y"), REAL("v_ic_z"),
    REAL("w_ic_x"), REAL("w_ic_y"), REAL("w_ic_z"), IGNORED("v_ic_x_flag"),
    IGNORED("v_ic_y_flag"), IGNORED("v_ic_z_flag"), IGNORED("w_ic_x_flag"),
    IGNORED("w_ic_y_flag"), IGNORED("w_ic_z_flag"), END};

static void build_body(hx_draft *d, const hx_element_read *e)
{
    hx_body *b = push_body(d, e);
    if (b == NULL)
        return;
    raw_body *rb = &d->rbodies[d->m->nbodies - 1];
    rb->lprf_id = hx_attr_int(e, "lprf_id", 0);
    if (hx_attr_number(e, "isground", 0.0) != 0.0) {
        /* a ground body: no mass, no motion; its markers are fixed in the world */
        make_ground(d, e, b);
        return;
    }
    static const char *const needed[] = {"cg_id", "mass", "inertia_xx", "inertia_yy",
                                         "inertia_zz"};
    for (size_t k = 0; k < sizeof needed / sizeof needed[0]; ++k)
        if (!hx_attr_present(e, needed[k])) {
            hx_draft_fail(d, e->line, "Body_Rigid %d: attribute %s is missing", e->id, needed[k]);
            return;
        }
    rb->cg_id = hx_attr_int(e, "cg_id", 0);
    rb->im_id = hx_attr_int(e, "im_id", rb->cg_id);
    b->mass = hx_attr_number(e, "mass", 0.0);
    const double ixx = hx_attr_number(e, "inertia_xx", 0.0), iyy = hx_attr_number(e, "inertia_yy", 0.0),
                 izz = hx_attr_number(e, "inertia_zz", 0.0);
    if (!(b->mass > 0.0) || !(ixx > 0.0) || !(iyy > 0.0) || !(izz > 0.0)) {
        hx_draft_fail(d, e->line, "Body_Rigid %d: mass and inertia_xx/yy/zz must be positive"
                      " (got %g, %g, %g, %g)", e->id, b->mass, ixx, iyy, izz);
        return;
    }
    /* products of inertia are the positive integrals (Ixy = integral of x y dm),
     * so they enter the tensor with a minus sign (docs/interface.md §7) */
    const double ixy = hx_attr_number(e, "inertia_xy", 0.0), iyz = hx_attr_number(e, "inertia_yz", 0.0),
                 ixz = hx_attr_number(e, "inertia_xz", 0.0);
    const double I[9] = {ixx, -ixy, -ixz, -ixy, iyy, -iyz, -ixz, -iyz, izz};
    memcpy(rb->inertia, I, sizeof I);
    static const char *const v[6] = {"v_ic_x", "v_ic_y", "v_ic_z", "w_ic_x", "w_ic_y", "w_ic_z"};
    for (int k = 0; k < 3; ++k) {
        b->v0[k] = hx_attr_number(e, v[k], 0.0);
        b->w0[k] = hx_attr_number(e, v[3 + k], 0.0);
    }
}

static const hx_attr_spec marker_attrs[] = {
    ID, REQUIRED("body_id", HX_ATTR_INT), TEXT("body_type"), INT("rm_id"), REAL("pos_x"),
    REAL("pos_y"), REAL("pos_z"), REAL("a00"), REAL("a01"), REAL("a02"), REAL("a10"),
    REAL("a11"), REAL("a12"), REAL("a20"), REAL("a21"), REAL("a22"), REAL("psi"), REAL("theta"),
    REAL("phi"), REAL("e0"), REAL("e1"), REAL("e2"), REAL("e3"), REAL("yaw"), REAL("pitch"),
    REAL("roll"), END};

static void build_marker(hx_draft *d, const hx_element_read *e)
{
    hx_model *m = d->m;
    const int earlier = hx_draft_find_marker(d, e->id);
    if (earlier >= 0) {
        hx_draft_fail(d, e->line, "Reference_Marker %d is defined twice (line %d)", e->id,
                      m->markers[earlier].line);
        return;
    }
    const char *body_type = hx_attr_text(e, "body_type");
    if (body_type != NULL && strcasecmp(body_type, "RIGIDBODY") != 0) {
        hx_draft_fail(d, e->line, "Reference_Marker %d: body_type %s is not supported (RIGIDBODY"
                      " only)", e->id, body_type);
        return;
    }
    double R[9];
    hx_message why;
    if (hx_marker_orientation(e, R, &why) != 0) {
        hx_draft_fail(d, e->line, "Reference_Marker %d: %s", e->id, why.text);
        return;
    }
    hx_marker *mk = hx_draft_push(d, (void **)&m->markers, &m->nmarkers, &d->cap_markers,
                                  sizeof *mk, (void **)&d->rmarkers, sizeof(raw_marker));
    if (mk == NULL)
        return;
    raw_marker *rm = &d->rmarkers[m->nmarkers - 1];
    mk->id = e->id;
    mk->line = e->line;
    if (hx_draft_enter_marker(d) != 0)
        return;
    rm->body_id = hx_attr_int(e, "body_id", 0);
    rm->rm_id = hx_attr_int(e, "rm_id", 0);
    rm->pos[0] = hx_attr_number(e, "pos_x", 0.0);
    rm->pos[1] = hx_attr_number(e, "pos_y", 0.0);
    rm->pos[2] = hx_attr_number(e, "pos_z", 0.0);
    memcpy(rm->R, R, sizeof R);
}

/* ---- constraints -------------------------------------------------------------------------- */

static const hx_attr_spec coupler_attrs[] = {
    ID, REQUIRED("joint1_id", HX_ATTR_INT), TEXT("freedom_1"), REQUIRED("joint2_id", HX_ATTR_INT),
    TEXT("freedom_2"), INT("joint3_id"), TEXT("freedom_3"), TEXT("coefficients"),
    TEXT("usrsub_der1_name"), TEXT("usrsub_der2_name"), IGNORED("is_virtual"), USER_CALL, END};

static void build_coupler(hx_draft *d, const hx_element_read *e)
{
    hx_model *m = d->m;
    hx_coupler *c = hx_draft_push(d, (void **)&m->couplers, &m->ncouplers, &d->cap_couplers,
                                  sizeof *c, (void **)&d->rcouplers, sizeof(raw_refs));
    if (c == NULL)
        return;
    raw_refs *refs = &d->rcouplers[m->ncouplers - 1];
    c->id = e->id;
    c->line = e->line;
    static const char *const joint_names[] = {"joint1_id", "joint2_id", "joint3_id"};
    static const char *const freedom_names[] = {"freedom_1", "freedom_2", "freedom_3"};
    c->njoints = hx_attr_present(e, "joint3_id") ? 3 : 2;
    for (int k = 0; k < c->njoints; ++k) {
        refs->ids[k] = hx_attr_int(e, joint_names[k], 0);
        const char *f = hx_attr_text(e, freedom_names[k]);
        refs->freedom[k] = f != NULL ? (char)(f[0] & ~0x20) : 0;
        if (f != NULL && ((refs->freedom[k] != 'T' && refs->freedom[k] != 'R') || f[1] != '\0')) {
            hx_draft_fail(d, e->line, "Constraint_Coupler %d: %s = \"%s\": expected \"T\" or \"R\"",
                          e->id, freedom_names[k], f);
            return;
        }
    }
    const char *coefficients = hx_attr_text(e, "coefficients");
    if (coefficients == NULL) {
        c->is_user = 1;
        hx_draft_user_call(d, e, &c->user);
        return;
    }
    if (hx_attr_present(e, "usrsub_param_string")) {
        hx_draft_fail(d, e->line, "Constraint_Coupler %d: give either coefficients or a user"
                      " subroutine, not both", e->id);
        return;
    }
    char list[512];
    snprintf(list, sizeof list, "USER(%s)", coefficients);
    double *values = NULL;
    int n = 0;
    hx_message why;
    if (hx_parse_user_list(list, &values, &n, &why) != 0 || n != c->njoints) {
        free(values);
        hx_draft_fail(d, e->line, "Constraint_Coupler %d: coefficients = \"%s\": expected %d"
                      " numbers", e->id, coefficients, c->njoints);
        return;
    }
    memcpy(c->coefficients, values, sizeof(double) * (size_t)n);
    free(values);
}

/* ---- force elements and loads -------------------------------------------------------------- */

static hx_force *push_force(hx_draft *d, const hx_element_read *e, enum hx_force_interface kind)
{
    hx_model *m = d->m;
    hx_force *f = hx_draft_push(d, (void **)&m->forces, &m->nforces, &d->cap_forces, sizeof *f,
                                (void **)&d->rforces, sizeof(raw_refs));
    if (f == NULL)
        return NULL;
    f->id = e->id;
    f->interface = kind;
    f->line = e->line;
    return f;
}

/* A vector force with a user routine (GFOSUB, VFOSUB or VTOSUB by its type,
 * which defaults to ForceAndTorque), its markers' ids as written (0 when
 * absent); NULL with the draft failed when the type is none of those. */
static hx_force *push_vector_user_force(hx_draft *d, const hx_element_read *e, const char *type,
                                        int i_id, int j_id, int ref_id)
{
    static const char *const types[3] = {"ForceAndTorque", "ForceOnly", "TorqueOnly"};
    int part = 0;
    while (part < 3 && strcasecmp(type != NULL ? type : types[0], types[part]) != 0)
        ++part;
    if (part == 3) {
        hx_draft_fail(d, e->line, "%s %d: type \"%s\" is not one the harness reads"
                      " (ForceAndTorque: GFOSUB, ForceOnly: VFOSUB, TorqueOnly: VTOSUB)", e->name,
                      e->id, type);
        return NULL;
    }
    hx_force *f = push_force(d, e, HX_FORCE_GFOSUB);
    if (f == NULL)
        return NULL;
    f->part = (enum hx_user_output)part;
    raw_refs *refs = &d->rforces[d->m->nforces - 1];
    refs->ids[0] = i_id, refs->ids[1] = j_id, refs->ids[2] = ref_id;
    hx_draft_user_call(d, e, &f->user);
    return f;
}

static int names_a_user_routine(const hx_element_read *e)
{
    return hx_attr_present(e, "usrsub_param_string") || hx_attr_present(e, "usrsub_dll_name");
}

/* An element given both a user routine and a value of its own (value_attr):
 * which one a solver takes is not documented, so neither is guessed. */
static void refuse_routine_and_value(hx_draft *d, const hx_element_read *e, const char *value_attr)
{
    hx_draft_fail(d, e->line, "%s %d: %s = \"%s\" and a user routine (usrsub_param_string,"
                  " usrsub_dll_name): give one of them", e->name, e->id, value_attr,
                  hx_attr_text(e, value_attr));
}

static const hx_attr_spec force_vector_attrs[] = {
    ID, REQUIRED("type", HX_ATTR_TEXT), REQUIRED("i_marker_id", HX_ATTR_INT),
    REQUIRED("j_floating_marker_id", HX_ATTR_INT), INT("ref_marker_id"), IGNORED("body1_id"),
    IGNORED("body2_id"), IGNORED("ref_body_id"), TEXT("fx_expression"), TEXT("fy_expression"),
    TEXT("fz_expression"), TEXT("tx_expression"), TEXT("ty_expression"), TEXT("tz_expression"),
    USER_CALL, END};

/* With a user routine (GFOSUB, VFOSUB, VTOSUB), or by expressions: a load
 * on I whose reaction J's body takes (load_elements.h). */
static void build_force_vector(hx_draft *d, const hx_element_read *e)
{
    static const char *const comps[6] = {"fx_expression", "fy_expression", "fz_expression",
                                         "tx_expression", "ty_expression", "tz_expression"};
    int given = -1;
    for (int k = 0; k < 6 && given < 0; ++k)
        if (hx_attr_present(e, comps[k]))
            given = k;
    if (given >= 0) {
        if (names_a_user_routine(e))
            refuse_routine_and_value(d, e, comps[given]);
        else
            hx_build_vector_load(d, e, hx_attr_int(e, "i_marker_id", 0),
                                 hx_attr_int(e, "j_floating_marker_id", 0),
                                 hx_attr_int(e, "ref_marker_id", 0));
        return;
    }
    push_vector_user_force(d, e, hx_attr_text(e, "type"), hx_attr_int(e, "i_marker_id", 0),
                           hx_attr_int(e, "j_floating_marker_id", 0),
                           hx_attr_int(e, "ref_marker_id", 0));
}

/* A Force_Field calling FIESUB, or, with no routine named, the linear one
 * (builtin_forces.h); a routine and linear attributes both, or neither, and
 * a second Force_Field of an id (of either form): refused. */
static void build_force_field(hx_draft *d, const hx_element_read *e)
{
    const hx_model *m = d->m;
    int before = 0;
    for (int k = 0; k < m->nforces && before == 0; ++k)
        if (m->forces[k].id == e->id && m->forces[k].interface == HX_FORCE_FIESUB)
            before = m->forces[k].line;
    for (int k = 0; k < m->nloads && before == 0; ++k)
        if (m->loads[k].id == e->id && m->loads[k].builtin == HX_LOAD_FIELD)
            before = m->loads[k].line;
    if (before != 0) {
        hx_draft_fail(d, e->line, "%s %d is defined twice (line %d)", e->name, e->id, before);
        return;
    }
    static const char *const routine[] = {"usrsub_param_string", "usrsub_dll_name",
                                          "usrsub_fnc_name", "script_name", "interpreter"};
    const char *named = NULL;
    for (size_t k = 0; k < sizeof routine / sizeof routine[0] && named == NULL; ++k)
        if (hx_attr_present(e, routine[k]))
            named = routine[k];
    const char *linear = hx_field_linear_attribute(e);
    if (named == NULL && linear == NULL) {
        hx_draft_fail(d, e->line, "%s %d: neither a routine (usrsub_param_string: FIESUB) nor a"
                      " linear field's attributes (K11 .. K66, C11 .. C66, CRATIO, length_*,"
                      " preload_*): it would apply nothing", e->name, e->id);
        return;
    }
    if (named == NULL) {
        hx_build_field(d, e);
        return;
    }
    if (linear != NULL) {
        hx_draft_fail(d, e->line, "%s %d: %s is a linear field's, and %s names a routine (FIESUB):"
                      " give one of them", e->name, e->id, linear, named);
        return;
    }
    hx_force *f = push_force(d, e, HX_FORCE_FIESUB);
    if (f == NULL)
        return;
    raw_refs *refs = &d->rforces[d->m->nforces - 1];
    refs->ids[0] = hx_attr_int(e, "i_marker_id", 0);
    refs->ids[1] = hx_attr_int(e, "j_marker_id", 0);
    hx_draft_user_call(d, e, &f->user);
}

static const hx_attr_spec vector_load_attrs[] = {
    ID, TEXT("type"), REQUIRED("marker_id", HX_ATTR_INT), INT("ref_marker_id"),
    TEXT("fx_expression"), TEXT("fy_expression"), TEXT("fz_expression"), TEXT("tx_expression"),
    TEXT("ty_expression"), TEXT("tz_expression"), IGNORED("body_id"), IGNORED("ref_body_id"),
    USER_CALL, END};

/* A Force_Vector_OneBody with a user routine: a user force element on its
 * marker whose J is the ground's origin, so that the reaction is lost to
 * ground (resolve.c); its results are in ref_marker_id's axes. */
static void build_vector_user_load(hx_draft *d, const hx_element_read *e)
{
    hx_force *f = push_vector_user_force(d, e, hx_attr_text(e, "type"),
                                         hx_attr_int(e, "marker_id", 0), 0,
                                         hx_attr_int(e, "ref_marker_id", 0));
    if (f != NULL)
        f->one_body = 1;
}

static void build_vector_load(hx_draft *d, const hx_element_read *e)
{
    static const char *const comps[6] = {"fx_expression", "fy_expression", "fz_expression",
                                         "tx_expression", "ty_expression", "tz_expression"};
    if (names_a_user_routine(e)) {
        for (int k = 0; k < 6; ++k)
            if (hx_attr_present(e, comps[k])) {
                refuse_routine_and_value(d, e, comps[k]);
                return;
            }
        build_vector_user_load(d, e);
        return;
    }
    hx_build_vector_load(d, e, hx_attr_int(e, "marker_id", 0), 0,
                         hx_attr_int(e, "ref_marker_id", 0));
}

static const hx_attr_spec scalar_load_attrs[] = {
    ID, REQUIRED("type", HX_ATTR_TEXT), REQUIRED("i_marker_id", HX_ATTR_INT),
    REQUIRED("j_marker_id", HX_ATTR_INT), {"is_action_only", HX_ATTR_BOOL, 0}, TEXT("val"),
    TEXT("val_expression"), USER_CALL, END};

/* A Force_Scalar_TwoBody with a user routine (SFOSUB): a user force element
 * whose one value acts along the line from J to I, or about J's z axis. */
static void build_scalar_user_force(hx_draft *d, const hx_element_read *e, int torque)
{
    if (hx_attr_number(e, "is_action_only", 0.0) != 0.0) {
        hx_draft_fail(d, e->line, "Force_Scalar_TwoBody %d: is_action_only with a user routine"
                      " is not one the harness runs (it applies the reaction on J)", e->id);
        return;
    }
    hx_force *f = push_force(d, e, HX_FORCE_GFOSUB);
    if (f == NULL)
        return;
    f->part = torque ? HX_OUTPUT_SCALAR_TORQUE : HX_OUTPUT_SCALAR_FORCE;
    raw_refs *refs = &d->rforces[d->m->nforces - 1];
    refs->ids[0] = hx_attr_int(e, "i_marker_id", 0);
    refs->ids[1] = hx_attr_int(e, "j_marker_id", 0);
    hx_draft_user_call(d, e, &f->user);
}

static void build_scalar_load(hx_draft *d, const hx_element_read *e)
{
    const char *type = hx_attr_text(e, "type");
    const int torque = strcasecmp(type, "TORQUE") == 0;
    if (!torque && strcasecmp(type, "FORCE") != 0) {
        hx_draft_fail(d, e->line, "Force_Scalar_TwoBody %d: type \"%s\": expected FORCE or TORQUE",
                      e->id, type);
        return;
    }
    const char *value = hx_attr_present(e, "val") ? "val" : "val_expression";
    if (names_a_user_routine(e)) {
        if (hx_attr_present(e, value))
            refuse_routine_and_value(d, e, value);
        else
            build_scalar_user_force(d, e, torque);
        return;
    }
    if (!hx_attr_present(e, value)) {
        hx_draft_fail(d, e->line, "Force_Scalar_TwoBody %d: attribute val or val_expression is"
                      " missing", e->id);
        return;
    }
    hx_build_scalar_load(d, e, torque, value);
}

/* ---- the table ------------------------------------------------------------------------------- */

static const hx_attr_spec no_attrs[] = {END};

const hx_element_spec hx_element_specs[] = {
    {"MotionSolve", no_attrs, NULL, NULL, 0},
    {"Model", no_attrs, NULL, NULL, 0},
    {"Param_Unit", param_unit_attrs, build_param_unit, NULL, 0},
    {"Force_Gravity", gravity_attrs, build_gravity, NULL, 0},
    {"Reference_String", string_attrs, build_string, NULL, 0},
    {"Body_Ground", ground_attrs, build_ground, NULL, 0},
    {"Body_Rigid", body_attrs, build_body, NULL, 0},
    {"Reference_Marker", marker_attrs, build_marker, NULL, 0},
    {"Constraint_Joint", hx_joint_attrs, hx_build_joint, NULL, 0},
    {"Constraint_Jprim", hx_joint_attrs, hx_build_jprim, NULL, 0},
    {"Constraint_Coupler", coupler_attrs, build_coupler, NULL, 0},
    {"Constraint_General", hx_gcon_attrs, hx_build_gcon, NULL, 0},
    {"Force_Vector_TwoBody", force_vector_attrs, build_force_vector, NULL, 0},
    {"Force_Field", hx_field_attrs, build_force_field, NULL, 0},
    {"Force_Vector_OneBody", vector_load_attrs, build_vector_load, NULL, 0},
    {"Force_Scalar_TwoBody", scalar_load_attrs, build_scalar_load, NULL, 0},
    {"Force_StateEqn", hx_stateeqn_attrs, hx_build_stateeqn, NULL, 0},
    {"Force_SpringDamper", hx_springdamper_attrs, hx_build_springdamper, NULL, 0},
    {"Force_Bushing", hx_bushing_attrs, hx_build_bushing, NULL, 0},
    {"Force_Beam", hx_beam_attrs, hx_build_beam, NULL, 0},
    {"Reference_Array", hx_array_attrs, hx_build_array, hx_array_text, 0},
    {"Reference_Variable", hx_variable_attrs, hx_build_variable, NULL, 0},
    {"Post_Request", hx_request_attrs, hx_build_request, NULL, 0},
    {"Control_Diff", hx_diff_attrs, hx_build_diff, NULL, 0},
    {"Motion_Joint", hx_motion_attrs, hx_build_motion, NULL, 0},
    {"Reference_Spline", hx_spline_attrs, hx_build_spline, hx_spline_text, 0},
};
const int hx_element_spec_count = (int)(sizeof hx_element_specs / sizeof hx_element_specs[0]);

int hx_element_is_output_only(const char *name)
{
    /* outputs, solver settings and analysis commands: they do not act on the
     * dynamics the harness computes */
    static const char *const prefixes[] = {"Post_", "Param_", "Simulate", "Analysis"};
    for (size_t k = 0; k < sizeof prefixes / sizeof prefixes[0]; ++k)
        if (strncasecmp(name, prefixes[k], strlen(prefixes[k])) == 0)
            return 1;
    return 0;
}
