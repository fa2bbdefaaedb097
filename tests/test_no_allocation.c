/*
 * No entry of the library allocates after its element's set-up: malloc,
 * calloc, realloc and the aligned forms are interposed (the test exports its
 * own, which the dlopen'd library binds to) and counted across a million
 * calls of every entry of the benchmark models, the host bound as in a
 * solver. The counter is first shown to count, so that the test can fail.
 */
#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host/call.h"
#include "session/session.h"
#include "sim_support.h"
#include "frames/measures.h"
#include "test_support.h"

#define CALLS 1000000L

/* glibc's own allocator, under the names it keeps for interposers */
extern void *__libc_malloc(size_t size);
extern void *__libc_calloc(size_t count, size_t size);
extern void *__libc_realloc(void *p, size_t size);
extern void *__libc_memalign(size_t alignment, size_t size);

static atomic_long allocations;
static atomic_int counting;

static void count(void)
{
    if (atomic_load_explicit(&counting, memory_order_relaxed))
        atomic_fetch_add_explicit(&allocations, 1, memory_order_relaxed);
}

void *malloc(size_t size)
{
    count();
    return __libc_malloc(size);
}

void *calloc(size_t n, size_t size)
{
    count();
    return __libc_calloc(n, size);
}

void *realloc(void *p, size_t size)
{
    count();
    return __libc_realloc(p, size);
}

void *aligned_alloc(size_t alignment, size_t size)
{
    count();
    return __libc_memalign(alignment, size);
}

int posix_memalign(void **p, size_t alignment, size_t size)
{
    count();
    *p = __libc_memalign(alignment, size);
    return *p != NULL ? 0 : 12; /* ENOMEM */
}

static void start_counting(void)
{
    atomic_store(&allocations, 0);
    atomic_store(&counting, 1);
}

static long stop_counting(void)
{
    atomic_store(&counting, 0);
    return atomic_load(&allocations);
}

/* The counter sees the test's allocations and the dlopen'd library's: a
 * coupler entry called for an element id it has not seen sets one up. */
static void the_counter_counts(void **state)
{
    (void)state;
    start_counting();
    void *volatile p = malloc(16);
    void *volatile q = calloc(2, 8);
    long counted = stop_counting();
    free(p), free(q);
    assert_int_equal(counted, 2);

    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, EXAMPLES_DIR "/bench_coupler.xml", stderr, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_binding *b = &s.bindings.items[0];
    assert_int_equal(b->kind, HX_BIND_COUPLER);
    int id = b->id + 1000, npar = b->npar, n = s.model->couplers[b->index].njoints, flag = 0;
    double time = 0.0, angles[3] = {0.1, 0.2, 0.3}, out[9];
    start_counting();
    b->fn.coupler[0](&id, &time, b->par, &npar, angles, &n, &flag, out);
    counted = stop_counting();
    printf("  a new coupler element's set-up: %ld allocations\n", counted);
    assert_true(counted > 0);
    hx_session_close(&s);
}

/* A million calls of each entry of a model after its set-up (the session's
 * dependency passes and one evaluation); returns the allocations counted. */
