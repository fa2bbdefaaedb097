/*
 * Control_Diff elements (a dataset's DIFF) given by a function expression
 * (docs/interface.md §7.10, §9.6): the state's rate is the expression. Runs
 * against closed forms worked by hand, DIF and DIF1 read by other states and
 * variables, the Jacobian's row against differences of the right-hand side
 * and BDF with it against BDF with differences, the XML and the dataset
 * forms bit for bit, and bad inputs refused with file:line. The implicit
 * form: test_implicit_diffs.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host/variable_values.h"
#include "model_runs.h"
#include "sim_support.h"
#include "test_support.h"

/* Marker 10 the ground's origin; body 2 (cm marker 20) at (3, 4, 0) moving
 * at (2, 0, 0), no force on it (the dataset gives no gravity). */
#define ADM_HEAD                                                                               \
    "ADAMS/View model\nPART/1, GROUND\nMARKER/10, PART=1\n"                                    \
    "PART/2, MASS=2, CM=20, IP=1,1,1, VX=2\nMARKER/20, PART=2, QP=3,4,0\n"

/* y' = -a y + b, y(0) = y0: y(t) = b/a + (y0 - b/a) e^{-a t}. With a = 2,
 * b = 3, y0 = 0.5: y(1) = 1.5 - e^{-2} = 1.3646647167633873. Both methods,
 * BDF with the analytic Jacobian (its entry -a exact from the expression's
 * partial in DIF(1)) and with differences. */
static void linear_rate_against_the_closed_form(void **state)
{
    (void)state;
    static const char *const text = ADM_HEAD "DIFF/1, IC=0.5, FUNCTION=-2*DIF(1) + 3\nEND\n";
    const double expected = 1.5 - exp(-2.0);
    static const hx_method methods[3] = {HX_METHOD_DOPRI5, HX_METHOD_BDF, HX_METHOD_BDF};
    static const hx_jacobian_method jacobians[3] = {HX_JACOBIAN_ANALYTIC, HX_JACOBIAN_ANALYTIC,
                                                    HX_JACOBIAN_FD};
    for (int i = 0; i < 3; ++i) {
        model m;
        double *y = model_run_text("linear.adm", text, methods[i], jacobians[i], 1e-10, 1.0, &m);
        assert_int_equal(m.session.model->nunsimulated, 0);
        assert_close(model_diff_state(&m, y, 1), expected, 0, 1e-7);
        free(y);
        close_model(&m);
    }
}

/* DIFF 2 integrates DX(20,10) = 3 + 2t: DIF(2)(1) = 3 + 1 = 4. DIFF 3's
 * rate is DIF1(2) (DIFF 2's rate, computed before it whatever the order
 * written): DIF(3)(1) = 4 too. VARIABLE 5 = 2 DIF(2) = 8, and DIFF 4's rate
 * VARVAL(5) - DIF(4) reads it: y' + y = 2(3t + t^2) from 0; trying
 * y = A t^2 + B t + C + K e^{-t}: A = 2, 2A + B = 6 (B = 2), B + C = 0
 * (C = -2), y(0) = 0 (K = 2): y(1) = 2 + 2/e = 2.7357588823428847. */
static void states_integrating_a_displacement(void **state)
{
    (void)state;
    static const char *const text =
        ADM_HEAD "DIFF/3, FUNCTION=DIF1(2)\n"
                 "DIFF/2, IC=0, FUNCTION=DX(20,10)\n"
                 "VARIABLE/5, FUNCTION=2*DIF(2)\n"
                 "DIFF/4, FUNCTION=VARVAL(5) - DIF(4)\nEND\n";
    model m;
    double *y = model_run_text("integral.adm", text, HX_METHOD_DOPRI5,
                               HX_JACOBIAN_ANALYTIC, 1e-11, 1.0, &m);
    assert_close(model_diff_state(&m, y, 2), 4.0, 0, 1e-8);
    assert_close(model_diff_state(&m, y, 3), 4.0, 0, 1e-8);
    assert_close(model_diff_state(&m, y, 4), 2.0 + 2.0 / exp(1.0), 0, 1e-8);
    hx_dynamics_kinematics(&m.d, &m.data, 1.0, y);
    double values[1];
    hx_message msg;
    assert_int_equal(hx_variables_values(&m.data.frames, m.d.routine_binding, values, &msg), 0);
    assert_close(values[0], 8.0, 0, 1e-8);
    free(y);
    close_model(&m);
}

