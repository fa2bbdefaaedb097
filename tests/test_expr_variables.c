/*
 * Reference_Variable elements (a dataset's VARIABLE) given by any function
 * expression (docs/interface.md §7.10, §8, §9.6): their values worked by
 * hand, each computed after the variables it reads whatever the order
 * written; a force reading a variable runs as the force with the measure
 * written inline; the Jacobian's load blocks on the bodies a force reads
 * through its variables; a cycle of VARVALs, an unknown id and what is not
 * simulated yet refused, named with file:line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host/variable_values.h"
#include "model_runs.h"
#include "sim/dynamics/loads.h"
#include "sim/simulation/requests.h"
#include "sim_support.h"
#include "test_support.h"

/* Marker 20 on body 2 at (3, 4, 0) moving at (1, 2, 0.5); marker 30 on body
 * 3 at (1, -1, 2) moving at (-0.5, 0, 0) turning at 0.3 about z; marker 10 the
 * ground's origin. */
#define HEAD                                                                                   \
    "<MotionSolve><Model>\n"                                                                   \
    "<Body_Ground id=\"1\"/>\n"                                                                \
    "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"                                            \
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"1\""           \
    " inertia_zz=\"1\" v_ic_x=\"1\" v_ic_y=\"2\" v_ic_z=\"0.5\"/>\n"                           \
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"3\" pos_y=\"4\"/>\n"                    \
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""           \
    " inertia_zz=\"1\" v_ic_x=\"-0.5\" w_ic_z=\"0.3\"/>\n"                                     \
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"1\" pos_y=\"-1\" pos_z=\"2\"/>\n"
#define TAIL "</Model></MotionSolve>\n"

static void open_text(model *m, const char *name, const char *xml, double **y)
{
    open_model(m, test_write_file(name, xml));
    *y = model_state(m);
    model_initial_state(m, *y);
}

static double value_of(const model *m, int id)
{
    const hx_model *mm = m->session.model;
    const int k = hx_model_variable(mm, id);
    assert_true(k >= 0);
    return m->data.frames.variables[k];
}

/* Written out of order (2 reads 1, 4 reads 3 and 2): at t = 0,
 *   1 = 2 DX(20,10) + 1          = 2 (3) + 1      = 7
 *   2 = VARVAL(1) DY(30,10) - TIME = 7 (-1) - 0   = -7
 *   3 = DZ(30)  (one measure)                     = 2
 *   4 = VARVAL(3) + VARVAL(2)                     = 2 - 7 = -5
 * and at t = 0.25 (the same state) 2 = -7.25 and 4 = -5.25; the force on
 * marker 20 is VARVAL(4) along x. */
static void values_worked_by_hand_in_dependency_order(void **state)
{
    (void)state;
    model m;
    double *y;
    open_text(&m, "values.xml",
              HEAD "<Reference_Variable id=\"4\" expr=\"VARVAL(3) + VARVAL(2)\"/>\n"
                   "<Reference_Variable id=\"2\" expr=\"VARVAL(1)*DY(30,10) - TIME\"/>\n"
                   "<Reference_Variable id=\"3\" expr=\"DZ(30)\"/>\n"
                   "<Reference_Variable id=\"1\" type=\"EXPRESSION\" expr=\"2*DX(20,10)+1\"/>\n"
                   "<Force_Vector_OneBody id=\"7\" marker_id=\"20\" fx_expression=\"VARVAL(4)\"/>\n"
                   TAIL,
              &y);
    const hx_model *mm = m.session.model;
    assert_true(mm->variables_read);
    assert_null(mm->variables[hx_model_variable(mm, 3)].program); /* the one-measure form */
    double *ydot = model_state(&m);
    static const double t[2] = {0.0, 0.25};
    for (int i = 0; i < 2; ++i) {
        assert_int_equal(hx_dynamics_evaluate(&m.d, &m.data, t[i], y, ydot, 0), 0);
        assert_close(value_of(&m, 1), 7.0, 0, 1e-15);
        assert_close(value_of(&m, 2), -7.0 - t[i], 0, 1e-15);
        assert_close(value_of(&m, 3), 2.0, 0, 1e-15);
        assert_close(value_of(&m, 4), -5.0 - t[i], 0, 1e-15);
        hx_load_share share;
        hx_message msg;
        assert_int_equal(hx_load_share_at(mm, &m.data.frames, m.data.turn + mm->njoints, 0, &share,
                                          &msg), 0);
        assert_close(share.F[0][0], -5.0 - t[i], 0, 1e-15);
    }
    free(y), free(ydot);
    close_model(&m);
}

