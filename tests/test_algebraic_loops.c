/*
 * The algebraic loop (docs/interface.md §8.8; sim/dynamics/algebraic_loop.h):
 * forces and variables that read accelerations, joint reactions and SFORCE
 * forces within the right-hand side, solved at each. An added mass
 * -ma ACCZ on a free body and a pushed one reading a variable of ACCX, both
 * against their accelerations by hand; a block braked by friction
 * proportional to its joint's normal reaction, against mu g; a loop with no
 * solution (ma = -m) refused naming its inputs and elements; DOPRI5 and BDF
 * agreeing with each other and the closed forms.
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

/* A free body of mass 2 (its centre, marker 20, at the origin, at rest),
 * gravity (0, 0, -9.81), with `loads` after it. */
static const char *free_body(const char *name, const char *loads)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"0\" grav_z=\"-9.81\"/>\n"
             "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""
             " inertia_zz=\"0.1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "%s"
             "</Model></MotionSolve>\n",
             loads);
    return test_write_file(name, text);
}

/* m's initial state into *y and ydot = f(0, y) into *ydot (both the
 * caller's to free): the evaluation's status. */
static int evaluate_initial(model *m, double **y, double **ydot)
{
    *y = model_state(m), *ydot = model_state(m);
    model_initial_state(m, *y);
    return hx_dynamics_rhs(&m->d, &m->data, 0.0, *y, *ydot);
}

/* m run from its initial state by method at rtol 1e-9 to t = 1 (y: the state
 * there), the BDF's Jacobian as the model gives it; the run ended well. */
static hx_simulation_result run_to_one_second(model *m, hx_method method, double *y)
{
    model_initial_state(m, y);
    const hx_simulation_result r = simulate(m, method, HX_JACOBIAN_ANALYTIC, 1e-9, 1.0, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    return r;
}

/* The added mass: m z'' = F - m g - ma z'' with m = 2, ma = 3, F = 30, so
 * z'' = (30 - 2 * 9.81) / (2 + 3) = 10.38 / 5 = 2.076. */
#define ADDED_MASS                                                                          \
    "<Force_Vector_OneBody id=\"5\" marker_id=\"20\" fz_expression=\"30 - 3*ACCZ(20)\"/>\n"
#define ADDED_MASS_A 2.076

/* A free body: y = [p (3), q (4) | v (3), w (3) | works]. */
enum { Z = 2, VX = 7, VZ = 9 };

/* With a Control_Diff integrating ACCZ(20) too (the same input, one slot):
 * its state is the velocity, a t. */
static void added_mass_accelerates_at_f_over_m_plus_ma(void **state)
{
    (void)state;
    model m;
    open_model(&m, free_body("added_mass.xml", ADDED_MASS
                             "<Control_Diff id=\"1\" type=\"EXPRESSION\" ic=\"0\""
                             " expr=\"ACCZ(20)\"/>\n"));
    const hx_model *md = m.session.model;
    assert_int_equal(md->nloop_inputs, 1);
    char text[160];
    assert_string_equal(hx_loop_input_text(md, 0, text, sizeof text),
                        "ACCZ(20) (Force_Vector_OneBody 5)");
    double *y, *ydot;
    assert_int_equal(evaluate_initial(&m, &y, &ydot), 0);
    assert_close(ydot[VZ], ADDED_MASS_A, 0, 1e-9);
    assert_close(m.data.frames.loop[0], ADDED_MASS_A, 0, 1e-9); /* z = g(z) */
    /* the trajectory: z = a t^2 / 2, v = a t at t = 1, both methods */
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 2; ++k) {
        const hx_simulation_result r = run_to_one_second(&m, methods[k], y);
        assert_close(y[Z], ADDED_MASS_A / 2, 0, 1e-6);
        assert_close(y[VZ], ADDED_MASS_A, 0, 1e-6);
        assert_close(y[m.d.diff_offset], ADDED_MASS_A, 0, 1e-6);
        if (methods[k] == HX_METHOD_BDF) /* its Jacobian by differences, and it says so */
            assert_non_null(strstr(r.jacobian, "central differences of the whole right-hand"));
    }
    free(y), free(ydot);
    close_model(&m);
}

/* A variable of ACCX(20) read by a force: m x'' = 6 - 1 * x'', x'' = 6 / 3 = 2;
 * and an SFORCE's force read by another: the scalar force 7 along x from
 * J = 11 at x = -5 to I = 20 (pushes I away: +x) read by a vector force as
 * SFORCE(7, 0, 2, 0) = 7 (FX on I): m x'' = 6 - x'' + 7 + 7, x'' = 20 / 3. */
static void a_variable_of_accx_and_an_sforce_read_by_forces(void **state)
{
    (void)state;
    model m;
    open_model(&m, free_body("variable.xml",
                             "<Reference_Variable id=\"3\" expr=\"ACCX(20)\"/>\n"
                             "<Force_Vector_OneBody id=\"5\" marker_id=\"20\""
                             " fx_expression=\"6 - VARVAL(3)\"/>\n"));
    assert_int_equal(m.session.model->nloop_inputs, 1);
    double *y, *ydot;
    assert_int_equal(evaluate_initial(&m, &y, &ydot), 0);
    assert_close(ydot[VX], 2.0, 0, 1e-9);
    assert_close(ydot[VZ], -G, 0, 1e-12);
    free(y), free(ydot);
    close_model(&m);

    open_model(&m, free_body("sforce.xml",
                             "<Reference_Marker id=\"11\" body_id=\"1\" pos_x=\"-5\"/>\n"
                             "<Reference_Variable id=\"3\" expr=\"ACCX(20)\"/>\n"
                             "<Force_Scalar_TwoBody id=\"7\" type=\"FORCE\" i_marker_id=\"20\""
                             " j_marker_id=\"11\" val_expression=\"7\"/>\n"
                             "<Force_Vector_OneBody id=\"5\" marker_id=\"20\""
                             " fx_expression=\"6 - VARVAL(3) + SFORCE(7, 0, 2, 0)\"/>\n"));
    assert_int_equal(m.session.model->nloop_inputs, 2);
    assert_int_equal(evaluate_initial(&m, &y, &ydot), 0);
    assert_close(ydot[VX], 20.0 / 3.0, 0, 1e-9);
    free(y), free(ydot);
    close_model(&m);
}

