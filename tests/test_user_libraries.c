/*
 * usrsub-harness check on user libraries written independently of this
 * project (tests/user_libraries/README.md): correct ones pass; each planted bug
 * is caught and named where it is (the routine, the output and input, the
 * query, the signal); the harness survives a crash. The harness runs as a
 * user runs it, as a program, its output read back.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "session/session.h"
#include "sim/dynamics/dynamics.h"
#include "sim_support.h"
#include "test_support.h"
#include "tools/check/checks.h"

/* Runs the harness's `verb` on the model at path with options; returns the
 * exit status and the output (stdout and stderr). */
static int harness_on(const char *verb, const char *path, const char *options, char *output,
                      size_t size)
{
    /* a sanitizer's own SEGV handler would turn the crash into an exit status */
    setenv("ASAN_OPTIONS", "handle_segv=0:detect_leaks=1", 1);
    char command[2048];
    snprintf(command, sizeof command, "'%s' %s '%s' %s 2>&1", HARNESS_EXE, verb, path, options);
    FILE *p = popen(command, "r");
    assert_non_null(p);
    size_t n = fread(output, 1, size - 1, p);
    output[n] = '\0';
    const int status = pclose(p);
    if (!WIFEXITED(status))
        fail_msg("%s %s did not exit: status %d; output:\n%s", verb, path, status, output);
    return WEXITSTATUS(status);
}

static int check_model(const char *path, char *output, size_t size)
{
    return harness_on("check", path, "--timeout 5", output, size);
}

/* check on tests/user_libraries/tp_NAME.xml. */
static int check(const char *name, char *output, size_t size)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/tp_%s.xml", USER_LIBRARIES_DIR, name);
    return check_model(path, output, size);
}

static char output[65536];

static void expect(const char *name, int status, const char *const *needles,
                   const char *const *absent)
{
    const int got = check(name, output, sizeof output);
    if (got != status)
        fail_msg("check tp_%s: exit %d, expected %d; output:\n%s", name, got, status, output);
    for (; needles != NULL && *needles != NULL; ++needles)
        if (strstr(output, *needles) == NULL)
            fail_msg("check tp_%s: '%s' is not in the output:\n%s", name, *needles, output);
    for (; absent != NULL && *absent != NULL; ++absent)
        if (strstr(output, *absent) != NULL)
            fail_msg("check tp_%s: '%s' should not be in the output:\n%s", name, *absent, output);
}

#define NEEDLES(...) ((const char *const[]){__VA_ARGS__, NULL})

static void correct_libraries_pass(void **state)
{
    (void)state;
    static const char *const good[] = {"good_sysary", "good_sysfnc", "good_field",
                                       "coupler_good"};
    for (size_t k = 0; k < sizeof good / sizeof good[0]; ++k)
        expect(good[k], 0, NEEDLES("1 passed, 0 failed"), NEEDLES("FAIL"));
    /* a query answered with more than six numbers: an array of 40 whose last
     * twelve are the gains, beyond the 32 bits of a machine word */
    expect("array_gains", 0, NEEDLES("ARRAY(7) uses 12 of 40", "1 passed, 0 failed"),
           NEEDLES("FAIL"));
}

static void a_hidden_state_is_named(void **state)
{
    (void)state;
    expect("hidden_state", 1, NEEDLES("history audit: FAIL: a hidden state"),
           NEEDLES("which no declared query"));
}

/* A library built as on Linux, exporting only gfosub_, binds and passes. */
static void a_linux_entry_name_binds(void **state)
{
    (void)state;
    expect("linux_names", 0, NEEDLES("Force_Vector_TwoBody 1 (gfosub_ in libtp_linux_names.so)",
                                     "1 passed, 0 failed"), NEEDLES("FAIL"));
}

/* Damping from a displacement cached at an earlier call, refreshed after the
 * first ordinary call at a later time: two calls in a row differ. */
static void a_cache_refreshed_when_time_advances_fails(void **state)
{
    (void)state;
    expect("cached_displacement", 1,
           NEEDLES("FAIL: two calls in a row at the same state and time", "a hidden state",
                   "history audit: FAIL: a hidden state: at the same input A", "0 passed, 1 failed"),
           NEEDLES("not judged"));
}

/* A rate estimated across time steps: calls in a row agree, the order of
 * calls across times shows the hidden state. */
static void a_cache_across_time_steps_fails(void **state)
{
    (void)state;
    expect("step_cache", 1,
           NEEDLES("history audit: FAIL: a hidden state: at the same input A",
                   "a value kept from an earlier call", "0 passed, 1 failed"),
           NEEDLES("two calls in a row", "not judged"));
}

/* What the host notes in the history audit's processes comes back: the late
 * reads of tp_late_query (at t > 0, where the audit's calls are) are noted in
 * this process, so that check fails them. */
