/*
 * A command file's VARIABLE/id, FUNCTION= between segments (docs/interface.md
 * §9.9): a push read from a variable follows the closed form of each
 * segment's definition with DOPRI5 and BDF; a redefinition that reads another
 * body through a variable it now reads, in an order the model's did not
 * have, is followed too, and BDF's Jacobian (its pattern widened before the
 * run) equals differences in that segment; the model's definitions are back
 * after a run; a cycle, an unknown id, a bad expression, a rate and a state
 * equation's input are refused with the command file's file:line(:column).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "model_runs.h"
#include "sim/simulation/command_schedule.h"
#include "test_support.h"

/* Body 2 (2 kg) at the origin at rest, pushed along x by VARVAL(1); body 3
 * (1 kg) moving freely along x at 1 m/s from x = 0 (x3 = t); no gravity.
 * VARIABLE 1 is 0 and VARIABLE 2 is 3 TIME in the model. */
static const char *const dataset =
    "redef: a push read from a variable a command file redefines\n"
    "PART/1, GROUND\nMARKER/10, PART = 1\nMARKER/31, PART = 1\n"
    "PART/2, MASS = 2, CM = 20, IP = 1, 1, 1\nMARKER/20, PART = 2, QP = 0, 0, 0\n"
    "PART/3, MASS = 1, CM = 30, IP = 1, 1, 1, VX = 1\nMARKER/30, PART = 3, QP = 0, 1, 0\n"
    "VARIABLE/1, FUNCTION = 0\n"
    "VARIABLE/2, FUNCTION = 3*TIME\n"
    "VFORCE/1, I = 20, JFLOAT = 31, RM = 10, FX = VARVAL(1), FY = 0, FZ = 0\n"
    "END\n";

/* VARIABLE 1 from 0 to 10 at 0.5 s: x2 = 0 to 0.5 s, then 10 N on 2 kg,
 * x2 = 2.5 (t - 0.5)^2 (x2(1) = 0.625). */
static const char *const constant_push =
    "redef\n\nSIMULATE/DYNAMIC, END=0.5, STEPS=5\nVARIABLE/1, FUNCTION = 10\n"
    "SIMULATE/DYNAMIC, END=1, STEPS=5\n";

/* At 0.5 s VARIABLE 2 becomes -100 DX(30,10) = -100 x3 = -100 t (body 3, which
 * neither the load nor the model's variables read) and VARIABLE 1 reads it
 * (so it is computed after VARIABLE 2, the model's order reversed): a2 =
 * -50 t, v2 = -25 (t^2 - 0.25), x2 = -25 ((t^3 - 0.125)/3 - 0.25 (t - 0.5))
 * (x2(1) = -25 (0.875/3 - 0.125) = -4.1667). */
static const char *const body_push =
    "redef\n\nSIMULATE/DYNAMIC, END=0.5, STEPS=5\n"
    "VARIABLE/2, FUNCTION = -100*DX(30,10)\nVARIABLE/1, FUNCTION = VARVAL(2)\n"
    "SIMULATE/DYNAMIC, END=1, STEPS=5\n";

static double constant_x(double t)
{
    return t > 0.5 ? 2.5 * (t - 0.5) * (t - 0.5) : 0.0;
}

static double body_x(double t)
{
    return t > 0.5 ? -25.0 * ((t * t * t - 0.125) / 3.0 - 0.25 * (t - 0.5)) : 0.0;
}

typedef struct follow {
    double (*x)(double t);
    double worst;
    int outputs;
} follow;

/* At each output: body 2's x against the closed form. */
static int observe(void *ctx, const hx_dynamics *d, hx_dynamics_data *dd, double t,
                   const double *y)
{
    (void)dd;
    follow *f = ctx;
    const int body = hx_model_marker(d->m, 20) >= 0 ? d->m->markers[hx_model_marker(d->m, 20)].body
                                                    : -1;
    assert_true(body >= 0);
    f->worst = fmax(f->worst, fabs(y[d->dof[body].q] - f->x(t)));
    f->outputs++;
    return 0;
}