/* A block of mass 4 on a TRANSLATIONAL along x to ground (reduced), gravity
 * (0, -9.81, 0), moving at 3 along x, braked by friction mu |N| sign(v) with
 * mu = 0.25 and N the joint's reaction FY on the block, JOINT(1, 0, 3, 0)
 * = m g = 39.24: x'' = -mu g = -2.4525 while it moves, so at t = 1
 * v = 3 - 2.4525 = 0.5475 and x = 3 - 2.4525 / 2 = 1.77375. */
static const char *braked_block(void)
{
    return test_write_file(
        "friction.xml",
        "<MotionSolve><Model>\n"
        "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
        "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" psi=\"1.5707963267948966\""
        " theta=\"1.5707963267948966\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"4\" inertia_xx=\"0.1\" inertia_yy=\"1.5\""
        " inertia_zz=\"1.5\" v_ic_x=\"3\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
        "<Reference_Marker id=\"21\" body_id=\"2\" psi=\"1.5707963267948966\""
        " theta=\"1.5707963267948966\"/>\n"
        "<Constraint_Joint id=\"1\" type=\"TRANSLATIONAL\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "<Force_Vector_OneBody id=\"5\" marker_id=\"20\""
        " fx_expression=\"-0.25*ABS(JOINT(1, 0, 3, 0))*SIGN(1, VX(20))\"/>\n"
        "</Model></MotionSolve>\n");
}

static void friction_of_the_normal_reaction_brakes_at_mu_g(void **state)
{
    (void)state;
    model m;
    open_model(&m, braked_block());
    assert_int_equal(m.d.joint_row[0], -1); /* reduced: y = [x | v | works] */
    double *y, *ydot;
    assert_int_equal(evaluate_initial(&m, &y, &ydot), 0);
    assert_close(m.data.frames.loop[0], 4 * G, 0, 1e-9);
    assert_close(ydot[m.d.nq], -0.25 * G, 0, 1e-9);
    double end[2][8];
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 2; ++k) {
        run_to_one_second(&m, methods[k], y);
        assert_close(y[0], 1.77375, 0, 1e-6);
        assert_close(y[m.d.nq], 0.5475, 0, 1e-6);
        end[k][0] = y[0], end[k][1] = y[m.d.nq];
    }
    /* BDF and DOPRI5 agree with each other as with the closed form */
    assert_close(end[1][0], end[0][0], 0, 2e-6);
    assert_close(end[1][1], end[0][1], 0, 2e-6);
    free(y), free(ydot);
    close_model(&m);
}

/* ma = -m: m z'' = 30 - m g + m z'' has no z'' (z - g(z) = -(30/2 - 9.81)
 * whatever z): the run refused, naming the loop's input and element. */
static void a_loop_without_a_solution_is_refused_naming_it(void **state)
{
    (void)state;
    model m;
    open_model(&m, free_body("singular.xml",
                             "<Force_Vector_OneBody id=\"5\" marker_id=\"20\""
                             " fz_expression=\"30 + 2*ACCZ(20)\"/>\n"));
    double *y, *ydot;
    assert_int_equal(evaluate_initial(&m, &y, &ydot), -1);
    const char *text = m.data.message;
    printf("%s\n", text);
    assert_non_null(strstr(text, "the algebraic loop of ACCZ(20) (Force_Vector_OneBody 5)"));
    assert_non_null(strstr(text, "at t = 0"));
    assert_non_null(strstr(text, "no solution"));
    assert_non_null(strstr(text, "residual 5.19")); /* 30 / 2 - 9.81 */
    /* and a run stops with it */
    model_initial_state(&m, y);
    hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-9, 1.0, y);
    assert_int_not_equal(r.status, HX_INTEGRATION_OK);
    assert_non_null(strstr(r.message, "algebraic loop of ACCZ(20)"));
    free(y), free(ydot);
    close_model(&m);
}

/* A general constraint still may not read one: the loop is solved for the
 * forces, variables and Control_Diff rates. */
static void a_general_constraint_reading_one_is_refused(void **state)
{
    (void)state;
    char text[2048];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""
             " inertia_zz=\"0.1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "<Constraint_General id=\"4\" i_marker_id=\"20\" expr=\"DX(20) - ACCX(20)\"/>\n"
             "</Model></MotionSolve>\n");
    sim_expect_parse_error("gcon.xml", text, (const char *const[]){"gcon.xml:6:", "ACCX(20)",
                           "algebraic loop", NULL});
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(added_mass_accelerates_at_f_over_m_plus_ma),
        cmocka_unit_test(a_variable_of_accx_and_an_sforce_read_by_forces),
        cmocka_unit_test(friction_of_the_normal_reaction_brakes_at_mu_g),
        cmocka_unit_test(a_loop_without_a_solution_is_refused_naming_it),
        cmocka_unit_test(a_general_constraint_reading_one_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
