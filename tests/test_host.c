/*
 * The harness as a host, seen from a library loaded through dlopen: answers
 * of c_sysary/c_sysfnc from the model's state, dependencies recorded in the
 * dependency pass, reads outside them noted, strings and units served, and
 * c_errmes STOP ending a harness run with the message and a non-zero status.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "host/invoke.h"
#include "host/binding.h"
#include "session/session.h"
#include "host/queries.h"
#include "model/expr/functions.h"
#include "test_support.h"
#include "tools/check/checks.h"

#define DEG (M_PI / 180.0)

/* USER(probe, i_marker, j_marker) on a Force_Vector_TwoBody between markers 21 and 11.
 * Ground markers 10 (origin) and 11 (at x = 0.5, turned 90 deg about z);
 * body 2 at (1,2,3) turned 30 deg about z, moving at (0.1,0.2,0.3) and
 * spinning at 2 rad/s about z, with marker 21; body 3 turned 40 deg about x. */
static const char *probe_model(int probe, int i_marker, int j_marker)
{
    static char text[4096];
    const double c30 = cos(30 * DEG), s30 = sin(30 * DEG), c40 = cos(40 * DEG), s40 = sin(40 * DEG);
    snprintf(text, sizeof text,
             "<MotionSolve>\n<Model>\n"
             "<Param_Unit length_unit=\"CENTIMETER\" force_unit=\"KNEWTON\" mass_unit=\"GRAM\" time_unit=\"MINUTE\"/>\n"
             "<Reference_String id=\"7\" string=\"hello.gbs\"/>\n"
             "<Reference_Array id=\"5\" type=\"IC\" num_element=\"3\">1.5, -2, 7</Reference_Array>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Reference_Marker id=\"11\" body_id=\"1\" pos_x=\"0.5\" a00=\"0\" a10=\"1\" a01=\"-1\" a11=\"0\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"\n"
             "  v_ic_x=\"0.1\" v_ic_y=\"0.2\" v_ic_z=\"0.3\" w_ic_z=\"2\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\"\n"
             "  a00=\"%.17g\" a10=\"%.17g\" a01=\"%.17g\" a11=\"%.17g\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\"\n"
             "  a00=\"%.17g\" a10=\"%.17g\" a01=\"%.17g\" a11=\"%.17g\"/>\n"
             "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
             "<Reference_Marker id=\"30\" body_id=\"3\" a11=\"%.17g\" a21=\"%.17g\" a12=\"%.17g\" a22=\"%.17g\"/>\n"
             "<Force_Vector_TwoBody id=\"100\" type=\"ForceAndTorque\" i_marker_id=\"21\"\n"
             "  j_floating_marker_id=\"11\" ref_marker_id=\"11\"\n"
             "  usrsub_param_string=\"USER(%d, %d, %d)\" usrsub_dll_name=\"%s\"/>\n"
             "</Model>\n</MotionSolve>\n",
             c30, s30, -s30, c30, c30, s30, -s30, c30, c40, s40, -s40, c40, probe, i_marker,
             j_marker, HOSTPROBE_LIBRARY);
    char name[64];
    snprintf(name, sizeof name, "probe_%d_%d_%d.xml", probe, i_marker, j_marker);
    return test_write_file(name, text);
}

/* A session on the probe model; the test fails when it does not open. */
static void open_probe(hx_session *s, int probe, int i, int j, FILE *stream)
{
    hx_message msg;
    if (hx_session_open(s, probe_model(probe, i, j), stream, &msg) != 0)
        fail_msg("%s", msg.text);
}

static void evaluate_probe(int probe, int i, int j, double result[6], hx_call *call)
{
    hx_session s;
    open_probe(&s, probe, i, j, stderr);
    hx_binding *b = &s.bindings.items[0];
    hx_invoke_force(b, &s.frames, 0, 1, result, NULL); /* dependency pass */
    hx_binding_call_init(b, call, 0, &s.frames, 0);
    hx_invoke_force(b, &s.frames, 0, 0, result, call);
    hx_session_close(&s);
}

