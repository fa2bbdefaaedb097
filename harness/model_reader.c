/*
 * MotionSolve XML reader (expat) for the subset the harness supports.
 * Element and attribute names are matched case-insensitively, as MotionSolve
 * does. An element the harness does not support is named in a warning; a
 * malformed one is an error with the file and line.
 */
#include <errno.h>
#include <expat.h>
#include <libgen.h>
#include <limits.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "model.h"
#include "usrsub/units.h"
#include "vecmath.h"

typedef struct raw_marker {
    int body_id, rm_id, has_rm;
    double pos[3], R[9];
    int state; /* 0 unresolved, 1 resolving, 2 resolved */
} raw_marker;

typedef struct raw_body {
    int cg_id, im_id;
    double inertia[9]; /* in the IM marker's axes, about its origin */
} raw_body;

typedef struct raw_refs {
    int ids[4]; /* marker or joint ids, 0 when absent */
    char freedom[3];
} raw_refs;

typedef struct reader {
    XML_Parser parser;
    const char *path;
    FILE *warnings;
    hx_model *m;
    usrsub_message *msg;
    int failed;
    int ground_line;
    raw_marker *rmarkers;
    raw_body *rbodies;
    raw_refs *rjoints, *rcouplers, *rforces, *rloads;
    int cap_markers, cap_bodies, cap_joints, cap_couplers, cap_forces, cap_loads, cap_strings;
} reader;

/* ---- diagnostics -------------------------------------------------------- */

