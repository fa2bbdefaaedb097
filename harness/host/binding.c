/* Binding user elements to the functions of their libraries (binding.h). */
#include "host/binding.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host/records.h"

/* A state equation's partial routines: one the model names (usrsub_derN_name)
 * must exist; a default name the library does not export is left NULL, and
 * the harness differences YFOSUB instead (docs/interface.md §5). */
static int bind_state_partials(void *handle, const char *path, hx_binding *b,
                               const hx_user_call *u, hx_message *msg)
{
    const char *named[4] = {u->der1_name, u->der2_name, u->der3_name, u->der4_name};
    for (int k = 0; k < 4; ++k) {
        hx_message absent;
        hx_message *report = named[k] != NULL ? msg : &absent;
        void *fn = hx_loader_entry(handle, path, b->names[1 + k], b->symbols[1 + k],
                                   sizeof b->symbols[1 + k], report);
        if (fn == NULL && named[k] != NULL)
            return -1;
        b->fn.stateeqn.partial[k] = (usrsub_state_partial_fn *)fn;
    }
    return 0;
}

/* The functions of b in the library at path, in the classic form; when the
 * element's routine has its default name and the library exports none of its
 * classic spellings, in Adams' C-style form (host/records.h). */
static int bind_functions(hx_binding *b, void *handle, const char *path, const hx_user_call *u,
                          hx_message *msg)
{
    const int nfun = b->kind == HX_BIND_COUPLER ? 3 : 1;
    void *fn[3] = {0};
    for (int k = 0; k < nfun; ++k)
        if ((fn[k] = hx_loader_entry(handle, path, b->names[k], b->symbols[k],
                                     sizeof b->symbols[k], msg)) == NULL) {
            if (u->fnc_name != NULL || b->kind == HX_BIND_STATEEQN)
                return -1;
            hx_message classic = *msg;
            if (hx_record_bind(b, handle, path, msg) == 0)
                return 0;
            hx_message record = *msg;
            return hx_fail(msg, "%s; nor in the C-style form: %.400s", classic.text, record.text);
        }
    switch (b->kind) {
    case HX_BIND_COUPLER:
        for (int k = 0; k < 3; ++k)
            b->fn.coupler[k] = (usrsub_coupler_fn *)fn[k];
        return 0;
    case HX_BIND_FORCE: b->fn.force = (usrsub_gfosub_fn *)fn[0]; return 0;
    case HX_BIND_FIELD: b->fn.field = (usrsub_fiesub_fn *)fn[0]; return 0;
    case HX_BIND_STATEEQN:
        b->fn.stateeqn.rates = (usrsub_yfosub_fn *)fn[0];
        return bind_state_partials(handle, path, b, u, msg);
    case HX_BIND_REQUEST: b->fn.request = (hx_reqsub_fn *)fn[0]; return 0;
    default: b->fn.value = (hx_value_fn *)fn[0]; return 0;
    }
}

static int bind_one(const hx_model *m, hx_bindings *bs, hx_binding *b, const hx_user_call *u,
                    int line, hx_message *msg)
{
    b->model = m;
    b->setup_bytes = -1;
    memset(b->loop_slot, -1, sizeof b->loop_slot);
    b->npar = u->npar;
    b->par = malloc(sizeof(double) * (size_t)(u->npar > 0 ? u->npar : 1));
    if (b->par == NULL)
        return hx_fail(msg, "out of memory");
    if (u->npar > 0)
        memcpy(b->par, u->par, sizeof(double) * (size_t)u->npar);
    char path[PATH_MAX];
    if (hx_loader_resolve(u->dll_name, m->dir, path, sizeof path, msg) != 0 ||
        (b->library = strdup(path)) == NULL)
        goto failed;
    void *handle = hx_loader_open(&bs->loader, path, msg);
    if (handle == NULL || bind_functions(b, handle, path, u, msg) != 0)
        goto failed;
    return 0;
failed:
    hx_message_prefix(msg, "%s:%d: %s %d", m->path, line, b->element, b->id);
    return -1;
}

/* The FIESUB twin of a GFOSUB element, when the library exports it
 * (docs/interface.md §3.0): GFOSUB(code, I, J, rest) -> FIESUB(code, rest),
 * NAME(I, J, rest) -> NAME_FIELD(rest). A library without one is no error. */
