/* Binding user elements to library functions and calling them (binding.h). */
#include "binding.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

static int bind_one(const hx_model *m, hx_bindings *bs, hx_binding *b, const hx_user_call *u,
                    int line, usrsub_message *msg)
{
    char path[PATH_MAX];
    if (hx_loader_resolve(u->dll_name, m->dir, path, sizeof path, msg) != 0 ||
        (b->library = strdup(path)) == NULL)
        goto failed;
    void *handle = hx_loader_open(&bs->loader, path, msg);
    if (handle == NULL)
        goto failed;
    const int nfun = b->kind == HX_BIND_COUPLER ? 3 : 1;
    void *fn[3] = {0};
    for (int k = 0; k < nfun; ++k)
        if ((fn[k] = hx_loader_symbol(handle, path, b->names[k], msg)) == NULL)
            goto failed;
    if (b->kind == HX_BIND_COUPLER)
        for (int k = 0; k < 3; ++k)
            b->coupler[k] = (usrsub_coupler_fn *)fn[k];
    else if (b->kind == HX_BIND_GFOSUB)
        b->gfosub = (usrsub_gfosub_fn *)fn[0];
    else
        b->fiesub = (usrsub_fiesub_fn *)fn[0];
    b->npar = u->npar;
    b->par = malloc(sizeof(double) * (size_t)(u->npar > 0 ? u->npar : 1));
    if (b->par == NULL)
        return usrsub_fail(msg, "out of memory");
    if (u->npar > 0)
        memcpy(b->par, u->par, sizeof(double) * (size_t)u->npar);
    return 0;
failed:
    usrsub_message_prefix(msg, "%s:%d: %s %d", m->path, line, b->element, b->id);
    return -1;
}

int hx_bind(const hx_model *m, hx_bindings *bs, usrsub_message *msg)
{
    memset(bs, 0, sizeof *bs);
    int user_couplers = 0;
    for (int k = 0; k < m->ncouplers; ++k)
        user_couplers += m->couplers[k].is_user;
    const int total = user_couplers + m->nforces;
    bs->items = calloc((size_t)(total > 0 ? total : 1), sizeof *bs->items);
    if (bs->items == NULL)
        return usrsub_fail(msg, "out of memory");
    for (int k = 0; k < m->ncouplers; ++k) {
        const hx_coupler *c = &m->couplers[k];
        if (!c->is_user)
            continue;
        hx_binding *b = &bs->items[bs->count++];
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
        const int gfo = f->interface == HX_FORCE_GFOSUB;
        b->kind = gfo ? HX_BIND_GFOSUB : HX_BIND_FIESUB;
        b->index = k;
        b->id = f->id;
        b->element = gfo ? "Force_Vector_TwoBody" : "Force_Field";
        b->names[0] = f->user.fnc_name ? f->user.fnc_name : gfo ? "GFOSUB" : "FIESUB";
        if (bind_one(m, bs, b, &f->user, f->line, msg) != 0)
            return -1;
    }
    return 0;
}

void hx_bindings_free(hx_bindings *bs)
{
    for (int k = 0; k < bs->count; ++k) {
        free(bs->items[k].library);
        free(bs->items[k].par);
    }
    free(bs->items);
    hx_loader_close_all(&bs->loader);
    memset(bs, 0, sizeof *bs);
}

hx_binding *hx_binding_of_coupler(hx_bindings *bs, int coupler_index)
{
    for (int k = 0; k < bs->count; ++k)
        if (bs->items[k].kind == HX_BIND_COUPLER && bs->items[k].index == coupler_index)
            return &bs->items[k];
    return NULL;
}

hx_binding *hx_binding_of_force(hx_bindings *bs, int force_index)
{
    for (int k = 0; k < bs->count; ++k)
        if (bs->items[k].kind != HX_BIND_COUPLER && bs->items[k].index == force_index)
            return &bs->items[k];
    return NULL;
}

void hx_binding_call_init(hx_binding *b, hx_call *call, int iflag)
{
    hx_call_init(call, b->element, b->id, iflag != 0, &b->deps);
    call->warned = &b->warned_undeclared;
}

int hx_dependency_passes(hx_bindings *bs, const hx_model *m, const hx_frame *frames)
{
    for (int k = 0; k < bs->count; ++k) {
        hx_binding *b = &bs->items[k];
        double out[64];
        if (b->kind == HX_BIND_COUPLER) {
            const hx_coupler *c = &m->couplers[b->index];
            double disp[3];
            for (int i = 0; i < c->njoints; ++i)
                disp[i] = hx_joint_coordinate(m, frames, c->joint[i]);
            for (int fn = 0; fn < 3; ++fn)
                hx_call_coupler(b, fn, 0.0, disp, c->njoints, 1, out, NULL);
        } else if (b->kind == HX_BIND_GFOSUB) {
            hx_call_gfosub(b, 0.0, 0, 1, out, NULL);
        } else {
            const hx_force *f = &m->forces[b->index];
            hx_frame I, J;
            hx_marker_frame(m, frames, f->i_marker, &I);
            hx_marker_frame(m, frames, f->j_marker, &J);
            double disp[6], velo[6], dfd[36], dfv[36];
            hx_field_state(&I, &J, disp, velo);
            hx_call_fiesub(b, 0.0, disp, velo, 0, 1, out, dfd, dfv, NULL);
        }
        if (hx_host_stop_requested())
            return -1;
    }
    return 0;
}

/* The caller's record (set up with hx_binding_call_init) or a default one. */
static void begin(hx_binding *b, int iflag, hx_call *call, hx_call *local)
{
    if (call == NULL) {
        hx_binding_call_init(b, local, iflag);
        call = local;
    }
    hx_host_begin_call(call);
}

void hx_call_coupler(hx_binding *b, int which, double time, const double *disp, int ndisp,
                     int iflag, double *out, hx_call *call)
{
    hx_call local;
    begin(b, iflag, call, &local);
    int id = b->id, npar = b->npar, n = ndisp, flag = iflag;
    double t = time, d[3] = {0, 0, 0};
    for (int k = 0; k < ndisp && k < 3; ++k)
        d[k] = disp[k];
    b->coupler[which](&id, &t, b->par, &npar, d, &n, &flag, out);
    hx_host_end_call();
}

void hx_call_gfosub(hx_binding *b, double time, int dflag, int iflag, double result[6],
                    hx_call *call)
{
    hx_call local;
    begin(b, iflag, call, &local);
    int id = b->id, npar = b->npar, df = dflag, flag = iflag;
    double t = time;
    b->gfosub(&id, &t, b->par, &npar, &df, &flag, result);
    hx_host_end_call();
}

void hx_call_fiesub(hx_binding *b, double time, const double disp[6], const double velo[6],
                    int dflag, int iflag, double field[6], double dfddis[36], double dfdvel[36],
                    hx_call *call)
{
    hx_call local;
    begin(b, iflag, call, &local);
    int id = b->id, npar = b->npar, df = dflag, flag = iflag;
    double t = time, d[6], v[6];
    memcpy(d, disp, sizeof d);
    memcpy(v, velo, sizeof v);
    b->fiesub(&id, &t, b->par, &npar, d, v, &df, &flag, field, dfddis, dfdvel);
    hx_host_end_call();
}
