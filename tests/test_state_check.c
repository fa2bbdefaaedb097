/*
 * usrsub-harness check and rig on Force_StateEqn elements: the bundled
 * bushing passes (every partial routine against differences of YFOSUB, the
 * history audit, its set-up footprint); a YFOXX off by a factor fails and is
 * named; a library without partial routines is said to be differenced, not
 * failed; a YFOSUB that crashes is reported, and check survives it; the rig
 * writes the hysteresis loop of friction and its plots; bench times the
 * routines. The harness runs as a program, its output read back.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "session/session.h"
#include "sim_support.h"
#include "test_support.h"

static char output[65536];

/* usrsub-harness ARGS (a command line of the harness's own): its exit status,
 * its output (stdout and stderr) in output. */
static int harness(const char *args)
{
    /* the planted crash must reach check as a signal, not as a sanitizer's report */
    setenv("ASAN_OPTIONS", "handle_segv=0:detect_leaks=1", 1);
    char command[4096];
    snprintf(command, sizeof command, "'%s' %s 2>&1", HARNESS_EXE, args);
    FILE *pipe = popen(command, "r");
    assert_non_null(pipe);
    const size_t n = fread(output, 1, sizeof output - 1, pipe);
    output[n] = '\0';
    const int status = pclose(pipe);
    if (!WIFEXITED(status))
        fail_msg("%s ended without an exit status (%d):\n%s", command, status, output);
    return WEXITSTATUS(status);
}

static int check_model(const char *path)
{
    char args[2048];
    snprintf(args, sizeof args, "check '%s' --timeout 20", path);
    return harness(args);
}

/* The scaled state equation (tests/implicit_support/scaled_state.c) between
 * a body and ground, USER(user), on the library given. */
static const char *scaled_model(const char *name, const char *library, const char *user)
{
    char xml[8192];
    int n = snprintf(xml, sizeof xml,
                     "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
                     "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
                     "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\""
                     " inertia_yy=\"1\" inertia_zz=\"1\" v_ic_x=\"0.3\"/>\n"
                     "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.2\"/>\n"
                     "<Reference_Variable id=\"1\" expr=\"DX(20,10,10)\"/>\n"
                     "<Reference_Variable id=\"2\" expr=\"0\"/>\n"
                     "<Reference_Variable id=\"3\" expr=\"VX(20,10,10,10)\"/>\n"
                     "<Reference_Array id=\"30\" type=\"U\" num_element=\"7\">1 2 2 2 2 2 3"
                     "</Reference_Array>\n"
                     "<Reference_Array id=\"31\" type=\"X\" num_element=\"2\"/>\n"
                     "<Reference_Array id=\"32\" type=\"IC\" num_element=\"2\">0.01 -0.02"
                     "</Reference_Array>\n");
    snprintf(xml + n, sizeof xml - (size_t)n,
             "<Force_StateEqn id=\"4\" type=\"USERSUB\" x_array_id=\"31\" u_array_id=\"30\""
             " ic_array_id=\"32\" num_state=\"2\" i_marker_id=\"20\" j_floating_marker_id=\"10\""
             " ref_marker_id=\"10\" usrsub_param_string=\"USER(%s)\" usrsub_dll_name=\"%s\"/>\n"
             "</Model></MotionSolve>\n", user, library);
    return test_write_file(name, xml);
}

static void the_bundled_bushing_passes(void **state)
{
    (void)state;
    const char *model = EXAMPLES_DIR "/suspension_bushing.xml";
    assert_int_equal(check_model(model), 0);
    assert_contains(output, "Force_StateEqn 1 (YFOSUB YFOXX YFOXU YFOYX YFOYU in libusrsub.so)",
                    "YFOXX (d stated/d states) against central differences of YFOSUB",
                    "YFOXU (d stated/d inputs) against", "YFOYX (d outputs/d states) against");
    assert_contains(output, "YFOYU (d outputs/d inputs) against",
                    "history audit: at input A and t = ", "bit-identical outputs after 8 different"
                    " histories", "1 passed, 0 failed");
    assert_null(strstr(output, "FAIL"));
    /* the set-up footprint, where the C library's allocator is counted (its
     * size depends on what the process allocated before) */
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, model, NULL, &msg) != 0)
        fail_msg("%s", msg.text);
    if (s.bindings.items[0].setup_bytes >= 0) {
        const char *line = strstr(output, "set-up footprint: ");
        assert_non_null(line);
        assert_true(atol(line + 18) > 1000); /* a file read, splines built */
    }
    hx_session_close(&s);
}