static void sysfnc_answers_from_the_model(void **state)
{
    (void)state;
    double r[6];
    hx_call call;
    evaluate_probe(2, 21, 11, r, &call);
    /* R_11^T (p21 - p11) = Rz(-90) (0.5, 2, 3) = (2, -0.5, 3); Rz(-90) Rz(30) = Rz(-60) */
    assert_close(r[0], 2.0, 0, 1e-14);
    assert_close(r[1], -0.5, 0, 1e-14);
    assert_close(r[2], 3.0, 0, 1e-14);
    assert_close(r[3], 0.0, 0, 1e-14);
    assert_close(r[4], 0.0, 0, 1e-14);
    assert_close(r[5], -60 * DEG, 0, 1e-14);
    assert_int_equal(call.host_calls, 6);
    assert_int_equal(call.undeclared.count, 0);
    evaluate_probe(2, 30, 10, r, &call);
    assert_close(r[3], 40 * DEG, 0, 1e-14); /* AX of a 40 deg turn about x */
}

static void sysary_disp_and_vel(void **state)
{
    (void)state;
    double r[6];
    hx_call call;
    evaluate_probe(1, 21, 11, r, &call);
    assert_close(r[0], 2.0, 0, 1e-14);
    assert_close(r[1], -0.5, 0, 1e-14);
    assert_close(r[2], 3.0, 0, 1e-14);
    assert_close(r[3], -60 * DEG, 0, 1e-14); /* 3-1-3 Euler of Rz(-60): psi = -60, theta = 0 */
    assert_close(r[4], 0.0, 0, 1e-14);
    assert_close(r[5], 0.0, 0, 1e-14);
    assert_int_equal(call.host_calls, 1);
    evaluate_probe(1, 30, 10, r, &call);
    assert_close(r[3], 0.0, 0, 1e-14);
    assert_close(r[4], 40 * DEG, 0, 1e-14); /* theta of a turn about x */
    assert_close(r[5], 0.0, 0, 1e-14);
    /* VEL(21,11,11,11): Rz(-90) applied to (0.1,0.2,0.3) and to (0,0,2) */
    evaluate_probe(3, 21, 11, r, &call);
    assert_close(r[0], 0.2, 0, 1e-14);
    assert_close(r[1], -0.1, 0, 1e-14);
    assert_close(r[2], 0.3, 0, 1e-14);
    assert_close(r[3], 0.0, 0, 1e-14);
    assert_close(r[4], 0.0, 0, 1e-14);
    assert_close(r[5], 2.0, 0, 1e-14);
}

/* The angle functions and ARRAY, answered from the state and the model:
 * marker 30 (Rx(40)) relative to 21 (Rz(30)) is Rz(-30) Rx(40): yaw -30,
 * pitch 0, roll 40; psi -30, theta 40, phi 0. Accelerations are refused. */