static int bind_twin(hx_bindings *bs, hx_binding *b)
{
    const int named = strcmp(b->names[0], "GFOSUB") != 0;
    const int first_marker = named ? 0 : 1;
    if (b->npar < first_marker + 2)
        return 0;
    char name[256];
    if (named)
        snprintf(name, sizeof name, "%s_FIELD", b->names[0]);
    else
        snprintf(name, sizeof name, "FIESUB");
    hx_message ignored;
    void *handle = hx_loader_open(&bs->loader, b->library, &ignored);
    char symbol[HX_ENTRY_NAME_MAX];
    void *fn = handle != NULL ? hx_loader_entry(handle, b->library, name, symbol, sizeof symbol,
                                                &ignored)
                              : NULL;
    if (fn == NULL)
        return 0;
    b->twin_name = strdup(symbol);
    b->twin_par = malloc(sizeof(double) * (size_t)b->npar);
    if (b->twin_name == NULL || b->twin_par == NULL)
        return -1;
    b->twin_npar = 0;
    for (int k = 0; k < b->npar; ++k)
        if (k != first_marker && k != first_marker + 1)
            b->twin_par[b->twin_npar++] = b->par[k];
    b->twin = (usrsub_fiesub_fn *)fn;
    return 0;
}

int hx_bind(const hx_model *m, hx_messages *messages, hx_bindings *bs, hx_message *msg)
{
    memset(bs, 0, sizeof *bs);
    int user_couplers = 0;
    for (int k = 0; k < m->ncouplers; ++k)
        user_couplers += m->couplers[k].is_user;
    const int total = user_couplers + m->nforces + m->nstateeqns + m->nroutines;
    bs->items = calloc((size_t)(total > 0 ? total : 1), sizeof *bs->items);
    if (bs->items == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < m->ncouplers; ++k) {
        const hx_coupler *c = &m->couplers[k];
        if (!c->is_user)
            continue;
        hx_binding *b = &bs->items[bs->count++];
        b->messages = messages;
        b->kind = HX_BIND_COUPLER;
        b->index = k;
        b->id = c->id;
        b->element = "Constraint_Coupler";
        b->names[0] = c->user.fnc_name ? c->user.fnc_name : "COUSUB";
        b->names[1] = c->user.der1_name ? c->user.der1_name : "COUXX";
        b->names[2] = c->user.der2_name ? c->user.der2_name : "COUXX2";
        if (bind_one(m, bs, b, &c->user, c->line, msg) != 0)
            return -1;
    }
    for (int k = 0; k < m->nforces; ++k) {
        const hx_force *f = &m->forces[k];
        hx_binding *b = &bs->items[bs->count++];
        b->messages = messages;
        const int gfo = f->interface == HX_FORCE_GFOSUB;
        b->kind = gfo ? HX_BIND_FORCE : HX_BIND_FIELD;
        b->index = k;
        b->id = f->id;
        b->element = hx_force_element_name(f);
        static const char *const vector_names[5] = {"GFOSUB", "VFOSUB", "VTOSUB", "SFOSUB",
                                                    "SFOSUB"};
        b->part = f->part;
        b->names[0] = f->user.fnc_name ? f->user.fnc_name
                      : gfo                ? vector_names[f->part]
                                           : "FIESUB";
        if (bind_one(m, bs, b, &f->user, f->line, msg) != 0)
            return -1;
        /* a FIESUB twin answers all six: only a GFOSUB's can stand in for it */
        if (gfo && f->part == HX_OUTPUT_FORCE_AND_TORQUE && bind_twin(bs, b) != 0)
            return hx_fail(msg, "out of memory");
    }
    for (int k = 0; k < m->nstateeqns; ++k) {
        const hx_stateeqn *f = &m->stateeqns[k];
        hx_binding *b = &bs->items[bs->count++];
        static const char *const defaults[5] = {"YFOSUB", "YFOXX", "YFOXU", "YFOYX", "YFOYU"};
        const char *named[5] = {f->user.fnc_name, f->user.der1_name, f->user.der2_name,
                                f->user.der3_name, f->user.der4_name};
        b->messages = messages;
        b->kind = HX_BIND_STATEEQN;
        b->index = k;
        b->id = f->id;
        b->element = "Force_StateEqn";
        for (int i = 0; i < 5; ++i)
            b->names[i] = named[i] != NULL ? named[i] : defaults[i];
        if (bind_one(m, bs, b, &f->user, f->line, msg) != 0)
            return -1;
    }
    for (int k = 0; k < m->nroutines; ++k) {
        const hx_routine *r = &m->routines[k];
        if (r->program != NULL)
            continue; /* a Control_Diff by expression: no routine to bind */
        static const hx_binding_kind kinds[HX_ROUTINE_KINDS] = {HX_BIND_REQUEST, HX_BIND_VARIABLE,
                                                                HX_BIND_DIFF, HX_BIND_MOTION};
        static const char *const defaults[HX_ROUTINE_KINDS] = {"REQSUB", "VARSUB", "DIFSUB",
                                                               "MOTSUB"};
        hx_binding *b = &bs->items[bs->count++];
        b->messages = messages;
        b->kind = kinds[r->kind];
        b->index = k;
        b->id = r->id;
        b->element = hx_routine_element_name(r->kind);
        b->names[0] = r->user.fnc_name != NULL ? r->user.fnc_name : defaults[r->kind];
        if (bind_one(m, bs, b, &r->user, r->line, msg) != 0)
            return -1;
    }
    return 0;
}

