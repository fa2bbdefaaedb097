/*
 * Per-element set-up cache of the library.
 *
 * An element is set up once per (entry form, element id), keyed also on a copy
 * of its USER list (and one discriminating code, such as ndisp), so that an
 * element whose list changes is rebuilt. Look-ups take no lock: records are
 * immutable once published and are only freed when the library is unloaded.
 * Set-ups are serialized by one mutex; a failed set-up is cached too, so its
 * error is reported once.
 */
#ifndef USRSUB_ELEMENT_CACHE_H
#define USRSUB_ELEMENT_CACHE_H

#include "usrsub/core/message.h"
#include "usrsub/readers/property_file.h"

/* The entry form an element is called through: the same id set up through
 * two forms is two elements (a GFOSUB element and its FIESUB twin). */
enum usrsub_element_form {
    USRSUB_ELEMENT_COUPLER = 1, /* COUSUB, COUXX, COUXX2 share one set-up */
    USRSUB_ELEMENT_GFOSUB = 2,  /* GFOSUB and the named GFOSUB-style entries */
    USRSUB_ELEMENT_FIESUB = 3,  /* FIESUB and the named FIESUB-style entries */
    USRSUB_ELEMENT_YFOSUB = 4   /* YFOSUB and its four partials share one set-up */
};

typedef struct usrsub_element_signature {
    int form;          /* enum usrsub_element_form */
    int id;
    int code;          /* ndisp for couplers, the entry code for forces */
    const double *par; /* USER list as the host passed it */
    int npar;
} usrsub_element_signature;

/* What a set-up wants said to the host, after the cache's lock is released
 * (a host may end the run inside c_errmes). */
typedef struct usrsub_element_setup_report {
    usrsub_message error;  /* set when the set-up fails */
    usrsub_read_report notices; /* informational text, when notices.has_notice */
} usrsub_element_setup_report;

/* Builds the immutable model of an element, or returns NULL and fills
 * report->error. Runs under the cache's lock. */
typedef void *usrsub_element_setup_fn(const usrsub_element_signature *sig, void *ctx,
                               usrsub_element_setup_report *report);
typedef void usrsub_element_release_fn(void *model);

/* Returns the element's model, or NULL when its set-up failed. *set_up_now is
 * 1 when this call ran the set-up: the caller then passes report on. */
void *usrsub_element_cache_get(const usrsub_element_signature *sig, usrsub_element_setup_fn *setup,
                        usrsub_element_release_fn *release, void *ctx, int *set_up_now,
                        usrsub_element_setup_report *report);

/* ---- the look-up every call makes, inline ----------------------------------- */

#include <stdatomic.h>
#include <string.h>

#define USRSUB_ELEMENT_CACHE_BUCKETS 1024u

typedef struct usrsub_element_record {
    _Atomic(struct usrsub_element_record *) next;
    struct usrsub_element_record *retired_next;
    int form, id, code, npar;
    void *model; /* NULL: the set-up failed */
    usrsub_element_release_fn *release;
    double par[];
} usrsub_element_record;

extern _Atomic(usrsub_element_record *) usrsub_element_cache_buckets[USRSUB_ELEMENT_CACHE_BUCKETS];

static inline unsigned usrsub_element_cache_bucket(int form, int id)
{
    return ((unsigned)id * 2654435761u ^ (unsigned)form * 40503u) &
           (USRSUB_ELEMENT_CACHE_BUCKETS - 1u);
}

/* The element's current record, or NULL. */
static inline usrsub_element_record *usrsub_element_cache_record(int form, int id)
{
    usrsub_element_record *r = atomic_load_explicit(
        &usrsub_element_cache_buckets[usrsub_element_cache_bucket(form, id)], memory_order_acquire);
    while (r != NULL && (r->id != id || r->form != form))
        r = atomic_load_explicit(&r->next, memory_order_acquire);
    return r;
}

/* Bitwise comparison, so that a NaN in the list still matches itself. */
static inline int usrsub_element_cache_matches(const usrsub_element_record *r, const usrsub_element_signature *sig)
{
    return r->code == sig->code && r->npar == sig->npar &&
           (sig->npar <= 0 ||
            memcmp(r->par, sig->par, sizeof(double) * (size_t)sig->npar) == 0);
}

/* The fast path: the set-up model when the element is cached with this very
 * list (*hit = 1), else falls back to usrsub_element_cache_get. */
static inline void *usrsub_element_cache_lookup(const usrsub_element_signature *sig, usrsub_element_setup_fn *setup,
                                         usrsub_element_release_fn *release, void *ctx,
                                         int *set_up_now, usrsub_element_setup_report *report)
{
    const usrsub_element_record *r = usrsub_element_cache_record(sig->form, sig->id);
    if (r != NULL && usrsub_element_cache_matches(r, sig)) {
        *set_up_now = 0;
        return r->model;
    }
    return usrsub_element_cache_get(sig, setup, release, ctx, set_up_now, report);
}

/* Number of live (not superseded) records; for tests. */
int usrsub_element_cache_size(void);

/* Frees every record; runs when the library is unloaded. */
void usrsub_element_cache_clear(void);

#endif