static void reads_noted_in_the_history_audit_come_back(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, USER_LIBRARIES_DIR "/tp_late_query.xml", NULL, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_binding *b = &s.bindings.items[0];
    assert_int_equal(b->reported_undeclared.count, 0);
    FILE *out = fopen("/dev/null", "w");
    assert_non_null(out);
    hx_audit_history(&s, b, out);
    fclose(out);
    assert_true(b->reported_undeclared.count > 0);
    char text[64];
    assert_string_equal(hx_query_text(&b->reported_undeclared.query[0], text, sizeof text),
                        "VX(20,10,10,10)");
    hx_session_close(&s);
}

static void a_read_at_a_later_time_is_caught(void **state)
{
    (void)state;
    expect("late_query", 1, NEEDLES("reads outside the dependencies", "VX(20,10,10,10)",
                                    "WZ(20,10,10)"), NULL);
}

static void a_wrong_field_partial_is_named_by_row_and_column(void **state)
{
    (void)state;
    expect("wrong_partial", 1, NEEDLES("dfddis[1 + 6*3] = dFy/dax", "FAIL"), NULL);
}

static void a_crash_is_reported_and_survived(void **state)
{
    (void)state;
    expect("crash", 1, NEEDLES("Force_Vector_TwoBody 1: FAIL: crashed with signal 11",
                               "GFOSUB", "libtp_crash.so", "iflag = 0", "1 crashed or hung"),
           NULL);
}

static void libraries_using_the_utilities_pass(void **state)
{
    (void)state;
    expect("utilities", 0, NEEDLES("1 passed, 0 failed"), NEEDLES("FAIL", "host:"));
}

static void a_fortran_library_loads_and_passes(void **state)
{
    (void)state;
#ifdef TP_FORTRAN
    expect("fortran", 0, NEEDLES("gfosub_", "1 passed, 0 failed"), NEEDLES("FAIL", "host:"));
#else
    skip(); /* no Fortran compiler at configure time (Debian: gfortran) */
#endif
}

/* A ligament-wrapping GFOSUB (Fortran) that computes 0/0 where every state is
 * zero and hands it to AKISPL: in the dependency pass, where a solver answers
 * zeros and discards what the routine returns, that is a note; the same
 * library returning NaN at a sampled state fails. */
static void a_dependency_pass_on_zeros_is_a_note_not_a_fault(void **state)
{
    (void)state;
#ifdef TP_FORTRAN
    expect("wrapping", 0,
           NEEDLES("called c_akispl with a non-finite argument", "in its dependency pass",
                   "returned a non-finite output in its dependency pass", "not a fault",
                   "1 passed, 0 failed"),
           NEEDLES("FAIL", "refuses"));
    expect("wrapping_nan", 1, NEEDLES("FAIL: output 1 is nan", "(a sampled state)",
                                      "0 passed, 1 failed"), NULL);
#else
    skip(); /* no Fortran compiler at configure time (Debian: gfortran) */
#endif
}

/* An SFOSUB whose value depends on DZ and VZ alone, applied along the line
 * from J to I (which turns with every coordinate), and a VFOSUB whose values
 * are in a turning reference marker's axes: each is judged on what it
 * returns, and passes; the same routines with a read outside their
 * dependency pass fail, both. */
static void routines_are_judged_on_the_values_they_return(void **state)
{
    (void)state;
    expect("direction", 0, NEEDLES("Force_Scalar_TwoBody 1", "Force_Vector_TwoBody 2",
                                   "2 passed, 0 failed"),
           NEEDLES("FAIL", "no declared query"));
    expect("direction_undeclared", 1,
           NEEDLES("Force_Scalar_TwoBody 1: FAIL: the force depends on body 2's x, which no"
                   " declared query", "DX(20,10)", "WX(30,12)", "0 passed, 2 failed"),
           NULL);
}

static void a_utility_not_offered_is_named(void **state)
{
    (void)state;
    expect("unoffered", 1, NEEDLES("host: Force_Vector_TwoBody 1 (GFOSUB) needs c_quispl, which"
                                   " this host does not offer",
                                   "FAIL: needs c_quispl, which this host does not offer"),
           NULL);
}

static void host_habits_are_those_of_a_solver(void **state)
{
    (void)state;
    /* outputs zeroed before each call; NaN in the dependency pass a note */
    expect("habits", 0, NEEDLES("note: GFOSUB never writes output 5 of its call",
                                "returned a non-finite output in its dependency pass",
                                "not a fault", "1 passed, 0 failed"),
           NEEDLES("FAIL"));
    /* partials asked for with dflag set, dfdvel zeroed first */
    expect("habits_field", 0, NEEDLES("1 passed, 0 failed"), NEEDLES("FAIL", "never writes"));
}

/* VFOSUB and VTOSUB (Force_Vector_TwoBody ForceOnly, TorqueOnly) pass check,
 * and together run as the GFOSUB of the same law: one trajectory. */