static void angles_and_arrays(void **state)
{
    (void)state;
    hx_session s;
    open_probe(&s, 1, 21, 11, stderr);
    const int ipar[2] = {30, 21};
    static const char *const names[6] = {"YAW", "PITCH", "ROLL", "PSI", "THETA", "PHI"};
    const double expected[6] = {-30 * DEG, 0.0, 40 * DEG, -30 * DEG, 40 * DEG, 0.0};
    for (int k = 0; k < 6; ++k) {
        double v = 99.0;
        assert_int_equal(hx_answer_query(&s.frames, names[k], ipar, 2, 0, &v), 1);
        assert_close(v, expected[k], 0, 1e-14);
    }
    /* marker 21 (Rz(30)) relative to ground: all of it is yaw */
    double v = 0.0;
    const int about_z[2] = {21, 10};
    assert_int_equal(hx_answer_query(&s.frames, "YAW", about_z, 2, 0, &v), 1);
    assert_close(v, 30 * DEG, 0, 1e-14);
    double a[4] = {0, 0, 0, 0};
    const int array[1] = {5};
    assert_int_equal(hx_answer_query(&s.frames, "ARRAY", array, 1, 1, a), 3);
    assert_true(a[0] == 1.5 && a[1] == -2.0 && a[2] == 7.0);
    const int missing[1] = {6};
    assert_int_equal(hx_answer_query(&s.frames, "ARRAY", missing, 1, 1, a), -1);
    /* an acceleration's ids are checked, its values are the loop's (zeros here) */
    double acc[6] = {1, 1, 1, 1, 1, 1};
    assert_int_equal(hx_answer_query(&s.frames, "ACC", ipar, 2, 1, acc), 6);
    assert_true(acc[0] == 0.0 && acc[5] == 0.0);
    /* a force's the same: a value of the loop (a zero here); its ids and count checked */
    a[0] = 1.0;
    assert_int_equal(hx_answer_query(&s.frames, "FX", ipar, 2, 0, a), 1);
    assert_true(a[0] == 0.0);
    assert_int_equal(hx_answer_query(&s.frames, "FX", ipar, 2, 1, a), -1); /* a scalar */
    const int joint[4] = {1, 0, 4, 0};
    assert_int_equal(hx_answer_query(&s.frames, "JOINT", joint, 4, 0, a), 1);
    assert_int_equal(hx_answer_query(&s.frames, "JOINT", joint, 3, 0, a), -1); /* rm left out */
    assert_int_equal(hx_answer_query(&s.frames, "FORCE", joint, 4, 0, a), -1); /* unknown */
    /* every force's name is its function's, with the function's argument counts */
    static const char *const forces[] = {"JOINT", "JPRIM", "MOTION", "COUPLER", "GCON", "SFORCE",
                                         "VFORCE", "VTORQ", "GFORCE", "FIELD", "BUSHING", "BEAM",
                                         "SPDP", "FX", "FY", "FZ", "FM", "TX", "TY", "TZ", "TM"};
    for (size_t k = 0; k < sizeof forces / sizeof forces[0]; ++k) {
        hx_query q;
        hx_query_make(&q, forces[k], joint, 1, 0);
        const int code = hx_expr_function_find(forces[k]);
        assert_true(code >= 0);
        assert_int_equal(hx_query_force(&q), code);
        const hx_expr_function *f = hx_expr_function_at(code);
        assert_int_equal(hx_answer_query(&s.frames, forces[k], joint, f->most, 0, a), 1);
        assert_int_equal(hx_answer_query(&s.frames, forces[k], joint, f->most + 1, 0, a), -1);
        if (f->least > 1)
            assert_int_equal(hx_answer_query(&s.frames, forces[k], joint, f->least - 1, 0, a),
                             -1);
    }
    assert_int_equal(hx_answer_query(&s.frames, "YAW", ipar, 2, 1, a), -1); /* a scalar */
    hx_session_close(&s);
}

static void dependency_pass_records_queries(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    assert_int_equal(hx_session_open(&s, probe_model(1, 21, 11), stderr, &msg), 0);
    hx_binding *b = &s.bindings.items[0];
    double r[6] = {1, 1, 1, 1, 1, 1};
    hx_invoke_force(b, &s.frames, 0, 1, r, NULL);
    assert_int_equal(b->deps.count, 1);
    char text[128];
    assert_string_equal(hx_query_text(&b->deps.query[0], text, sizeof text), "DISP(21,11,11)");
    for (int k = 0; k < 6; ++k)
        assert_close(r[k], 0.0, 0, 0); /* zeros in the dependency pass */
    hx_session_close(&s);
}

static void undeclared_read_is_noted(void **state)
{
    (void)state;
    double r[6];
    hx_call call;
    evaluate_probe(4, 21, 11, r, &call);
    assert_int_equal(call.undeclared.count, 1);
    char text[64];
    assert_string_equal(hx_query_text(&call.undeclared.query[0], text, sizeof text),
                        "DISP(21,11,11)");
}

/* A null array for the answer is refused (errflg 1, no values), not written through. */
static void a_null_answer_array_is_refused(void **state)
{
    (void)state;
    double r[6];
    hx_call call;
    evaluate_probe(6, 21, 11, r, &call);
    assert_close(r[0], 1.0, 0, 0);
    assert_close(r[1], 0.0, 0, 0);
    assert_int_equal(call.refused.count, 1);
}

