/* Lock-free look-up, locked set-up cache of elements (element_cache.h). */
#include "element_cache.h"

#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "mutex.h"

_Atomic(usrsub_element_record *) usrsub_element_cache_buckets[USRSUB_ELEMENT_CACHE_BUCKETS];
static usrsub_element_record *retired; /* superseded records, freed at unload */
static usrsub_mutex setup_lock = USRSUB_MUTEX_INIT;

static int same_element(const usrsub_element_record *r, const usrsub_element_signature *sig)
{
    return r->id == sig->id && r->form == sig->form;
}

static void free_record(usrsub_element_record *r)
{
    if (r->model != NULL && r->release != NULL)
        r->release(r->model);
    free(r);
}

/* Takes the element's current record out of its chain (under the lock). A
 * reader standing on it still finds its way on through its own next. */
static void retire_current(unsigned bucket, const usrsub_element_signature *sig)
{
    _Atomic(usrsub_element_record *) *link = &usrsub_element_cache_buckets[bucket];
    for (usrsub_element_record *r = atomic_load(link); r != NULL; r = atomic_load(link)) {
        if (same_element(r, sig)) {
            atomic_store_explicit(link, atomic_load(&r->next), memory_order_release);
            r->retired_next = retired;
            retired = r;
            return;
        }
        link = &r->next;
    }
}

void *usrsub_element_cache_get(const usrsub_element_signature *sig, usrsub_element_setup_fn *setup,
                        usrsub_element_release_fn *release, void *ctx, int *set_up_now,
                        usrsub_element_setup_report *report)
{
    const unsigned bucket = usrsub_element_cache_bucket(sig->form, sig->id);
    *set_up_now = 0;
    usrsub_element_record *r = usrsub_element_cache_record(sig->form, sig->id);
    if (r != NULL && usrsub_element_cache_matches(r, sig))
        return r->model;

    usrsub_mutex_lock(&setup_lock);
    r = usrsub_element_cache_record(sig->form, sig->id); /* set up meanwhile? */
    if (r != NULL && usrsub_element_cache_matches(r, sig)) {
        usrsub_mutex_unlock(&setup_lock);
        return r->model;
    }
    const int npar = sig->npar > 0 ? sig->npar : 0;
    usrsub_element_record *fresh = malloc(sizeof *fresh + sizeof(double) * (size_t)npar);
    if (fresh == NULL) {
        usrsub_mutex_unlock(&setup_lock);
        *set_up_now = 1;
        report->notices.has_notice = 0;
        usrsub_fail(&report->error, "out of memory while setting up the element");
        return NULL;
    }
    fresh->form = sig->form;
    fresh->id = sig->id;
    fresh->code = sig->code;
    fresh->npar = npar;
    if (npar > 0)
        memcpy(fresh->par, sig->par, sizeof(double) * (size_t)npar);
    fresh->release = release;
    fresh->retired_next = NULL;
    report->notices.has_notice = 0;
    fresh->model = setup(sig, ctx, report);
    *set_up_now = 1;
    retire_current(bucket, sig);
    atomic_store_explicit(&fresh->next, atomic_load(&usrsub_element_cache_buckets[bucket]), memory_order_relaxed);
    atomic_store_explicit(&usrsub_element_cache_buckets[bucket], fresh, memory_order_release);
    usrsub_mutex_unlock(&setup_lock);
    return fresh->model;
}

int usrsub_element_cache_size(void)
{
    int count = 0;
    usrsub_mutex_lock(&setup_lock);
    for (unsigned b = 0; b < USRSUB_ELEMENT_CACHE_BUCKETS; ++b)
        for (usrsub_element_record *r = atomic_load(&usrsub_element_cache_buckets[b]); r != NULL; r = atomic_load(&r->next))
            ++count;
    usrsub_mutex_unlock(&setup_lock);
    return count;
}

void usrsub_element_cache_clear(void)
{
    usrsub_mutex_lock(&setup_lock);
    for (unsigned b = 0; b < USRSUB_ELEMENT_CACHE_BUCKETS; ++b) {
        usrsub_element_record *r = atomic_exchange(&usrsub_element_cache_buckets[b], NULL);
        while (r != NULL) {
            usrsub_element_record *next = atomic_load(&r->next);
            free_record(r);
            r = next;
        }
    }
    while (retired != NULL) {
        usrsub_element_record *next = retired->retired_next;
        free_record(retired);
        retired = next;
    }
    usrsub_mutex_unlock(&setup_lock);
}

__attribute__((destructor)) static void usrsub_element_cache_unload(void)
{
    usrsub_element_cache_clear();
}
