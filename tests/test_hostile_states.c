/*
 * Non-finite and extreme states into every entry: NaN, +-Inf, +-1e308,
 * denormals, exact zeros (r = 0 of a coupled bushing) and mixes of them, as
 * disp and velo (FIESUB, couplers) or as the host's answers (GFOSUB, through
 * bodies placed there). Every output is finite, always: the entry either
 * copes or reports an error and returns zeros. Never NaN or Inf out.
 *
 * Zeros are finite, so each test first shows its subject ran: every entry,
 * at ordinary states, sets up without an error and returns real (non-zero)
 * outputs, and a share of the hostile calls still does (docs/testing.md, "A
 * test that cannot fail is a defect").
 */
#include <dlfcn.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "frames/frames.h"
#include "sim_support.h"
#include "test_support.h"
#include "usrsub/solver_abi.h"

static const double values[] = {NAN, INFINITY, -INFINITY, 1e308, -1e308, 4.9e-324, -4.9e-324,
                                DBL_MIN, 0.0, -0.0, 1e-300, 1e150, 3.0};
#define NVALUES ((int)(sizeof values / sizeof values[0]))

static int all_finite(const double *v, int n)
{
    for (int k = 0; k < n; ++k)
        if (!isfinite(v[k]))
            return 0;
    return 1;
}

static int any_nonzero(const double *v, int n)
{
    for (int k = 0; k < n; ++k)
        if (v[k] != 0.0)
            return 1;
    return 0;
}

static void *library;
static host_model host;

/* The subject ran: no error reported since the messages were last reset
 * (a property file not found, a bad USER list), and real outputs. */
static void expect_real_outputs(const char *entry, const double *out, int n)
{
    if (host.messages.errors != 0)
        fail_msg("%s at an ordinary state reported an error: %s", entry, host.messages.last_error);
    if (!any_nonzero(out, n))
        fail_msg("%s at an ordinary state returned only zeros", entry);
}

/* A share of the hostile calls answered with real values: the entries cope
 * with most extreme states rather than refusing them all. */
static void expect_share(const char *what, long real, long calls, double share)
{
    printf("%s: %ld calls, every output finite, %ld with non-zero outputs\n", what, calls, real);
    if ((double)real < share * (double)calls)
        fail_msg("%s: only %ld of %ld calls returned non-zero outputs", what, real, calls);
}

static void set_up(void)
{
    char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>\n"
             "<Reference_String id=\"401\" string=\"" EXAMPLES_DIR "/bench_bushing.gbs\"/>\n"
             "<Reference_String id=\"402\" string=\"" EXAMPLES_DIR "/mount_limits.gbi\"/>\n"
             "<Reference_String id=\"403\" string=\"" EXAMPLES_DIR "/flex_coupled.gfj\"/>\n"
             "<Reference_String id=\"404\" string=\"" EXAMPLES_DIR "/steering_ratio.tbl\"/>\n"
             "<Reference_String id=\"405\" string=\"" EXAMPLES_DIR "/coupled_isotropic.gbs\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "</Model></MotionSolve>\n");
    host_model_attach(&host, "hostile.xml", text);
    host.messages.stream = NULL;
    library = load_library();
}

static void tear_down(void)
{
    dlclose(library);
    host_model_detach(&host);
}

static const struct {
    int ndisp, npar;
    double par[24];
} couplers[] = {
    {2, 4, {1, 20, 1, 40}},                                     /* linear */
    {2, 10, {2, 3, 0, 1, 0, 0.2, 5, 1.5, 1.0, 0.0}},            /* polynomial, sine */
    {3, 13, {3, 3, -1, -2, 0, 0, 1, 3, 4, 404, 0.5, 1, 2}},     /* inline spline, file, linear */
};

