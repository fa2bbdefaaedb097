/* The draft model's diagnostics and growing arrays (draft.h). */
#include <libgen.h>
#include <limits.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "model/draft.h"

void hx_draft_fail(hx_draft *d, int line, const char *fmt, ...)
{
    if (d->failed)
        return;
    char what[HX_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (line > 0)
        hx_fail(d->msg, "%s:%d: %s", d->path, line, what);
    else
        hx_fail(d->msg, "%s: %s", d->path, what);
    d->failed = 1;
}

void hx_draft_warn(hx_draft *d, int line, const char *fmt, ...)
{
    d->m->nwarnings++;
    if (d->warnings == NULL)
        return;
    va_list ap;
    va_start(ap, fmt);
    fprintf(d->warnings, "%s:%d: warning: ", d->path, line);
    vfprintf(d->warnings, fmt, ap);
    fputc('\n', d->warnings);
    va_end(ap);
}

/* Room for element `count` (realloc only when the array is full, doubling:
 * a realloc per push copies the whole array under a sanitizer's allocator),
 * the new element zeroed. */
static int grow(hx_draft *d, void **array, int count, int capacity, int grown, size_t size)
{
    if (grown != capacity || *array == NULL) {
        void *p = realloc(*array, size * (size_t)grown);
        if (p == NULL) {
            hx_draft_fail(d, 0, "out of memory");
            return -1;
        }
        *array = p;
    }
    memset((char *)*array + size * (size_t)count, 0, size);
    return 0;
}

void *hx_draft_push(hx_draft *d, void **array, int *count, int *capacity, size_t size,
                    void **raw, size_t raw_size)
{
    const int needed = *count + 1;
    const int grown = *count == *capacity ? (*capacity ? 2 * *capacity : 16) : *capacity;
    if (grow(d, array, *count, *capacity, grown, size) != 0 ||
        (raw != NULL && grow(d, raw, *count, *capacity, grown, raw_size) != 0))
        return NULL;
    *capacity = grown;
    *count = needed;
    return (char *)*array + size * (size_t)(needed - 1);
}

int hx_draft_open(hx_draft *d, const char *path, int from_text, FILE *warnings, hx_message *msg)
{
    memset(d, 0, sizeof *d);
    d->path = path;
    d->warnings = warnings;
    d->msg = msg;
    hx_model *m = d->m = calloc(1, sizeof *m);
    if (m == NULL)
        return hx_fail(msg, "out of memory");
    m->ground = -1;
    for (int k = 0; k < HX_UNIT_COUNT; ++k)
        m->unit_scales[k] = 1.0;
    char real[PATH_MAX];
    m->path = strdup(!from_text && realpath(path, real) != NULL ? real : path);
    char *copy = m->path != NULL ? strdup(m->path) : NULL;
    m->dir = copy != NULL ? strdup(dirname(copy)) : NULL;
    free(copy);
    return m->path == NULL || m->dir == NULL ? hx_fail(msg, "out of memory") : 0;
}

hx_model *hx_draft_finish(hx_draft *d, int status)
{
    if (status == 0 && d->m != NULL)
        status = hx_draft_resolve(d);
    free(d->rmarkers);
    free(d->rbodies);
    free(d->rjoints);
    free(d->rcouplers);
    free(d->rforces);
    free(d->rloads);
    free(d->rstateeqns);
    free(d->marker_slots);
    free(d->body_slots);
    hx_model *m = d->m;
    d->m = NULL;
    if (status != 0) {
        hx_model_free(m);
        return NULL;
    }
    return m;
}

static unsigned id_slot(int id, int slots)
{
    return ((unsigned)id * 2654435761u) & (unsigned)(slots - 1);
}

/* The index among count items (ids at id_of(k)) with this id, or -1. */
static int find_id(const int *slots, int nslots, int id, const void *items, size_t size,
                   size_t id_offset)
{
    if (nslots == 0)
        return -1;
    for (unsigned s = id_slot(id, nslots);; s = (s + 1) & (unsigned)(nslots - 1)) {
        const int k = slots[s];
        if (k < 0)
            return -1;
        int other;
        memcpy(&other, (const char *)items + size * (size_t)k + id_offset, sizeof other);
        if (other == id)
            return k;
    }
}

/* Enters the last of count items; the table regrown (load under half). */
static int enter_id(hx_draft *d, int **slots, int *nslots, const void *items, int count,
                    size_t size, size_t id_offset)
{
    if (2 * count > *nslots) {
        const int n = *nslots ? 4 * *nslots : 64;
        int *grown = malloc(sizeof(int) * (size_t)n);
        if (grown == NULL) {
            hx_draft_fail(d, 0, "out of memory");
            return -1;
        }
        free(*slots);
        *slots = grown;
        *nslots = n;
        for (int s = 0; s < n; ++s)
            grown[s] = -1;
        count--; /* the earlier items again, then the last below */
        for (int k = 0; k <= count; ++k) {
            int id;
            memcpy(&id, (const char *)items + size * (size_t)k + id_offset, sizeof id);
            unsigned s = id_slot(id, n);
            while (grown[s] >= 0)
                s = (s + 1) & (unsigned)(n - 1);
            grown[s] = k;
        }
        return 0;
    }
    const int k = count - 1;
    int id;
    memcpy(&id, (const char *)items + size * (size_t)k + id_offset, sizeof id);
    unsigned s = id_slot(id, *nslots);
    while ((*slots)[s] >= 0)
        s = (s + 1) & (unsigned)(*nslots - 1);
    (*slots)[s] = k;
    return 0;
}

int hx_draft_find_marker(const hx_draft *d, int id)
{
    return find_id(d->marker_slots, d->nmarker_slots, id, d->m->markers, sizeof(hx_marker),
                   offsetof(hx_marker, id));
}

int hx_draft_enter_marker(hx_draft *d)
{
    return enter_id(d, &d->marker_slots, &d->nmarker_slots, d->m->markers, d->m->nmarkers,
                    sizeof(hx_marker), offsetof(hx_marker, id));
}

int hx_draft_find_body(const hx_draft *d, int id)
{
    return find_id(d->body_slots, d->nbody_slots, id, d->m->bodies, sizeof(hx_body),
                   offsetof(hx_body, id));
}

int hx_draft_enter_body(hx_draft *d)
{
    return enter_id(d, &d->body_slots, &d->nbody_slots, d->m->bodies, d->m->nbodies,
                    sizeof(hx_body), offsetof(hx_body, id));
}
