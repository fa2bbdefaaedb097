/*
 * Other elements' forces answered to user routines (docs/interface.md §5.1,
 * §8.8; host/loop_queries.h): a routine that declares c_sysfnc JOINT, FZ or
 * SFORCE in its dependency pass reads inputs of the algebraic loop, answered
 * from its iterate and solved at each right-hand side, as an expression's
 * are (tests/force_support/force_routines.c). A slider pushed down and
 * braked in proportion to its joint's normal force (the force it reads
 * changes the force it reads) against the closed form and against the same
 * model by expression; the same through FZ at the joint's marker; a spring's
 * force read by SFORCE against the oscillator's closed form; and the bad
 * paths: an unknown joint, a comp out of range, a read outside the
 * dependency pass; a request's routine answered at its output times.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/loop_inputs.h"
#include "model_runs.h"
#include "sim_support.h"
#include "test_support.h"

#define G 9.81
#define QUARTER "1.5707963267948966"

/* A 2 kg slider on a TRANSLATIONAL joint along the world's x (JOINT 1: I 21
 * on it, J 11 on ground, both z axes along x), moving at 3 m/s, under gravity
 * along -z, with `force` after it; 10 and 12 the ground's origin. */
static const char *slider(const char *name, const char *force)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"0\" grav_z=\"-9.81\"/>\n"
             "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Reference_Marker id=\"11\" body_id=\"1\" psi=\"" QUARTER "\" theta=\"" QUARTER
             "\"/>\n"
             "<Reference_Marker id=\"12\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"1\""
             " inertia_zz=\"1\" v_ic_x=\"3\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\" psi=\"" QUARTER "\" theta=\"" QUARTER
             "\"/>\n"
             "<Constraint_Joint id=\"1\" type=\"TRANSLATIONAL\" i_marker_id=\"21\""
             " j_marker_id=\"11\"/>\n"
             "%s"
             "</Model></MotionSolve>\n",
             force);
    return test_write_file(name, text);
}

/* READ_FORCE's force on marker 20 (JFLOAT 12, in 10's axes). */
#define READER(user)                                                                           \
    "<Force_Vector_TwoBody id=\"7\" type=\"ForceAndTorque\" i_marker_id=\"20\""                 \
    " j_floating_marker_id=\"12\" ref_marker_id=\"10\" usrsub_param_string=\"" user "\""       \
    " usrsub_fnc_name=\"READ_FORCE\" usrsub_dll_name=\"" FORCE_LIBRARY "\"/>\n"

/* Pushed down by 0.5 N and braked by 0.2 N along x per N of the joint's
 * normal force N (JOINT(1, 0, 4, 10): the reaction's z on I): N = m g + 0.5
 * N, so N = 2 m g = 39.24 N, and x'' = -0.2 N / m = -3.924: x = 3 t - 1.962
 * t^2, x' = 3 - 3.924 t. */
#define NORMAL (2 * 2 * G)
#define BRAKE (0.2 * NORMAL / 2)

/* The slider's place and speed along x at t from its initial state, run by
 * method; ends[0], ends[1]. */
