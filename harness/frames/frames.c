/* The model's state and its kinematics stage (state.h). */
#include "frames/frames.h"

#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"

const hx_frame hx_world_frame = {{0, 0, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0}};

void hx_marker_frame(const hx_model *m, const hx_frame *b, int marker, hx_frame *out)
{
    const hx_marker *mk = &m->markers[marker];
    if (mk->local_axes)
        m3_copy(out->R, b->R);
    else
        m3_mul(out->R, b->R, mk->R_local);
    v3_copy(out->w, b->w);
    if (mk->at_body_origin) {
        v3_copy(out->p, b->p);
        v3_copy(out->v, b->v);
        return;
    }
    double r[3], wr[3];
    m3_apply(r, b->R, mk->r_local);
    v3_add(out->p, b->p, r);
    v3_cross(wr, b->w, r);
    v3_add(out->v, b->v, wr);
}

static void all_markers(hx_frames *fr)
{
    const hx_model *m = fr->model;
    for (int k = 0; k < m->nmarkers; ++k)
        hx_marker_frame(m, &fr->bodies[m->markers[k].body], k, &fr->markers[k]);
}

int hx_frames_init(hx_frames *fr, const hx_model *m)
{
    memset(fr, 0, sizeof *fr);
    fr->model = m;
    fr->bodies = calloc((size_t)m->nbodies + 1, sizeof *fr->bodies);
    fr->markers = calloc((size_t)m->nmarkers + 1, sizeof *fr->markers);
    fr->tracked = calloc((size_t)m->nmarkers + 1, sizeof *fr->tracked);
    fr->first_tracked = calloc((size_t)m->nbodies + 1, sizeof *fr->first_tracked);
    fr->diffs = calloc(2 * (size_t)m->nroutines_of[HX_ROUTINE_DIFF] + 1, sizeof *fr->diffs);
    fr->variables = calloc((size_t)m->nvariables + 1, sizeof *fr->variables);
    fr->loop = calloc((size_t)m->nloop_inputs + 1, sizeof *fr->loop);
    if (fr->bodies == NULL || fr->markers == NULL || fr->tracked == NULL ||
        fr->first_tracked == NULL || fr->diffs == NULL || fr->variables == NULL ||
        fr->loop == NULL) {
        hx_frames_free(fr);
        return -1;
    }
    for (int k = 0; k < m->nbodies; ++k) {
        const hx_body *b = &m->bodies[k];
        hx_frame *f = &fr->bodies[k];
        v3_copy(f->p, b->p0);
        m3_copy(f->R, b->R0);
        v3_copy(f->v, b->v0);
        v3_copy(f->w, b->w0);
    }
    /* grouped by body (a counting sort), so that one body's markers can be
     * updated alone: count, then place each at its body's next free slot */
    for (int k = 0; k < m->nmarkers; ++k)
        if (m->markers[k].tracked)
            fr->first_tracked[m->markers[k].body + 1]++;
    for (int b = 0; b < m->nbodies; ++b)
        fr->first_tracked[b + 1] += fr->first_tracked[b];
    for (int k = 0; k < m->nmarkers; ++k)
        if (m->markers[k].tracked)
            fr->tracked[fr->first_tracked[m->markers[k].body]++] = k;
    for (int b = m->nbodies; b > 0; --b) /* each now holds the next body's start */
        fr->first_tracked[b] = fr->first_tracked[b - 1];
    fr->first_tracked[0] = 0;
    for (int k = 0; k < m->nroutines; ++k)
        if (m->routines[k].kind == HX_ROUTINE_DIFF)
            memcpy(&fr->diffs[2 * m->routines[k].slot], m->routines[k].ic, sizeof(double[2]));
    all_markers(fr);
    return 0;
}

void hx_frames_free(hx_frames *fr)
{
    free(fr->bodies);
    free(fr->markers);
    free(fr->tracked);
    free(fr->first_tracked);
    free(fr->diffs);
    free(fr->variables);
    free(fr->loop);
    memset(fr, 0, sizeof *fr);
}

int hx_frames_clone(hx_frames *to, const hx_frames *from)
{
    if (hx_frames_init(to, from->model) != 0)
        return -1;
    hx_frames_copy(to, from);
    return 0;
}

void hx_frames_copy(hx_frames *to, const hx_frames *from)
{
    const hx_model *m = from->model;
    to->time = from->time;
    memcpy(to->bodies, from->bodies, sizeof *to->bodies * (size_t)m->nbodies);
    memcpy(to->markers, from->markers, sizeof *to->markers * (size_t)m->nmarkers);
    memcpy(to->diffs, from->diffs, sizeof *to->diffs * 2 * (size_t)m->nroutines_of[HX_ROUTINE_DIFF]);
    memcpy(to->variables, from->variables, sizeof *to->variables * (size_t)m->nvariables);
    memcpy(to->loop, from->loop, sizeof *to->loop * (size_t)m->nloop_inputs);
}

void hx_frames_update(hx_frames *fr)
{
    const hx_model *m = fr->model;
    for (int b = 0; b < m->nbodies; ++b)
        if (!m->bodies[b].is_ground) /* those on ground never move */
            hx_frames_update_body(fr, b);
}

void hx_frames_update_body(hx_frames *fr, int body)
{
    const hx_model *m = fr->model;
    for (int n = fr->first_tracked[body]; n < fr->first_tracked[body + 1]; ++n) {
        const int k = fr->tracked[n];
        hx_marker_frame(m, &fr->bodies[body], k, &fr->markers[k]);
    }
}

void hx_frames_copy_body(hx_frames *to, const hx_frames *from, int body)
{
    to->bodies[body] = from->bodies[body];
    for (int n = from->first_tracked[body]; n < from->first_tracked[body + 1]; ++n) {
        const int k = from->tracked[n];
        to->markers[k] = from->markers[k];
    }
}

const hx_frame *hx_frames_marker(const hx_frames *fr, int index, hx_frame *scratch)
{
    if (index < 0)
        return &hx_world_frame;
    const hx_model *m = fr->model;
    if (m->markers[index].tracked)
        return &fr->markers[index];
    hx_marker_frame(m, &fr->bodies[m->markers[index].body], index, scratch);
    return scratch;
}
