/*
 * Accelerations answered to user routines (docs/interface.md §5.1, §8.8;
 * host/loop_queries.h): a routine that declares c_sysfnc ACCX .. WDTM or
 * c_sysary ACC in its dependency pass reads inputs of the algebraic loop,
 * answered from its iterate and solved at each right-hand side, as an
 * expression's are (tests/accel_support/accel_routines.c). An added mass
 * -ma ACCZ by a GFOSUB on a sprung body against the closed form of a body of
 * mass m + ma, and against the same model by expression; a DIFSUB of WDTZ
 * against Iz wdot = T; c_sysary ACC's six values
 * against the harness's own accelerations; and the bad paths: an unknown
 * marker, a loop without a solution, a read outside the dependency pass;
 * a request's routine answered at its output times.
 */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/loop_inputs.h"
#include "model_runs.h"
#include "sim_support.h"
#include "test_support.h"

#define G 9.81

/* A free body of mass 2 (inertia 0.1, 0.2, 0.4), its centre marker 20 at the
 * origin at rest, gravity (0, 0, -9.81), with `elements` after it; the
 * library's routines named by ACCEL_LIBRARY. */
static const char *free_body(const char *name, const char *elements)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"0\" grav_z=\"-9.81\"/>\n"
             "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.2\""
             " inertia_zz=\"0.4\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "%s"
             "</Model></MotionSolve>\n",
             elements);
    return test_write_file(name, text);
}

/* A GFOSUB-style force of the library on marker 20 (J the ground's 10). */
#define USER_FORCE(id, routine, user)                                                           \
    "<Force_Vector_TwoBody id=\"" id "\" type=\"ForceAndTorque\" i_marker_id=\"20\""            \
    " j_floating_marker_id=\"10\" ref_marker_id=\"10\" usrsub_param_string=\"" user "\""       \
    " usrsub_fnc_name=\"" routine "\" usrsub_dll_name=\"" ACCEL_LIBRARY "\"/>\n"

/* A spring k = 50 along z: (m + ma) z'' = -k z - m g with m = 2, ma = 3
 * oscillates about z_eq = -m g / k = -0.3924 at w = sqrt(k / (m + ma))
 * = sqrt(10), from rest at 0: z = z_eq (1 - cos w t), z'(t) = z_eq w sin w t. */
#define SPRING "<Force_Vector_OneBody id=\"6\" marker_id=\"20\" fz_expression=\"-50*DZ(20)\"/>\n"
#define Z_EQ (-2 * G / 50)
#define OMEGA sqrt(10.0)

/* A free body: y = [p (3), q (4) | v (3), w (3) | works]. */
enum { Z = 2, VX = 7, VY = 8, VZ = 9, WZ = 12 };

static int evaluate_initial(model *m, double **y, double **ydot)
{
    *y = model_state(m), *ydot = model_state(m);
    model_initial_state(m, *y);
    return hx_dynamics_rhs(&m->d, &m->data, 0.0, *y, *ydot);
}

static void added_mass_by_a_routine_is_the_closed_form_and_the_expression(void **state)
{
    (void)state;
    model m;
    open_model(&m, free_body("routine.xml", USER_FORCE("1", "ADDED_MASS", "USER(20, 3)") SPRING));
    const hx_model *md = m.session.model;
    assert_int_equal(md->nloop_inputs, 1);
    char text[160];
    assert_string_equal(hx_loop_input_text(md, 0, text, sizeof text),
                        "ACCZ(20) (ADDED_MASS of Force_Vector_TwoBody 1)");
    double *y, *ydot;
    assert_int_equal(evaluate_initial(&m, &y, &ydot), 0);
    /* at rest at z = 0: z'' = -m g / (m + ma) = -2 * 9.81 / 5 */
    assert_close(ydot[VZ], -2 * G / 5, 0, 1e-9);
    assert_close(m.data.frames.loop[0], -2 * G / 5, 0, 1e-9);
    const double t = 1.0;
    double ends[2][13];
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 2; ++k) {
        model_initial_state(&m, y);
        const hx_simulation_result r = simulate(&m, methods[k], HX_JACOBIAN_ANALYTIC, 1e-10, t, y);
        assert_int_equal(r.status, HX_INTEGRATION_OK);
        assert_close(y[Z], Z_EQ * (1 - cos(OMEGA * t)), 0, 1e-6);
        assert_close(y[VZ], Z_EQ * OMEGA * sin(OMEGA * t), 0, 1e-6);
        memcpy(ends[k], y, sizeof ends[k]);
        if (methods[k] == HX_METHOD_BDF) /* its Jacobian by differences, and it says so */
            assert_non_null(strstr(r.jacobian, "central differences of the whole right-hand"));
    }
    free(y), free(ydot);
    close_model(&m);

    /* the same model by expression: the same loop, the same run */
    open_model(&m, free_body("expression.xml", "<Force_Vector_OneBody id=\"1\" marker_id=\"20\""
                                               " fz_expression=\"-3*ACCZ(20)\"/>\n" SPRING));
    y = model_state(&m);
    model_initial_state(&m, y);
    const hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-10, t, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    assert_close(y[Z], ends[0][Z], 0, 1e-9);
    assert_close(y[VZ], ends[0][VZ], 0, 1e-9);
    free(y);
    close_model(&m);
}