static void vector_routines_run_as_the_gfosub_of_their_law(void **state)
{
    (void)state;
    expect("vector", 0, NEEDLES("(VFOSUB in libtp_vector.so)", "(VTOSUB in libtp_vector.so)",
                                "2 passed, 0 failed"),
           NEEDLES("FAIL", "never writes"));
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    sim one, two;
    sim_run(&one, USER_LIBRARIES_DIR "/tp_good_sysfnc.xml", HX_METHOD_DOPRI5, 1e-10, 0.3, 0.3);
    sim_run(&two, USER_LIBRARIES_DIR "/tp_vector.xml", HX_METHOD_DOPRI5, 1e-10, 0.3, 0.3);
    const int last = one.path.rows - 1, n = one.dynamics.nq + one.dynamics.nu;
    assert_int_equal(two.path.rows - 1, last);
    double worst = 0.0, size = 0.0;
    for (int k = 0; k < n; ++k) {
        worst = fmax(worst, fabs(sim_state(&one, last, k) - sim_state(&two, last, k)));
        size = fmax(size, fabs(sim_state(&one, last, k)));
    }
    printf("  VFOSUB + VTOSUB against GFOSUB after 0.3 s: largest state difference %.2g (of"
           " %.3g)\n", worst, size);
    assert_true(size > 0.1 && worst <= 1e-9 * size);
    sim_close(&one);
    sim_close(&two);
}

/* A line spring on slider 5 and a twist spring on hinge 6 (tp_scalar.xml,
 * tp_spline.xml): the largest distance of a run from x - x0 = 2 (cos 1000 t
 * - 1) and a - a0 = 0.1 (cos 316.23 t - 1), of each amplitude; *stretch (may
 * be NULL) receives the least x - x0. */
static double off_the_springs_closed_forms(const sim *s, double *stretch)
{
    const int x = sim_joint_q(s, 5), a = sim_joint_q(s, 6);
    double worst = 0.0, least = 0.0;
    for (int row = 0; row < s->path.rows; ++row) {
        const double t = s->path.t[row];
        worst = fmax(worst, fabs(sim_state(s, row, x) - sim_state(s, 0, x) -
                                 2.0 * (cos(1000.0 * t) - 1.0)) / 2.0);
        worst = fmax(worst, fabs(sim_state(s, row, a) - sim_state(s, 0, a) -
                                 0.1 * (cos(sqrt(1e5) * t) - 1.0)) / 0.1);
        least = fmin(least, sim_state(s, row, x) - sim_state(s, 0, x));
    }
    if (stretch != NULL)
        *stretch = least;
    return worst;
}

/* SFOSUB (Force_Scalar_TwoBody FORCE and TORQUE): check passes; a line spring
 * on a slider and a twist spring on a hinge oscillate as spring-masses do,
 * x - x0 = 2 (cos 1000 t - 1), a - a0 = 0.1 (cos 316.23 t - 1) (tp_scalar.xml). */
static void scalar_routines_act_along_the_line_and_about_z(void **state)
{
    (void)state;
    expect("scalar", 0, NEEDLES("Force_Scalar_TwoBody 1 (LINE_SPRING in libtp_scalar.so)",
                                "Force_Scalar_TwoBody 2 (TWIST_SPRING in libtp_scalar.so)",
                                "2 passed, 0 failed"),
           NEEDLES("FAIL", "never writes"));
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    sim s;
    sim_run(&s, USER_LIBRARIES_DIR "/tp_scalar.xml", HX_METHOD_DOPRI5, 1e-11, 0.01, 0.001);
    const double worst = off_the_springs_closed_forms(&s, NULL);
    printf("  SFOSUB line and twist springs over 0.01 s: off the closed form by %.2g of the"
           " amplitude\n", worst);
    assert_true(s.path.rows > 5 && worst < 1e-6);
    sim_close(&s);
}

/* REQSUB, VARSUB, DIFSUB, MOTSUB and a VFOSUB on one body (tp_routines.c):
 * check passes each; the run follows the closed forms of tp_routines.xml. */