static void a_wrong_yfoxx_is_named(void **state)
{
    (void)state;
    assert_int_equal(check_model(scaled_model("right.xml", SCALED_STATE_LIBRARY, "5, 2, 3, 1")), 0);
    assert_contains(output, "Force_StateEqn 4", "YFOXX (d stated/d states) against", "pass");
    assert_null(strstr(output, "FAIL"));
    assert_int_equal(check_model(scaled_model("wrong.xml", SCALED_STATE_LIBRARY, "5, 2, 3, 1.5")), 1);
    assert_contains(output, "YFOXX (d stated/d states) against central differences of YFOSUB:"
                    " worst relative error", "pxxmat[", "FAIL", "1 failed");
    /* the other three are right, and said so */
    assert_contains(output, "YFOXU (d stated/d inputs) against central differences of YFOSUB:");
    const char *yu = strstr(output, "YFOYU (d outputs/d inputs) against");
    assert_non_null(yu);
    assert_contains(yu, ": pass");
}

static void a_library_without_partials_is_said_not_failed(void **state)
{
    (void)state;
    assert_int_equal(check_model(scaled_model("plain.xml", PLAIN_STATE_LIBRARY, "5, 2, 3, 1")), 0);
    assert_contains(output, "YFOXX (not exported)",
                    "YFOXX (d stated/d states): not exported; the harness differences YFOSUB in"
                    " its place", "YFOYU (d outputs/d inputs): not exported", "1 passed");
}

static void a_crash_in_yfosub_is_reported(void **state)
{
    (void)state;
    assert_int_equal(check_model(scaled_model("crash.xml", SCALED_STATE_LIBRARY, "5, 2, 3, 1, 1")), 1);
    assert_contains(output, "Force_StateEqn 4: FAIL: crashed with signal 11", "in YFOSUB",
                    "iflag = 0", "input (", "1 crashed or hung");
}

static void the_rig_draws_the_friction_loop(void **state)
{
    (void)state;
    char args[4096], prefix[1024];
    snprintf(prefix, sizeof prefix, "%s/loop", test_temp_dir());
    snprintf(args, sizeof args, "rig '%s/suspension_bushing_rig.xml' --element 1 --line y,-1,-1"
             " --sine az,0.05,1 --end 2 --step 0.002 --plot '%s'", EXAMPLES_DIR, prefix);
    assert_int_equal(harness(args), 0);
    assert_contains(output, "rig: Force_StateEqn 1, deformation-controlled, 1000 steps",
                    "5 states integrated by bdf", "(YFOXX)", "work done on the element");
    /* a loop: the work over whole cycles is what friction took, positive */
    const char *work = strstr(output, "dissipated): ");
    assert_non_null(work);
    assert_true(atof(work + 13) > 100.0);
    char csv[1100];
    snprintf(csv, sizeof csv, "%s.csv", prefix);
    csv_table t;
    csv_read(csv, &t);
    assert_int_equal(t.rows, 1001);
    /* at az = 0 the torque has two values, one per direction of turning: their
     * difference is twice the friction torque, between mu_d and mu_s N r_B */
    double up = 0.0, down = 0.0;
    for (int r = 1; r < t.rows; ++r)
        if (csv_at(&t, r - 1, 6) < 0.0 && csv_at(&t, r, 6) >= 0.0 && csv_at(&t, r, 0) > 0.5)
            up = csv_at(&t, r, 18);
        else if (csv_at(&t, r - 1, 6) > 0.0 && csv_at(&t, r, 6) <= 0.0)
            down = csv_at(&t, r, 18);
    const double normal = fabs(csv_at(&t, t.rows - 1, 14)); /* Fy */
    printf("  friction loop at az = 0: Tz %.6g turning up, %.6g turning down; N = %.6g N\n",
           up, down, normal);
    assert_true(down - up > 2.0 * 0.25 * normal * 12.0 && down - up < 2.0 * 0.4 * normal * 12.0);
    csv_free(&t);
    if (system("command -v gnuplot >/dev/null 2>&1") == 0) {
        struct stat st;
        char png[1100];
        snprintf(png, sizeof png, "%s_force_deformation.png", prefix);
        assert_int_equal(stat(png, &st), 0);
        snprintf(png, sizeof png, "%s_states.png", prefix);
        assert_int_equal(stat(png, &st), 0);
    }
}