static void schedule_of(const model *m, const char *acf_text, hx_command_schedule *s)
{
    hx_message msg;
    hx_command_file *f = hx_command_file_parse(acf_text, strlen(acf_text), "redef.acf", &msg);
    if (f == NULL)
        fail_msg("%s", msg.text);
    const hx_command_overrides none = {0};
    if (hx_command_schedule_make(f, "redef.acf", m->session.model, "redef.adm", 1e-10, 1e-10,
                                 &none, NULL, s, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_command_file_free(f);
}

/* The schedule of acf_text run with method on m: the largest distance of x2
 * from x_of at the outputs; the result in r, the end state in y_end. */
static double run(model *m, const char *acf_text, hx_method method, double (*x_of)(double),
                  hx_simulation_result *r, double *y_end)
{
    hx_command_schedule s;
    schedule_of(m, acf_text, &s);
    follow f = {x_of, 0.0, 0};
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = method;
    so.integration.jacobian = HX_JACOBIAN_ANALYTIC;
    so.integration.t_end = s.t_end;
    so.observer = observe;
    so.observer_ctx = &f;
    so.skip_energy = 1;
    if (hx_simulate_segments(&m->d, &so, s.segments, s.nsegments, y_end, r) != 0)
        fail_msg("%s", r->message);
    hx_command_schedule_free(&s);
    assert_int_equal(f.outputs, 11); /* t = 0 and five a segment */
    return f.worst;
}

/* DOPRI5 is exact on these polynomials (to rounding); BDF within its
 * tolerance (1e-10). */
static void each_segment_follows_its_definition(void **state)
{
    (void)state;
    model m;
    open_model(&m, test_write_file("redef.adm", dataset));
    double *y = model_state(&m);
    hx_simulation_result r;
    assert_true(run(&m, constant_push, HX_METHOD_DOPRI5, constant_x, &r, y) < 1e-12);
    assert_close(y[m.d.dof[1].q], 0.625, 0.0, 1e-12); /* it moved: not 0 all along */
    assert_true(run(&m, constant_push, HX_METHOD_BDF, constant_x, &r, y) < 1e-6);
    assert_int_equal(r.jacobian_outside, 0);
    assert_true(run(&m, body_push, HX_METHOD_DOPRI5, body_x, &r, y) < 1e-12);
    assert_close(y[m.d.dof[1].q], -25.0 * (0.875 / 3.0 - 0.125), 0.0, 1e-12);
    assert_true(run(&m, body_push, HX_METHOD_BDF, body_x, &r, y) < 1e-6);
    assert_int_equal(r.jacobian_outside, 0); /* body 3's columns in body 2's rows */
    free(y);
    close_model(&m);
}

/* A run puts the model's definitions back however it ends: a second run is
 * the first bit for bit, and a run of no command file after it is the
 * model's (VARIABLE 1 = 0: body 2 stays at the origin), its programs and
 * order the ones read. */
static void the_model_definitions_are_back_after_a_run(void **state)
{
    (void)state;
    model m;
    open_model(&m, test_write_file("redef.adm", dataset));
    const hx_model *mm = m.session.model;
    hx_expr_program *programs[2] = {mm->variables[0].program, mm->variables[1].program};
    const int order[2] = {mm->variable_order[0], mm->variable_order[1]};
    double *a = model_state(&m), *b = model_state(&m);
    hx_simulation_result r;
    run(&m, body_push, HX_METHOD_DOPRI5, body_x, &r, a);
    assert_ptr_equal(mm->variables[0].program, programs[0]);
    assert_ptr_equal(mm->variables[1].program, programs[1]);
    assert_memory_equal(mm->variable_order, order, sizeof order);
    run(&m, body_push, HX_METHOD_DOPRI5, body_x, &r, b);
    assert_memory_equal(a, b, sizeof(double) * (size_t)m.d.n);
    r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-10, 1.0, a);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    assert_true(a[m.d.dof[1].q] == 0.0);
    free(a), free(b);
    close_model(&m);
}

/* In the second segment of body_push: BDF's Jacobian, built with the
 * pattern of the model's definitions widened by the segment's
 * (hx_jacobian_widen), against central differences of the right-hand side
 * under the segment's definitions; d(udot2_x)/d(x3) = -100/2 = -50 is in it. */
/* BDF's Jacobian of the model text in the second segment of acf (its pattern
 * widened before, as a run does) against central differences of the
 * right-hand side at a state where body 2 is moved and body 3 moves: every
 * entry within 1e-5, none outside the pattern; returns d(u2x')/d(x3). */
static double second_segment_jacobian(const char *text, const char *acf)
{
    model m;
    open_model(&m, test_write_file("redef.adm", text));
    hx_command_schedule s;
    schedule_of(&m, acf, &s);
    assert_int_equal(s.nsegments, 2);
    assert_null(s.segments[0].variables);
    assert_non_null(s.segments[1].variables);
    hx_variable_definitions own;
    hx_message msg;
    assert_int_equal(hx_variable_definitions_of(&own, m.session.model, &msg), 0);
    hx_jacobian jac;
    if (hx_jacobian_init(&jac, &m.d, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_variable_definitions_apply(s.segments[1].variables, m.session.model);
    if (hx_jacobian_widen(&jac, &msg) != 0)
        fail_msg("%s", msg.text);
    const int n = m.d.n;
    double *y = model_state(&m), *fy = model_state(&m), *up = model_state(&m),
           *down = model_state(&m);
    model_initial_state(&m, y);
    const int x2 = m.d.dof[1].q, x3 = m.d.dof[2].q, u2 = m.d.nq + m.d.dof[1].u;
    y[x2] = 0.1, y[x3] = 0.7, y[m.d.nq + m.d.dof[2].u] = 1.0;
    double *values = calloc((size_t)jac.pattern.nnz + 1, sizeof(double));
    assert_non_null(values);
    if (hx_dynamics_rhs(&m.d, &m.data, 0.7, y, fy) != 0 ||
        hx_jacobian_build(&jac, 0.7, y, fy, values) != 0)
        fail_msg("%s %s", m.data.message, jac.dd.message);
    assert_int_equal(jac.outside, 0);
    double worst = 0.0;
    for (int c = 0; c < n; ++c) {
        const double h = 1e-6 * fmax(1.0, fabs(y[c])), keep = y[c];
        y[c] = keep + h;
        assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.7, y, up), 0);
        y[c] = keep - h;
        assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.7, y, down), 0);
        y[c] = keep;
        for (int row = 0; row < n; ++row) {
            if (row == m.d.load_work || row == m.d.element_work)
                continue; /* the work accumulators' rows are on nothing (newton_matrix.h) */
            const int at = hx_sparsity_find(&jac.pattern, row, c);
            const double exact = at >= 0 ? values[at] : 0.0;
            const double e = fabs(exact - (up[row] - down[row]) / (2.0 * h));
            if (e > 1e-5)
                print_message("row %d column %d: %g against %g\n", row, c, exact,
                              (up[row] - down[row]) / (2.0 * h));
            worst = fmax(worst, e);
        }
    }
    assert_true(worst < 1e-5);
    const int at = hx_sparsity_find(&jac.pattern, u2, x3);
    assert_true(at >= 0);
    const double entry = values[at];
    hx_variable_definitions_apply(&own, m.session.model);
    hx_variable_definitions_free(&own);
    free(values), free(y), free(fy), free(up), free(down);
    hx_jacobian_free(&jac);
    hx_command_schedule_free(&s);
    close_model(&m);
    return entry;
}