static void routines_that_are_not_forces_are_checked_and_run(void **state)
{
    (void)state;
    expect("routines", 0,
           NEEDLES("Force_Vector_OneBody 3 (ANCHOR in libtp_routines.so)",
                   "Motion_Joint 6 (SWING in libtp_routines.so)",
                   "SWING rate (iord 1) against differences in time",
                   "Control_Diff 7 (LAG in libtp_routines.so)",
                   "declared dependencies: AZ(30,12) DIF(7)",
                   "Reference_Variable 9 (SPEED in libtp_routines.so)",
                   "Post_Request 8 (REPORT in libtp_routines.so)", "5 passed, 0 failed"),
           NEEDLES("FAIL", "never writes"));
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    char csv[512];
    snprintf(csv, sizeof csv, "%s/routines.csv", test_temp_dir());
    const char *args[] = {"--end", "0.05", "--rtol", "1e-10", "--atol", "1e-12",
                          "--output-interval", "0.001", "--quiet", NULL};
    assert_int_equal(sim_run_csv(USER_LIBRARIES_DIR "/tp_routines.xml", csv, args), 0);
    static const char *const names[] = {"t", "body2.x", "variable9", "joint6.q",
                                        "motion6.error", "diff7", "request8.1", "request8.2",
                                        "request8.3", "request8.4", "joint6.u"};
    int col[11];
    for (int k = 0; k < 11; ++k)
        assert_true((col[k] = csv_column(csv, names[k])) >= 0);
    csv_table tb;
    csv_read(csv, &tb);
    double worst[5] = {0}, report = 0.0;
    const double a = 0.2, w = 50.0, tau = 0.01, r = w * tau;
    for (int row = 0; row < tb.rows; ++row) {
        const double t = csv_at(&tb, row, col[0]);
        const double lag = a / (1.0 + r * r) * (sin(w * t) - r * cos(w * t) + r * exp(-t / tau));
        worst[0] = fmax(worst[0], fabs(csv_at(&tb, row, col[1]) - 10.0 - 2.0 * cos(1000.0 * t)) / 2.0);
        worst[1] = fmax(worst[1], fabs(csv_at(&tb, row, col[2]) + 2000.0 * sin(1000.0 * t)) / 2000.0);
        worst[2] = fmax(worst[2], fabs(csv_at(&tb, row, col[3]) - a * sin(w * t)) / a);
        /* the rate from iord 1, from the start on */
        worst[2] = fmax(worst[2], fabs(csv_at(&tb, row, col[10]) - a * w * cos(w * t)) / (a * w));
        worst[3] = fmax(worst[3], fabs(csv_at(&tb, row, col[4])) / a);
        worst[4] = fmax(worst[4], fabs(csv_at(&tb, row, col[5]) - lag) / a);
        /* the request reports the states the run has */
        const double z = csv_at(&tb, row, col[5]), q = csv_at(&tb, row, col[3]);
        report = fmax(report, fabs(csv_at(&tb, row, col[6]) - z) / a);
        report = fmax(report, fabs(csv_at(&tb, row, col[7]) - (q - z) / tau) * tau / a);
        report = fmax(report, fabs(csv_at(&tb, row, col[8]) - q) / a);
        report = fmax(report, fabs(csv_at(&tb, row, col[9]) - csv_at(&tb, row, col[1])) / 2.0);
    }
    printf("  tp_routines over 0.05 s, off the closed forms (of each amplitude): anchored body"
           " %.2g, its speed variable %.2g, driven joint %.2g (motion error %.2g), lag %.2g;"
           " request off the run's own values %.2g\n", worst[0], worst[1], worst[2], worst[3],
           worst[4], report);
    assert_true(tb.rows > 40);
    for (int k = 0; k < 5; ++k)
        assert_true(worst[k] < 1e-7);
    assert_true(report < 1e-9);
    csv_free(&tb);
    /* bench measures what its cost split can replay and says what it cannot */
    assert_int_equal(harness_on("bench", USER_LIBRARIES_DIR "/tp_routines.xml", "--quick", output,
                                sizeof output), 0);
    assert_contains(output, "cost per call and right-hand side split: not measured: Motion_Joint 6"
                    " (SWING): bench splits the cost of force elements, couplers and state"
                    " equations in the classic form only", "stability at t = 0");
}

/* tp_routines.xml with `from` replaced by `to`, in the temporary folder:
 * run's set-up refuses it with a message holding `needle`. */
/* tp_BASE.xml with each of the n texts from[k] replaced by to[k], written as
 * `name` in the temporary folder: its path. */
static const char *model_variant(const char *base, const char *name, int n,
                                 const char *const *from, const char *const *to)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/tp_%s.xml", USER_LIBRARIES_DIR, base);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    static char text[16384], changed[16384];
    const size_t size = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[size] = '\0';
    for (int k = 0; k < n; ++k) {
        const char *at = strstr(text, from[k]);
        if (at == NULL)
            fail_msg("'%s' is not in %s", from[k], path);
        snprintf(changed, sizeof changed, "%.*s%s%s", (int)(at - text), text, to[k],
                 at + strlen(from[k]));
        memcpy(text, changed, strlen(changed) + 1);
    }
    return test_write_file(name, text);
}

static void run_refuses_variant(const char *name, const char *from, const char *to,
                                const char *needle)
{
    const char *path = model_variant("routines", name, 1, &from, &to);
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, path, NULL, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_dynamics d;
    const int status = hx_dynamics_init(&d, &s, &msg);
    hx_dynamics_free(&d);
    hx_session_close(&s);
    assert_int_equal(status, -1);
    assert_non_null(strstr(msg.text, needle));
}

/* SWING as a velocity (val_type V, from ic_disp 0.05) and as an acceleration
 * (A, from ic_vel 0.3 and, ic_disp not written, the model's angle 0.1):
 *   V: q = 0.05 + (a / w) (1 - cos w t), its rate error column zero;
 *   A: q = 0.1 + (0.3 + a / w) t - (a / w^2) sin w t, and no error column. */