static void slide(model *m, hx_method method, double t, double ends[2])
{
    double *y = model_state(m);
    model_initial_state(m, y);
    const hx_simulation_result r = simulate(m, method, HX_JACOBIAN_ANALYTIC, 1e-10, t, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    ends[0] = y[m->d.dof[1].q], ends[1] = y[m->d.nq + m->d.dof[1].u];
    free(y);
}

static void a_brake_by_the_normal_force_is_the_closed_form_and_the_expression(void **state)
{
    (void)state;
    const double t = 0.5;
    model m;
    open_model(&m, slider("joint.xml", READER("USER(1, 1, 0, 4, 10, -0.2, -0.5)")));
    const hx_model *md = m.session.model;
    assert_int_equal(md->nloop_inputs, 1);
    char text[160];
    assert_string_equal(hx_loop_input_text(md, 0, text, sizeof text),
                        "JOINT(1,0,4,10) (READ_FORCE of Force_Vector_TwoBody 7)");
    double *y = model_state(&m), *ydot = model_state(&m);
    model_initial_state(&m, y);
    assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.0, y, ydot), 0);
    assert_close(m.data.frames.loop[0], NORMAL, 0, 1e-9);
    assert_close(ydot[m.d.nq + m.d.dof[1].u], -BRAKE, 0, 1e-9);
    free(y), free(ydot);
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    double ends[2][2];
    for (int k = 0; k < 2; ++k) {
        slide(&m, methods[k], t, ends[k]);
        assert_close(ends[k][0], 3 * t - 0.5 * BRAKE * t * t, 0, 1e-8);
        assert_close(ends[k][1], 3 - BRAKE * t, 0, 1e-8);
    }
    close_model(&m);

    /* the same model by expression: the same loop, the same run */
    open_model(&m, slider("expression.xml",
                          "<Force_Vector_TwoBody id=\"7\" type=\"ForceAndTorque\""
                          " i_marker_id=\"20\" j_floating_marker_id=\"12\" ref_marker_id=\"10\""
                          " fx_expression=\"-0.2*JOINT(1,0,4,10)\""
                          " fz_expression=\"-0.5*JOINT(1,0,4,10)\"/>\n"));
    double by_expression[2];
    slide(&m, HX_METHOD_DOPRI5, t, by_expression);
    assert_close(by_expression[0], ends[0][0], 0, 1e-12);
    assert_close(by_expression[1], ends[0][1], 0, 1e-12);
    close_model(&m);

    /* through FZ(21, 11, 10): the net force at the joint's I marker from the
     * elements between it and J, the joint's alone: the same normal force */
    open_model(&m, slider("fz.xml", READER("USER(2, 21, 11, 10, 0, -0.2, -0.5)")));
    double through_fz[2];
    slide(&m, HX_METHOD_DOPRI5, t, through_fz);
    assert_close(through_fz[0], 3 * t - 0.5 * BRAKE * t * t, 0, 1e-8);
    close_model(&m);
}

/* A 1 kg body at x = 1 on a spring to the origin, SFORCE 3 = -4 DM (no
 * gravity), and READ_FORCE adding 0.5 of the spring's x force (SFORCE(3, 0,
 * 2, 10)): x'' = -6 x, x = cos(sqrt(6) t). */
static void a_spring_force_read_by_sforce_is_the_oscillator(void **state)
{
    (void)state;
    const char *path = test_write_file(
        "spring.xml",
        "<MotionSolve><Model>\n"
        "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Reference_Marker id=\"12\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
        " inertia_zz=\"1\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\"/>\n"
        "<Force_Scalar_TwoBody id=\"3\" type=\"FORCE\" i_marker_id=\"20\" j_marker_id=\"10\""
        " val_expression=\"-4*DM(20,10)\"/>\n" READER("USER(3, 3, 0, 2, 10, 0.5, 0)")
        "</Model></MotionSolve>\n");
    model m;
    open_model(&m, path);
    assert_int_equal(m.session.model->nloop_inputs, 1);
    const double t = 1.3;
    double *y = model_state(&m);
    model_initial_state(&m, y);
    const hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-11, t, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    assert_close(y[m.d.dof[1].q], cos(sqrt(6.0) * t), 0, 1e-8);
    free(y);
    close_model(&m);
}

