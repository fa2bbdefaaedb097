/*
 * Implicit Control_Diff elements by expression (docs/interface.md §7.10,
 * §9.6): the expression is a residual F(DIF1, DIF, ...) = 0 whose rate the
 * dynamics solves by Newton's method at every evaluation. Runs against
 * closed forms worked by hand (linear, nonlinear in the rate, two coupled
 * through each other's rate), a force and an explicit rate reading the
 * implicit state, the XML and dataset forms bit for bit, BDF against DOPRI5
 * with the Jacobian's rows against differences, and the refusals: a residual
 * that does not read its own rate, one reading an explicit rate, a singular
 * dF/dDIF1 and a Newton that does not converge, each named with file:line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_runs.h"
#include "sim/dynamics/implicit_diffs.h"
#include "sim_support.h"
#include "test_support.h"

/* Marker 10 the ground's origin; body 2 (cm marker 20) at (3, 4, 0) moving
 * at (2, 0, 0), no gravity. */
#define ADM_HEAD                                                                               \
    "ADAMS/View model\nPART/1, GROUND\nMARKER/10, PART=1\n"                                    \
    "PART/2, MASS=2, CM=20, IP=1,1,1, VX=2\nMARKER/20, PART=2, QP=3,4,0\n"

static const hx_method methods[3] = {HX_METHOD_DOPRI5, HX_METHOD_BDF, HX_METHOD_BDF};
static const hx_jacobian_method jacobians[3] = {HX_JACOBIAN_ANALYTIC, HX_JACOBIAN_ANALYTIC,
                                                HX_JACOBIAN_FD};

/* At an output time after the start, the run's data keeps the last accepted
 * step's rate, where Newton starts next: -y/2 at the step's end, at or past
 * t (5% covers a step of 0.1). */
static int accepted_rate(void *ctx, const hx_dynamics *d, hx_dynamics_data *dd, double t,
                         const double *y)
{
    if (t > 0.0) {
        assert_close(dd->implicit_start[0], -0.5 * y[d->diff_offset], 0.05, 0);
        ++*(int *)ctx;
    }
    return 0;
}

/* 2 y' + y = 0, y(0) = 1: y = e^{-t/2}, y(1) = 0.6065306597126334; the rate
 * at the start -1/2 (no ic_dot: Newton from 0, one step on a linear
 * residual). DOPRI5, BDF with its Jacobian and BDF with differences. */
static void linear_residual_against_the_closed_form(void **state)
{
    (void)state;
    static const char *const text =
        ADM_HEAD "DIFF/1, IMPLICIT, IC=1, FUNCTION=2*DIF1(1) + DIF(1)\nEND\n";
    for (int i = 0; i < 3; ++i) {
        model m;
        open_model(&m, test_write_file("linear.adm", text));
        double *y = model_state(&m), *ydot = model_state(&m);
        model_initial_state(&m, y);
        assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.0, y, ydot), 0);
        assert_close(ydot[m.d.diff_offset], -0.5, 0, 1e-15);
        assert_close(m.data.frames.diffs[1], -0.5, 0, 1e-15); /* what DIF1(1) answers */
        hx_simulation_options so = {0};
        hx_integrator_defaults(&so.integration);
        so.integration.method = methods[i];
        so.integration.jacobian = jacobians[i];
        so.integration.rtol = 1e-10;
        so.integration.atol = 1e-13;
        so.integration.t_end = 1.0;
        so.integration.output_interval = 0.25;
        so.skip_energy = 1;
        so.observer = accepted_rate;
        int outputs = 0;
        so.observer_ctx = &outputs;
        hx_simulation_result r;
        hx_simulate(&m.d, &so, y, &r);
        assert_int_equal(r.status, HX_INTEGRATION_OK);
        assert_int_equal(outputs, 4);
        assert_close(model_diff_state(&m, y, 1), exp(-0.5), 0, 1e-7);
        free(y), free(ydot);
        close_model(&m);
    }
}

/* Where Newton starts moves only with an accepted step: no evaluation moves
 * it (a rejected step's are evaluations alone), the run's accept hook does
 * (hx_implicit_diffs_keep, after the step's last evaluation). On 2 y' + y = 0
 * (rate -y/2), evaluated as an integrator would: a step ending at 0.5
 * (y = 1, rate -0.5), rejected, its retry ending at 0.4 (y = 0.8, rate -0.4)
 * accepted, then the next step's first evaluation at 0.45. */
