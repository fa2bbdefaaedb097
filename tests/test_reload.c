/*
 * Unload and reload, as hosts do between runs: after dlclose the library
 * holds nothing (its caches are freed by its destructor: LeakSanitizer in the
 * sanitizer build and valgrind in scripts/test.sh check that nothing leaks),
 * and after dlopen it sets its elements up afresh: property files are read
 * again, and an element's set-up error is reported again.
 */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "frames/frames.h"
#include "sim_support.h"
#include "test_support.h"
#include "usrsub/solver_abi.h"

static void reload_sets_up_afresh(void **state)
{
    (void)state;
    /* no model units: reading a property file says "used as they are", once a load */
    char text[2048];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Reference_String id=\"901\" string=\"" EXAMPLES_DIR "/bench_bushing.gbs\"/>\n"
             "<Reference_String id=\"902\" string=\"" EXAMPLES_DIR "/flex_coupled.gfj\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\"/>\n"
             "</Model></MotionSolve>\n");
    host_model host;
    host_model_attach(&host, "reload.xml", text);
    host.messages.stream = NULL;
    double first[3][6];
    for (int load = 0; load < 3; ++load) {
        hx_messages_reset(&host.messages);
        void *lib = load_library();
        usrsub_gfosub_fn *gfosub = (usrsub_gfosub_fn *)dlsym(lib, "GFOSUB");
        usrsub_fiesub_fn *fiesub = (usrsub_fiesub_fn *)dlsym(lib, "FIESUB");
        usrsub_coupler_fn *cousub = (usrsub_coupler_fn *)dlsym(lib, "COUSUB");
        double t = 0.0, out[6], F[6], J[72], phi;
        int flag = 0, dflag = 0;
        for (int call = 0; call < 3; ++call) {
            double par[4] = {1, 20, 10, 901};
            int id = 1, npar = 4;
            gfosub(&id, &t, par, &npar, &dflag, &flag, out);
            double jpar[2] = {3, 902}, disp[6] = {0.1, 0.2, 0.3, 0.01, 0.02, 0.03}, velo[6] = {0};
            int jid = 2, jnpar = 2;
            fiesub(&jid, &t, jpar, &jnpar, disp, velo, &dflag, &flag, F, J, J + 36);
            double bad[2] = {9, 1}, d2[2] = {0, 0};
            int bid = 3, bnpar = 2, nd = 2;
            cousub(&bid, &t, bad, &bnpar, d2, &nd, &flag, &phi);
        }
        if (load == 0) {
            memcpy(first[0], out, sizeof out);
            assert_true(out[0] != 0.0 || out[1] != 0.0 || out[2] != 0.0); /* a real force */
        }
        assert_memory_equal(out, first[0], sizeof out); /* the same forces every load */
        /* each load reads both files (one notice each) and reports the bad coupler once */
        assert_int_equal(host.messages.notices, 2);
        assert_int_equal(host.messages.errors, 1);
        assert_contains(host.messages.last_error, "COUSUB element 3");
        assert_int_equal(dlclose(lib), 0);
    }
    hx_messages_reset(&host.messages);
    host_model_detach(&host);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reload_sets_up_afresh),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
