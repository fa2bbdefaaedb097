/*
 * A USERSUB Reference_Variable's value as an input (docs/interface.md
 * §7.10, §5.1): a force, an expression variable and a Control_Diff's rate
 * read it by VARVAL, a Force_StateEqn by its U array, another VARSUB by
 * c_sysfnc VARVAL, each computed at every right-hand side in one order with
 * the expression variables (tests/varsub_support/varsub_routines.c). A
 * spring by VARSUB against the same spring by expression, with both
 * integrators; the order; a cycle through a VARSUB refused; the dataset's
 * VARIABLE, FUNCTION=USER; the BDF Jacobian against differences; and the
 * bad paths: a force routine that asks VARVAL, a command file's VARIABLE
 * redefining a VARSUB variable, a VARSUB that turns NaN.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_runs.h"
#include "sim/simulation/command_schedule.h"
#include "test_support.h"

/* A free body of mass 2 (inertia 0.1, 0.2, 0.4), its centre marker 20 at
 * (1.2, 0.3, -0.2) moving and turning, marker 21 on it off the centre,
 * ground marker 10 at the origin; `elements` after them (from line 7). */
static const char *body_text(const char *elements)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.2\""
             " inertia_zz=\"0.4\" v_ic_x=\"0.3\" v_ic_y=\"-0.5\" v_ic_z=\"0.2\" w_ic_x=\"0.4\""
             " w_ic_z=\"-0.7\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1.2\" pos_y=\"0.3\""
             " pos_z=\"-0.2\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"1.3\" pos_y=\"0.35\""
             " pos_z=\"-0.15\"/>\n"
             "%s"
             "</Model></MotionSolve>\n",
             elements);
    return text;
}

/* The same written as name; its path. */
static const char *body_model(const char *name, const char *elements)
{
    return test_write_file(name, body_text(elements));
}

/* A Reference_Variable id by VARSUB routine with USER list user. */
#define VARSUB(id, routine, user)                                                               \
    "<Reference_Variable id=\"" id "\" type=\"USERSUB\" usrsub_param_string=\"" user "\""       \
    " usrsub_fnc_name=\"" routine "\" usrsub_dll_name=\"" VARSUB_LIBRARY "\"/>\n"
/* A scalar force between markers 21 and 10 of value `value`. */
#define SFORCE(value)                                                                           \
    "<Force_Scalar_TwoBody id=\"9\" type=\"FORCE\" i_marker_id=\"21\" j_marker_id=\"10\""        \
    " val_expression=\"" value "\"/>\n"
/* The spring law both ways: by expression, and by SPRING_VAR's USER list. */
#define LAW "-40*(DM(21,10) - 1)"
#define SPRING_VARSUB(id) VARSUB(id, "SPRING_VAR", "USER(21, 10, 40, 1)")

/* A second free body, moving: its centre marker 30 at (0, -1, 0.5). */
#define THIRD_BODY                                                                              \
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""        \
    " inertia_zz=\"0.1\" v_ic_x=\"-0.4\" v_ic_y=\"0.6\"/>\n"                                     \
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_y=\"-1\" pos_z=\"0.5\"/>\n"

#define T_END 0.4

/* The model at path from its initial state to T_END; the end state
 * (malloc'ed), its size in *n. */
static double *run_path(const char *path, hx_method method, hx_jacobian_method jacobian, int *n)
{
    model m;
    open_model(&m, path);
    double *y = model_state(&m);
    model_initial_state(&m, y);
    const hx_simulation_result r = simulate(&m, method, jacobian, 1e-9, T_END, y);
    if (r.status != HX_INTEGRATION_OK)
        fail_msg("%s: %s", path, r.message);
    *n = m.d.n;
    close_model(&m);
    return y;
}

/* The largest difference of a and b relative to b's largest component. */
static double worst_relative(const double *a, const double *b, int n)
{
    double size = 0.0, diff = 0.0;
    for (int i = 0; i < n; ++i)
        size = fmax(size, fabs(b[i])), diff = fmax(diff, fabs(a[i] - b[i]));
    return diff / size;
}