static void velocity_and_acceleration_motions_follow_their_integrals(void **state)
{
    (void)state;
    const double a = 0.2, w = 50.0, c = cos(0.1), sn = sin(0.1);
    char turned[256];
    snprintf(turned, sizeof turned, "<Reference_Marker id=\"30\" body_id=\"3\" a00=\"%.17g\""
             " a01=\"%.17g\" a10=\"%.17g\" a11=\"%.17g\"/>", c, -sn, sn, c);
    const char *const from[3] = {"val_type=\"D\"", "ic_disp=\"0\" ic_vel=\"0\"",
                                 "<Reference_Marker id=\"30\" body_id=\"3\"/>"};
    const char *const to_v[2] = {"val_type=\"V\"", "ic_disp=\"0.05\""};
    const char *const to_a[3] = {"val_type=\"A\"", "ic_vel=\"0.3\"", turned};
    const char *const args[] = {"--end", "0.05", "--rtol", "1e-10", "--atol", "1e-12",
                                "--output-interval", "0.001", "--quiet", NULL};
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    double worst[3] = {0};
    for (int variant = 0; variant < 2; ++variant) {
        const char *path = variant == 0 ? model_variant("routines", "motion_v.xml", 2, from, to_v)
                                        : model_variant("routines", "motion_a.xml", 3, from, to_a);
        char csv[512];
        snprintf(csv, sizeof csv, "%s/motion_%c.csv", test_temp_dir(), "va"[variant]);
        assert_int_equal(sim_run_csv(path, csv, args), 0);
        const int t_col = csv_column(csv, "t"), q_col = csv_column(csv, "joint6.q");
        const int error_col = csv_column(csv, "motion6.error");
        assert_true(t_col >= 0 && q_col >= 0);
        assert_true(variant == 0 ? error_col >= 0 : error_col < 0);
        csv_table tb;
        csv_read(csv, &tb);
        assert_true(tb.rows > 40);
        for (int row = 0; row < tb.rows; ++row) {
            const double t = csv_at(&tb, row, t_col), q = csv_at(&tb, row, q_col);
            const double expected = variant == 0 ? 0.05 + a / w * (1.0 - cos(w * t))
                                                 : 0.1 + (0.3 + a / w) * t - a / (w * w) * sin(w * t);
            worst[variant] = fmax(worst[variant], fabs(q - expected) / a);
            if (variant == 0)
                worst[2] = fmax(worst[2], fabs(csv_at(&tb, row, error_col)) / a);
        }
        csv_free(&tb);
    }
    printf("  SWING as a velocity: joint off its integral by %.2g of the amplitude (rate error"
           " %.2g); as an acceleration: %.2g\n", worst[0], worst[2], worst[1]);
    for (int k = 0; k < 3; ++k)
        assert_true(worst[k] < 1e-7);
}

/* Queries a routine may not make, or of what does not exist, are named by
 * check; a NaN from DIFSUB or MOTSUB stops run, naming the routine and the
 * time (tp_routines_bad.c). */
static void bad_queries_and_values_of_the_routines_are_named(void **state)
{
    (void)state;
    expect("routines_bad", 1,
           NEEDLES("Motion_Joint 6: FAIL: asks queries the host refuses: DX(30,12)",
                   "Motion_Joint 6 (PEEKING_SWING) asked c_sysfnc DX(30,12) at t = 0, which the"
                   " host refuses: this routine may not call c_sysary or c_sysfnc",
                   "Control_Diff 7: FAIL: output 1 is nan at t = 0.0909090909",
                   "Control_Diff 7: FAIL: asks queries the host refuses: DIF(99) at t = 0,"
                   " DIF(7,7) at t = 0", "0 passed, 2 failed"),
           NULL);
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    const char *path = USER_LIBRARIES_DIR "/tp_routines_bad.xml";
    assert_int_not_equal(harness_on("run", path, "--end 0.02 --quiet", output, sizeof output), 0);
    assert_contains(output, "Control_Diff 7 (LOST_LAG) returned a non-finite value at t = 0.005");
    const char *const from[2] = {"USER(0.2, 50, 30, 12, 0)", "USER(99, 0.01, 0.005)"};
    const char *const to[2] = {"USER(0.2, 50, 30, 12, 0.002)", "USER(99, 0.01, 0)"};
    path = model_variant("routines_bad", "nan_motion.xml", 2, from, to);
    assert_int_not_equal(harness_on("run", path, "--end 0.02 --quiet", output, sizeof output), 0);
    assert_contains(output, "Motion_Joint 6 (PEEKING_SWING) returned a non-finite acceleration"
                    " (iord 2) at t = 0.002");
}

/* What run does not integrate is refused, naming the element. */
static void run_refuses_an_implicit_diff_and_a_motion_on_a_coupled_joint(void **state)
{
    (void)state;
    run_refuses_variant("implicit.xml", "is_implicit=\"FALSE\"", "is_implicit=\"TRUE\"",
                        "Control_Diff 7: is_implicit=\"TRUE\" with DIFSUB: the harness runs an"
                        " implicit Control_Diff by expression only");
    run_refuses_variant("coupled.xml", "<Force_Vector_OneBody",
                        "<Reference_Marker id=\"50\" body_id=\"5\"/>"
                        "<Body_Rigid id=\"5\" cg_id=\"50\" mass=\"1\" inertia_xx=\"1\""
                        " inertia_yy=\"1\" inertia_zz=\"1\"/><Reference_Marker id=\"13\" body_id=\"1\"/>"
                        "<Constraint_Joint id=\"9\" type=\"REVOLUTE\" i_marker_id=\"50\""
                        " j_marker_id=\"13\"/><Constraint_Coupler id=\"1\" joint1_id=\"6\""
                        " freedom_1=\"R\" joint2_id=\"9\" freedom_2=\"R\" coefficients=\"1, -2\"/>"
                        "<Force_Vector_OneBody",
                        "Motion_Joint 6 drives joint 6, which Constraint_Coupler 1 couples");
}