static void the_rig_refuses_what_it_cannot_drive(void **state)
{
    (void)state;
    char args[2048];
    snprintf(args, sizeof args, "rig '%s/suspension_bushing_rig.xml' --element 1 --force-sine"
             " fy,10,1 --end 1 --step 0.01", EXAMPLES_DIR);
    assert_int_equal(harness(args), 1);
    assert_contains(output, "Force_StateEqn 1", "deformation paths only");
    snprintf(args, sizeof args, "rig '%s/suspension_bushing_rig.xml' --element stateeqn:9"
             " --sine az,0.1,1 --end 1 --step 0.01", EXAMPLES_DIR);
    assert_int_equal(harness(args), 1);
    assert_contains(output, "the model has no Force_StateEqn 9");
    /* an id that a Force_Field and a Force_StateEqn both use */
    char xml[4096];
    snprintf(xml, sizeof xml,
             "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
             " inertia_zz=\"1\"/>\n<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "<Reference_String id=\"303\" string=\"%s/bushing_full.gbs\"/>\n"
             "<Force_Field id=\"4\" i_marker_id=\"20\" j_marker_id=\"10\""
             " usrsub_param_string=\"USER(1, 303)\" usrsub_dll_name=\"%s\"/>\n"
             "<Reference_Array id=\"31\" type=\"X\" num_element=\"2\"/>\n"
             "<Force_StateEqn id=\"4\" type=\"USERSUB\" x_array_id=\"31\" num_state=\"2\""
             " i_marker_id=\"20\" j_floating_marker_id=\"10\" ref_marker_id=\"10\""
             " usrsub_param_string=\"USER(5, 2, 3, 1)\" usrsub_dll_name=\"%s\"/>\n"
             "</Model></MotionSolve>\n", EXAMPLES_DIR, USRSUB_LIBRARY, SCALED_STATE_LIBRARY);
    snprintf(args, sizeof args, "rig '%s' --element 4 --sine x,0.1,1 --end 1 --step 0.01",
             test_write_file("both.xml", xml));
    assert_int_equal(harness(args), 1);
    assert_contains(output, "element 4 is both a Force_StateEqn and a force element",
                    "stateeqn:4", "field:4");
    snprintf(args, sizeof args, "rig '%s/both.xml' --element stateeqn:4 --sine x,0.1,1 --end 1"
             " --step 0.01", test_temp_dir());
    assert_int_equal(harness(args), 0);
    assert_contains(output, "rig: Force_StateEqn 4", "2 states integrated by bdf");
}

/* bench times YFOSUB and each partial routine it exports, and the
 * right-hand side against the one entry it calls (its stand-in replays the
 * rates and outputs) */
static void bench_times_the_state_equation(void **state)
{
    (void)state;
    assert_int_equal(harness("bench '" EXAMPLES_DIR "/suspension_bushing.xml' --repeats 3"), 0);
    assert_contains(output, "Force_StateEqn 1           YFOSUB", "Force_StateEqn 1           YFOXX",
                    "Force_StateEqn 1           YFOYU", "the 1 user entry calls in it");
    assert_int_equal(harness("bench '" EXAMPLES_DIR "/suspension_bushing.xml' --work-precision"
                             " --quick --end 0.01"), 0);
    assert_contains(output, "bdf", "dopri5");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_bundled_bushing_passes),
        cmocka_unit_test(a_wrong_yfoxx_is_named),
        cmocka_unit_test(a_library_without_partials_is_said_not_failed),
        cmocka_unit_test(a_crash_in_yfosub_is_reported),
        cmocka_unit_test(the_rig_draws_the_friction_loop),
        cmocka_unit_test(the_rig_refuses_what_it_cannot_drive),
        cmocka_unit_test(bench_times_the_state_equation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
