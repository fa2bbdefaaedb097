/*
 * The state-equation entries (YFOSUB, YFOXX, YFOXU, YFOYX, YFOYU) loaded
 * through dlopen, the harness answering c_gtstrg as a host: without states
 * YFOSUB is FIESUB to the bit; the four partial routines give the blocks of
 * one Jacobian, against differences of YFOSUB itself; a bushing with states
 * is refused by GFOSUB and FIESUB with the way to run it; wrong sizes, a
 * non-finite input, another element code and the rotation-vector measure are
 * each reported once, naming what was expected, with zeros out.
 */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sim_support.h"
#include "test_support.h"
#include "usrsub/solver_abi.h"

static const char gbs_head[] =
    "[HEADER]\nFILE_TYPE = 'gbs'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\nFORCE = 'newton'\n"
    "MASS = 'kg'\nTIME = 'second'\n[GLOBAL]\nCOUPLING = 'CYLINDRICAL'\n%s[DIRECTIONS]\n(ACTIVITY)\n"
    "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 1 1 1 1 1 1\n"
    "'CONSTANT_DAMPING' 1 1 1 1 1 1\n"
    "[CONSTANT_STIFFNESS_FX]\nK = 100\n[CONSTANT_STIFFNESS_FY]\nK = 150\n[CONSTANT_STIFFNESS_FZ]\nK = 80\n"
    "[CONSTANT_STIFFNESS_TX]\nK = 1e4\n[CONSTANT_STIFFNESS_TY]\nK = 2e4\n[CONSTANT_STIFFNESS_TZ]\nK = 3e4\n"
    "[CONSTANT_DAMPING_FX]\nC = 2\n[CONSTANT_DAMPING_FY]\nC = 3\n[CONSTANT_DAMPING_FZ]\nC = 1\n"
    "[CONSTANT_DAMPING_TX]\nC = 20\n[CONSTANT_DAMPING_TY]\nC = 30\n[CONSTANT_DAMPING_TZ]\nC = 10\n%s";

static const char *gbs(const char *name, const char *global, const char *blocks)
{
    char text[4096];
    snprintf(text, sizeof text, gbs_head, global, blocks);
    return test_write_file(name, text);
}

static const char states_blocks[] =
    "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\nMU_DYNAMIC = 0.3\nTRANSITION_VELOCITY = 20\n"
    "BRISTLE_STIFFNESS = 100\nBRISTLE_DAMPING = 0.02\nBALL_RADIUS = 10\n"
    "[MOUNT_STIFFNESS]\n{ direction K C }\nFX 2000 5\nTZ 3e5 0\n";

typedef struct entries {
    void *library;
    usrsub_yfosub_fn *yfosub;
    usrsub_state_partial_fn *partial[4]; /* XX XU YX YU */
    usrsub_fiesub_fn *fiesub;
    usrsub_gfosub_fn *gfosub;
    host_model host;
} entries;

static void open_entries(entries *e)
{
    char xml[4096];
    snprintf(xml, sizeof xml,
             "<MotionSolve><Model>\n"
             "<Param_Unit length_unit=\"MILLIMETER\" force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" time_unit=\"SECOND\"/>\n"
             "<Reference_String id=\"1\" string=\"%s\"/>\n<Reference_String id=\"2\" string=\"%s\"/>\n"
             "<Reference_String id=\"3\" string=\"%s\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n</Model></MotionSolve>\n",
             gbs("plain.gbs", "", ""), gbs("states.gbs", "", states_blocks),
             gbs("vector.gbs", "ROTATION_MEASURE = 'ROTATION_VECTOR'\n", ""));
    host_model_attach(&e->host, "states.xml", xml);
    e->library = load_library();
    e->yfosub = (usrsub_yfosub_fn *)dlsym(e->library, "YFOSUB");
    static const char *const names[4] = {"YFOXX", "YFOXU", "YFOYX", "YFOYU"};
    for (int k = 0; k < 4; ++k)
        e->partial[k] = (usrsub_state_partial_fn *)dlsym(e->library, names[k]);
    e->fiesub = (usrsub_fiesub_fn *)dlsym(e->library, "FIESUB");
    e->gfosub = (usrsub_gfosub_fn *)dlsym(e->library, "GFOSUB");
    assert_non_null(e->yfosub);
    for (int k = 0; k < 4; ++k)
        assert_non_null(e->partial[k]);
}