/* C ported to Linux through a port header (tp_mdi_names.h: sfosub_, reqsub_),
 * reading its spring from a relative path: the model's folder is the working
 * folder, as the solver's; the body oscillates as x - 10 = 2 cos(1000 t). */
static void ported_c_names_and_the_working_folder(void **state)
{
    (void)state;
    expect("mdi", 0, NEEDLES("Force_Scalar_TwoBody 1 (sfosub_ in libtp_mdi.so)",
                             "Post_Request 2 (reqsub_ in libtp_mdi.so)", "outputs at t = 0: 12 1000 10",
                             "2 passed, 0 failed"),
           NEEDLES("FAIL", "cannot read"));
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    char csv[512];
    snprintf(csv, sizeof csv, "%s/mdi.csv", test_temp_dir());
    const char *args[] = {"--end", "0.01", "--rtol", "1e-11", "--atol", "1e-12",
                          "--output-interval", "0.0005", "--quiet", NULL};
    assert_int_equal(sim_run_csv(USER_LIBRARIES_DIR "/tp_mdi.xml", csv, args), 0);
    const int t = csv_column(csv, "t"), x = csv_column(csv, "joint5.q"),
              length = csv_column(csv, "request2.1"), k = csv_column(csv, "request2.2");
    assert_true(t >= 0 && x >= 0 && length >= 0 && k >= 0);
    csv_table tb;
    csv_read(csv, &tb);
    double worst = 0.0;
    for (int row = 0; row < tb.rows; ++row) {
        const double time = csv_at(&tb, row, t);
        worst = fmax(worst, fabs(csv_at(&tb, row, x) - csv_at(&tb, 0, x) -
                                 2.0 * (cos(1000.0 * time) - 1.0)) / 2.0);
        assert_true(csv_at(&tb, row, k) == 1000.0);
        assert_true(fabs(csv_at(&tb, row, length) - 10.0 - 2.0 * cos(1000.0 * time)) < 1e-6);
    }
    printf("  tp_mdi over 0.01 s: off x - 10 = 2 cos(1000 t) by %.2g of the amplitude\n", worst);
    assert_true(tb.rows > 15 && worst < 1e-6);
    csv_free(&tb);
}

/* Each routine's planted fault is named (tp_routines_faults.c): MOTSUB's
 * acceleration, DIFSUB's read outside its declared queries, VARSUB's hidden
 * state; REQSUB's unwritten values are a note. */
static void faults_of_the_routines_are_named(void **state)
{
    (void)state;
    expect("routines_faults", 1,
           NEEDLES("BAD_SWING rate (iord 1) against differences in time of its value (iord 0)"
                   " at 11 times: worst",
                   "BAD_SWING acceleration (iord 2) against differences in time of its rate"
                   " (iord 1)",
                   "Control_Diff 7: FAIL: the output depends on body 3's rotation about z, which"
                   " no declared query (none) reaches",
                   "Control_Diff 7: FAIL: the output depends on Control_Diff 7's state, which no"
                   " declared query (none) reaches",
                   "Reference_Variable 9: history audit: FAIL: a hidden state",
                   "note: SHORT_REPORT never writes outputs 6, 7, 8",
                   "check: 5 elements: 2 passed, 3 failed"),
           NEEDLES("Post_Request 8: FAIL"));
    /* each on its own line: the rate passes, the acceleration fails */
    static const char *const lines[2][2] = {{"BAD_SWING rate (iord 1)", ": pass"},
                                           {"BAD_SWING acceleration (iord 2)", ": FAIL"}};
    for (int k = 0; k < 2; ++k) {
        const char *at = strstr(output, lines[k][0]);
        assert_non_null(at);
        const char *end = strchr(at, '\n');
        assert_non_null(end);
        assert_memory_equal(end - strlen(lines[k][1]), lines[k][1], strlen(lines[k][1]));
    }
}

/* Adams' C-style form (tp_records.c): bound by the mixed-case default names
 * when the library has no classic ones, given records whose fields the
 * routines check (a wrong one returns NaN); the run follows the closed forms. */