static void couplers_take_any_disp(void **state)
{
    (void)state;
    set_up();
    usrsub_coupler_fn *fn[3] = {(usrsub_coupler_fn *)dlsym(library, "COUSUB"),
                                (usrsub_coupler_fn *)dlsym(library, "COUXX"),
                                (usrsub_coupler_fn *)dlsym(library, "COUXX2")};
    for (size_t c = 0; c < sizeof couplers / sizeof couplers[0]; ++c)
        for (int w = 0; w < 2; ++w) { /* COUXX2 of the linear coupler is zero */
            double par[24], disp[3] = {0.3, -0.2, 0.1}, out[9];
            memcpy(par, couplers[c].par, sizeof par);
            int id = 500 + (int)c, npar = couplers[c].npar, nd = couplers[c].ndisp, flag = 0;
            double t = 0.0;
            hx_messages_reset(&host.messages);
            fn[w](&id, &t, par, &npar, disp, &nd, &flag, out);
            expect_real_outputs(w == 0 ? "COUSUB" : "COUXX", out, w == 0 ? 1 : nd);
        }
    long calls = 0, real = 0;
    for (size_t c = 0; c < sizeof couplers / sizeof couplers[0]; ++c) {
        int npar = couplers[c].npar;
        for (int a = 0; a < NVALUES; ++a)
            for (int b = 0; b < NVALUES; b += 3)
                for (int w = 0; w < 3; ++w) {
                    double par[24], disp[3] = {values[a], values[b], values[(a + b) % NVALUES]};
                    memcpy(par, couplers[c].par, sizeof par);
                    int id = 500 + (int)c, nd = couplers[c].ndisp, flag = 0;
                    double t = 0.0, out[9];
                    fn[w](&id, &t, par, &npar, disp, &nd, &flag, out);
                    const int count = w == 0 ? 1 : w == 1 ? nd : nd * nd;
                    if (!all_finite(out, count))
                        fail_msg("%s coupler %zu at disp (%g %g %g): a non-finite output",
                                 w == 0 ? "COUSUB" : w == 1 ? "COUXX" : "COUXX2", c, disp[0],
                                 disp[1], disp[2]);
                    ++calls;
                    real += any_nonzero(out, count);
                }
    }
    tear_down();
    expect_share("couplers", real, calls, 0.2);
}

static const struct {
    const char *entry;
    int npar;
    double par[4];
} fields[] = {
    {"FIESUB", 2, {1, 401}},         /* splines, damping, cylindrical coupling */
    {"FIESUB", 2, {1, 405}},         /* cubic, spherical coupling */
    {"FIESUB", 3, {1, 401, 402}},    /* with mount limits */
    {"MOUNT_LIMITS_FIELD", 1, {402}},
    {"FLEX_JOINT_FIELD", 1, {403}},
    {"ABM_BUSHING_FIELD", 1, {405}},
};

static void field_entries_take_any_state(void **state)
{
    (void)state;
    set_up();
    long calls = 0, real = 0;
    for (size_t e = 0; e < sizeof fields / sizeof fields[0]; ++e) {
        usrsub_fiesub_fn *fn = (usrsub_fiesub_fn *)dlsym(library, fields[e].entry);
        assert_non_null(fn);
        { /* beyond every mount limit's gap (3 and 5 mm, 0.1 and 0.3 rad) */
            double disp[6] = {4, -4, 6, 0.2, -0.2, 0.4}, velo[6] = {1, 2, 3, 0.1, 0.2, 0.3};
            double par[4], F[6], J[72], t = 0.0;
            memcpy(par, fields[e].par, sizeof par);
            int id = 600 + (int)e, npar = fields[e].npar, dflag = 0, iflag = 0;
            hx_messages_reset(&host.messages);
            fn(&id, &t, par, &npar, disp, velo, &dflag, &iflag, F, J, J + 36);
            expect_real_outputs(fields[e].entry, F, 6);
        }
        for (int a = 0; a < NVALUES; ++a)
            for (int slot = 0; slot < 12; ++slot)
                for (int mix = 0; mix < 3; ++mix) {
                    /* one hostile value in one slot, over a plain, a zero or a huge state */
                    const double base = mix == 0 ? 0.3 : mix == 1 ? 0.0 : 1e200;
                    double disp[6], velo[6], F[6], J[72];
                    for (int i = 0; i < 6; ++i)
                        disp[i] = base * (i < 3 ? 1.0 : 0.1), velo[i] = base;
                    (slot < 6 ? disp : velo)[slot % 6] = values[a];
                    double par[4];
                    memcpy(par, fields[e].par, sizeof par);
                    int id = 600 + (int)e, npar = fields[e].npar, dflag = 0, iflag = 0;
                    double t = 0.0;
                    fn(&id, &t, par, &npar, disp, velo, &dflag, &iflag, F, J, J + 36);
                    if (!all_finite(F, 6) || !all_finite(J, 72))
                        fail_msg("%s USER(%g, ...): a non-finite output with %s[%d] = %g over %g",
                                 fields[e].entry, par[0], slot < 6 ? "disp" : "velo", slot % 6,
                                 values[a], base);
                    ++calls;
                    real += any_nonzero(F, 6);
                }
    }
    tear_down();
    expect_share("field entries", real, calls, 0.2);
}