static void a_rejected_step_moves_no_start(void **state)
{
    (void)state;
    model m;
    open_model(&m, test_write_file("start.adm", ADM_HEAD "DIFF/1, IMPLICIT, IC=1,"
                                   " FUNCTION=2*DIF1(1) + DIF(1)\nEND\n"));
    double *y = model_state(&m), *ydot = model_state(&m);
    model_initial_state(&m, y);
    const double *start = m.data.implicit_start;
    assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.5, y, ydot), 0);
    assert_true(start[0] == 0.0); /* no ic_dot: 0, and the evaluation moved nothing */
    y[m.d.diff_offset] = 0.8; /* the retry, before 0.5 */
    assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.4, y, ydot), 0);
    assert_close(ydot[m.d.diff_offset], -0.4, 0, 1e-15);
    assert_true(start[0] == 0.0); /* the rejected step's -0.5 is not taken */
    hx_implicit_diffs_keep(&m.d, &m.data); /* the retry accepted */
    assert_close(start[0], -0.4, 0, 1e-15); /* the accepted step's rate */
    y[m.d.diff_offset] = 0.6;
    assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.45, y, ydot), 0);
    assert_close(start[0], -0.4, 0, 1e-15);
    assert_close(ydot[m.d.diff_offset], -0.3, 0, 1e-15);
    free(y), free(ydot);
    close_model(&m);
}

/* Residuals nonlinear in the rate, x^3 + x = g, one real root as x^3 + x
 * rises: DIFF 1's g = y^3 + y makes y' = y, y(0) = 1: y(1) = e; DIFF 2's
 * g = cos^3 t + cos t makes y' = cos t, y(0) = 0: y(1) = sin 1. */
static void nonlinear_residual_against_closed_forms(void **state)
{
    (void)state;
    static const char *const text =
        ADM_HEAD "DIFF/1, IMPLICIT, IC=1, FUNCTION=DIF1(1)**3 + DIF1(1) - DIF(1)**3 - DIF(1)\n"
                 "DIFF/2, IMPLICIT, IC=0, FUNCTION=DIF1(2)**3 + DIF1(2) - COS(TIME)**3"
                 " - COS(TIME)\nEND\n";
    for (int i = 0; i < 3; ++i) {
        model m;
        double *y = model_run_text("cubic.adm", text, methods[i], jacobians[i], 1e-10, 1.0, &m);
        assert_close(model_diff_state(&m, y, 1), exp(1.0), 0, 1e-6);
        assert_close(model_diff_state(&m, y, 2), sin(1.0), 0, 1e-7);
        free(y);
        close_model(&m);
    }
}

/* Two residuals coupled through each other's rate:
 *   y1' + y2'/2 + y1 = 0,  y1'/2 + y2' + 2 y2 = 0,
 * M y' = -K y with M = [1 1/2; 1/2 1], K = diag(1, 2): y' = A y,
 * A = -M^-1 K = [-4/3 4/3; 2/3 -8/3]. Its trace -4 and determinant 8/3 give
 * e^{At} = e^{st} (cosh(qt) I + sinh(qt)/q (A - sI)), s = -2, q = sqrt(4/3)
 * ((A - sI)^2 = q^2 I). From y(0) = (1, 1/2). */
static void two_residuals_coupled_through_their_rates(void **state)
{
    (void)state;
    static const char *const text =
        ADM_HEAD "DIFF/1, IMPLICIT, IC=1, FUNCTION=DIF1(1) + 0.5*DIF1(2) + DIF(1)\n"
                 "DIFF/2, IMPLICIT, IC=0.5, FUNCTION=0.5*DIF1(1) + DIF1(2) + 2*DIF(2)\nEND\n";
    const double t = 1.0, s = -2.0, q = sqrt(4.0 / 3.0);
    const double c = cosh(q * t), sq = sinh(q * t) / q, e = exp(s * t);
    const double B[4] = {2.0 / 3.0, 4.0 / 3.0, 2.0 / 3.0, -2.0 / 3.0}; /* A - sI */
    const double y0[2] = {1.0, 0.5};
    const double expected[2] = {e * (c * y0[0] + sq * (B[0] * y0[0] + B[1] * y0[1])),
                                e * (c * y0[1] + sq * (B[2] * y0[0] + B[3] * y0[1]))};
    for (int i = 0; i < 3; ++i) {
        model m;
        double *y = model_run_text("coupled.adm", text, methods[i], jacobians[i], 1e-10, t, &m);
        assert_close(model_diff_state(&m, y, 1), expected[0], 0, 1e-7);
        assert_close(model_diff_state(&m, y, 2), expected[1], 0, 1e-7);
        free(y);
        close_model(&m);
    }
}