/* Runs the models at paths a and b with each integrator; fails unless they
 * end within tol of each other (relative). */
static void same_runs(const char *a, const char *b, double tol)
{
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 2; ++k) {
        int na = 0, nb = 0;
        /* BDF on differences of the whole right-hand side: the same Newton
         * matrix for the same right-hand side, hence the same steps */
        double *ya = run_path(a, methods[k], HX_JACOBIAN_FD, &na);
        double *yb = run_path(b, methods[k], HX_JACOBIAN_FD, &nb);
        assert_int_equal(na, nb);
        const double worst = worst_relative(ya, yb, na);
        if (!(worst <= tol))
            fail_msg("%s against %s (%s): %.3g apart", a, b, k == 0 ? "DOPRI5" : "BDF", worst);
        free(ya), free(yb);
    }
}

static void a_force_reading_a_varsub_runs_as_its_expression(void **state)
{
    (void)state;
    const char *direct = body_model("direct.xml", SFORCE(LAW));
    const char *varsub = body_model("varsub.xml", SPRING_VARSUB("5") SFORCE("VARVAL(5)"));
    same_runs(varsub, direct, 1e-12);

    /* BDF on its own Jacobian, the force on body 2 of a spring law of body
     * 3's distance: the force by differences on the columns of the bodies
     * its markers sit on and of those its VARSUB declared (body 3's),
     * against differences of the whole right-hand side (model_runs.h), and
     * the run within the tolerance of the direct one */
    model m;
    double *y = model_diffs_jacobian_checked("bdf.xml", body_text(THIRD_BODY
                                             VARSUB("5", "SPRING_VAR", "USER(30, 10, 40, 1)")
                                             SFORCE("VARVAL(5)")), "varsub force", 1, 0, &m);
    double *y0 = model_state(&m);
    model_initial_state(&m, y0);
    int n = 0;
    double *yd = run_path(body_model("direct_bdf.xml", THIRD_BODY SFORCE("-40*(DM(30,10) - 1)")),
                          HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, &n);
    assert_int_equal(n, m.d.n);
    assert_true(state_difference(&m.d, y, yd, y0) < 1e-6);
    free(y), free(y0), free(yd);
    close_model(&m);
}

/* Defined in the wrong order on purpose: VARSUB 7 reads 6 by c_sysfnc
 * VARVAL, the expression 6 reads VARSUB 5; 0.5 (2 x) is x exactly. */
static void varsubs_and_expression_variables_in_one_order(void **state)
{
    (void)state;
    const char *direct = body_model("direct.xml", SFORCE(LAW));
    const char *chain = body_model("chain.xml",
                                   VARSUB("7", "SCALED_VAR", "USER(6, 0.5)")
                                   "<Reference_Variable id=\"6\" type=\"EXPRESSION\""
                                   " expr=\"2*VARVAL(5)\"/>\n"
                                   SPRING_VARSUB("5") SFORCE("VARVAL(7)"));
    model m;
    open_model(&m, chain);
    const hx_model *mm = m.session.model;
    int place[3];
    for (int i = 0; i < mm->nvariables; ++i)
        for (int id = 5; id <= 7; ++id)
            if (mm->variables[mm->variable_order[i]].id == id)
                place[id - 5] = i;
    assert_true(place[0] < place[1] && place[1] < place[2]);
    close_model(&m);
    same_runs(chain, direct, 1e-12);
}

static void a_cycle_through_a_varsub_is_refused(void **state)
{
    (void)state;
    const char *path = body_model("cycle.xml", VARSUB("5", "SCALED_VAR", "USER(6, 1)")
                                  "<Reference_Variable id=\"6\" type=\"EXPRESSION\""
                                  " expr=\"VARVAL(5) + 1\"/>\n" SFORCE("VARVAL(6)"));
    hx_session s;
    hx_message msg;
    assert_int_equal(hx_session_open(&s, path, stderr, &msg), -1);
    printf("  %s\n", msg.text);
    assert_non_null(strstr(msg.text, "a cycle of variables"));
    assert_non_null(strstr(msg.text, "cycle.xml:7: Reference_Variable 5 (its VARSUB) reads"
                                     " VARVAL(6)"));
    assert_non_null(strstr(msg.text, "cycle.xml:8: Reference_Variable 6 reads VARVAL(5)"));
}