/* A stiff rate coupled to the body and to another state, read directly and
 * through a variable: the Jacobian against differences of the whole
 * right-hand side away from the start, and BDF with it against BDF with
 * differences. */
static void jacobian_row_against_differences(void **state)
{
    (void)state;
    static const char *const text =
        ADM_HEAD "VARIABLE/5, FUNCTION=DIF(2)*DX(20,10)\n"
                 "DIFF/1, IC=0.5, FUNCTION=-500*DIF(1) + 3*SIN(DIF(2)) + DY(20,10)*VX(20,10)\n"
                 "DIFF/2, IC=0.1, FUNCTION=-DIF(2)*DIF(1) + 0.01*VARVAL(5)\n"
                 "SFORCE/7, TRANSLATION, I=20, J=10, FUNCTION=-40*(DM(20,10) - 5) - "
                 "2*VR(20,10)\nEND\n";
    model m;
    free(model_diffs_jacobian_checked("jacobian.adm", text, "diffs", 1, 2, &m));
    close_model(&m);
}

/* A rate read by DIF1 whose own rate depends on the body: DIFF 3's rate reads
 * DIF1(2), DIFF 2's rate the body's DX and VY, and a spring reads DIF(3), so
 * the body's columns reach DIFF 3's row through DIFF 2's rate and the
 * body's rows through DIFF 3's state. The Jacobian (DIFF 3's row on the
 * body's and DIFF 2's columns, DIF1(2) computed again at each moved state)
 * against differences of the whole right-hand side away from the start,
 * and BDF with it against BDF with differences. */
static void rate_read_by_dif1_in_the_jacobian(void **state)
{
    (void)state;
    static const char *const text =
        ADM_HEAD "DIFF/2, IC=0.2, FUNCTION=DX(20,10)*VY(20,10) - 3*DIF(2)\n"
                 "DIFF/3, IC=0.1, FUNCTION=-5*DIF(3) + 2*DIF1(2) + DIF1(2)*DIF(3)\n"
                 "SFORCE/7, TRANSLATION, I=20, J=10, FUNCTION=-40*(DM(20,10) - 5) - "
                 "2*VR(20,10) + 3*DIF(3)\nEND\n";
    model m;
    free(model_diffs_jacobian_checked("rate.adm", text, "a rate read by DIF1", 2, 3, &m));
    close_model(&m);
}

/* Forces reading DIF, directly and through a variable: a spring whose
 * stiffness a state ramps (DIF(1) -> 3 with rate 2 (3 - DIF(1))), and a
 * damping force scaled by VARVAL(5) = DIF(2)^2. At the start, DIF(1) = 0.5:
 * the spring's force along I-J is -40 (1 + 0.5) (DM - 4) (worked at the state
 * below); the Jacobian (its columns of the states, by differences of the
 * load alone) against differences of the whole right-hand side, and BDF with
 * it against BDF with differences. */