static void close_entries(entries *e)
{
    dlclose(e->library);
    host_model_detach(&e->host);
}

static const double u0[12] = {0.8, -0.4, 0.35, 0.004, -0.012, 0.02, 12, -7, 3, 0.4, -0.25, 0.6};

static void without_states_yfosub_is_fiesub(void **state)
{
    (void)state;
    entries e;
    open_entries(&e);
    int id = 1, npar = 2, flag = 0, nstate = 0, ninput = 12, noutpt = 6;
    double par[2] = {1, 1}, t = 0.0, u[12], y[6], field[6], dfd[36], dfv[36], yu[72];
    memcpy(u, u0, sizeof u);
    e.yfosub(&id, &t, par, &npar, &flag, &flag, &nstate, NULL, &ninput, u, &noutpt, NULL, y);
    int fid = 2;
    e.fiesub(&fid, &t, par, &npar, u, u + 6, &flag, &flag, field, dfd, dfv);
    e.partial[3](&id, &t, par, &npar, &flag, &nstate, NULL, &ninput, u, &noutpt, yu);
    for (int i = 0; i < 6; ++i) {
        assert_true(y[i] == field[i]);
        for (int j = 0; j < 6; ++j)
            assert_true(yu[i + 6 * j] == dfd[i + 6 * j] && yu[i + 6 * (6 + j)] == dfv[i + 6 * j]);
    }
    assert_int_equal(e.host.messages.errors, 0);
    close_entries(&e);
}

static void the_partial_routines_are_the_jacobian(void **state)
{
    (void)state;
    entries e;
    open_entries(&e);
    /* bristles, the x mount, the z mount's node (s, sdot): inertial in series with friction */
    enum { NS = 6 };
    int id = 3, npar = 2, flag = 0, nstate = NS, ninput = 12, noutpt = 6;
    double par[2] = {1, 2}, t = 0.0, x[NS] = {0.001, -0.002, 0.0015, 0.01, 0.002, -0.3};
    double xdot[NS], y[6], m[4][NS * (NS + 12)];
    e.yfosub(&id, &t, par, &npar, &flag, &flag, &nstate, x, &ninput, (double *)u0, &noutpt, xdot, y);
    assert_int_equal(e.host.messages.errors, 0);
    for (int k = 0; k < 4; ++k)
        e.partial[k](&id, &t, par, &npar, &flag, &nstate, x, &ninput, (double *)u0, &noutpt, m[k]);
    double worst = 0.0;
    for (int j = 0; j < NS + 12; ++j) {
        double xp[NS], xm[NS], up[12], um[12], dp[NS], dm[NS], yp[6], ym[6];
        memcpy(xp, x, sizeof x), memcpy(xm, x, sizeof x);
        memcpy(up, u0, sizeof up), memcpy(um, u0, sizeof um);
        double *a = j < NS ? &xp[j] : &up[j - NS], *b = j < NS ? &xm[j] : &um[j - NS];
        const double h = 1e-6 * fmax(1e-3, fabs(*a));
        *a += h, *b -= h;
        e.yfosub(&id, &t, par, &npar, &flag, &flag, &nstate, xp, &ninput, up, &noutpt, dp, yp);
        e.yfosub(&id, &t, par, &npar, &flag, &flag, &nstate, xm, &ninput, um, &noutpt, dm, ym);
        for (int i = 0; i < NS + 6; ++i) {
            const double fd = i < NS ? (dp[i] - dm[i]) / (2 * h) : (yp[i - NS] - ym[i - NS]) / (2 * h);
            const double exact = i < NS ? (j < NS ? m[0][i + NS * j] : m[1][i + NS * (j - NS)])
                                        : (j < NS ? m[2][i - NS + 6 * j] : m[3][i - NS + 6 * (j - NS)]);
            worst = fmax(worst, fabs(exact - fd) / fmax(1.0, fabs(fd)));
        }
    }
    printf("  YFOXX, YFOXU, YFOYX, YFOYU against differences of YFOSUB: worst %.2g\n", worst);
    assert_true(worst < 1e-5);
    close_entries(&e);
}