/* A Control_Diff's rate VARVAL(5): the same state as by the law, and its
 * row of the Jacobian against differences. */
static void a_control_diff_rate_reading_a_varsub(void **state)
{
    (void)state;
    const char *direct = body_model("direct.xml", SFORCE(LAW)
                                    "<Control_Diff id=\"8\" type=\"EXPRESSION\" ic=\"0.5\""
                                    " expr=\"" LAW "\"/>\n");
    const char *varsub = body_model("varsub.xml", SPRING_VARSUB("5") SFORCE("VARVAL(5)")
                                    "<Control_Diff id=\"8\" type=\"EXPRESSION\" ic=\"0.5\""
                                    " expr=\"VARVAL(5)\"/>\n");
    same_runs(varsub, direct, 1e-12);
    model m;
    free(model_diffs_jacobian_checked("jacobian.xml", body_text(SPRING_VARSUB("5")
                                      SFORCE("VARVAL(5)") "<Control_Diff id=\"8\""
                                      " type=\"EXPRESSION\" ic=\"0.5\" expr=\"VARVAL(5)\"/>\n"),
                                      "a rate reading a VARSUB", 8, 8, &m));
    close_model(&m);
}

/* A Force_StateEqn (a lag of its input) whose U array names a VARSUB: as
 * the same by an expression variable. */
#define STATEEQN                                                                                \
    "<Reference_Array id=\"30\" type=\"U\" num_element=\"1\" variable_id=\"5\"/>\n"            \
    "<Reference_Array id=\"31\" type=\"X\" num_element=\"1\"/>\n"                              \
    "<Force_StateEqn id=\"1\" type=\"USERSUB\" x_array_id=\"31\" u_array_id=\"30\""              \
    " num_state=\"1\" i_marker_id=\"21\" j_floating_marker_id=\"10\" ref_marker_id=\"10\""       \
    " usrsub_param_string=\"USER(0.05)\" usrsub_fnc_name=\"LAG_FORCE\""                         \
    " usrsub_dll_name=\"" VARSUB_LIBRARY "\"/>\n"

/* Its input a spring law of body 3's distance: the input's columns are
 * those its VARSUB declared, not the element's own bodies'. */
static void a_state_equation_input_by_varsub(void **state)
{
    (void)state;
    const char *direct = body_model("direct.xml", THIRD_BODY "<Reference_Variable id=\"5\""
                                    " type=\"EXPRESSION\" expr=\"-40*(DM(30,10) - 1)\"/>\n"
                                    STATEEQN);
    const char *varsub = body_model("varsub.xml", THIRD_BODY VARSUB("5", "SPRING_VAR",
                                    "USER(30, 10, 40, 1)") STATEEQN);
    same_runs(varsub, direct, 1e-12);
    model m; /* and its Jacobian against differences, as the force's */
    free(model_diffs_jacobian_checked("stateeqn.xml", body_text(THIRD_BODY VARSUB("5",
                                      "SPRING_VAR", "USER(30, 10, 40, 1)") STATEEQN),
                                      "stateeqn input", 1, 0, &m));
    close_model(&m);
}