/* The same force with the measure inline, through a variable of one measure
 * and through an expression variable: the same run, bit for bit (the
 * engine's measures are the host's, and the same operations in the same
 * order), by DOPRI5 and by BDF. */
static void force_through_a_variable_runs_as_inline(void **state)
{
    (void)state;
    static const char *const forms[3] = {
        "<Force_Vector_OneBody id=\"7\" marker_id=\"20\""
        " fx_expression=\"-50*DX(20,30) - 3*VX(20,30)\" fy_expression=\"-20*DY(20,30)\"/>\n",
        "<Reference_Variable id=\"1\" expr=\"DX(20,30)\"/>\n"
        "<Force_Vector_OneBody id=\"7\" marker_id=\"20\""
        " fx_expression=\"-50*VARVAL(1) - 3*VX(20,30)\" fy_expression=\"-20*DY(20,30)\"/>\n",
        "<Reference_Variable id=\"1\" expr=\"-50*DX(20,30)\"/>\n"
        "<Reference_Variable id=\"2\" expr=\"VARVAL(1) - 3*VX(20,30)\"/>\n"
        "<Force_Vector_OneBody id=\"7\" marker_id=\"20\""
        " fx_expression=\"VARVAL(2)\" fy_expression=\"-20*DY(20,30)\"/>\n"};
    static const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int method = 0; method < 2; ++method) {
        double *end[3];
        int n = 0;
        for (int f = 0; f < 3; ++f) {
            char xml[4096], name[32];
            snprintf(xml, sizeof xml, HEAD "%s" TAIL, forms[f]);
            snprintf(name, sizeof name, "inline%d.xml", f);
            model m;
            open_text(&m, name, xml, &end[f]);
            n = m.d.n;
            hx_simulation_result r =
                simulate(&m, methods[method], HX_JACOBIAN_ANALYTIC, 1e-8, 0.5, end[f]);
            assert_int_equal(r.status, HX_INTEGRATION_OK);
            close_model(&m);
        }
        assert_true(fabs(end[0][0] - 3.0) > 0.1); /* it moved */
        for (int f = 1; f < 3; ++f)
            for (int k = 0; k < n; ++k)
                if (end[f][k] != end[0][k])
                    fail_msg("%s, form %d: y[%d] %.17g, inline %.17g",
                             method == 0 ? "DOPRI5" : "BDF", f, k, end[f][k], end[0][k]);
        for (int f = 0; f < 3; ++f)
            free(end[f]);
    }
}

/* A force on body 2 that reads body 3 only through a chain of variables:
 * the Jacobian's load blocks (on the columns of body 3, known from the
 * parse through VARVAL) against differences of the whole right-hand side,
 * away from the start; and BDF runs it. */