/* One call that must be refused: zeros out and one error holding the needles. */
static void expect_refusal(entries *e, int id, double *par, int npar, int nstate, int ninput,
                           const double *u, const char *const needles[3])
{
    const int before = e->host.messages.errors;
    int flag = 0, noutpt = 6;
    double t = 0.0, x[8] = {0}, xdot[8], y[6], in[12];
    memcpy(in, u, sizeof in);
    for (int k = 0; k < 8; ++k)
        xdot[k] = 9.0;
    y[0] = 9.0;
    e->yfosub(&id, &t, par, &npar, &flag, &flag, &nstate, x, &ninput, in, &noutpt, xdot, y);
    for (int i = 0; i < 6; ++i)
        assert_true(y[i] == 0.0);
    for (int i = 0; i < nstate && i < 8; ++i)
        assert_true(xdot[i] == 0.0);
    assert_int_equal(e->host.messages.errors, before + 1);
    assert_contains(e->host.messages.last_error, needles[0], needles[1], needles[2]);
    /* a second call with the same fault adds nothing */
    e->yfosub(&id, &t, par, &npar, &flag, &flag, &nstate, x, &ninput, in, &noutpt, xdot, y);
    assert_int_equal(e->host.messages.errors, before + 1);
}

static void errors_name_what_was_expected(void **state)
{
    (void)state;
    entries e;
    open_entries(&e);
    double with_states[2] = {1, 2}, limits_code[2] = {2, 1}, vector[2] = {1, 3};
    expect_refusal(&e, 10, with_states, 2, 3, 12, u0,
                   (const char *const[]){"YFOSUB element 10",
                                         "6 states (friction 3, balanced mounts 1, inertial mounts 2 x 1",
                                         "nstate 3"});
    expect_refusal(&e, 11, with_states, 2, 6, 6, u0,
                   (const char *const[]){"12 inputs (DX DY DZ AX AY AZ", "ninput 6", "U array"});
    double bad[12];
    memcpy(bad, u0, sizeof bad);
    bad[7] = NAN;
    expect_refusal(&e, 12, with_states, 2, 6, 12, bad,
                   (const char *const[]){"YFOSUB element 12", "not finite", "outputs are zero"});
    expect_refusal(&e, 13, limits_code, 2, 0, 12, u0,
                   (const char *const[]){"element code 2", "only the bushing", "code 1"});
    expect_refusal(&e, 14, vector, 2, 0, 12, u0,
                   (const char *const[]){"Reference_String 3", "ROTATION_VECTOR", "state-equation form"});

    /* GFOSUB and FIESUB refuse a bushing with states, and say how to run it */
    int id = 15, npar = 2, flag = 0;
    double t = 0.0, field[6], dfd[36], dfv[36], u[12];
    memcpy(u, u0, sizeof u);
    const int before = e.host.messages.errors;
    e.fiesub(&id, &t, with_states, &npar, u, u + 6, &flag, &flag, field, dfd, dfv);
    assert_int_equal(e.host.messages.errors, before + 1);
    assert_contains(e.host.messages.last_error, "FIESUB element 15", "internal states",
                    "Force_StateEqn with YFOSUB");
    for (int i = 0; i < 6; ++i)
        assert_true(field[i] == 0.0);
    close_entries(&e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(without_states_yfosub_is_fiesub),
        cmocka_unit_test(the_partial_routines_are_the_jacobian),
        cmocka_unit_test(errors_name_what_was_expected),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