/* A DIFSUB whose rate is 0.6 WDTZ(20) (its routine answered after the loop,
 * at the solved values) on a body turned by a torque 2 about z: wdot = 2 /
 * 0.4 = 5, the state 0.6 * 5 t = 3 at t = 1. (A VARSUB's value is read by
 * no force yet: §7.12.) */
static void a_diff_routine_of_wdtz(void **state)
{
    (void)state;
    model m;
    open_model(&m, free_body("diff.xml",
                             "<Control_Diff id=\"7\" type=\"USERSUB\" is_implicit=\"FALSE\" ic=\"0\""
                             " usrsub_param_string=\"USER(20, 0.6)\" usrsub_fnc_name=\"ANGULAR_DRAG\""
                             " usrsub_dll_name=\"" ACCEL_LIBRARY "\"/>\n"
                             "<Force_Vector_OneBody id=\"5\" marker_id=\"20\""
                             " tz_expression=\"2\"/>\n"));
    assert_int_equal(m.session.model->nloop_inputs, 1);
    double *y, *ydot;
    assert_int_equal(evaluate_initial(&m, &y, &ydot), 0);
    assert_close(ydot[WZ], 5.0, 0, 1e-9);
    assert_close(ydot[m.d.diff_offset], 3.0, 0, 1e-9);
    model_initial_state(&m, y);
    const hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-10, 1.0, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    assert_close(y[WZ], 5.0, 0, 1e-7);
    assert_close(model_diff_state(&m, y, 7), 3.0, 0, 1e-7);
    free(y), free(ydot);
    close_model(&m);
}

/* c_sysary ACC(20, 0, 0) of a body pushed by F = (1, -3, 4) and T = (0.1,
 * -0.3, 0.2) at rest with gravity: a = (0.5, -1.5, 4 / 2 - 9.81) and
 * alpha = T / I = (1, -1.5, 0.5), each value a different number; the
 * library's last answer against them and against the harness's own. */
static void c_sysary_acc_is_the_harness_accelerations(void **state)
{
    (void)state;
    evaluated e;
    evaluate_text(&e, "probe.xml",
                  "<MotionSolve><Model>\n"
                  "<Force_Gravity grav_x=\"0\" grav_y=\"0\" grav_z=\"-9.81\"/>\n"
                  "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
                  "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\""
                  " inertia_yy=\"0.2\" inertia_zz=\"0.4\"/>\n"
                  "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
                  "<Force_Vector_OneBody id=\"5\" marker_id=\"20\" fx_expression=\"1\""
                  " fy_expression=\"-3\" fz_expression=\"4\" tx_expression=\"0.1\""
                  " ty_expression=\"-0.3\" tz_expression=\"0.2\"/>\n"
                  USER_FORCE("1", "ACC_PROBE", "USER(20, 0, 0)")
                  "</Model></MotionSolve>\n");
    assert_int_equal(e.m.session.model->nloop_inputs, 6);
    void *library = dlopen(ACCEL_LIBRARY, RTLD_NOW | RTLD_NOLOAD);
    assert_non_null(library);
    int (*last)(double *) = (int (*)(double *))dlsym(library, "accel_probe_last");
    assert_non_null(last);
    double acc[6];
    assert_int_equal(last(acc), 6);
    const double want[6] = {0.5, -1.5, 2 - G, 1.0, -1.5, 0.5};
    static const char *const harness[6] = {"ACCX(20)", "ACCY(20)", "ACCZ(20)",
                                           "WDTX(20)", "WDTY(20)", "WDTZ(20)"};
    for (int k = 0; k < 6; ++k) {
        assert_close(acc[k], want[k], 0, 1e-9);
        EXPECT(&e, harness[k], acc[k], 1e-9);
    }
    dlclose(library);
    release(&e);
}

/* A session of the model at path whose host messages land in *text (the
 * caller frees it): 0, or -1 with msg. */
static int open_recorded(hx_session *s, const char *path, char **text, hx_message *msg)
{
    size_t size = 0;
    FILE *stream = open_memstream(text, &size);
    assert_non_null(stream);
    const int status = hx_session_open(s, path, stream, msg);
    fflush(stream);
    fclose(stream);
    return status;
}

/* An unknown marker: refused in the dependency pass, named. */
static void an_unknown_marker_is_refused_naming_the_query(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    char *text = NULL;
    assert_int_equal(open_recorded(&s, free_body("unknown.xml",
                                                 USER_FORCE("1", "ADDED_MASS", "USER(99, 3)")),
                                   &text, &msg), 0);
    printf("%s", text);
    assert_non_null(strstr(text, "Force_Vector_TwoBody 1 (ADDED_MASS) asked c_sysfnc ACCZ(99)"));
    assert_non_null(strstr(text, "which the host refuses"));
    assert_int_equal(s.model->nloop_inputs, 0); /* nothing declared, no loop */
    free(text);
    hx_session_close(&s);
}