static void an_unknown_joint_or_comp_is_refused_naming_the_query(void **state)
{
    (void)state;
    char force[512];
    hx_session s;
    hx_message msg;
    static const char *const cases[][2] = {
        {"USER(1, 9, 0, 4, 10, -0.2, -0.5)",
         "JOINT(9,0,4,10) in its dependency pass: no Constraint_Joint (JOINT) 9 in the model"},
        {"USER(1, 1, 0, 9, 10, -0.2, -0.5)",
         "JOINT(1,0,9,10) in its dependency pass: JOINT: comp (argument 3) is 9: 1 to 8"},
        {"USER(1, 1, 2, 4, 10, -0.2, -0.5)",
         "JOINT(1,2,4,10) in its dependency pass: JOINT: jflag (argument 2) is 2: 0 to 1"},
        {"USER(3, 5, 0, 2, 10, 0.5, 0)",
         "SFORCE(5,0,2,10) in its dependency pass: no Force_Scalar_TwoBody or"
         " Force_SpringDamper (SFORCE) 5 in the model"},
        {"USER(2, 21, 99, 10, 0, -0.2, -0.5)",
         "FZ(21,99,10) in its dependency pass: no Reference_Marker 99 in the model"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        snprintf(force, sizeof force,
                 "<Force_Vector_TwoBody id=\"7\" type=\"ForceAndTorque\" i_marker_id=\"20\""
                 " j_floating_marker_id=\"12\" ref_marker_id=\"10\" usrsub_param_string=\"%s\""
                 " usrsub_fnc_name=\"READ_FORCE\" usrsub_dll_name=\"" FORCE_LIBRARY "\"/>\n",
                 cases[k][0]);
        assert_int_equal(hx_session_open(&s, slider("bad.xml", force), stderr, &msg), -1);
        printf("%s\n", msg.text);
        assert_contains(msg.text, "bad.xml:11: Force_Vector_TwoBody 7 (READ_FORCE) declares",
                        cases[k][1]);
    }
}

/* A force asked only outside the dependency pass: undeclared, as any such
 * read, and not answered (the loop has no place for it). */
static void a_read_outside_the_dependency_pass_is_undeclared(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    char *text = NULL;
    size_t size = 0;
    FILE *stream = open_memstream(&text, &size);
    assert_int_equal(hx_session_open(&s, slider("late.xml",
                                                READER("USER(1, 1, 0, 4, 10, -0.2, -0.5, 1)")),
                                     stream, &msg), 0);
    assert_int_equal(s.model->nloop_inputs, 0);
    hx_dynamics d;
    assert_int_equal(hx_dynamics_init(&d, &s, &msg), 0);
    hx_dynamics_data dd;
    assert_int_equal(hx_dynamics_data_init(&dd, &d, &msg), 0);
    double *y = calloc((size_t)d.n, sizeof *y), *ydot = calloc((size_t)d.n, sizeof *ydot);
    assert_int_equal(hx_dynamics_model_state(&d, &dd, y), 0);
    assert_int_equal(hx_dynamics_rhs(&d, &dd, 0.0, y, ydot), 0);
    assert_close(ydot[d.nq + d.dof[1].u], 0.0, 0, 1e-12); /* not braked: not answered */
    fflush(stream);
    fclose(stream);
    printf("%s", text);
    assert_contains(text, "Force_Vector_TwoBody 7 (READ_FORCE) reads JOINT(1,0,4,10) at t = 0"
                          " outside the dependencies it declared");
    free(y), free(ydot), free(text);
    hx_dynamics_data_free(&dd);
    hx_dynamics_free(&d);
    hx_session_close(&s);
}

/* A request's REQSUB runs at output times, once the forces are known: its
 * JOINT(1, 0, 4, 0) is an output query, not a loop input (the model alone
 * has no loop), answered at every output time from that time's reaction
 * (docs/interface.md §5.1): the slider's normal force m g = 19.62 N, and
 * with the brake's push 2 m g = 39.24 N, the loop's answer (request8.3; its
 * other values 0). */
static void a_request_routine_reads_the_output_times_force(void **state)
{
    (void)state;
    const char *request = "<Post_Request id=\"8\" usrsub_param_string=\"USER(1)\""
                          " usrsub_fnc_name=\"REQUEST_FORCE\" usrsub_dll_name=\""
                          FORCE_LIBRARY "\"/>\n";
    char braked[2048];
    snprintf(braked, sizeof braked, "%s%s", request, READER("USER(1, 1, 0, 4, 10, -0.2, -0.5)"));
    const char *const models[2] = {request, braked};
    const double normal[2] = {2 * G, NORMAL};
    for (int k = 0; k < 2; ++k) {
        char path[1024];
        snprintf(path, sizeof path, "%s", slider("request.xml", models[k]));
        model m;
        open_model(&m, path);
        assert_int_equal(m.session.model->nloop_inputs, k); /* the brake's JOINT alone */
        assert_int_equal(m.session.model->noutput_queries, 1);
        close_model(&m);
        const char *csv = test_temp_path("request.csv");
        assert_int_equal(sim_run_csv(path, csv,
                                     (const char *const[]){"--end", "0.5", "--output-interval",
                                                           "0.1", "--quiet", NULL}),
                         0);
        csv_table tb;
        csv_read(csv, &tb);
        assert_int_equal(tb.rows, 6);
        for (int j = 1; j <= 8; ++j) {
            char name[32];
            snprintf(name, sizeof name, "request8.%d", j);
            const int c = csv_column(csv, name);
            assert_true(c >= 0);
            for (int r = 0; r < tb.rows; ++r)
                assert_close(csv_at(&tb, r, c), j == 3 ? normal[k] : 0.0, 0, 1e-8);
        }
        csv_free(&tb);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_brake_by_the_normal_force_is_the_closed_form_and_the_expression),
        cmocka_unit_test(a_spring_force_read_by_sforce_is_the_oscillator),
        cmocka_unit_test(an_unknown_joint_or_comp_is_refused_naming_the_query),
        cmocka_unit_test(a_read_outside_the_dependency_pass_is_undeclared),
        cmocka_unit_test(a_request_routine_reads_the_output_times_force),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
