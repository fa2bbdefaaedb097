/*
 * Adams' C-style form of the user routines (records.h). The records' layouts
 * are those of Adams' C utility header (docs/sources.md §5.3): each begins
 * with the element's id, its USER list's length and the list, then what
 * the element names, as ints (ids) and C strings.
 */
#include "host/records.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

typedef struct gforce_record { int id, npar; const double *par; int i, rm, jfloat; } gforce_record;
/* VFORCE and VTORQUE: the same ids in another order */
typedef struct vector_record { int id, npar; const double *par; int i, jfloat, rm; } vector_record;
typedef struct sforce_record {
    int id, npar;
    const double *par;
    int i, j, action_only;
    const char *type; /* "TRANSLATION" or "ROTATION" */
} sforce_record;
typedef struct field_record { int id, npar; const double *par; int i, j; } field_record;
typedef struct coupler_record {
    int id, npar;
    const double *par;
    int njoint, joints[3];
    char type[3]; /* each joint's freedom: 'T' or 'R' */
} coupler_record;
typedef struct request_record {
    int id, npar;
    const double *par;
    const char *comment, *title[8];
} request_record;
typedef struct variable_record { int id, npar; const double *par; double ic; } variable_record;
typedef struct diff_record {
    int id, npar;
    const double *par;
    int static_hold, implicit;
    double ic, ic_dot;
} diff_record;
typedef struct motion_record {
    int id, npar;
    const double *par;
    int joint;
    const char *type; /* "TRANSLATION" or "ROTATION" */
    int i, j;
    char which[2];    /* the joint's axis: "Z" */
    const char *dva;  /* "DISP", "VEL" or "ACC": what the value is */
} motion_record;

typedef void value_fn(const void *record, double time, int flag, int iflag, double *result);
typedef void request_fn(const void *record, double time, int iflag, double *result);
typedef void field_fn(const void *record, double time, double *disp, double *velo, int dflag,
                      int iflag, double *field, double *dfddis, double *dfdvel);
typedef void coupler_fn(const void *record, double time, double *disp, int iflag, double *out);

typedef struct hx_record {
    void *fn[3];
    union {
        gforce_record gforce;
        vector_record vector;
        sforce_record sforce;
        field_record field;
        coupler_record coupler;
        request_record request;
        variable_record variable;
        diff_record diff;
        motion_record motion;
    } u;
} hx_record;

static const char *const empty_titles[8] = {"", "", "", "", "", "", "", ""};

/* The record of b's element; its USER list is b's. */
static void build(hx_record *r, const hx_binding *b)
{
    const hx_model *m = b->model;
    const int id = b->id, npar = b->npar;
    const double *par = b->par;
    if (b->kind == HX_BIND_COUPLER) {
        const hx_coupler *c = &m->couplers[b->index];
        coupler_record *k = &r->u.coupler;
        *k = (coupler_record){id, npar, par, c->njoints, {0, 0, 0}, {0, 0, 0}};
        for (int j = 0; j < c->njoints; ++j) {
            k->joints[j] = m->joints[c->joint[j]].id;
            k->type[j] = m->joints[c->joint[j]].type == HX_JOINT_TRANSLATIONAL ? 'T' : 'R';
        }
        return;
    }
    if (b->kind == HX_BIND_FORCE || b->kind == HX_BIND_FIELD) {
        const hx_force *f = &m->forces[b->index];
        const int i = m->markers[f->i_marker].id, j = m->markers[f->j_marker].id;
        const int rm = f->ref_marker >= 0 ? m->markers[f->ref_marker].id : 0;
        if (b->kind == HX_BIND_FIELD)
            r->u.field = (field_record){id, npar, par, i, j};
        else if (f->part == HX_OUTPUT_FORCE_AND_TORQUE)
            r->u.gforce = (gforce_record){id, npar, par, i, rm, j};
        else if (f->part < HX_OUTPUT_SCALAR_FORCE)
            r->u.vector = (vector_record){id, npar, par, i, j, rm};
        else
            r->u.sforce = (sforce_record){id, npar, par, i, j, 0,
                                          f->part == HX_OUTPUT_SCALAR_TORQUE ? "ROTATION"
                                                                             : "TRANSLATION"};
        return;
    }
    const hx_routine *rt = &m->routines[b->index];
    switch (b->kind) {
    case HX_BIND_REQUEST:
        r->u.request = (request_record){id, npar, par, "", {0}};
        memcpy(r->u.request.title, empty_titles, sizeof empty_titles);
        break;
    case HX_BIND_VARIABLE: r->u.variable = (variable_record){id, npar, par, rt->ic[0]}; break;
    case HX_BIND_DIFF:
        r->u.diff = (diff_record){id, npar, par, rt->static_hold, rt->implicit, rt->ic[0], rt->ic[1]};
        break;
    default: {
        const hx_joint *jt = &m->joints[rt->joint];
        const int translational = jt->type == HX_JOINT_TRANSLATIONAL;
        r->u.motion = (motion_record){id, npar, par, jt->id,
                                      translational ? "TRANSLATION" : "ROTATION",
                                      m->markers[jt->i_marker].id, m->markers[jt->j_marker].id,
                                      {'Z', '\0'},
                                      rt->val_type == 'V' ? "VEL" : rt->val_type == 'A' ? "ACC"
                                                                                         : "DISP"};
        break;
    }
    }
}

/* "GFOSUB" -> "Gfosub" */
static void c_style_name(const char *name, char *out, size_t size)
{
    size_t k = 0;
    for (; name[k] != '\0' && k + 1 < size; ++k)
        out[k] = (char)(k == 0 ? toupper((unsigned char)name[k]) : tolower((unsigned char)name[k]));
    out[k] = '\0';
}

int hx_record_bind(hx_binding *b, void *handle, const char *path, hx_message *msg)
{
    hx_record *r = calloc(1, sizeof *r);
    if (r == NULL)
        return hx_fail(msg, "out of memory");
    const int nfun = b->kind == HX_BIND_COUPLER ? 3 : 1;
    for (int k = 0; k < nfun; ++k) {
        char name[HX_ENTRY_NAME_MAX];
        c_style_name(b->names[k], name, sizeof name);
        if ((r->fn[k] = hx_loader_entry_exact(handle, path, name, b->symbols[k],
                                              sizeof b->symbols[k], msg)) == NULL) {
            free(r);
            return -1;
        }
    }
    build(r, b);
    b->record = r;
    return 0;
}

void hx_record_free(struct hx_record *r)
{
    free(r);
}

void hx_record_coupler(hx_binding *b, int which, double time, double *disp, int iflag,
                       double *out)
{
    ((coupler_fn *)b->record->fn[which])(&b->record->u, time, disp, iflag, out);
}

void hx_record_values(hx_binding *b, double time, int flag, int iflag, double *result)
{
    if (b->kind == HX_BIND_REQUEST)
        ((request_fn *)b->record->fn[0])(&b->record->u, time, iflag, result);
    else
        ((value_fn *)b->record->fn[0])(&b->record->u, time, flag, iflag, result);
}

void hx_record_fiesub(hx_binding *b, double time, double *disp, double *velo, int dflag,
                      int iflag, double *field, double *dfddis, double *dfdvel)
{
    ((field_fn *)b->record->fn[0])(&b->record->u, time, disp, velo, dflag, iflag, field, dfddis,
                                   dfdvel);
}