static void the_jacobian_follows_the_segment(void **state)
{
    (void)state;
    assert_close(second_segment_jacobian(dataset, body_push), -50.0, 0.0, 1e-5);
}

/* The same push on body 2 hung from the ground by a SPHERICAL joint 1 m above
 * its centre: its accelerations are a group of the constraint system, whose
 * rows BDF's Jacobian writes at places found in the pattern; the widened
 * pattern gives them body 3's column, and the places must be found again.
 * By hand (m = 2, unit inertias, the arm r = (0, 1, 0) from the centre, at
 * rest): the pivot's force l along x gives m a = F + l, alpha = r x l, and
 * the pivot held, a + alpha x r = 0, so l (1/m + 1) = -F/m, l = -F/3 and
 * a = (F - F/3)/2 = F/3; F = VARVAL(1) = -100 x3: d(u2x')/d(x3) = -100/3. */
static const char *const hung =
    "redef: the push on a hung body\n"
    "PART/1, GROUND\nMARKER/10, PART = 1\nMARKER/31, PART = 1\n"
    "MARKER/11, PART = 1, QP = 0, 1, 0\n"
    "PART/2, MASS = 2, CM = 20, IP = 1, 1, 1\nMARKER/20, PART = 2, QP = 0, 0, 0\n"
    "MARKER/21, PART = 2, QP = 0, 1, 0\n"
    "PART/3, MASS = 1, CM = 30, IP = 1, 1, 1, VX = 1\nMARKER/30, PART = 3, QP = 0, 1, 0\n"
    "JOINT/1, SPHERICAL, I = 21, J = 11\n"
    "VARIABLE/1, FUNCTION = 0\n"
    "VARIABLE/2, FUNCTION = 3*TIME\n"
    "VFORCE/1, I = 20, JFLOAT = 31, RM = 10, FX = VARVAL(1), FY = 0, FZ = 0\n"
    "END\n";

static void the_jacobian_of_a_constrained_group_follows_the_segment(void **state)
{
    (void)state;
    assert_close(second_segment_jacobian(hung, body_push), -100.0 / 3.0, 0.0, 1e-5);
}