void hx_bindings_free(hx_bindings *bs)
{
    for (int k = 0; k < bs->count; ++k) {
        free(bs->items[k].library);
        free(bs->items[k].par);
        free(bs->items[k].twin_name);
        free(bs->items[k].twin_par);
        hx_record_free(bs->items[k].record);
    }
    free(bs->items);
    hx_loader_close_all(&bs->loader);
    memset(bs, 0, sizeof *bs);
}

hx_binding_family hx_binding_family_of(hx_binding_kind kind)
{
    switch (kind) {
    case HX_BIND_COUPLER: return HX_FAMILY_COUPLER;
    case HX_BIND_FORCE:
    case HX_BIND_FIELD: return HX_FAMILY_FORCE;
    case HX_BIND_STATEEQN: return HX_FAMILY_STATEEQN;
    default: return HX_FAMILY_ROUTINE;
    }
}

int hx_binding_line(const hx_model *m, const hx_binding *b)
{
    switch (hx_binding_family_of(b->kind)) {
    case HX_FAMILY_FORCE: return m->forces[b->index].line;
    case HX_FAMILY_ROUTINE: return m->routines[b->index].line;
    case HX_FAMILY_STATEEQN: return m->stateeqns[b->index].line;
    default: return m->couplers[b->index].line;
    }
}

hx_binding *hx_bindings_find(hx_bindings *bs, hx_binding_family family, int index)
{
    for (int k = 0; k < bs->count; ++k)
        if (bs->items[k].index == index && hx_binding_family_of(bs->items[k].kind) == family)
            return &bs->items[k];
    return NULL;
}

const char *hx_binding_routine(const hx_binding *b, int which)
{
    return b->symbols[which][0] != '\0' ? b->symbols[which] : b->names[which];
}

void hx_binding_call_init(hx_binding *b, hx_call *call, int which, const hx_frames *fr, int iflag)
{
    hx_call_init(call, b->element, b->id, hx_binding_routine(b, which), b->model, fr, b->messages,
                 iflag != 0, &b->deps);
    /* couplers, FIESUB, YFOSUB and MOTSUB get their state in their arguments or
     * from time alone (docs/interface.md §1, §5.1) */
    call->may_query = b->kind == HX_BIND_FORCE || b->kind == HX_BIND_REQUEST ||
                      b->kind == HX_BIND_VARIABLE || b->kind == HX_BIND_DIFF;
    call->loop_slot = b->loop_slot;
    call->at_output = b->kind == HX_BIND_REQUEST;
    call->reported_undeclared = &b->reported_undeclared;
    call->reported_refused = &b->reported_refused;
    call->reported_unoffered = &b->reported_unoffered;
    call->reported_misused = &b->reported_misused;
    call->reported_non_finite = &b->reported_non_finite;
}