static void the_c_style_record_form_binds_and_runs(void **state)
{
    (void)state;
    expect("records", 0,
           NEEDLES("Force_Vector_TwoBody 1 (Gfosub in libtp_records.so)",
                   "Force_Scalar_TwoBody 2 (Sfosub in libtp_records.so)",
                   "Motion_Joint 6 (Motsub in libtp_records.so)",
                   "Control_Diff 7 (Difsub in libtp_records.so)",
                   "Reference_Variable 9 (Varsub in libtp_records.so)",
                   "Post_Request 8 (Reqsub in libtp_records.so)",
                   "Force_Vector_OneBody 11 (Vfosub in libtp_records.so)",
                   "Force_Field 12 (Fiesub in libtp_records.so)",
                   "Constraint_Coupler 1 (Cousub Couxx Couxx2 in libtp_records.so)",
                   "9 passed, 0 failed"),
           NEEDLES("FAIL", "never writes", "non-finite"));
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    char csv[512];
    snprintf(csv, sizeof csv, "%s/records.csv", test_temp_dir());
    const char *args[] = {"--end", "0.02", "--rtol", "1e-10", "--atol", "1e-12",
                          "--output-interval", "0.001", "--quiet", NULL};
    assert_int_equal(sim_run_csv(USER_LIBRARIES_DIR "/tp_records.xml", csv, args), 0);
    static const char *const names[] = {"t", "body2.x", "joint5.q", "variable9", "joint6.q",
                                        "diff7", "request8.1", "request8.2", "request8.3",
                                        "body5.x", "body6.x", "joint7.q", "joint8.q"};
    int col[13];
    for (int k = 0; k < 13; ++k)
        assert_true((col[k] = csv_column(csv, names[k])) >= 0);
    csv_table tb;
    csv_read(csv, &tb);
    double worst = 0.0;
    const double a = 0.2, w = 50.0, tau = 0.01, r = w * tau;
    for (int row = 0; row < tb.rows; ++row) {
        const double t = csv_at(&tb, row, col[0]);
        const double lag = a / (1.0 + r * r) * (sin(w * t) - r * cos(w * t) + r * exp(-t / tau));
        const double errors[12] = {
            (csv_at(&tb, row, col[1]) - 10.0 - 2.0 * cos(1000.0 * t)) / 2.0,
            (csv_at(&tb, row, col[2]) - csv_at(&tb, 0, col[2]) - 2.0 * (cos(1000.0 * t) - 1.0)) / 2.0,
            (csv_at(&tb, row, col[3]) + 2000.0 * sin(1000.0 * t)) / 2000.0,
            (csv_at(&tb, row, col[4]) - a * sin(w * t)) / a,
            (csv_at(&tb, row, col[5]) - lag) / a,
            (csv_at(&tb, row, col[6]) - csv_at(&tb, row, col[5])) / a,
            (csv_at(&tb, row, col[7]) - csv_at(&tb, row, col[4])) / a,
            (csv_at(&tb, row, col[8]) - csv_at(&tb, row, col[1])) / 2.0,
            (csv_at(&tb, row, col[9]) - 10.0 - 2.0 * cos(1000.0 * t)) / 2.0,
            (csv_at(&tb, row, col[10]) - 10.0 - 2.0 * cos(1000.0 * t)) / 2.0,
            /* the coupled joints turn steadily, q7 + 2 q8 = 0 */
            (csv_at(&tb, row, col[11]) - 2.0 * t) / 0.04,
            (csv_at(&tb, row, col[12]) + t) / 0.02};
        for (int k = 0; k < 12; ++k)
            worst = fmax(worst, fabs(errors[k]));
    }
    printf("  tp_records over 0.02 s: off the closed forms and the run's own values by %.2g of"
           " each amplitude\n", worst);
    assert_true(tb.rows > 15 && worst < 1e-7);
    csv_free(&tb);
}

/* SFOSUB laws read from the model's curves with c_akispl and c_cubspl: check
 * passes; the curves are straight lines (the spring's continued linearly
 * beyond its points), so the bodies oscillate as tp_scalar's do:
 * x - x0 = 2 (cos 1000 t - 1), a - a0 = 0.1 (cos 316.23 t - 1) (tp_spline.xml). */
static void spline_laws_are_answered_from_the_models_curves(void **state)
{
    (void)state;
    expect("spline", 0, NEEDLES("Force_Scalar_TwoBody 1 (SPLINE_SPRING in libtp_spline.so)",
                                "Force_Scalar_TwoBody 2 (SPLINE_TWIST in libtp_spline.so)",
                                "2 passed, 0 failed"),
           NEEDLES("FAIL", "host:", "ERRMES"));
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    sim s;
    sim_run(&s, USER_LIBRARIES_DIR "/tp_spline.xml", HX_METHOD_DOPRI5, 1e-11, 0.01, 0.001);
    double stretch;
    const double worst = off_the_springs_closed_forms(&s, &stretch);
    printf("  AKISPL and CUBSPL laws over 0.01 s: off the closed form by %.2g of the amplitude;"
           " the spring's stretch reached %.3g mm (its points end at -1)\n", worst,
           2.0 + stretch);
    assert_true(s.path.rows > 5 && worst < 1e-6);
    assert_true(2.0 + stretch < -1.5); /* well beyond the points: linear_extrap */
    sim_close(&s);
}

/* The same library asking for a spline the model does not have: the host
 * answers errflg and names the id; the library stops the run. */
static void an_unknown_spline_is_named(void **state)
{
    (void)state;
    char path[1024], *xml = NULL;
    snprintf(path, sizeof path, "%s/tp_spline.xml", USER_LIBRARIES_DIR);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t size = 0;
    assert_true(getdelim(&xml, &size, '\0', f) > 0);
    fclose(f);
    char *spring = strstr(xml, "USER(20, 10, 101,"); /* spline 999 for the spring */
    assert_non_null(spring);
    memcpy(strstr(spring, "101"), "999", 3);
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1); /* the model is elsewhere */
    const int status = check_model(test_write_file("tp_spline_missing.xml", xml), output,
                                   sizeof output);
    free(xml);
    assert_int_equal(status, 1);
    assert_contains(output, "host: Force_Scalar_TwoBody 1 (SPLINE_SPRING) called c_akispl with"
                    " id 999, which names no Reference_Spline of the model; it answered"
                    " errflg = 1", "the spline utility set errflg");
}