static void refused(const hx_model *m, const char *commands, const char *a, const char *b,
                    const char *c)
{
    char text[1024];
    snprintf(text, sizeof text, "redef\n\nSIMULATE/DYNAMIC, END=0.5, STEPS=5\n%s"
             "SIMULATE/DYNAMIC, END=1, STEPS=5\n", commands);
    hx_message msg;
    hx_command_file *f = hx_command_file_parse(text, strlen(text), "redef.acf", &msg);
    if (f == NULL)
        fail_msg("%s", msg.text);
    const hx_command_overrides none = {0};
    hx_command_schedule s;
    assert_int_equal(hx_command_schedule_make(f, "redef.acf", m, "redef.adm",
                                              1e-10, 1e-10, &none, NULL, &s, &msg), -1);
    assert_contains(msg.text, a, b, c);
    hx_command_file_free(f);
}

/* A state equation's input (a U array's variable: TIME and measures only) and a
 * Control_Diff by an expression, on a model read alone (no library bound). */
static const char inputs[] =
    "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
    " inertia_zz=\"1\"/>\n<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
    "<Reference_Variable id=\"1\" expr=\"DX(20,10)\"/>\n"
    "<Reference_Variable id=\"2\" expr=\"2*DX(20,10)\"/>\n"
    "<Reference_Array id=\"30\" type=\"U\" num_element=\"1\" variable_id=\"1\"/>\n"
    "<Reference_Array id=\"31\" type=\"X\" num_element=\"1\"/>\n"
    "<Control_Diff id=\"5\" type=\"EXPRESSION\" expr=\"-DIF(5)\" ic=\"1\"/>\n"
    "<Force_StateEqn id=\"7\" type=\"USERSUB\" i_marker_id=\"20\" j_floating_marker_id=\"10\""
    " ref_marker_id=\"10\" usrsub_param_string=\"USER(1)\" x_array_id=\"31\" u_array_id=\"30\""
    " num_state=\"1\"/>\n</Model></MotionSolve>\n";

static void what_cannot_be_redefined_is_refused(void **state)
{
    (void)state;
    model mm;
    open_model(&mm, test_write_file("redef.adm", dataset));
    const hx_model *m = mm.session.model;
    /* a cycle: each variable of it with the line that defines it */
    refused(m, "VARIABLE/1, FUNCTION = VARVAL(2)\nVARIABLE/2, FUNCTION = 1 + VARVAL(1)\n",
            "redef.acf:5: VARIABLE/2: a cycle of variables",
            "redef.acf:5: Reference_Variable 2 reads VARVAL(1)",
            "redef.acf:4: Reference_Variable 1 reads VARVAL(2)");
    refused(m, "VARIABLE/1, FUNCTION = 2*VARVAL(1)\n", "redef.acf:4: VARIABLE/1: a cycle",
            "redef.acf:4: Reference_Variable 1 reads VARVAL(1)", "");
    refused(m, "VARIABLE/7, FUNCTION = 1\n", "redef.acf:4: VARIABLE/7: ",
            "the model has no VARIABLE/7", "");
    /* the expression's own errors, at their line and column in the command file */
    refused(m, "VARIABLE/1, FUNCTION = DX(20,99)\n", "redef.acf:4:24: VARIABLE/1: FUNCTION: ",
            "DX(20,99)", "99");
    refused(m, "VARIABLE/1, FUNCTION = 1 +\n", "redef.acf:4:", "VARIABLE/1: FUNCTION: ", "");
    refused(m, "VARIABLE/1, FUNCTION = VARVAL(9)\n", "redef.acf:4:24: VARIABLE/1: FUNCTION: ",
            "VARVAL(9)", "");
    close_model(&mm);
    hx_message msg;
    hx_model *u = hx_model_parse(inputs, strlen(inputs), "inputs.xml", NULL, &msg);
    if (u == NULL)
        fail_msg("%s", msg.text);
    refused(u, "VARIABLE/1, FUNCTION = 3*VARVAL(2)\n", "redef.acf:4:26: VARIABLE/1: FUNCTION: ",
            "VARVAL(2): an input of a state equation (the U array 30 names it)",
            "reads TIME and measures only");
    refused(u, "VARIABLE/2, FUNCTION = DIF1(5)\n", "redef.acf:4:24: DIF1(5): ",
            "a variable reads a Control_Diff's state (DIF), not its rate", "");
    hx_model_free(u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(each_segment_follows_its_definition),
        cmocka_unit_test(the_model_definitions_are_back_after_a_run),
        cmocka_unit_test(the_jacobian_follows_the_segment),
        cmocka_unit_test(the_jacobian_of_a_constrained_group_follows_the_segment),
        cmocka_unit_test(what_cannot_be_redefined_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