static void gfosub_entries_take_any_host_answer(void **state)
{
    (void)state;
    set_up();
    static const struct {
        const char *entry;
        int npar;
        double par[6];
    } forces[] = {
        {"GFOSUB", 4, {1, 20, 10, 401}}, {"GFOSUB", 5, {1, 20, 10, 401, 402}},
        {"MOUNT_LIMITS", 3, {20, 10, 402}}, {"FLEX_JOINT", 3, {20, 10, 403}},
        {"ABM_BUSHING", 3, {20, 10, 405}},
    };
    /* body 2 beyond every mount limit's gap (3 and 5 mm), turning and moving */
    hx_frame *b = &host.frames.bodies[1];
    const double p[3] = {4, -4, 6}, v[3] = {1, 2, 3}, w[3] = {0.1, 0.2, 0.3};
    memcpy(b->p, p, sizeof p), memcpy(b->v, v, sizeof v), memcpy(b->w, w, sizeof w);
    hx_frames_update(&host.frames);
    hx_frames initial;
    assert_int_equal(hx_frames_clone(&initial, &host.frames), 0);
    long calls = 0, real = 0;
    for (size_t e = 0; e < sizeof forces / sizeof forces[0]; ++e) {
        usrsub_gfosub_fn *fn = (usrsub_gfosub_fn *)dlsym(library, forces[e].entry);
        assert_non_null(fn);
        {
            hx_frames_copy(&host.frames, &initial);
            double par[6], out[6], t = 0.0;
            memcpy(par, forces[e].par, sizeof par);
            int id = 700 + (int)e, npar = forces[e].npar, dflag = 0, iflag = 0;
            hx_messages_reset(&host.messages);
            fn(&id, &t, par, &npar, &dflag, &iflag, out);
            expect_real_outputs(forces[e].entry, out, 6);
        }
        for (int a = 0; a < NVALUES; ++a)
            for (int slot = 0; slot < 12; ++slot) {
                /* body 2 placed with one hostile position, angle or velocity */
                hx_frames_copy(&host.frames, &initial);
                hx_frame *f = &host.frames.bodies[1];
                if (slot < 3)
                    f->p[slot] = values[a];
                else if (slot < 6)
                    for (int i = 0; i < 3; ++i) /* a hostile rotation matrix row */
                        f->R[3 * (slot - 3) + i] = values[a];
                else if (slot < 9)
                    f->v[slot - 6] = values[a];
                else
                    f->w[slot - 9] = values[a];
                hx_frames_update(&host.frames);
                double par[6], out[6];
                memcpy(par, forces[e].par, sizeof par);
                int id = 700 + (int)e, npar = forces[e].npar, dflag = 0, iflag = 0;
                double t = 0.0;
                fn(&id, &t, par, &npar, &dflag, &iflag, out);
                if (!all_finite(out, 6))
                    fail_msg("%s: a non-finite output with state slot %d = %g", forces[e].entry,
                             slot, values[a]);
                ++calls;
                real += any_nonzero(out, 6);
            }
    }
    hx_frames_copy(&host.frames, &initial);
    hx_frames_free(&initial);
    tear_down();
    expect_share("GFOSUB-form entries", real, calls, 0.2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(couplers_take_any_disp),
        cmocka_unit_test(field_entries_take_any_state),
        cmocka_unit_test(gfosub_entries_take_any_host_answer),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