/* A spring whose stiffness the implicit state scales, and an explicit rate
 * reading the implicit one's (DIF1(1), solved before it): at the start
 * DIF(1) = 1, DM = 5: the force along I-J is -40 (5 - 4) = -40, the body's x
 * acceleration (3/5)(-40)/2 = -12, DIFF 3's rate -1/2; DIF(3) = DIF(1) - 1
 * throughout. The run against its explicit twin (DIFF 1's rate -DIF(1)/2
 * written out). */
static void a_force_reading_the_implicit_state(void **state)
{
    (void)state;
    static const char *const body =
        "DIFF/3, IC=0, FUNCTION=DIF1(1)\n"
        "SFORCE/7, TRANSLATION, I=20, J=10, FUNCTION=-40*DIF(1)*(DM(20,10) - 4)\nEND\n";
    char implicit[1024], explicit_twin[1024];
    snprintf(implicit, sizeof implicit, "%sDIFF/1, IMPLICIT, IC=1, FUNCTION=2*DIF1(1) + DIF(1)\n%s",
             ADM_HEAD, body);
    snprintf(explicit_twin, sizeof explicit_twin, "%sDIFF/1, IC=1, FUNCTION=-0.5*DIF(1)\n%s",
             ADM_HEAD, body);
    model m;
    open_model(&m, test_write_file("force.adm", implicit));
    double *y = model_state(&m), *ydot = model_state(&m);
    model_initial_state(&m, y);
    assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.0, y, ydot), 0);
    const int b = hx_model_body(m.session.model, 2);
    assert_close(ydot[m.d.nq + m.d.dof[b].u], -12.0, 0, 1e-12);
    const int k3 = hx_model_routine(m.session.model, HX_ROUTINE_DIFF, 3);
    assert_close(ydot[m.d.diff_offset + m.session.model->routines[k3].slot], -0.5, 0, 1e-15);
    hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-10, 1.0, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    assert_close(model_diff_state(&m, y, 3), model_diff_state(&m, y, 1) - 1.0, 0, 1e-9);
    model twin;
    double *yt = model_run_text("force_twin.adm", explicit_twin, HX_METHOD_DOPRI5,
                                HX_JACOBIAN_ANALYTIC, 1e-10, 1.0, &twin);
    for (int j = 0; j < m.d.n; ++j)
        assert_close(y[j], yt[j], 0, 1e-8);
    assert_true(fabs(y[m.d.nq + m.d.dof[b].u] - 2.0) > 0.1); /* the spring moved the body */
    free(y), free(ydot), free(yt);
    close_model(&m), close_model(&twin);
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
        "<Control_Diff id=\"1\" type=\"EXPRESSION\" is_implicit=\"TRUE\" ic=\"0.5\""
        " ic_dot=\"0.3\" expr=\"DIF1(1)**3 + 4*DIF1(1) + 2*DIF(1) - DX(20,10)\"/>\n"
        "</Model></MotionSolve>\n";
    static const char *const adm =
        ADM_HEAD "DIFF/1, IMPLICIT, IC=0.5, 0.3, FUNCTION=DIF1(1)**3 + 4*DIF1(1) + 2*DIF(1)"
                 " - DX(20,10)\nEND\n";
    for (int i = 0; i < 2; ++i) {
        model a, b;
        double *ya = model_run_text("twin.xml", xml, methods[i], jacobians[i], 1e-8, 0.5, &a);
        double *yb = model_run_text("twin.adm", adm, methods[i], jacobians[i], 1e-8, 0.5, &b);
        assert_int_equal(a.d.n, b.d.n);
        assert_true(fabs(model_diff_state(&a, ya, 1) - 0.5) > 0.1); /* it moved */
        assert_memory_equal(ya, yb, sizeof(double) * (size_t)a.d.n);
        free(ya), free(yb);
        close_model(&a), close_model(&b);
    }
}

/* Two implicit states coupled to the body and to each other (a stiff one,
 * one nonlinear in its rate), an explicit one reading an implicit rate, and
 * a spring reading both implicit states: the Jacobian (the implicit rows by
 * differences of the rates solved again) against differences of the whole
 * right-hand side away from the start; BDF with it, BDF with differences
 * and DOPRI5 agree. */