static void strings_and_units(void **state)
{
    (void)state;
    double r[6];
    hx_call call;
    evaluate_probe(5, 7, 0, r, &call);
    assert_close(r[0], 9.0, 0, 0); /* strlen("hello.gbs") */
    /* the Adams-compatible order: time, length, force, mass, sizes in SI */
    assert_close(r[1], 60.0, 0, 0);  /* minute */
    assert_close(r[2], 1e-2, 0, 0);  /* centimetre */
    assert_close(r[3], 1e3, 0, 0);   /* kilonewton */
    assert_close(r[4], 1e-3, 0, 0);  /* gram */
    assert_close(r[5], 1.0, 0, 0);   /* nothing written past 4 doubles and 12 characters */
}

/* The units' names: four of three characters in the same order, exactly twelve. */
static void unit_names(void **state)
{
    (void)state;
    hx_session s;
    open_probe(&s, 5, 7, 0, stderr);
    hx_call call;
    hx_binding_call_init(&s.bindings.items[0], &call, 0, &s.frames, 0);
    hx_host_bind(&call);
    int exists = 0;
    char units[16];
    memset(units, '#', sizeof units);
    c_gtunts(&exists, NULL, units);
    hx_host_unbind();
    assert_int_equal(exists, 1);
    assert_memory_equal(units, "MINCM KN G  ####", 16);
    /* outside any call there is no model: no units */
    exists = 1;
    c_gtunts(&exists, NULL, NULL);
    assert_int_equal(exists, 0);
    hx_session_close(&s);
}

static void stop_is_recorded(void **state)
{
    (void)state;
    /* the session runs the dependency pass, where the probe stops the run */
    hx_session s;
    hx_message msg;
    assert_int_equal(hx_session_open(&s, probe_model(99, 21, 11), NULL, &msg), -1);
    assert_contains(msg.text, "dependency pass", "probe asked to stop");
}

/* check's history audit runs its histories in processes of their own: a STOP
 * there stops this process's run too, named once. */
static void a_stop_in_the_history_audit_stops_the_run(void **state)
{
    (void)state;
    hx_session s;
    open_probe(&s, 98, 21, 11, NULL);
    char text[4096] = {0};
    FILE *out = fmemopen(text, sizeof text - 1, "w");
    assert_non_null(out);
    assert_int_equal(hx_audit_history(&s, &s.bindings.items[0], out), 1);
    fclose(out);
    assert_true(hx_messages_stopped(&s.messages));
    assert_string_equal(s.messages.stop_message, "probe asked to stop later");
    assert_contains(text, "history audit: the element stopped the run in the calls");
    hx_session_close(&s);
}

static void stop_ends_a_harness_run(void **state)
{
    (void)state;
    char command[1024];
    snprintf(command, sizeof command, "'%s' check '%s' 2>&1", HARNESS_EXE,
             probe_model(99, 21, 11));
    FILE *p = popen(command, "r");
    assert_non_null(p);
    char output[8192] = {0};
    size_t n = fread(output, 1, sizeof output - 1, p);
    output[n] = '\0';
    const int status = pclose(p);
    assert_true(WIFEXITED(status));
    assert_int_not_equal(WEXITSTATUS(status), 0);
    assert_contains(output, "probe asked to stop", "STOP");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sysfnc_answers_from_the_model),
        cmocka_unit_test(sysary_disp_and_vel),
        cmocka_unit_test(angles_and_arrays),
        cmocka_unit_test(dependency_pass_records_queries),
        cmocka_unit_test(undeclared_read_is_noted),
        cmocka_unit_test(a_null_answer_array_is_refused),
        cmocka_unit_test(strings_and_units),
        cmocka_unit_test(unit_names),
        cmocka_unit_test(a_stop_in_the_history_audit_stops_the_run),
        cmocka_unit_test(stop_is_recorded),
        cmocka_unit_test(stop_ends_a_harness_run),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