/* ma = -m: m z'' = -m g + m z'' has no z'': the run refused naming the
 * routine and its query. */
static void a_loop_without_a_solution_names_the_routine(void **state)
{
    (void)state;
    model m;
    open_model(&m, free_body("singular.xml", USER_FORCE("1", "ADDED_MASS", "USER(20, -2)")));
    double *y, *ydot;
    assert_int_equal(evaluate_initial(&m, &y, &ydot), -1);
    const char *text = m.data.message;
    printf("%s\n", text);
    assert_non_null(strstr(text, "the algebraic loop of ACCZ(20) (ADDED_MASS of"
                                 " Force_Vector_TwoBody 1) at t = 0"));
    assert_non_null(strstr(text, "no solution"));
    free(y), free(ydot);
    close_model(&m);
}

/* A request's routine runs at output times, once the accelerations are
 * known: its ACCZ(20) is an output query, no loop input, answered from each
 * output time's accelerations. On the spring of k = 50 alone the body
 * oscillates about -m g / k from rest at 0, w = sqrt(k / m) = 5:
 * ACCZ = -g cos(w t) (request8.4; its other values 0). */
static void a_request_routine_reads_the_output_times_acceleration(void **state)
{
    (void)state;
    char path[1024];
    snprintf(path, sizeof path, "%s",
             free_body("request.xml", SPRING "<Post_Request id=\"8\" usrsub_param_string=\"USER(20)\""
                                      " usrsub_fnc_name=\"REQUEST_ACC\" usrsub_dll_name=\""
                                      ACCEL_LIBRARY "\"/>\n"));
    model m;
    open_model(&m, path);
    assert_int_equal(m.session.model->nloop_inputs, 0);
    assert_int_equal(m.session.model->noutput_queries, 1);
    close_model(&m);
    const char *csv = test_temp_path("request.csv");
    assert_int_equal(sim_run_csv(path, csv,
                                 (const char *const[]){"--end", "1", "--output-interval", "0.1",
                                                       "--rtol", "1e-10", "--quiet", NULL}),
                     0);
    csv_table tb;
    csv_read(csv, &tb);
    assert_int_equal(tb.rows, 11);
    const int tc = csv_column(csv, "t");
    for (int j = 1; j <= 8; ++j) {
        char name[32];
        snprintf(name, sizeof name, "request8.%d", j);
        const int c = csv_column(csv, name);
        assert_true(c >= 0);
        for (int r = 0; r < tb.rows; ++r)
            assert_close(csv_at(&tb, r, c), j == 4 ? -G * cos(5 * csv_at(&tb, r, tc)) : 0.0, 0,
                         1e-6);
    }
    csv_free(&tb);
}

/* An acceleration asked only outside the dependency pass: undeclared, as
 * any such read, and not answered (the loop has no place for it). */
static void a_read_outside_the_dependency_pass_is_undeclared(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    char *text = NULL;
    const char *path = free_body("late.xml", USER_FORCE("1", "LATE_ADDED_MASS", "USER(20, 3)"));
    size_t size = 0;
    FILE *stream = open_memstream(&text, &size);
    assert_int_equal(hx_session_open(&s, path, stream, &msg), 0);
    assert_int_equal(s.model->nloop_inputs, 0);
    hx_dynamics d;
    assert_int_equal(hx_dynamics_init(&d, &s, &msg), 0);
    hx_dynamics_data dd;
    assert_int_equal(hx_dynamics_data_init(&dd, &d, &msg), 0);
    double *y = calloc((size_t)d.n, sizeof *y), *ydot = calloc((size_t)d.n, sizeof *ydot);
    assert_int_equal(hx_dynamics_model_state(&d, &dd, y), 0);
    assert_int_equal(hx_dynamics_rhs(&d, &dd, 0.0, y, ydot), 0);
    assert_close(ydot[VZ], -G, 0, 1e-12); /* no added mass: the query was not answered */
    fflush(stream);
    fclose(stream);
    printf("%s", text);
    assert_non_null(strstr(text, "Force_Vector_TwoBody 1 (LATE_ADDED_MASS) reads ACCZ(20) at"
                                 " t = 0 outside the dependencies it declared"));
    free(y), free(ydot), free(text);
    hx_dynamics_data_free(&dd);
    hx_dynamics_free(&d);
    hx_session_close(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(added_mass_by_a_routine_is_the_closed_form_and_the_expression),
        cmocka_unit_test(a_diff_routine_of_wdtz),
        cmocka_unit_test(c_sysary_acc_is_the_harness_accelerations),
        cmocka_unit_test(an_unknown_marker_is_refused_naming_the_query),
        cmocka_unit_test(a_loop_without_a_solution_names_the_routine),
        cmocka_unit_test(a_request_routine_reads_the_output_times_acceleration),
        cmocka_unit_test(a_read_outside_the_dependency_pass_is_undeclared),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