static void fail(reader *r, int line, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static void fail(reader *r, int line, const char *fmt, ...)
{
    if (r->failed)
        return;
    char what[USRSUB_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    usrsub_fail(r->msg, "%s:%d: %s", r->path, line, what);
    r->failed = 1;
    if (r->parser != NULL)
        XML_StopParser(r->parser, XML_FALSE);
}

static void warn(reader *r, int line, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static void warn(reader *r, int line, const char *fmt, ...)
{
    r->m->nwarnings++;
    if (r->warnings == NULL)
        return;
    va_list ap;
    va_start(ap, fmt);
    fprintf(r->warnings, "%s:%d: warning: ", r->path, line);
    vfprintf(r->warnings, fmt, ap);
    fputc('\n', r->warnings);
    va_end(ap);
}

/* ---- attributes ----------------------------------------------------------- */

typedef struct element_context {
    reader *r;
    const char *name; /* element name as the reader spells it */
    const XML_Char **atts;
    int line;
    int id;
} element_context;

static const char *attr(const element_context *e, const char *name)
{
    for (int k = 0; e->atts[k] != NULL; k += 2)
        if (strcasecmp(e->atts[k], name) == 0)
            return e->atts[k + 1];
    return NULL;
}

/* Warns about attributes the harness does not read. */
static void check_known(const element_context *e, const char *const *known)
{
    for (int k = 0; e->atts[k] != NULL; k += 2) {
        int found = strcasecmp(e->atts[k], "label") == 0;
        for (const char *const *n = known; !found && *n != NULL; ++n)
            found = strcasecmp(e->atts[k], *n) == 0;
        if (!found)
            warn(e->r, e->line, "%s %d: attribute %s is not supported by the harness; ignored",
                 e->name, e->id, e->atts[k]);
    }
}

static int parse_double(const char *text, double *out)
{
    char *end;
    errno = 0;
    const double v = strtod(text, &end);
    if (end == text || errno == ERANGE || !isfinite(v))
        return -1;
    while (*end == ' ' || *end == '\t' || *end == '\n' || *end == '\r')
        ++end;
    if (*end != '\0')
        return -1;
    *out = v;
    return 0;
}

static int real_attr(element_context *e, const char *name, int required, double fallback,
                     double *out)
{
    const char *text = attr(e, name);
    if (text == NULL) {
        if (required) {
            fail(e->r, e->line, "%s %d: attribute %s is missing", e->name, e->id, name);
            return -1;
        }
        *out = fallback;
        return 0;
    }
    if (parse_double(text, out) != 0) {
        fail(e->r, e->line, "%s %d: attribute %s = \"%s\" is not a finite number (expressions"
             " are not supported by the harness)", e->name, e->id, name, text);
        return -1;
    }
    return 0;
}

static int int_attr(element_context *e, const char *name, int required, int fallback, int *out)
{
    const char *text = attr(e, name);
    if (text == NULL) {
        if (required) {
            fail(e->r, e->line, "%s %d: attribute %s is missing", e->name, e->id, name);
            return -1;
        }
        *out = fallback;
        return 0;
    }
    double v;
    if (parse_double(text, &v) != 0 || v != floor(v) || fabs(v) > INT_MAX) {
        fail(e->r, e->line, "%s %d: attribute %s = \"%s\" is not an integer", e->name, e->id,
             name, text);
        return -1;
    }
    *out = (int)v;
    return 0;
}

static int id_attr(element_context *e)
{
    e->id = 0;
    int id;
    if (int_attr(e, "id", 1, 0, &id) != 0)
        return -1;
    if (id <= 0) {
        fail(e->r, e->line, "%s: id %d must be a positive integer", e->name, id);
        return -1;
    }
    e->id = id;
    return 0;
}

static char *copy_text(const char *text)
{
    return text != NULL ? strdup(text) : NULL;
}

/* usrsub_dll_name and usrsub_fnc_name: "NULL" means absent. */
static char *optional_name(const element_context *e, const char *name)
{
    const char *text = attr(e, name);
    if (text == NULL || *text == '\0' || strcasecmp(text, "NULL") == 0)
        return NULL;
    return strdup(text);
}

static int read_user_call(element_context *e, hx_user_call *u)
{
    const char *params = attr(e, "usrsub_param_string");
    if (params == NULL) {
        fail(e->r, e->line, "%s %d: a user-subroutine element needs usrsub_param_string",
             e->name, e->id);
        return -1;
    }
    usrsub_message why;
    if (hx_parse_user_list(params, &u->par, &u->npar, &why) != 0) {
        fail(e->r, e->line, "%s %d: usrsub_param_string: %s", e->name, e->id, why.text);
        return -1;
    }
    u->param_string = strdup(params);
    u->dll_name = optional_name(e, "usrsub_dll_name");
    u->fnc_name = optional_name(e, "usrsub_fnc_name");
    u->der1_name = optional_name(e, "usrsub_der1_name");
    u->der2_name = optional_name(e, "usrsub_der2_name");
    if (attr(e, "script_name") != NULL || attr(e, "interpreter") != NULL) {
        fail(e->r, e->line, "%s %d: script_name/interpreter user subroutines are not"
             " supported by the harness (compiled libraries only)", e->name, e->id);
        return -1;
    }
    return 0;
}

/* ---- arrays ----------------------------------------------------------------- */

static void *push(reader *r, void **array, int *count, int *capacity, size_t size)
{
    if (*count == *capacity) {
        const int grown = *capacity ? 2 * *capacity : 16;
        void *p = realloc(*array, size * (size_t)grown);
        if (p == NULL) {
            fail(r, 0, "out of memory");
            return NULL;
        }
        *array = p;
        *capacity = grown;
    }
    void *slot = (char *)*array + size * (size_t)*count;
    memset(slot, 0, size);
    ++*count;
    return slot;
}

/* Pushes onto a model array and its parallel raw array together. */
static int push_pair(reader *r, void **array, void **raw, int *count, int *capacity,
                     size_t size, size_t raw_size)
{
    int raw_count = *count, raw_capacity = *capacity;
    if (push(r, array, count, capacity, size) == NULL)
        return -1;
    if (push(r, raw, &raw_count, &raw_capacity, raw_size) == NULL)
        return -1;
    if (raw_capacity != *capacity) { /* both grow by the same rule from the same sizes */
        fail(r, 0, "internal: parallel arrays out of step");
        return -1;
    }
    return 0;
}

/* ---- elements --------------------------------------------------------------- */

static void read_param_unit(element_context *e)
{
    static const char *const known[] = {"force_unit", "mass_unit", "length_unit", "time_unit",
                                        "mass_mult_factor", NULL};
    e->id = 0;
    check_known(e, known);
    static const struct {
        const char *attribute;
        enum usrsub_unit_kind kind;
        double fallback;
    } units[] = {{"length_unit", USRSUB_UNIT_LENGTH, 1.0},
                 {"force_unit", USRSUB_UNIT_FORCE, 1.0},
                 {"mass_unit", USRSUB_UNIT_MASS, 1.0},
                 {"time_unit", USRSUB_UNIT_TIME, 1.0}};
    hx_model *m = e->r->m;
    for (size_t k = 0; k < sizeof units / sizeof units[0]; ++k) {
        const char *name = attr(e, units[k].attribute);
        m->unit_scales[units[k].kind] = units[k].fallback;
        if (name != NULL && usrsub_unit_size(units[k].kind, name, &m->unit_scales[units[k].kind]) != 0) {
            fail(e->r, e->line, "Param_Unit: %s = \"%s\" is not a unit the harness knows (%s)",
                 units[k].attribute, name, usrsub_unit_names(units[k].kind));
            return;
        }
    }
    m->unit_scales[USRSUB_UNIT_ANGLE] = 1.0;
    double factor;
    if (real_attr(e, "mass_mult_factor", 0, 1.0, &factor) != 0)
        return;
    if (factor != 1.0)
        warn(e->r, e->line, "Param_Unit: mass_mult_factor %g is not supported; the units named"
             " are used as they are", factor);
    m->has_units = 1;
}

static void read_gravity(element_context *e)
{
    static const char *const known[] = {"grav_x", "grav_y", "grav_z", NULL};
    e->id = 0;
    check_known(e, known);
    double *g = e->r->m->gravity;
    if (real_attr(e, "grav_x", 0, 0.0, &g[0]) == 0 && real_attr(e, "grav_y", 0, 0.0, &g[1]) == 0)
        real_attr(e, "grav_z", 0, 0.0, &g[2]);
}

static void read_string(element_context *e)
{
    static const char *const known[] = {"id", "string", NULL};
    if (id_attr(e) != 0)
        return;
    check_known(e, known);
    const char *text = attr(e, "string");
    if (text == NULL) {
        fail(e->r, e->line, "Reference_String %d: attribute string is missing (user-subroutine"
             " strings are not supported)", e->id);
        return;
    }
    reader *r = e->r;
    if (hx_model_string(r->m, e->id) != NULL) {
        fail(r, e->line, "Reference_String %d is defined twice", e->id);
        return;
    }
    hx_string *s = push(r, (void **)&r->m->strings, &r->m->nstrings, &r->cap_strings, sizeof *s);
    if (s != NULL) {
        s->id = e->id;
        s->text = strdup(text);
    }
}

static void read_ground(element_context *e)
{
    static const char *const known[] = {"id", NULL};
    if (id_attr(e) != 0)
        return;
    check_known(e, known);
    reader *r = e->r;
    if (r->m->ground >= 0) {
        fail(r, e->line, "Body_Ground %d: the model already has a Body_Ground (line %d)", e->id,
             r->ground_line);
        return;
    }
    int count = r->m->nbodies;
    if (push_pair(r, (void **)&r->m->bodies, (void **)&r->rbodies, &count, &r->cap_bodies,
                  sizeof(hx_body), sizeof(raw_body)) != 0)
        return;
    r->m->nbodies = count;
    hx_body *b = &r->m->bodies[count - 1];
    b->id = e->id;
    b->is_ground = 1;
    b->joint = -1;
    b->cg_marker = -1;
    b->line = e->line;
    m3_identity(b->R0);
    m3_identity(b->inertia);
    r->m->ground = count - 1;
    r->ground_line = e->line;
}

static void read_body_rigid(element_context *e)
{
    static const char *const known[] = {
        "id", "cg_id", "im_id", "lprf_id", "mass", "inertia_xx", "inertia_yy", "inertia_zz",
        "inertia_xy", "inertia_yz", "inertia_xz", "v_ic_x", "v_ic_y", "v_ic_z", "w_ic_x",
        "w_ic_y", "w_ic_z", "v_ic_x_flag", "v_ic_y_flag", "v_ic_z_flag", "w_ic_x_flag",
        "w_ic_y_flag", "w_ic_z_flag", NULL};
    if (id_attr(e) != 0)
        return;
    check_known(e, known);
    reader *r = e->r;
    if (hx_model_body(r->m, e->id) >= 0) {
        fail(r, e->line, "Body_Rigid %d: a body with this id is already defined", e->id);
        return;
    }
    int count = r->m->nbodies;
    if (push_pair(r, (void **)&r->m->bodies, (void **)&r->rbodies, &count, &r->cap_bodies,
                  sizeof(hx_body), sizeof(raw_body)) != 0)
        return;
    r->m->nbodies = count;
    hx_body *b = &r->m->bodies[count - 1];
    raw_body *rb = &r->rbodies[count - 1];
    b->id = e->id;
    b->joint = -1;
    b->line = e->line;
    b->label = copy_text(attr(e, "label"));
    double ixx, iyy, izz, ixy, iyz, ixz;
    if (int_attr(e, "cg_id", 1, 0, &rb->cg_id) != 0 ||
        int_attr(e, "im_id", 0, rb->cg_id, &rb->im_id) != 0 ||
        real_attr(e, "mass", 1, 0.0, &b->mass) != 0 ||
        real_attr(e, "inertia_xx", 1, 0.0, &ixx) != 0 ||
        real_attr(e, "inertia_yy", 1, 0.0, &iyy) != 0 ||
        real_attr(e, "inertia_zz", 1, 0.0, &izz) != 0 ||
        real_attr(e, "inertia_xy", 0, 0.0, &ixy) != 0 ||
        real_attr(e, "inertia_yz", 0, 0.0, &iyz) != 0 ||
        real_attr(e, "inertia_xz", 0, 0.0, &ixz) != 0 ||
        real_attr(e, "v_ic_x", 0, 0.0, &b->v0[0]) != 0 ||
        real_attr(e, "v_ic_y", 0, 0.0, &b->v0[1]) != 0 ||
        real_attr(e, "v_ic_z", 0, 0.0, &b->v0[2]) != 0 ||
        real_attr(e, "w_ic_x", 0, 0.0, &b->w0[0]) != 0 ||
        real_attr(e, "w_ic_y", 0, 0.0, &b->w0[1]) != 0 ||
        real_attr(e, "w_ic_z", 0, 0.0, &b->w0[2]) != 0)
        return;
    if (!(b->mass > 0.0) || !(ixx > 0.0) || !(iyy > 0.0) || !(izz > 0.0)) {
        fail(r, e->line, "Body_Rigid %d: mass and inertia_xx/yy/zz must be positive (got %g,"
             " %g, %g, %g)", e->id, b->mass, ixx, iyy, izz);
        return;
    }
    const double I[9] = {ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz};
    memcpy(rb->inertia, I, sizeof I);
}

static void read_marker(element_context *e)
{
    static const char *const known[] = {"id", "body_id", "body_type", "rm_id", "pos_x", "pos_y",
                                        "pos_z", "a00", "a10", "a20", "a01", "a11", "a21", "a02",
                                        "a12", "a22", NULL};
    if (id_attr(e) != 0)
        return;
    check_known(e, known);
    reader *r = e->r;
    for (int k = 0; k < r->m->nmarkers; ++k)
        if (r->m->markers[k].id == e->id) {
            fail(r, e->line, "Reference_Marker %d is defined twice (line %d)", e->id,
                 r->m->markers[k].line);
            return;
        }
    const char *body_type = attr(e, "body_type");
    if (body_type != NULL && strcasecmp(body_type, "RIGIDBODY") != 0) {
        fail(r, e->line, "Reference_Marker %d: body_type %s is not supported (RIGIDBODY only)",
             e->id, body_type);
        return;
    }
    int count = r->m->nmarkers;
    if (push_pair(r, (void **)&r->m->markers, (void **)&r->rmarkers, &count, &r->cap_markers,
                  sizeof(hx_marker), sizeof(raw_marker)) != 0)
        return;
    r->m->nmarkers = count;
    hx_marker *mk = &r->m->markers[count - 1];
    raw_marker *rm = &r->rmarkers[count - 1];
    mk->id = e->id;
    mk->line = e->line;
    static const char *const cosines[9] = {"a00", "a01", "a02", "a10", "a11",
                                           "a12", "a20", "a21", "a22"};
    double R[9];
    m3_identity(R);
    rm->has_rm = attr(e, "rm_id") != NULL;
    if (int_attr(e, "body_id", 1, 0, &rm->body_id) != 0 ||
        int_attr(e, "rm_id", 0, 0, &rm->rm_id) != 0 ||
        real_attr(e, "pos_x", 0, 0.0, &rm->pos[0]) != 0 ||
        real_attr(e, "pos_y", 0, 0.0, &rm->pos[1]) != 0 ||
        real_attr(e, "pos_z", 0, 0.0, &rm->pos[2]) != 0)
        return;
    for (int k = 0; k < 9; ++k)
        if (real_attr(e, cosines[k], 0, R[k], &R[k]) != 0)
            return;
    /* The columns must be orthonormal; then make them so to the last bit. */
    double RtR[9];
    m3_tmul(RtR, R, R);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (fabs(RtR[3 * i + j] - (i == j)) > 1e-6) {
                fail(r, e->line, "Reference_Marker %d: the direction cosines a00..a22 are not"
                     " orthonormal (column %d . column %d = %g)", e->id, i, j, RtR[3 * i + j]);
                return;
            }
    double x[3] = {R[0], R[3], R[6]}, y[3] = {R[1], R[4], R[7]}, z[3];
    v3_scale(x, x, 1.0 / v3_norm(x));
    v3_cross(z, x, y);
    v3_scale(z, z, 1.0 / v3_norm(z));
    v3_cross(y, z, x);
    const double Rn[9] = {x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]};
    if (v3_dot(z, (double[3]){R[2], R[5], R[8]}) < 0) {
        fail(r, e->line, "Reference_Marker %d: the direction cosines form a left-handed frame",
             e->id);
        return;
    }
    memcpy(rm->R, Rn, sizeof Rn);
}

static int read_refs(element_context *e, raw_refs *refs, const char *const *names, int count)
{
    for (int k = 0; k < count; ++k)
        if (int_attr(e, names[k], 1, 0, &refs->ids[k]) != 0)
            return -1;
    return 0;
}

static void read_joint(element_context *e)
{
    static const char *const known[] = {"id", "type", "i_marker_id", "j_marker_id",
                                        "is_virtual", NULL};
    if (id_attr(e) != 0)
        return;
    check_known(e, known);
    reader *r = e->r;
    if (hx_model_joint(r->m, e->id) >= 0) {
        fail(r, e->line, "Constraint_Joint %d is defined twice", e->id);
        return;
    }
    const char *type = attr(e, "type");
    enum hx_joint_type jt;
    if (type != NULL && strcasecmp(type, "REVOLUTE") == 0)
        jt = HX_JOINT_REVOLUTE;
    else if (type != NULL && strcasecmp(type, "TRANSLATIONAL") == 0)
        jt = HX_JOINT_TRANSLATIONAL;
    else {
        fail(r, e->line, "Constraint_Joint %d: type \"%s\" is not supported by the harness"
             " (REVOLUTE or TRANSLATIONAL, J marker on ground)", e->id, type ? type : "");
        return;
    }
    int count = r->m->njoints;
    if (push_pair(r, (void **)&r->m->joints, (void **)&r->rjoints, &count, &r->cap_joints,
                  sizeof(hx_joint), sizeof(raw_refs)) != 0)
        return;
    r->m->njoints = count;
    hx_joint *j = &r->m->joints[count - 1];
    j->id = e->id;
    j->type = jt;
    j->line = e->line;
    static const char *const names[] = {"i_marker_id", "j_marker_id"};
    read_refs(e, &r->rjoints[count - 1], names, 2);
}

static void read_coupler(element_context *e)
{
    static const char *const known[] = {
        "id", "joint1_id", "freedom_1", "joint2_id", "freedom_2", "joint3_id", "freedom_3",
        "coefficients", "usrsub_dll_name", "usrsub_param_string", "usrsub_fnc_name",
        "usrsub_der1_name", "usrsub_der2_name", "is_virtual", "script_name", "interpreter",
        NULL};
    if (id_attr(e) != 0)
        return;
    check_known(e, known);
    reader *r = e->r;
    int count = r->m->ncouplers;
    if (push_pair(r, (void **)&r->m->couplers, (void **)&r->rcouplers, &count, &r->cap_couplers,
                  sizeof(hx_coupler), sizeof(raw_refs)) != 0)
        return;
    r->m->ncouplers = count;
    hx_coupler *c = &r->m->couplers[count - 1];
    raw_refs *refs = &r->rcouplers[count - 1];
    c->id = e->id;
    c->line = e->line;
    static const char *const joint_names[] = {"joint1_id", "joint2_id", "joint3_id"};
    static const char *const freedom_names[] = {"freedom_1", "freedom_2", "freedom_3"};
    c->njoints = attr(e, "joint3_id") != NULL ? 3 : 2;
    for (int k = 0; k < c->njoints; ++k) {
        if (int_attr(e, joint_names[k], 1, 0, &refs->ids[k]) != 0)
            return;
        const char *f = attr(e, freedom_names[k]);
        refs->freedom[k] = f != NULL ? (char)(f[0] & ~0x20) : 0;
        if (f != NULL && ((refs->freedom[k] != 'T' && refs->freedom[k] != 'R') || f[1] != '\0')) {
            fail(r, e->line, "Constraint_Coupler %d: %s = \"%s\": expected \"T\" or \"R\"", e->id,
                 freedom_names[k], f);
            return;
        }
    }
    const char *coefficients = attr(e, "coefficients");
    if (coefficients != NULL) {
        char list[512];
        snprintf(list, sizeof list, "USER(%s)", coefficients);
        double *values = NULL;
        int n = 0;
        usrsub_message why;
        if (hx_parse_user_list(list, &values, &n, &why) != 0 || n != c->njoints) {
            free(values);
            fail(r, e->line, "Constraint_Coupler %d: coefficients = \"%s\": expected %d numbers",
                 e->id, coefficients, c->njoints);
            return;
        }
        memcpy(c->coefficients, values, sizeof(double) * (size_t)n);
        free(values);
        if (attr(e, "usrsub_param_string") != NULL)
            warn(r, e->line, "Constraint_Coupler %d: has both coefficients and a user subroutine;"
                 " the coefficients are used", e->id);
        return;
    }
    c->is_user = 1;
    read_user_call(e, &c->user);
}

static void read_force_vector(element_context *e)
{
    static const char *const known[] = {
        "id", "type", "i_marker_id", "j_floating_marker_id", "ref_marker_id",
        "usrsub_dll_name", "usrsub_param_string", "usrsub_fnc_name", "body1_id", "body2_id",
        "ref_body_id", "script_name", "interpreter", NULL};
    if (id_attr(e) != 0)
        return;
    check_known(e, known);
    reader *r = e->r;
    const char *type = attr(e, "type");
    if (type == NULL || strcasecmp(type, "ForceAndTorque") != 0) {
        fail(r, e->line, "Force_Vector_TwoBody %d: type \"%s\" is not supported by the harness"
             " (ForceAndTorque with a GFOSUB-style user subroutine)", e->id, type ? type : "");
        return;
    }
    if (attr(e, "usrsub_param_string") == NULL) {
        fail(r, e->line, "Force_Vector_TwoBody %d: expression forces are not supported by the"
             " harness (user subroutines only)", e->id);
        return;
    }
    int count = r->m->nforces;
    if (push_pair(r, (void **)&r->m->forces, (void **)&r->rforces, &count, &r->cap_forces,
                  sizeof(hx_force), sizeof(raw_refs)) != 0)
        return;
    r->m->nforces = count;
    hx_force *f = &r->m->forces[count - 1];
    raw_refs *refs = &r->rforces[count - 1];
    f->id = e->id;
    f->interface = HX_FORCE_GFOSUB;
    f->line = e->line;
    static const char *const names[] = {"i_marker_id", "j_floating_marker_id"};
    if (read_refs(e, refs, names, 2) != 0 || int_attr(e, "ref_marker_id", 0, 0, &refs->ids[2]) != 0)
        return;
    read_user_call(e, &f->user);
}

static void read_force_field(element_context *e)
{
    static const char *const known[] = {"id", "i_marker_id", "j_marker_id", "usrsub_dll_name",
                                        "usrsub_param_string", "usrsub_fnc_name", "body1_id",
                                        "body2_id", "script_name", "interpreter", NULL};
    if (id_attr(e) != 0)
        return;
    reader *r = e->r;
    if (attr(e, "usrsub_param_string") == NULL) {
        fail(r, e->line, "Force_Field %d: the linear (matrix attribute) form is not supported by"
             " the harness (user subroutines only)", e->id);
        return;
    }
    check_known(e, known);
    int count = r->m->nforces;
    if (push_pair(r, (void **)&r->m->forces, (void **)&r->rforces, &count, &r->cap_forces,
                  sizeof(hx_force), sizeof(raw_refs)) != 0)
        return;
    r->m->nforces = count;
    hx_force *f = &r->m->forces[count - 1];
    f->id = e->id;
    f->interface = HX_FORCE_FIESUB;
    f->line = e->line;
    static const char *const names[] = {"i_marker_id", "j_marker_id"};
    if (read_refs(e, &r->rforces[count - 1], names, 2) != 0)
        return;
    read_user_call(e, &f->user);
}

static hx_load *push_load(element_context *e, raw_refs **refs)
{
    reader *r = e->r;
    int count = r->m->nloads;
    if (push_pair(r, (void **)&r->m->loads, (void **)&r->rloads, &count, &r->cap_loads,
                  sizeof(hx_load), sizeof(raw_refs)) != 0)
        return NULL;
    r->m->nloads = count;
    *refs = &r->rloads[count - 1];
    hx_load *l = &r->m->loads[count - 1];
    l->id = e->id;
    l->line = e->line;
    return l;
}

/* A load attribute: a number or STEP/STEP5(TIME, t0, h0, t1, h1). */
static int load_attr(element_context *e, const char *name, int required, hx_time_function *f)
{
    const char *text = attr(e, name);
    if (text == NULL) {
        if (required) {
            fail(e->r, e->line, "%s %d: attribute %s is missing", e->name, e->id, name);
            return -1;
        }
        memset(f, 0, sizeof *f);
        return 0;
    }
    if (hx_parse_time_function(text, f) != 0) {
        fail(e->r, e->line, "%s %d: %s = \"%s\": the harness reads a number or"
             " STEP(TIME, t0, h0, t1, h1) / STEP5(...) with t1 >= t0", e->name, e->id, name, text);
        return -1;
    }
    return 0;
}

static void read_vector_load(element_context *e)
{
    static const char *const known[] = {"id", "type", "marker_id", "ref_marker_id",
                                        "fx_expression", "fy_expression", "fz_expression",
                                        "tx_expression", "ty_expression", "tz_expression", NULL};
    if (id_attr(e) != 0)
        return;
    check_known(e, known);
    if (attr(e, "usrsub_param_string") != NULL) {
        fail(e->r, e->line, "Force_Vector_OneBody %d: user subroutines are not supported here"
             " (constant components only)", e->id);
        return;
    }
    raw_refs *refs;
    hx_load *l = push_load(e, &refs);
    if (l == NULL)
        return;
    l->kind = HX_LOAD_VECTOR;
    static const char *const comps[6] = {"fx_expression", "fy_expression", "fz_expression",
                                         "tx_expression", "ty_expression", "tz_expression"};
    for (int k = 0; k < 6; ++k)
        if (load_attr(e, comps[k], 0, k < 3 ? &l->force[k] : &l->torque[k - 3]) != 0)
            return;
    if (int_attr(e, "marker_id", 1, 0, &refs->ids[0]) == 0)
        int_attr(e, "ref_marker_id", 0, 0, &refs->ids[2]);
}

static void read_scalar_load(element_context *e)
{
    static const char *const known[] = {"id", "type", "i_marker_id", "j_marker_id",
                                        "is_action_only", "val", "val_expression", NULL};
    if (id_attr(e) != 0)
        return;
    check_known(e, known);
    const char *type = attr(e, "type");
    const int torque = type != NULL && strcasecmp(type, "TORQUE") == 0;
    if (!torque && (type == NULL || strcasecmp(type, "FORCE") != 0)) {
        fail(e->r, e->line, "Force_Scalar_TwoBody %d: type \"%s\": expected FORCE or TORQUE",
             e->id, type ? type : "");
        return;
    }
    raw_refs *refs;
    hx_load *l = push_load(e, &refs);
    if (l == NULL)
        return;
    l->kind = torque ? HX_LOAD_SCALAR_TORQUE : HX_LOAD_SCALAR_FORCE;
    const char *value_name = attr(e, "val") != NULL ? "val" : "val_expression";
    const char *action = attr(e, "is_action_only");
    l->action_only = action != NULL && strcasecmp(action, "TRUE") == 0;
    static const char *const names[] = {"i_marker_id", "j_marker_id"};
    if (load_attr(e, value_name, 1, &l->value) == 0)
        read_refs(e, refs, names, 2);
}

typedef struct element_handler {
    const char *name;
    void (*read)(element_context *e);
} element_handler;

static const element_handler handlers[] = {
    {"MotionSolve", NULL},
    {"Model", NULL},
    {"Param_Unit", read_param_unit},
    {"Force_Gravity", read_gravity},
    {"Reference_String", read_string},
    {"Body_Ground", read_ground},
    {"Body_Rigid", read_body_rigid},
    {"Reference_Marker", read_marker},
    {"Constraint_Joint", read_joint},
    {"Constraint_Coupler", read_coupler},
    {"Force_Vector_TwoBody", read_force_vector},
    {"Force_Field", read_force_field},
    {"Force_Vector_OneBody", read_vector_load},
    {"Force_Scalar_TwoBody", read_scalar_load},
};

static void XMLCALL on_start(void *data, const XML_Char *name, const XML_Char **atts)
{
    reader *r = data;
    if (r->failed)
        return;
    element_context e = {r, name, atts, (int)XML_GetCurrentLineNumber(r->parser), 0};
    for (size_t k = 0; k < sizeof handlers / sizeof handlers[0]; ++k)
        if (strcasecmp(handlers[k].name, name) == 0) {
            e.name = handlers[k].name;
            if (handlers[k].read != NULL)
                handlers[k].read(&e);
            return;
        }
    warn(r, e.line, "element <%s> is not supported by the harness; ignored", name);
}

/* ---- resolving references ------------------------------------------------------ */

static int resolve_marker(reader *r, int k)
{
    hx_model *m = r->m;
    raw_marker *rm = &r->rmarkers[k];
    hx_marker *mk = &m->markers[k];
    if (rm->state == 2)
        return 0;
    if (rm->state == 1) {
        fail(r, mk->line, "Reference_Marker %d: its rm_id chain leads back to itself", mk->id);
        return -1;
    }
    rm->state = 1;
    mk->body = hx_model_body(m, rm->body_id);
    if (mk->body < 0) {
        fail(r, mk->line, "Reference_Marker %d: body_id %d is not a Body_Rigid or Body_Ground",
             mk->id, rm->body_id);
        return -1;
    }
    if (rm->has_rm && rm->rm_id != 0) {
        int base = -1;
        for (int j = 0; j < m->nmarkers; ++j)
            if (m->markers[j].id == rm->rm_id)
                base = j;
        if (base < 0) {
            fail(r, mk->line, "Reference_Marker %d: rm_id %d is not a marker", mk->id, rm->rm_id);
            return -1;
        }
        if (resolve_marker(r, base) != 0)
            return -1;
        const hx_marker *b = &m->markers[base];
        m3_apply(mk->pos0, b->R0, rm->pos);
        v3_add(mk->pos0, mk->pos0, b->pos0);
        m3_mul(mk->R0, b->R0, rm->R);
    } else {
        v3_copy(mk->pos0, rm->pos);
        m3_copy(mk->R0, rm->R);
    }
    rm->state = 2;
    return 0;
}

static int marker_ref(reader *r, int id, int line, const char *owner, int owner_id,
                      const char *what, int *index)
{
    *index = hx_model_marker(r->m, id);
    if (*index < 0) {
        fail(r, line, "%s %d: %s %d is not a Reference_Marker", owner, owner_id, what, id);
        return -1;
    }
    return 0;
}

static int build_marker_index(reader *r)
{
    hx_model *m = r->m;
    m->marker_slot_count = 4;
    while (m->marker_slot_count < 2 * m->nmarkers)
        m->marker_slot_count *= 2;
    m->marker_slots = malloc(sizeof(int) * (size_t)m->marker_slot_count);
    if (m->marker_slots == NULL) {
        fail(r, 0, "out of memory");
        return -1;
    }
    for (int s = 0; s < m->marker_slot_count; ++s)
        m->marker_slots[s] = -1;
    for (int k = 0; k < m->nmarkers; ++k) {
        const unsigned mask = (unsigned)m->marker_slot_count - 1u;
        unsigned s = ((unsigned)m->markers[k].id * 2654435761u) & mask;
        while (m->marker_slots[s] >= 0)
            s = (s + 1) & mask;
        m->marker_slots[s] = k;
    }
    return 0;
}

static int resolve_bodies(reader *r)
{
    hx_model *m = r->m;
    for (int k = 0; k < m->nbodies; ++k) {
        hx_body *b = &m->bodies[k];
        if (b->is_ground)
            continue;
        raw_body *rb = &r->rbodies[k];
        int cg, im;
        if (marker_ref(r, rb->cg_id, b->line, "Body_Rigid", b->id, "cg_id", &cg) != 0 ||
            marker_ref(r, rb->im_id, b->line, "Body_Rigid", b->id, "im_id", &im) != 0)
            return -1;
        if (m->markers[cg].body != k || m->markers[im].body != k) {
            fail(r, b->line, "Body_Rigid %d: its cg_id and im_id markers must belong to it", b->id);
            return -1;
        }
        b->cg_marker = cg;
        v3_copy(b->p0, m->markers[cg].pos0);
        m3_copy(b->R0, m->markers[cg].R0);
        /* Inertia given in IM axes about the IM origin: rotate to body axes and move
         * to the centre of mass (parallel axes). */
        double Rbi[9], tmp[9];
        m3_tmul(Rbi, b->R0, m->markers[im].R0);
        m3_mul(tmp, Rbi, rb->inertia);
        m3_mult(b->inertia, tmp, Rbi);
        double d_world[3], d[3];
        v3_sub(d_world, b->p0, m->markers[im].pos0);
        m3_tapply(d, b->R0, d_world);
        const double dd = v3_dot(d, d);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                b->inertia[3 * i + j] -= b->mass * ((i == j ? dd : 0.0) - d[i] * d[j]);
    }
    for (int k = 0; k < m->nmarkers; ++k) {
        hx_marker *mk = &m->markers[k];
        const hx_body *b = &m->bodies[mk->body];
        double d[3];
        v3_sub(d, mk->pos0, b->p0);
        m3_tapply(mk->r_local, b->R0, d);
        m3_tmul(mk->R_local, b->R0, mk->R0);
        /* the common cases, marked so that frames skip their products; an
         * orientation equal to the body's up to rounding is taken as equal */
        double off = 0.0;
        for (int i = 0; i < 9; ++i)
            off = fmax(off, fabs(mk->R_local[i] - (i % 4 == 0 ? 1.0 : 0.0)));
        mk->local_axes = off <= 4.0 * DBL_EPSILON;
        if (mk->local_axes)
            m3_identity(mk->R_local);
        mk->at_body_origin = mk->r_local[0] == 0.0 && mk->r_local[1] == 0.0 && mk->r_local[2] == 0.0;
    }
    return 0;
}

static int resolve_joints(reader *r)
{
    hx_model *m = r->m;
    for (int k = 0; k < m->njoints; ++k) {
        hx_joint *j = &m->joints[k];
        const raw_refs *refs = &r->rjoints[k];
        if (marker_ref(r, refs->ids[0], j->line, "Constraint_Joint", j->id, "i_marker_id",
                       &j->i_marker) != 0 ||
            marker_ref(r, refs->ids[1], j->line, "Constraint_Joint", j->id, "j_marker_id",
                       &j->j_marker) != 0)
            return -1;
        const hx_marker *mi = &m->markers[j->i_marker], *mj = &m->markers[j->j_marker];
        if (!m->bodies[mj->body].is_ground || m->bodies[mi->body].is_ground) {
            fail(r, j->line, "Constraint_Joint %d: the harness supports joints whose J marker is"
                 " on ground and I marker on a rigid body", j->id);
            return -1;
        }
        hx_body *b = &m->bodies[mi->body];
        if (b->joint >= 0) {
            fail(r, j->line, "Constraint_Joint %d: Body_Rigid %d already has joint %d", j->id,
                 b->id, m->joints[b->joint].id);
            return -1;
        }
        const double zi[3] = {mi->R0[2], mi->R0[5], mi->R0[8]};
        const double zj[3] = {mj->R0[2], mj->R0[5], mj->R0[8]};
        if (v3_dot(zi, zj) < 1.0 - 1e-9) {
            fail(r, j->line, "Constraint_Joint %d: the z axes of the I and J markers must be"
                 " aligned", j->id);
            return -1;
        }
        if (j->type == HX_JOINT_REVOLUTE) {
            double d[3];
            v3_sub(d, mi->pos0, mj->pos0);
            if (v3_norm(d) > 1e-9 * (1.0 + v3_norm(mj->pos0))) {
                fail(r, j->line, "Constraint_Joint %d: a revolute joint's I and J markers must"
                     " coincide", j->id);
                return -1;
            }
        } else {
            double d[3], off[3];
            v3_sub(d, mi->pos0, mj->pos0);
            v3_cross(off, d, zj);
            if (v3_norm(off) > 1e-9 * (1.0 + v3_norm(mj->pos0))) {
                fail(r, j->line, "Constraint_Joint %d: a translational joint's I marker must lie"
                     " on the J marker's z axis", j->id);
                return -1;
            }
            double xi[3] = {mi->R0[0], mi->R0[3], mi->R0[6]}, xj[3] = {mj->R0[0], mj->R0[3], mj->R0[6]};
            if (v3_dot(xi, xj) < 1.0 - 1e-9) {
                fail(r, j->line, "Constraint_Joint %d: a translational joint's I and J markers"
                     " must have the same orientation", j->id);
                return -1;
            }
        }
        b->joint = k;
    }
    return 0;
}

static int resolve_couplers(reader *r)
{
    hx_model *m = r->m;
    for (int k = 0; k < m->ncouplers; ++k) {
        hx_coupler *c = &m->couplers[k];
        const raw_refs *refs = &r->rcouplers[k];
        for (int i = 0; i < c->njoints; ++i) {
            c->joint[i] = hx_model_joint(m, refs->ids[i]);
            if (c->joint[i] < 0) {
                fail(r, c->line, "Constraint_Coupler %d: joint%d_id %d is not a Constraint_Joint",
                     c->id, i + 1, refs->ids[i]);
                return -1;
            }
            const char expected = m->joints[c->joint[i]].type == HX_JOINT_REVOLUTE ? 'R' : 'T';
            if (refs->freedom[i] != 0 && refs->freedom[i] != expected) {
                fail(r, c->line, "Constraint_Coupler %d: freedom_%d is \"%c\" but joint %d is %s",
                     c->id, i + 1, refs->freedom[i], refs->ids[i],
                     expected == 'R' ? "revolute (\"R\")" : "translational (\"T\")");
                return -1;
            }
            for (int j = 0; j < i; ++j)
                if (c->joint[j] == c->joint[i]) {
                    fail(r, c->line, "Constraint_Coupler %d: joint %d is coupled twice", c->id,
                         refs->ids[i]);
                    return -1;
                }
        }
    }
    return 0;
}

static int resolve_forces(reader *r)
{
    hx_model *m = r->m;
    for (int k = 0; k < m->nforces; ++k) {
        hx_force *f = &m->forces[k];
        const raw_refs *refs = &r->rforces[k];
        const char *owner = f->interface == HX_FORCE_GFOSUB ? "Force_Vector_TwoBody" : "Force_Field";
        if (marker_ref(r, refs->ids[0], f->line, owner, f->id, "i_marker_id", &f->i_marker) != 0 ||
            marker_ref(r, refs->ids[1], f->line, owner, f->id,
                       f->interface == HX_FORCE_GFOSUB ? "j_floating_marker_id" : "j_marker_id",
                       &f->j_marker) != 0)
            return -1;
        f->ref_marker = -1;
        if (f->interface == HX_FORCE_GFOSUB && refs->ids[2] != 0 &&
            marker_ref(r, refs->ids[2], f->line, owner, f->id, "ref_marker_id", &f->ref_marker) != 0)
            return -1;
        if (m->markers[f->i_marker].body == m->markers[f->j_marker].body) {
            fail(r, f->line, "%s %d: its I and J markers are on the same body", owner, f->id);
            return -1;
        }
    }
    for (int k = 0; k < m->nloads; ++k) {
        hx_load *l = &m->loads[k];
        const raw_refs *refs = &r->rloads[k];
        const char *owner = l->kind == HX_LOAD_VECTOR ? "Force_Vector_OneBody" : "Force_Scalar_TwoBody";
        l->j_marker = l->ref_marker = -1;
        if (marker_ref(r, refs->ids[0], l->line, owner, l->id,
                       l->kind == HX_LOAD_VECTOR ? "marker_id" : "i_marker_id", &l->i_marker) != 0)
            return -1;
        if (l->kind != HX_LOAD_VECTOR &&
            marker_ref(r, refs->ids[1], l->line, owner, l->id, "j_marker_id", &l->j_marker) != 0)
            return -1;
        if (l->kind == HX_LOAD_VECTOR && refs->ids[2] != 0 &&
            marker_ref(r, refs->ids[2], l->line, owner, l->id, "ref_marker_id", &l->ref_marker) != 0)
            return -1;
    }
    return 0;
}

static int resolve(reader *r)
{
    hx_model *m = r->m;
    if (m->ground < 0) {
        fail(r, 1, "the model has no Body_Ground");
        return -1;
    }
    for (int k = 0; k < m->nmarkers; ++k)
        if (resolve_marker(r, k) != 0)
            return -1;
    if (build_marker_index(r) != 0 || resolve_bodies(r) != 0 || resolve_joints(r) != 0 ||
        resolve_couplers(r) != 0 || resolve_forces(r) != 0)
        return -1;
    return 0;
}

/* Feeds the XML to expat: from the file at r->path, or from text when not NULL. */
static int parse_source(reader *r, const char *text, size_t length)
{
    FILE *f = NULL;
    if (text == NULL && (f = fopen(r->path, "rb")) == NULL) {
        usrsub_fail(r->msg, "%s: cannot open the model: %s", r->path, strerror(errno));
        return -1;
    }
    r->parser = XML_ParserCreate(NULL);
    if (r->parser == NULL) {
        if (f != NULL)
            fclose(f);
        usrsub_fail(r->msg, "%s: out of memory", r->path);
        return -1;
    }
    XML_SetUserData(r->parser, r);
    XML_SetStartElementHandler(r->parser, on_start);
    char buffer[16384];
    size_t offset = 0;
    int done = 0;
    while (!done && !r->failed) {
        size_t n;
        if (f != NULL) {
            n = fread(buffer, 1, sizeof buffer, f);
            done = n < sizeof buffer;
        } else {
            n = length - offset < sizeof buffer ? length - offset : sizeof buffer;
            memcpy(buffer, text + offset, n);
            offset += n;
            done = offset == length;
        }
        if (XML_Parse(r->parser, buffer, (int)n, done) == XML_STATUS_ERROR && !r->failed) {
            usrsub_fail(r->msg, "%s:%lu: malformed XML: %s", r->path,
                        (unsigned long)XML_GetCurrentLineNumber(r->parser),
                        XML_ErrorString(XML_GetErrorCode(r->parser)));
            r->failed = 1;
        }
    }
    XML_ParserFree(r->parser);
    r->parser = NULL;
    if (f != NULL)
        fclose(f);
    return r->failed ? -1 : 0;
}

static hx_model *read_model(const char *path, const char *text, size_t length, FILE *warnings,
                            usrsub_message *msg)
{
    hx_model *m = calloc(1, sizeof *m);
    if (m == NULL) {
        usrsub_fail(msg, "out of memory");
        return NULL;
    }
    m->ground = -1;
    for (int k = 0; k < USRSUB_UNIT_COUNT; ++k)
        m->unit_scales[k] = 1.0;
    char real[PATH_MAX];
    m->path = strdup(text == NULL && realpath(path, real) != NULL ? real : path);
    char *copy = m->path != NULL ? strdup(m->path) : NULL;
    m->dir = copy != NULL ? strdup(dirname(copy)) : NULL;
    free(copy);
    reader r = {.path = path, .warnings = warnings, .m = m, .msg = msg};
    int status = (m->path == NULL || m->dir == NULL) ? usrsub_fail(msg, "out of memory") : 0;
    if (status == 0)
        status = parse_source(&r, text, length);
    if (status == 0)
        status = resolve(&r);
    free(r.rmarkers);
    free(r.rbodies);
    free(r.rjoints);
    free(r.rcouplers);
    free(r.rforces);
    free(r.rloads);
    if (status != 0) {
        hx_model_free(m);
        return NULL;
    }
    return m;
}

hx_model *hx_model_read(const char *path, FILE *warnings, usrsub_message *msg)
{
    return read_model(path, NULL, 0, warnings, msg);
}

hx_model *hx_model_parse(const char *text, size_t length, const char *name, FILE *warnings,
                         usrsub_message *msg)
{
    return read_model(name, text != NULL ? text : "", text != NULL ? length : 0, warnings, msg);
}
