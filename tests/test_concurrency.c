/*
 * Concurrency: several threads call COUSUB, COUXX, COUXX2, GFOSUB and FIESUB
 * on many element ids at once, starting from a freshly loaded library, so
 * that first calls set elements up while others evaluate. The results are
 * bit for bit those of a single-threaded run. Built also with
 * ThreadSanitizer (scripts/test.sh), which must see no race.
 */
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "frames/frames.h"
#include "sim_support.h"
#include "test_support.h"
#include "usrsub/solver_abi.h"

#define THREADS 4
#define ELEMENTS 48
#define ROUNDS 20

typedef struct entries {
    usrsub_coupler_fn *coupler[3];
    usrsub_gfosub_fn *gfosub;
    usrsub_fiesub_fn *fiesub;
} entries;

/* Element e's USER list: couplers, bushings, limits and joints in turn. */
static int user_list(int e, double *par, int *kind)
{
    static const double lists[5][10] = {
        {1, 20, 1, 40},                    /* coupler, 4 values */
        {2, 2, 0.5, 1, -0.3, 5, 2, 1, 0.2}, /* coupler: polynomial and sine, 9 values */
        {1, 20, 10, 801},                  /* GFOSUB bushing */
        {1, 20, 10, 801, 802},             /* GFOSUB bushing with limits */
        {3, 803},                          /* FIESUB flexible joint */
    };
    static const int counts[5] = {4, 9, 4, 5, 2};
    const int k = e % 5;
    memcpy(par, lists[k], sizeof lists[k]);
    if (k < 2) /* couplers differ from one another (a slope, a constant) */
        par[k + 1] += 0.01 * e;
    *kind = k < 2 ? 0 : k < 4 ? 1 : 2;
    return counts[k];
}

/* All outputs of one pass over the elements, in a fixed order. */
static void one_pass(const entries *en, int first, int step, double *out)
{
    for (int e = first; e < ELEMENTS; e += step) {
        double par[10], t = 0.0;
        int kind, id = 1000 + e, flag = 0, dflag = 0;
        int npar = user_list(e, par, &kind);
        double *o = out + (size_t)e * 90;
        if (kind == 0) {
            int nd = 2;
            double disp[2] = {0.1 * e, -0.05 * e};
            en->coupler[0](&id, &t, par, &npar, disp, &nd, &flag, o);
            en->coupler[1](&id, &t, par, &npar, disp, &nd, &flag, o + 1);
            en->coupler[2](&id, &t, par, &npar, disp, &nd, &flag, o + 3);
        } else if (kind == 1) {
            en->gfosub(&id, &t, par, &npar, &dflag, &flag, o);
        } else {
            double disp[6] = {0.3, -0.2, 0.1, 0.02, -0.01, 0.03}, velo[6] = {1, 2, 3, 0.1, 0.2, 0.3};
            disp[0] += 0.01 * e;
            en->fiesub(&id, &t, par, &npar, disp, velo, &dflag, &flag, o, o + 6, o + 42);
        }
    }
}

typedef struct worker {
    const entries *en;
    int index;
    double *out;
    host_model *host;
} worker;

static void *work(void *arg)
{
    worker *w = arg;
    /* the host's binding is per thread: each binds a call to the shared state */
    hx_call call;
    hx_call_init(&call, "thread", 0, "entry", w->host->model, &w->host->frames,
                 &w->host->messages, 0, NULL);
    hx_host_bind(&call);
    /* every thread covers every element, from a different start, again and again */
    for (int r = 0; r < ROUNDS; ++r)
        for (int shift = 0; shift < THREADS; ++shift)
            one_pass(w->en, (w->index + shift) % THREADS, THREADS, w->out);
    hx_host_unbind();
    return NULL;
}

static void *load(entries *en)
{
    void *lib = load_library();
    en->coupler[0] = (usrsub_coupler_fn *)dlsym(lib, "COUSUB");
    en->coupler[1] = (usrsub_coupler_fn *)dlsym(lib, "COUXX");
    en->coupler[2] = (usrsub_coupler_fn *)dlsym(lib, "COUXX2");
    en->gfosub = (usrsub_gfosub_fn *)dlsym(lib, "GFOSUB");
    en->fiesub = (usrsub_fiesub_fn *)dlsym(lib, "FIESUB");
    return lib;
}

static void threads_agree_with_one_thread(void **state)
{
    (void)state;
    char text[2048];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>\n"
             "<Reference_String id=\"801\" string=\"" EXAMPLES_DIR "/bench_bushing.gbs\"/>\n"
             "<Reference_String id=\"802\" string=\"" EXAMPLES_DIR "/mount_limits.gbi\"/>\n"
             "<Reference_String id=\"803\" string=\"" EXAMPLES_DIR "/flex_coupled.gfj\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\""
             " v_ic_x=\"3\" v_ic_y=\"-1\" w_ic_z=\"0.4\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"4.5\" pos_y=\"-0.5\" pos_z=\"0.2\"/>\n"
             "</Model></MotionSolve>\n");
    host_model host; /* the host's state: read-only from here on */
    host_model_attach(&host, "threads.xml", text);

    /* the single-threaded answer, from a fresh library */
    entries en;
    double *expected = calloc((size_t)ELEMENTS * 90, sizeof(double));
    void *lib = load(&en);
    one_pass(&en, 0, 1, expected);
    dlclose(lib);

    /* again from a fresh library, with every thread setting up and evaluating */
    lib = load(&en);
    pthread_t thread[THREADS];
    worker w[THREADS];
    for (int k = 0; k < THREADS; ++k) {
        w[k] = (worker){&en, k, calloc((size_t)ELEMENTS * 90, sizeof(double)), &host};
        assert_int_equal(pthread_create(&thread[k], NULL, work, &w[k]), 0);
    }
    for (int k = 0; k < THREADS; ++k)
        pthread_join(thread[k], NULL);
    dlclose(lib);
    int compared = 0;
    for (int k = 0; k < THREADS; ++k) {
        assert_memory_equal(w[k].out, expected, sizeof(double) * ELEMENTS * 90);
        free(w[k].out);
        ++compared;
    }
    int nonzero = 0;
    for (int i = 0; i < ELEMENTS * 90; ++i)
        nonzero += expected[i] != 0.0;
    assert_true(nonzero > ELEMENTS * 4); /* real forces and constraints, not zeros */
    assert_int_equal(host.messages.errors, 0);
    printf("%d threads x %d rounds over %d elements: identical to one thread\n", compared, ROUNDS,
           ELEMENTS);
    free(expected);
    host_model_detach(&host);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(threads_agree_with_one_thread),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