static long allocations_in_calls(const char *model)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", EXAMPLES_DIR, model);
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, path, stderr, &msg) != 0)
        fail_msg("%s", msg.text);
    long total = 0;
    for (int k = 0; k < s.bindings.count; ++k) {
        long counted = 0;
        hx_binding *b = &s.bindings.items[k];
        int id = b->id, npar = b->npar, flag = 0, dflag = 0;
        double time = 0.0, out[64], disp[6], velo[6], dfd[36], dfv[36];
        hx_call call;
        hx_binding_call_init(b, &call, 0, &s.frames, 0);
        if (b->kind == HX_BIND_COUPLER) {
            double q[3] = {0.1, -0.2, 0.3};
            int n = s.model->couplers[b->index].njoints;
            for (int fn = 0; fn < 3; ++fn) {
                b->fn.coupler[fn](&id, &time, b->par, &npar, q, &n, &flag, out); /* warm */
                start_counting();
                for (long c = 0; c < CALLS / 3; ++c) {
                    q[0] = 0.1 + 1e-7 * (double)(c & 1023);
                    b->fn.coupler[fn](&id, &time, b->par, &npar, q, &n, &flag, out);
                }
                counted += stop_counting();
            }
        } else if (b->kind == HX_BIND_FORCE) {
            hx_host_bind(&call);
            b->fn.force(&id, &time, b->par, &npar, &dflag, &flag, out);
            start_counting();
            for (long c = 0; c < CALLS; ++c)
                b->fn.force(&id, &time, b->par, &npar, &dflag, &flag, out);
            counted += stop_counting();
            hx_host_unbind();
        } else {
            hx_force_deformation(&s.frames, b->index, disp, velo);
            b->fn.field(&id, &time, b->par, &npar, disp, velo, &dflag, &flag, out, dfd, dfv);
            start_counting();
            for (long c = 0; c < CALLS; ++c) {
                disp[0] += 1e-9; /* a new state each call */
                b->fn.field(&id, &time, b->par, &npar, disp, velo, &dflag, &flag, out, dfd, dfv);
            }
            counted += stop_counting();
        }
        assert_int_equal(s.messages.errors, 0);
        printf("  %-18s %-22s %3d: %ld allocations in %ld calls\n", model, b->element, b->id,
               counted, CALLS);
        total += counted;
    }
    hx_session_close(&s);
    return total;
}

static void entries_allocate_nothing_after_set_up(void **state)
{
    (void)state;
    static const char *const models[] = {"bench_bushing.xml", "bench_coupler.xml",
                                         "bench_limits.xml", "flex_joint_rig.xml",
                                         "powertrain.xml"};
    for (size_t k = 0; k < sizeof models / sizeof models[0]; ++k)
        assert_int_equal(allocations_in_calls(models[k]), 0);
}

/* check's set-up footprint: the first element naming a property file holds
 * the file's data; a second element on the same file only its own record */
static void set_up_footprint_is_measured(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, EXAMPLES_DIR "/bench_bushing.xml", stderr, &msg) != 0)
        fail_msg("%s", msg.text);
    const long first = s.bindings.items[0].setup_bytes, second = s.bindings.items[1].setup_bytes;
    printf("  set-up footprints: %ld bytes (file and element), %ld bytes (element)\n", first,
           second);
    assert_true(first > 1000);  /* six splines, the element table */
    assert_true(second > 0 && second < first / 4);
    hx_session_close(&s);
}

/* The first footprint check prints for bench_bushing.xml, with the
 * environment prefix env; -1 when none is printed. */
static long check_first_footprint(const char *env)
{
    char command[2048], output[16384];
    snprintf(command, sizeof command, "%s '%s' check '%s/bench_bushing.xml' 2>&1", env,
             HARNESS_EXE, EXAMPLES_DIR);
    FILE *p = popen(command, "r");
    assert_non_null(p);
    const size_t n = fread(output, 1, sizeof output - 1, p);
    output[n] = '\0';
    assert_int_equal(pclose(p), 0);
    const char *line = strstr(output, "set-up footprint: ");
    return line != NULL ? atol(line + 18) : -1;
}

/* check's footprints are byte-exact: it re-executes itself with glibc's
 * per-thread cache off (freed small blocks it holds count as in use: this
 * element read 16 500 bytes with it, its data being about 4 600), so asking
 * for the cache off from the start changes nothing. */
static void check_footprint_is_exact(void **state)
{
    (void)state;
    const long as_run = check_first_footprint("env -u GLIBC_TUNABLES");
    const long cache_off = check_first_footprint("env GLIBC_TUNABLES=glibc.malloc.tcache_count=0");
    printf("  check's first footprint: %ld bytes (cache off from the start: %ld)\n", as_run,
           cache_off);
    if (as_run < 0) { /* a sanitizer's allocator: no footprint printed */
        assert_int_equal(cache_off, -1);
        return;
    }
    assert_true(as_run > 1000 && as_run < 8000); /* six splines, the element table */
    assert_true(labs(as_run - cache_off) <= 32);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_counter_counts),
        cmocka_unit_test(entries_allocate_nothing_after_set_up),
        cmocka_unit_test(set_up_footprint_is_measured),
        cmocka_unit_test(check_footprint_is_exact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
