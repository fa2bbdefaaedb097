/* The element cache: set-up once, rebuilt when the USER list changes, a
 * failed set-up reported once, and one consistent element when several
 * threads set up the same id at the same time. */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <unistd.h>

#include "element_cache.h"
#include "test_support.h"

typedef struct fake_model {
    double first_par;
    int serial;
} fake_model;

static atomic_int setups, releases;

static void *setup_fake(const usrsub_element_signature *sig, void *ctx, usrsub_element_setup_report *report)
{
    const int delay_us = ctx != NULL ? *(const int *)ctx : 0;
    if (delay_us > 0)
        usleep((useconds_t)delay_us); /* widen the window for racing threads */
    const int serial = atomic_fetch_add(&setups, 1) + 1;
    if (sig->npar > 0 && sig->par[0] < 0) {
        usrsub_fail(&report->error, "negative first parameter");
        return NULL;
    }
    fake_model *m = malloc(sizeof *m);
    m->first_par = sig->npar > 0 ? sig->par[0] : 0.0;
    m->serial = serial;
    return m;
}

static void release_fake(void *model)
{
    atomic_fetch_add(&releases, 1);
    free(model);
}

static const fake_model *get(int interface, int id, const double *par, int npar, int *now)
{
    usrsub_element_signature sig = {interface, id, 0, par, npar};
    usrsub_element_setup_report report;
    return usrsub_element_cache_get(&sig, setup_fake, release_fake, NULL, now, &report);
}

static int reset(void **state)
{
    (void)state;
    usrsub_element_cache_clear();
    atomic_store(&setups, 0);
    atomic_store(&releases, 0);
    return 0;
}

static void set_up_once(void **state)
{
    (void)state;
    const double par[] = {1.5, 2.0};
    int now;
    const fake_model *a = get(USRSUB_ELEMENT_GFOSUB, 7, par, 2, &now);
    assert_int_equal(now, 1);
    const double same[] = {1.5, 2.0}; /* another buffer, same values */
    const fake_model *b = get(USRSUB_ELEMENT_GFOSUB, 7, same, 2, &now);
    assert_int_equal(now, 0);
    assert_ptr_equal(a, b);
    assert_int_equal(atomic_load(&setups), 1);
}

static void changed_list_is_rebuilt(void **state)
{
    (void)state;
    double par[] = {1.5, 2.0};
    int now;
    const fake_model *a = get(USRSUB_ELEMENT_GFOSUB, 7, par, 2, &now);
    par[1] = 3.0;
    const fake_model *b = get(USRSUB_ELEMENT_GFOSUB, 7, par, 2, &now);
    assert_int_equal(now, 1);
    assert_ptr_not_equal(a, b);
    assert_int_equal(b->serial, 2);
    /* a shorter list is a change too */
    const fake_model *c = get(USRSUB_ELEMENT_GFOSUB, 7, par, 1, &now);
    assert_int_equal(now, 1);
    assert_int_equal(c->serial, 3);
    assert_int_equal(usrsub_element_cache_size(), 1); /* superseded records are not live */
    usrsub_element_cache_clear();
    assert_int_equal(atomic_load(&releases), 3); /* superseded ones freed at unload */
}

static void interfaces_and_ids_are_separate(void **state)
{
    (void)state;
    const double par[] = {4.0};
    int now;
    const fake_model *a = get(USRSUB_ELEMENT_GFOSUB, 3, par, 1, &now);
    const fake_model *b = get(USRSUB_ELEMENT_FIESUB, 3, par, 1, &now);
    const fake_model *c = get(USRSUB_ELEMENT_GFOSUB, 4, par, 1, &now);
    assert_ptr_not_equal(a, b);
    assert_ptr_not_equal(a, c);
    assert_int_equal(usrsub_element_cache_size(), 3);
}

static void failure_is_cached_and_reported_once(void **state)
{
    (void)state;
    const double par[] = {-1.0};
    int now;
    assert_null(get(USRSUB_ELEMENT_COUPLER, 9, par, 1, &now));
    assert_int_equal(now, 1);
    assert_null(get(USRSUB_ELEMENT_COUPLER, 9, par, 1, &now));
    assert_int_equal(now, 0);
    assert_int_equal(atomic_load(&setups), 1);
}

static void nan_in_the_list_still_matches(void **state)
{
    (void)state;
    const double par[] = {2.0, NAN};
    int now;
    get(USRSUB_ELEMENT_GFOSUB, 11, par, 2, &now);
    get(USRSUB_ELEMENT_GFOSUB, 11, par, 2, &now);
    assert_int_equal(now, 0);
    assert_int_equal(atomic_load(&setups), 1);
}

typedef struct racer {
    pthread_barrier_t *barrier;
    int id;
    const fake_model *got;
    int delay_us;
} racer;

static void *race(void *arg)
{
    racer *r = arg;
    const double par[] = {8.0};
    usrsub_element_signature sig = {USRSUB_ELEMENT_FIESUB, r->id, 0, par, 1};
    usrsub_element_setup_report report;
    int now;
    pthread_barrier_wait(r->barrier);
    r->got = usrsub_element_cache_get(&sig, setup_fake, release_fake, &r->delay_us, &now, &report);
    return NULL;
}

static void concurrent_set_up_gives_one_element(void **state)
{
    (void)state;
    enum { THREADS = 8 };
    pthread_barrier_t barrier;
    pthread_barrier_init(&barrier, NULL, THREADS);
    pthread_t threads[THREADS];
    racer racers[THREADS];
    for (int k = 0; k < THREADS; ++k) {
        racers[k] = (racer){&barrier, 42, NULL, 2000};
        pthread_create(&threads[k], NULL, race, &racers[k]);
    }
    for (int k = 0; k < THREADS; ++k)
        pthread_join(threads[k], NULL);
    pthread_barrier_destroy(&barrier);
    assert_int_equal(atomic_load(&setups), 1);
    for (int k = 0; k < THREADS; ++k) {
        assert_non_null(racers[k].got);
        assert_ptr_equal(racers[k].got, racers[0].got);
        assert_close(racers[k].got->first_par, 8.0, 0, 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(set_up_once, reset),
        cmocka_unit_test_setup(changed_list_is_rebuilt, reset),
        cmocka_unit_test_setup(interfaces_and_ids_are_separate, reset),
        cmocka_unit_test_setup(failure_is_cached_and_reported_once, reset),
        cmocka_unit_test_setup(nan_in_the_list_still_matches, reset),
        cmocka_unit_test_setup(concurrent_set_up_gives_one_element, reset),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