static void jacobian_through_variables_equals_differences(void **state)
{
    (void)state;
    model m;
    double *y;
    open_text(&m, "jacobian.xml",
              HEAD "<Reference_Variable id=\"1\" expr=\"DX(30,10) + 0.1*VY(30,10)\"/>\n"
                   "<Reference_Variable id=\"2\" expr=\"VARVAL(1)*VARVAL(1) + SIN(WZ(30))\"/>\n"
                   "<Reference_Variable id=\"3\" expr=\"DZ(30,10)\"/>\n"
                   "<Force_Vector_OneBody id=\"7\" marker_id=\"20\""
                   " fx_expression=\"-5*VARVAL(2) - DX(20,10)\" fz_expression=\"-3*VARVAL(3)\""
                   " tz_expression=\"-VARVAL(1)\"/>\n"
                   "<Force_Scalar_TwoBody id=\"9\" type=\"FORCE\" i_marker_id=\"30\""
                   " j_marker_id=\"10\" val_expression=\"-30*(DM(30,10) - 2)\"/>\n" TAIL,
              &y);
    int bodies[HX_LOAD_BODIES_MAX];
    const hx_model *mm = m.session.model;
    assert_int_equal(hx_load_bodies(&m.d, 0, bodies), 3); /* its own, body 3, the ground */
    assert_int_equal(bodies[1], hx_model_body(mm, 3));
    hx_simulation_result r = simulate(&m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, 1e-8, 0.3, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    long outside = 0;
    const double worst = jacobian_against_differences(&m.d, 0.3, y, "variables", &outside);
    assert_int_equal(outside, 0);
    assert_true(worst < 1e-6);
    free(y);
    close_model(&m);
}

/* A dataset's VARIABLE by an expression is simulated (no warning), and a
 * REQUEST reads it: at t = 0.5, STEP(0.5, 0, 0, 1, 1) = 0.5 (the cubic
 * step's midpoint), DX(20,10) = 3, VARVAL(2) = DZ(30) = 2: 0.5 (3) + 2 = 3.5. */
static void dataset_variables_and_requests(void **state)
{
    (void)state;
    const char *path = test_write_file(
        "variables.adm",
        "ADAMS/View model\n"
        "PART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=2, CM=20, IP=1,1,1\nMARKER/20, PART=2, QP=3,4,0\n"
        "PART/3, MASS=1, CM=30, IP=1,1,1\nMARKER/30, PART=3, QP=1,-1,2\n"
        "VARIABLE/1, FUNCTION=STEP(TIME,0,0,1,1)*DX(20,10)+VARVAL(2)\n"
        "VARIABLE/2, FUNCTION=DZ(30)\n"
        "REQUEST/7, F2=VARVAL(1)\n"
        "END\n");
    model m;
    open_model(&m, path);
    const hx_model *mm = m.session.model;
    assert_int_equal(mm->nunsimulated, 0);
    assert_int_equal(mm->nvariables, 2);
    assert_non_null(mm->variables[0].program);
    double *y = model_state(&m);
    model_initial_state(&m, y);
    hx_dynamics_kinematics(&m.d, &m.data, 0.5, y);
    double values[2];
    hx_message msg;
    assert_int_equal(hx_variables_values(&m.data.frames, m.d.routine_binding, values, &msg), 0);
    assert_close(values[0], 3.5, 0, 1e-15);
    char row[256] = "";
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(hx_requests_csv_row(f, &m.data.frames, m.d.routine_binding, NULL, &msg), 0);
    rewind(f);
    assert_non_null(fgets(row, sizeof row, f));
    fclose(f);
    assert_string_equal(row, ",0,3.5,0,0,0,0,0,0");
    free(y);
    close_model(&m);
}

static void bad_variables_are_named(void **state)
{
    (void)state;
    /* 1 reads 2, 2 reads 3, 3 reads 2: the loop is 2 and 3 (lines 9 and 10) */
    sim_expect_parse_error("cycle.xml",
                 HEAD "<Reference_Variable id=\"1\" expr=\"VARVAL(2)+1\"/>\n"
                      "<Reference_Variable id=\"2\" expr=\"2*VARVAL(3)\"/>\n"
                      "<Reference_Variable id=\"3\" expr=\"DX(20) - VARVAL(2)\"/>\n" TAIL,
                 (const char *const[]){"a cycle of variables",
                                       "cycle.xml:9: Reference_Variable 2 reads VARVAL(3)",
                                       "cycle.xml:10: Reference_Variable 3 reads VARVAL(2)",
                                       NULL});
    sim_expect_parse_error("self.adm",
                 "ADAMS/View model\nPART/1, GROUND\nMARKER/10, PART=1\n"
                 "VARIABLE/5, FUNCTION=1 + VARVAL(5)\nEND\n",
                 (const char *const[]){"self.adm:4: Reference_Variable 5 reads VARVAL(5)",
                                       "algebraic loop",
                                       /* the whole error at the loop's first variable */
                                       "self.adm:4: VARIABLE/5: a cycle of variables", NULL});
    sim_expect_parse_error("unknown.adm",
                 "ADAMS/View model\nPART/1, GROUND\nMARKER/10, PART=1\n"
                 "VARIABLE/5, FUNCTION=1 + VARVAL(9)\nEND\n",
                 (const char *const[]){"unknown.adm:4:26:", "Reference_Variable 5: expr:",
                                       "no Reference_Variable 9", NULL});
    sim_expect_parse_error("parse.xml",
                 HEAD "<Reference_Variable id=\"1\" expr=\"2*(DX(20)\"/>\n" TAIL,
                 (const char *const[]){"parse.xml:8:", "Reference_Variable 1: expr:", NULL});
    /* a force may read a Control_Diff's state (through a variable too), not its
     * rate, computed after the forces */
    sim_expect_parse_error("dif.adm",
                 "ADAMS/View model\nPART/1, GROUND\nMARKER/10, PART=1\n"
                 "PART/2, MASS=2, CM=20, IP=1,1,1\nMARKER/20, PART=2, QP=3,4,0\n"
                 "DIFF/3, IC=1, FUNCTION=USER(1)\n"
                 "VARIABLE/5, FUNCTION=2*DIF(3)\n"
                 "SFORCE/4, TRANSLATION, I=20, J=10, FUNCTION=VARVAL(5) + DIF1(3)\nEND\n",
                 (const char *const[]){"dif.adm:8:", "DIF1(3)", "rate", NULL});
    sim_expect_parse_error("dif1.adm",
                 "ADAMS/View model\nPART/1, GROUND\nMARKER/10, PART=1\n"
                 "DIFF/3, IC=1, FUNCTION=USER(1)\n"
                 "VARIABLE/5, FUNCTION=2*DIF1(3)\nEND\n",
                 (const char *const[]){"dif1.adm:5:", "DIF1(3)", "not its rate", NULL});
    /* a Force_StateEqn's inputs read TIME and measures only (docs/interface.md §7.10) */
    sim_expect_parse_error("stateeqn.xml",
                 HEAD "<Reference_Variable id=\"2\" expr=\"TIME\"/>\n"
                      "<Reference_Variable id=\"1\" expr=\"2*DX(20) + VARVAL(2)\"/>\n"
                      "<Reference_Array id=\"30\" type=\"U\" num_element=\"1\" variable_id=\"1\"/>\n"
                      "<Reference_Array id=\"31\" type=\"X\" num_element=\"1\"/>\n"
                      "<Force_StateEqn id=\"1\" type=\"USERSUB\" x_array_id=\"31\""
                      " u_array_id=\"30\" num_state=\"1\" i_marker_id=\"20\""
                      " j_floating_marker_id=\"10\" ref_marker_id=\"10\""
                      " usrsub_param_string=\"USER(1)\"/>\n" TAIL,
                 (const char *const[]){"stateeqn.xml:12:", "Force_StateEqn 1",
                                       "Reference_Variable 1", "which reads VARVAL(2)", NULL});
}

/* A fault of a variable's expression names it, file:line:column and the time. */
static void fault_of_a_variable_is_named(void **state)
{
    (void)state;
    model m;
    double *y;
    open_text(&m, "fault.xml",
              HEAD "<Reference_Variable id=\"6\" expr=\"1/(DX(20,10) - 3)\"/>\n"
                   "<Force_Vector_OneBody id=\"7\" marker_id=\"20\" fx_expression=\"VARVAL(6)\"/>\n"
                   TAIL,
              &y);
    double *ydot = model_state(&m);
    assert_int_equal(hx_dynamics_evaluate(&m.d, &m.data, 0.0, y, ydot, 0), -1);
    assert_contains(m.data.message, "fault.xml:8:", "Reference_Variable 6", "division by zero",
                    "t = 0");
    free(y), free(ydot);
    close_model(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(values_worked_by_hand_in_dependency_order),
        cmocka_unit_test(force_through_a_variable_runs_as_inline),
        cmocka_unit_test(jacobian_through_variables_equals_differences),
        cmocka_unit_test(dataset_variables_and_requests),
        cmocka_unit_test(bad_variables_are_named),
        cmocka_unit_test(fault_of_a_variable_is_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