static void a_dataset_variable_by_varsub(void **state)
{
    (void)state;
    static const char head[] =
        "dataset\nPART/1, GROUND\nMARKER/10, PART = 1\n"
        "PART/2, MASS = 2, CM = 20, IP = 0.1, 0.2, 0.4, VX = 0.3, VY = -0.5, VZ = 0.2\n"
        "MARKER/20, PART = 2, QP = 1.2, 0.3, -0.2\nMARKER/21, PART = 2, QP = 1.3, 0.35, -0.15\n";
    /* a dataset's ROUTINE takes a name, found in MS_USERDLL_DIR */
    char dir[1024];
    snprintf(dir, sizeof dir, "%s", VARSUB_LIBRARY);
    char *slash = strrchr(dir, '/');
    assert_non_null(slash);
    *slash = '\0';
    setenv("MS_USERDLL_DIR", dir, 1);
    char direct[1024], varsub[1024];
    snprintf(direct, sizeof direct, "%sSFORCE/9, TRANSLATION, I = 21, J = 10,\n"
             ", FUNCTION = -40*(DM(21,10) - 1)\nEND\n", head);
    snprintf(varsub, sizeof varsub, "%sVARIABLE/5, FUNCTION = USER(21, 10, 40, 1)\n"
             ", ROUTINE = %s::SPRING_VAR\n"
             "SFORCE/9, TRANSLATION, I = 21, J = 10, FUNCTION = VARVAL(5)\nEND\n", head,
             slash + 1);
    same_runs(test_write_file("varsub.adm", varsub), test_write_file("direct.adm", direct), 1e-12);
}

/* What may not be, each refused with where and why. */
static void bad_paths(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    /* a force routine that asks VARVAL: the forces are computed with the variables */
    const char *force = body_model("force.xml", SPRING_VARSUB("5")
                                   "<Force_Vector_TwoBody id=\"3\" type=\"ForceAndTorque\""
                                   " i_marker_id=\"20\" j_floating_marker_id=\"10\""
                                   " ref_marker_id=\"10\" usrsub_param_string=\"USER(5)\""
                                   " usrsub_fnc_name=\"VARVAL_FORCE\" usrsub_dll_name=\""
                                   VARSUB_LIBRARY "\"/>\n");
    assert_int_equal(hx_session_open(&s, force, stderr, &msg), -1);
    printf("  %s\n", msg.text);
    assert_non_null(strstr(msg.text, "force.xml:8: Force_Vector_TwoBody 3 (VARVAL_FORCE) declares"
                                     " VARVAL(5) in its dependency pass, which the host answers"
                                     " only to a VARSUB or a DIFSUB"));

    /* a command file's VARIABLE may not take a VARSUB variable's value from it */
    model c;
    open_model(&c, body_model("redef.xml", SPRING_VARSUB("5") SFORCE("VARVAL(5)")));
    static const char commands[] = "redef\n\nSIMULATE/DYNAMIC, END=0.5, STEPS=5\n"
                                   "VARIABLE/5, FUNCTION = 1\nSIMULATE/DYNAMIC, END=1, STEPS=5\n";
    hx_command_file *f = hx_command_file_parse(commands, strlen(commands), "redef.acf", &msg);
    assert_non_null(f);
    const hx_command_overrides none = {0};
    hx_command_schedule schedule;
    assert_int_equal(hx_command_schedule_make(f, "redef.acf", c.session.model, "redef.xml", 1e-9,
                                              1e-9, &none, NULL, &schedule, &msg), -1);
    assert_contains(msg.text, "redef.acf:4: VARIABLE/5: its value is its VARSUB's",
                    "(FUNCTION=USER, line 7)");
    hx_command_file_free(f);
    close_model(&c);

    /* a VARSUB that turns NaN stops the run naming it */
    model m;
    open_model(&m, body_model("nan.xml", VARSUB("5", "NAN_VAR", "USER(0.1)")
                              SFORCE("VARVAL(5)")));
    double *y = model_state(&m);
    model_initial_state(&m, y);
    const hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-9, T_END, y);
    assert_int_not_equal(r.status, HX_INTEGRATION_OK);
    assert_non_null(strstr(r.message, "nan.xml:7: Reference_Variable 5 (NAN_VAR) returned a"
                                      " non-finite value at t = 0.1"));
    free(y);
    close_model(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_force_reading_a_varsub_runs_as_its_expression),
        cmocka_unit_test(varsubs_and_expression_variables_in_one_order),
        cmocka_unit_test(a_cycle_through_a_varsub_is_refused),
        cmocka_unit_test(a_control_diff_rate_reading_a_varsub),
        cmocka_unit_test(a_state_equation_input_by_varsub),
        cmocka_unit_test(a_dataset_variable_by_varsub),
        cmocka_unit_test(bad_paths),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