static void forces_reading_states(void **state)
{
    (void)state;
    static const char *const text =
        ADM_HEAD "DIFF/1, IC=0.5, FUNCTION=2*(3 - DIF(1))\n"
                 "DIFF/2, IC=0.8, FUNCTION=-DIF(2) + 0.1*DX(20,10)\n"
                 "VARIABLE/5, FUNCTION=DIF(2)*DIF(2)\n"
                 "SFORCE/7, TRANSLATION, I=20, J=10, FUNCTION=-40*(1 + DIF(1))*(DM(20,10) - 4)"
                 " - VARVAL(5)*VR(20,10)\nEND\n";
    model m;
    open_model(&m, test_write_file("forces.adm", text));
    double *y = model_state(&m), *ydot = model_state(&m);
    model_initial_state(&m, y);
    /* at t = 0: DM = 5, VR = 2 * 3 / 5 = 1.2: F = -40 (1.5)(1) - 0.64 (1.2) = -60.768
     * along I-J, on a 2 kg body: its x acceleration (3/5) F / 2 = -18.2304 */
    assert_int_equal(hx_dynamics_evaluate(&m.d, &m.data, 0.0, y, ydot, 0), 0);
    const int body = hx_model_body(m.session.model, 2);
    assert_close(ydot[m.d.nq + m.d.dof[body].u], -18.2304, 0, 1e-12);
    free(ydot);
    hx_simulation_result r = simulate(&m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, 1e-9, 0.4, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    long outside = 0;
    const double worst = jacobian_against_differences(&m.d, 0.4, y, "forces", &outside);
    assert_int_equal(outside, 0);
    assert_true(worst < 1e-6);
    model f;
    double *yf = model_run_text("forces.adm", text, HX_METHOD_BDF, HX_JACOBIAN_FD, 1e-9, 0.4, &f);
    for (int k = 0; k < m.d.n; ++k)
        assert_close(y[k], yf[k], 1e-6, 1e-8);
    free(y), free(yf);
    close_model(&m), close_model(&f);
}

/* The XML and the dataset forms are one model: the same run bit for bit. */
static void xml_and_dataset_bit_identical(void **state)
{
    (void)state;
    static const char *const xml =
        "<MotionSolve><Model>\n"
        "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"1\""
        " inertia_zz=\"1\" v_ic_x=\"2\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"3\" pos_y=\"4\"/>\n"
        "<Control_Diff id=\"1\" type=\"EXPRESSION\" ic=\"0.5\" expr=\"-2*DIF(1) + DX(20,10)\"/>\n"
        "</Model></MotionSolve>\n";
    static const char *const adm = ADM_HEAD "DIFF/1, IC=0.5, FUNCTION=-2*DIF(1) + DX(20,10)\nEND\n";
    model a, b;
    double *ya = model_run_text("twin.xml", xml, HX_METHOD_BDF,
                                HX_JACOBIAN_ANALYTIC, 1e-8, 0.5, &a);
    double *yb = model_run_text("twin.adm", adm, HX_METHOD_BDF,
                                HX_JACOBIAN_ANALYTIC, 1e-8, 0.5, &b);
    assert_int_equal(a.d.n, b.d.n);
    assert_true(fabs(model_diff_state(&a, ya, 1) - 0.5) > 0.1); /* it moved */
    assert_memory_equal(ya, yb, sizeof(double) * (size_t)a.d.n);
    free(ya), free(yb);
    close_model(&a), close_model(&b);
}

static void bad_diffs_are_named(void **state)
{
    (void)state;
    sim_expect_parse_error("unknown.adm", ADM_HEAD "DIFF/1, FUNCTION=1 + DIF(9)\nEND\n",
                 (const char *const[]){"unknown.adm:6:", "DIF(9)", "no Control_Diff 9", NULL});
    sim_expect_parse_error("nofunction.adm", ADM_HEAD "DIFF/1, IC=2\nEND\n",
                 (const char *const[]){"nofunction.adm:6:", "FUNCTION", NULL});
    sim_expect_parse_error("self.adm", ADM_HEAD "DIFF/1, FUNCTION=1 + DIF1(1)\nEND\n",
                 (const char *const[]){"self.adm:6:", "DIF1(1)", "its own rate", NULL});
    sim_expect_parse_error("cycle.adm",
                 ADM_HEAD "DIFF/1, FUNCTION=DIF1(2)\nDIFF/2, FUNCTION=2*DIF1(1)\nEND\n",
                 (const char *const[]){"a cycle of Control_Diff rates",
                                       "cycle.adm:6: Control_Diff 1 reads DIF1(2)",
                                       "cycle.adm:7: Control_Diff 2 reads DIF1(1)", NULL});
    sim_expect_parse_error("parse.adm", ADM_HEAD "DIFF/1, FUNCTION=1 + \nEND\n",
                 (const char *const[]){"parse.adm:6:", NULL});
    static const char *const head =
        "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n";
    char xml[1024];
    snprintf(xml, sizeof xml, "%s<Control_Diff id=\"1\" type=\"EXPRESSION\" ic=\"1\"/>\n"
             "</Model></MotionSolve>\n", head);
    sim_expect_parse_error("noexpr.xml", xml,
                 (const char *const[]){"noexpr.xml:4:", "Control_Diff 1", "expr is missing", NULL});
    snprintf(xml, sizeof xml, "%s<Control_Diff id=\"1\" type=\"EXPRESSION\""
             " expr=\"DIF(1) + DX(99)\"/>\n</Model></MotionSolve>\n", head);
    sim_expect_parse_error("marker.xml", xml,
                 (const char *const[]){"marker.xml:4:", "Control_Diff 1: expr: DX(99)",
                                       "no Reference_Marker 99", NULL});
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(linear_rate_against_the_closed_form),
        cmocka_unit_test(states_integrating_a_displacement),
        cmocka_unit_test(jacobian_row_against_differences),
        cmocka_unit_test(rate_read_by_dif1_in_the_jacobian),
        cmocka_unit_test(forces_reading_states),
        cmocka_unit_test(xml_and_dataset_bit_identical),
        cmocka_unit_test(bad_diffs_are_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
