/*
 * What the commands say, run in-process with stdout and stderr captured:
 * a bad option value named with the value (run, bench, rig, check); a
 * missing library with MS_USERDLL_DIR (and that it is not set); run's
 * default integrator; output folders created; an output path that cannot be
 * created refused at once with the reason, before any long work.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cmd/commands.h"
#include "test_support.h"

#define MODEL EXAMPLES_DIR "/damped_oscillator.xml"

/* ---- option values ---------------------------------------------------------------------- */

static void bad_option_values_are_named(void **state)
{
    (void)state;
    test_captured c;
    test_capture(hx_command_run, (const char *const[]){"run", MODEL, "--end", "soon", NULL}, &c);
    assert_int_equal(c.status, 2);
    assert_contains(c.err, "usrsub-harness run", "--end 'soon'", "not a number");

    test_capture(hx_command_bench, (const char *const[]){"bench", MODEL, "--repeats", "0", NULL}, &c);
    assert_int_equal(c.status, 2);
    assert_contains(c.err, "usrsub-harness bench", "--repeats '0'", "whole number of at least 1");

    test_capture(hx_command_rig, (const char *const[]){"rig", MODEL, "--element", "1", "--end", "1",
                                                     "--step", "-0.5", "--circle", "1,1", NULL}, &c);
    assert_int_equal(c.status, 2);
    assert_contains(c.err, "usrsub-harness rig", "--step -0.5", "must be above zero");

    test_capture(hx_command_check, (const char *const[]){"check", MODEL, "--timeout", "never", NULL}, &c);
    assert_int_equal(c.status, 2);
    assert_contains(c.err, "usrsub-harness check", "--timeout 'never'", "not a number");
}

/* ---- the library's folder ------------------------------------------------------------------- */

static void a_missing_library_mentions_ms_userdll_dir(void **state)
{
    (void)state;
    const char *model = test_write_file("no_library.xml",
        "<MotionSolve><Model>\n"
        "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
        "<Force_Field id=\"5\" i_marker_id=\"20\" j_marker_id=\"10\" usrsub_param_string=\"USER(1)\""
        " usrsub_dll_name=\"libnothere.so\"/>\n"
        "</Model></MotionSolve>\n");
    const char *was = getenv("MS_USERDLL_DIR");
    char *saved = was != NULL ? strdup(was) : NULL;
    test_captured c;
    unsetenv("MS_USERDLL_DIR");
    test_capture(hx_command_check, (const char *const[]){"check", model, NULL}, &c);
    assert_int_equal(c.status, 1);
    assert_contains(c.err, "libnothere.so", "not found", test_temp_dir(), "MS_USERDLL_DIR is not set");

    setenv("MS_USERDLL_DIR", "/opt/nowhere", 1);
    test_capture(hx_command_check, (const char *const[]){"check", model, NULL}, &c);
    assert_int_equal(c.status, 1);
    assert_contains(c.err, "libnothere.so", "not found", "MS_USERDLL_DIR", "/opt/nowhere");
    assert_null(strstr(c.err, "not set"));

    if (saved != NULL)
        setenv("MS_USERDLL_DIR", saved, 1);
    else
        unsetenv("MS_USERDLL_DIR");
    free(saved);
}

/* ---- run ----------------------------------------------------------------------------------- */

static void run_defaults_to_dopri5(void **state)
{
    (void)state;
    test_captured c;
    test_capture(hx_command_run, (const char *const[]){"run", MODEL, "--end", "0.1", NULL}, &c);
    assert_int_equal(c.status, 0);
    assert_contains(c.out, "with dopri5", "t = 0.1");
}

static void run_creates_the_output_folders(void **state)
{
    (void)state;
    const char *csv = test_temp_path("outputs/sub/x.csv");
    struct stat st;
    assert_int_not_equal(stat(test_temp_path("outputs"), &st), 0);
    test_captured c;
    test_capture(hx_command_run, (const char *const[]){"run", MODEL, "--end", "0.01", "--out", csv, NULL},
                &c);
    assert_int_equal(c.status, 0);
    assert_int_equal(stat(test_temp_path("outputs/sub"), &st), 0);
    assert_true(S_ISDIR(st.st_mode));
    assert_int_equal(stat(csv, &st), 0);
    assert_true(st.st_size > 0);
}

static void an_output_that_cannot_be_created_fails_at_once(void **state)
{
    (void)state;
    test_captured c;
    /* under a regular file */
    const char *file = test_write_file("a_file", "not a folder\n");
    char under_file[600];
    snprintf(under_file, sizeof under_file, "%s/sub/x.csv", file);
    test_capture(hx_command_run, (const char *const[]){"run", MODEL, "--end", "1", "--out", under_file,
                                                     NULL}, &c);
    assert_int_equal(c.status, 1);
    assert_contains(c.err, "usrsub-harness run", "cannot create the folder", file);
    assert_null(strstr(c.out, "run:")); /* nothing integrated */

    /* a folder the system refuses: the reason is strerror's */
    test_capture(hx_command_run, (const char *const[]){"run", MODEL, "--end", "1", "--out",
                                                     "/proc/nonexistent/x.csv", NULL}, &c);
    assert_int_equal(c.status, 1);
    assert_contains(c.err, "/proc/nonexistent", strerror(ENOENT));
    assert_null(strstr(c.out, "run:"));

    test_capture(hx_command_rig, (const char *const[]){"rig", EXAMPLES_DIR "/bushing_coupling.xml",
                                                     "--element", "1", "--circle", "5,6.2832", "--end",
                                                     "1", "--step", "0.005", "--out",
                                                     "/proc/nonexistent/rig.csv", NULL}, &c);
    assert_int_equal(c.status, 1);
    assert_contains(c.err, "usrsub-harness rig", "/proc/nonexistent", strerror(ENOENT));
    assert_null(strstr(c.out, "rig:"));

    /* a plot prefix too long for the names the rig adds to it: refused, not cut */
    char prefix[4200];
    memset(prefix, 'p', sizeof prefix - 1);
    prefix[sizeof prefix - 1] = '\0';
    test_capture(hx_command_rig, (const char *const[]){"rig", EXAMPLES_DIR "/bushing_coupling.xml",
                                                     "--element", "1", "--circle", "5,6.2832", "--end",
                                                     "1", "--step", "0.005", "--plot", prefix, NULL},
                &c);
    assert_int_equal(c.status, 2);
    assert_contains(c.err, "usrsub-harness rig", "--plot pppp", "the path is too long");
    assert_null(strstr(c.out, "rig:"));
}

static void bench_refuses_its_output_before_the_sweep(void **state)
{
    (void)state;
    test_captured c;
    test_capture(hx_command_bench, (const char *const[]){"bench", MODEL, "--work-precision", "--out",
                                                       "/proc/nonexistent/wp", NULL}, &c);
    assert_int_equal(c.status, 1);
    assert_contains(c.err, "usrsub-harness bench", "/proc/nonexistent", strerror(ENOENT));
    /* refused before any work: the costs (measured before the sweep) and the sweep's
     * table were not printed */
    assert_null(strstr(c.out, "cost per call"));
    assert_null(strstr(c.out, "work-precision"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bad_option_values_are_named),
        cmocka_unit_test(a_missing_library_mentions_ms_userdll_dir),
        cmocka_unit_test(run_defaults_to_dopri5),
        cmocka_unit_test(run_creates_the_output_folders),
        cmocka_unit_test(an_output_that_cannot_be_created_fails_at_once),
        cmocka_unit_test(bench_refuses_its_output_before_the_sweep),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