/* run calls the library in its own process: a crash there is reported by the
 * signal handler, written with write(2) alone, naming the element, the entry,
 * the signal and the time, and the harness exits with 128 + the signal. */
static void run_reports_a_crash_in_the_users_code(void **state)
{
    (void)state;
    setenv("ASAN_OPTIONS", "handle_segv=0:detect_leaks=0", 1);
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    char command[2048];
    snprintf(command, sizeof command, "'%s' run '%s/tp_crash.xml' --end 0.01 2>&1", HARNESS_EXE,
             USER_LIBRARIES_DIR);
    FILE *p = popen(command, "r");
    assert_non_null(p);
    const size_t n = fread(output, 1, sizeof output - 1, p);
    output[n] = '\0';
    const int status = pclose(p);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 128 + 11);
    if (strstr(output, "usrsub-harness: Force_Vector_TwoBody 1 crashed in GFOSUB with signal 11"
                       " (segmentation fault) at t = 0.") == NULL)
        fail_msg("no crash report in:\n%s", output);
}

/* c_sysary ACC, once refused, is answered through the algebraic loop
 * (docs/interface.md §5.1): its six values declared, used and judged. */
static void an_acceleration_query_is_answered(void **state)
{
    (void)state;
    expect("bad_query", 0, NEEDLES("ACC(20,10,10,10) uses 6 of 6", "1 passed, 0 failed"),
           NEEDLES("refuses", "FAIL"));
}

static void a_wrong_couxx_is_reported_as_couxx(void **state)
{
    (void)state;
    expect("coupler_wrong_couxx", 1,
           NEEDLES("COUXX against central differences of COUSUB", "entry 2 (dphi/dM2)",
                   "COUXX2 not judged"), NULL);
    expect("coupler_consistent_wrong", 1,
           NEEDLES("COUXX against central differences of COUSUB", "entry 2 (dphi/dM2)"), NULL);
}

static void a_wrong_couxx2_is_named_by_row_and_column(void **state)
{
    (void)state;
    expect("coupler_wrong_couxx2", 1,
           NEEDLES("row 2, column 2 (d2phi/dM2 dM2)", "FAIL"), NULL);
    const char *couxx = strstr(output, "COUXX against central differences of COUSUB");
    assert_non_null(couxx);
    assert_true(strstr(couxx, ": pass") < strstr(couxx, "\n")); /* COUXX itself passes */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(correct_libraries_pass),
        cmocka_unit_test(a_hidden_state_is_named),
        cmocka_unit_test(a_linux_entry_name_binds),
        cmocka_unit_test(a_cache_refreshed_when_time_advances_fails),
        cmocka_unit_test(a_cache_across_time_steps_fails),
        cmocka_unit_test(a_read_at_a_later_time_is_caught),
        cmocka_unit_test(reads_noted_in_the_history_audit_come_back),
        cmocka_unit_test(a_wrong_field_partial_is_named_by_row_and_column),
        cmocka_unit_test(a_crash_is_reported_and_survived),
        cmocka_unit_test(an_acceleration_query_is_answered),
        cmocka_unit_test(run_reports_a_crash_in_the_users_code),
        cmocka_unit_test(routines_that_are_not_forces_are_checked_and_run),
        cmocka_unit_test(faults_of_the_routines_are_named),
        cmocka_unit_test(ported_c_names_and_the_working_folder),
        cmocka_unit_test(velocity_and_acceleration_motions_follow_their_integrals),
        cmocka_unit_test(bad_queries_and_values_of_the_routines_are_named),
        cmocka_unit_test(run_refuses_an_implicit_diff_and_a_motion_on_a_coupled_joint),
        cmocka_unit_test(the_c_style_record_form_binds_and_runs),
        cmocka_unit_test(libraries_using_the_utilities_pass),
        cmocka_unit_test(a_fortran_library_loads_and_passes),
        cmocka_unit_test(a_utility_not_offered_is_named),
        cmocka_unit_test(a_dependency_pass_on_zeros_is_a_note_not_a_fault),
        cmocka_unit_test(routines_are_judged_on_the_values_they_return),
        cmocka_unit_test(host_habits_are_those_of_a_solver),
        cmocka_unit_test(vector_routines_run_as_the_gfosub_of_their_law),
        cmocka_unit_test(scalar_routines_act_along_the_line_and_about_z),
        cmocka_unit_test(spline_laws_are_answered_from_the_models_curves),
        cmocka_unit_test(an_unknown_spline_is_named),
        cmocka_unit_test(a_wrong_couxx_is_reported_as_couxx),
        cmocka_unit_test(a_wrong_couxx2_is_named_by_row_and_column),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