static void bdf_and_dopri5_agree_and_the_jacobian(void **state)
{
    (void)state;
    static const char *const text =
        ADM_HEAD "DIFF/1, IMPLICIT, IC=0.5, FUNCTION=DIF1(1) + 0.2*DIF1(1)**3 + 50*DIF(1)"
                 " - DX(20,10)*VX(20,10) - 0.5*DIF1(2)\n"
                 "DIFF/2, IMPLICIT, IC=0.1, FUNCTION=2*DIF1(2) - 0.3*DIF1(1) + DIF(2)*DIF(1)\n"
                 "DIFF/3, IC=0, FUNCTION=DIF1(2) - DIF(3)\n"
                 "SFORCE/7, TRANSLATION, I=20, J=10, FUNCTION=-40*(DM(20,10) - 5) - "
                 "2*VR(20,10) + 3*DIF(1) - DIF(2)\nEND\n";
    model m, e;
    double *y = model_diffs_jacobian_checked("jacobian.adm", text, "implicit", 1, 3, &m);
    double *ye = model_run_text("jacobian.adm", text, HX_METHOD_DOPRI5,
                                HX_JACOBIAN_ANALYTIC, 1e-11, 0.4, &e);
    for (int id = 1; id <= 3; ++id)
        assert_close(model_diff_state(&m, y, id), model_diff_state(&e, ye, id), 1e-6, 1e-8);
    for (int j = 0; j < m.d.nq + m.d.nu; ++j)
        assert_close(y[j], ye[j], 1e-6, 1e-8);
    free(y), free(ye);
    close_model(&m), close_model(&e);
}

/* A run that stops: its message holds each needle. */
static void run_stops(const char *name, const char *text, const char *const *needles)
{
    model m;
    open_model(&m, test_write_file(name, text));
    double *y = model_state(&m);
    model_initial_state(&m, y);
    hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-8, 1.0, y);
    assert_int_equal(r.status, HX_INTEGRATION_FAILED);
    for (const char *const *n = needles; *n != NULL; ++n)
        if (strstr(r.message, *n) == NULL)
            fail_msg("\"%s\" does not contain \"%s\"", r.message, *n);
    free(y);
    close_model(&m);
}

static void bad_implicit_diffs_are_named(void **state)
{
    (void)state;
    /* r^2 + y = 0 with y = 1: no real rate. From 0 dF/dDIF1 = 0; from 0.5 Newton wanders */
    run_stops("singular.adm",
              ADM_HEAD "DIFF/1, IMPLICIT, IC=1, FUNCTION=DIF1(1)**2 + DIF(1)\nEND\n",
              (const char *const[]){"singular.adm:6: Control_Diff 1", "singular", "t = 0",
                                    "residual 1 ", NULL});
    run_stops("wander.adm",
              ADM_HEAD "DIFF/1, IMPLICIT, IC=1, 0.5, FUNCTION=DIF1(1)**2 + DIF(1)\nEND\n",
              (const char *const[]){"wander.adm:6: Control_Diff 1", "did not converge",
                                    "residual", NULL});
    sim_expect_parse_error("constraint.adm",
                           ADM_HEAD "DIFF/1, IMPLICIT, FUNCTION=DIF(1) - TIME\nEND\n",
                           (const char *const[]){"constraint.adm:6:", "Control_Diff 1",
                                                 "does not read DIF1(1)", "algebraic", NULL});
    sim_expect_parse_error("explicit_rate.adm",
                           ADM_HEAD "DIFF/1, IMPLICIT, FUNCTION=DIF1(1) + DIF1(2)\n"
                                    "DIFF/2, FUNCTION=-DIF(2)\nEND\n",
                           (const char *const[]){"explicit_rate.adm:6:", "DIF1(2)",
                                                 "rate of Control_Diff 2 (line 7)", NULL});
    static const char *const xml =
        "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Control_Diff id=\"4\" type=\"EXPRESSION\" is_implicit=\"TRUE\" expr=\"DIF(4) - 1\"/>\n"
        "</Model></MotionSolve>\n";
    sim_expect_parse_error("constraint.xml", xml,
                           (const char *const[]){"constraint.xml:4:", "Control_Diff 4",
                                                 "does not read DIF1(4)", NULL});
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(linear_residual_against_the_closed_form),
        cmocka_unit_test(a_rejected_step_moves_no_start),
        cmocka_unit_test(nonlinear_residual_against_closed_forms),
        cmocka_unit_test(two_residuals_coupled_through_their_rates),
        cmocka_unit_test(a_force_reading_the_implicit_state),
        cmocka_unit_test(xml_and_dataset_bit_identical),
        cmocka_unit_test(bdf_and_dopri5_agree_and_the_jacobian),
        cmocka_unit_test(bad_implicit_diffs_are_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
