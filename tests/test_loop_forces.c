/*
 * Other elements' forces read by forces (docs/interface.md §8.8): a motion's,
 * a coupler's and a general constraint's force (MOTION, COUPLER, GCON), a
 * user routine's force (SFORCE of an SFOSUB) and the net force at a marker
 * (FZ) as inputs of the algebraic loop, each against a balance worked by
 * hand with the force reading c times what it reads: a slider driven against
 * gravity, two coupled wheels, a point mass on a rod, a spring-mass whose
 * frequency becomes sqrt(k (1 + c) / m) (run with DOPRI5 and BDF); c = -1
 * leaves the loop no solution, refused naming its input.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_runs.h"
#include "sim_support.h"
#include "test_support.h"

#define TOL 1e-9
#define C 0.5 /* the share of what it reads each force adds */

/* A 3 kg slider up the world's z, driven at z = TIME**2 (a = 2) against
 * gravity, pushed by c times the motion's own force F:
 * m a = F (1 + c) - m g, F = (6 + 29.43) / 1.5 = 23.62. */
static const char *slider(const char *name, const char *c)
{
    char text[1024];
    snprintf(text, sizeof text, "slider\n"
             "ACCGRAV/IGRAV = 0, JGRAV = 0, KGRAV = -9.81\n"
             "PART/1, GROUND\n"
             "MARKER/10, PART = 1\n"
             "MARKER/11, PART = 1\n"
             "PART/2, MASS = 3, CM = 20, IP = 1, 1, 1\n"
             "MARKER/20, PART = 2\n"
             "MARKER/21, PART = 2\n"
             "JOINT/1, TRANSLATIONAL, I = 21, J = 10\n"
             "MOTION/2, JOINT = 1, TRANSLATION, FUNCTION = TIME**2\n"
             "VFORCE/5, I = 20, JFLOAT = 11, RM = 11, FX = 0, FY = 0,\n"
             ", FZ = %s*MOTION(2, 0, 4, 0)\nEND\n", c);
    return test_write_file(name, text);
}

static void a_force_of_a_motions_force(void **state)
{
    (void)state;
    evaluated e;
    evaluate_path(&e, slider("slider.adm", "0.5"));
    assert_int_equal(e.m.session.model->nloop_inputs, 1);
    const double F = (6.0 + 29.43) / (1.0 + C);
    EXPECT(&e, "MOTION(2, 0, 4, 0)", F, TOL);
    EXPECT(&e, "VFORCE(5, 0, 4, 0)", C * F, TOL);
    EXPECT(&e, "ACCZ(20)", 2.0, TOL);
    release(&e);
}

/* Two wheels on revolutes to ground, 0.5 and 1.5 about their axes, coupled
 * theta1 + 2 theta2 = 0: the coupler's torques lambda and 2 lambda, 3 on
 * the first and c times the coupler's torque on it: 0.5 alpha1 = 3 +
 * (1 + c) lambda, 1.5 alpha2 = 2 lambda, alpha1 = -2 alpha2, so
 * lambda = -3 / (4/3 + 1 + c) = -18/17 (-9/7 with c = 0). */
static void a_torque_of_a_couplers_torque(void **state)
{
    (void)state;
    evaluated e;
    evaluate_text(&e, "coupler.adm", "coupler\n"
                  "PART/1, GROUND\n"
                  "MARKER/10, PART = 1\n"
                  "MARKER/11, PART = 1, QP = 2, 0, 0\n"
                  "PART/2, MASS = 1, CM = 20, IP = 1, 1, 0.5\n"
                  "MARKER/20, PART = 2\n"
                  "PART/3, MASS = 1, CM = 31, IP = 1, 1, 1.5\n"
                  "MARKER/31, PART = 3, QP = 2, 0, 0\n"
                  "JOINT/1, REVOLUTE, I = 20, J = 10\n"
                  "JOINT/2, REVOLUTE, I = 31, J = 11\n"
                  "COUPLER/1, JOINTS = 1, 2, TYPE = R:R, SCALES = 1, 2\n"
                  "SFORCE/5, ROTATION, I = 20, J = 10, FUNCTION = 3\n"
                  "SFORCE/6, ROTATION, I = 20, J = 10, FUNCTION = 0.5*COUPLER(1, 0, 8, 0)\n"
                  "END\n");
    const double lambda = -18.0 / 17.0;
    EXPECT(&e, "COUPLER(1, 0, 8, 0)", lambda, TOL);
    EXPECT(&e, "COUPLER(1, 2, 8, 0)", 2.0 * lambda, TOL);
    EXPECT(&e, "SFORCE(6, 0, 8, 0)", C * lambda, TOL);
    EXPECT(&e, "WDTZ(20)", 2.0 * (3.0 + (1.0 + C) * lambda), TOL);
    release(&e);
}

/* 3 kg on a massless rod 2 long (DM(20,10) - 2), at the bottom moving 1
 * sideways, pushed up by c times the rod's pull T on it: T (1 + c) =
 * m v^2 / L + m g, T = (1.5 + 29.43) / 1.5. */
static void a_force_of_a_general_constraints_force(void **state)
{
    (void)state;
    evaluated e;
    evaluate_text(&e, "gcon.adm", "gcon\n"
                  "ACCGRAV/IGRAV = 0, JGRAV = -9.81, KGRAV = 0\n"
                  "PART/1, GROUND\n"
                  "MARKER/10, PART = 1\n"
                  "PART/2, MASS = 3, CM = 20, IP = 0.2, 0.2, 0.2, VX = 1\n"
                  "MARKER/20, PART = 2, QP = 0, -2, 0\n"
                  "GCON/1, I = 20, FUNCTION = DM(20, 10) - 2\n"
                  "VFORCE/5, I = 20, JFLOAT = 10, RM = 10, FX = 0, FY = 0.5*GCON(1, 0, 3, 0),"
                  " FZ = 0\nEND\n");
    const double T = (1.5 + 29.43) / (1.0 + C);
    EXPECT(&e, "GCON(1, 0, 3, 0)", T, TOL);
    EXPECT(&e, "VFORCE(5, 0, 3, 0)", C * T, TOL);
    EXPECT(&e, "ACCY(20)", 0.5, TOL); /* v^2 / L up, to the pivot */
    release(&e);
}

/* A 2 kg body on a spring of k 100 and length 1 along z from ground's
 * origin, 0.1 stretched, no gravity, pushed by `pushed` (c times the
 * spring's force, at marker 22 where the spring's I 20 is): z'' =
 * -k (z - 1) (1 + c) / m, so z = 1 + 0.1 cos(w t), w = sqrt(75). */
static const char *spring_mass(const char *name, const char *spring, const char *pushed)
{
    char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Reference_Marker id=\"11\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""
             " inertia_zz=\"0.1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_z=\"1.1\"/>\n"
             "<Reference_Marker id=\"22\" body_id=\"2\" pos_z=\"1.1\"/>\n"
             "%s\n"
             "<Force_Vector_OneBody id=\"5\" marker_id=\"22\" ref_marker_id=\"11\""
             " fz_expression=\"%s\"/>\n"
             "</Model></MotionSolve>\n", spring, pushed);
    return test_write_file(name, text);
}

enum { Z = 2 };

static void spring_mass_oscillates_at_the_pushed_frequency(const char *path)
{
    model m;
    open_model(&m, path);
    assert_int_equal(m.session.model->nloop_inputs, 1);
    double *y = model_state(&m), *ydot = model_state(&m);
    model_initial_state(&m, y);
    assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.0, y, ydot), 0);
    assert_close(ydot[m.d.nq + Z], -100.0 * 0.1 * (1.0 + C) / 2.0, 0, 1e-9);
    const double w = sqrt(100.0 * (1.0 + C) / 2.0);
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 2; ++k) {
        model_initial_state(&m, y);
        const hx_simulation_result r = simulate(&m, methods[k], HX_JACOBIAN_ANALYTIC, 1e-9,
                                                1.0, y);
        assert_int_equal(r.status, HX_INTEGRATION_OK);
        assert_close(y[Z], 1.0 + 0.1 * cos(w), 0, 1e-6);
    }
    free(y), free(ydot);
    close_model(&m);
}

/* A user routine's force (LINE_SPRING, an SFOSUB of tests/user_libraries)
 * read as SFORCE(1, 0, 4, 0). */
static void a_force_of_a_user_routines_force(void **state)
{
    (void)state;
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    spring_mass_oscillates_at_the_pushed_frequency(spring_mass(
        "user_spring.xml",
        "<Force_Scalar_TwoBody id=\"1\" type=\"FORCE\" i_marker_id=\"20\" j_marker_id=\"10\""
        " usrsub_param_string=\"USER(20, 10, 100, 1)\" usrsub_fnc_name=\"LINE_SPRING\""
        " usrsub_dll_name=\"libtp_scalar.so\"/>",
        "0.5*SFORCE(1, 0, 4, 0)"));
}

/* The net force at marker 20 from what acts between it and 10 (the spring by
 * an expression; the pushing force acts between 22 and 11, not summed). */
static void a_force_of_the_force_at_a_marker(void **state)
{
    (void)state;
    spring_mass_oscillates_at_the_pushed_frequency(spring_mass(
        "marker_spring.xml",
        "<Force_Scalar_TwoBody id=\"1\" type=\"FORCE\" i_marker_id=\"20\" j_marker_id=\"10\""
        " val_expression=\"-100*(DM(20, 10) - 1)\"/>",
        "0.5*FZ(20, 10)"));
}

/* c = -1: m a = F (1 - 1) - m g has no F; the run refused, naming the
 * loop's input and its element. */
static void a_loop_without_a_solution_is_refused_naming_it(void **state)
{
    (void)state;
    model m;
    open_model(&m, slider("singular.adm", "-1"));
    double *y = model_state(&m), *ydot = model_state(&m);
    model_initial_state(&m, y);
    assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, 0.0, y, ydot), -1);
    const char *text = m.data.message;
    printf("%s\n", text);
    assert_contains(text, "the algebraic loop of MOTION(2,0,4,0)", "at t = 0", "no solution");
    free(y), free(ydot);
    close_model(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_force_of_a_motions_force),
        cmocka_unit_test(a_torque_of_a_couplers_torque),
        cmocka_unit_test(a_force_of_a_general_constraints_force),
        cmocka_unit_test(a_force_of_a_user_routines_force),
        cmocka_unit_test(a_force_of_the_force_at_a_marker),
        cmocka_unit_test(a_loop_without_a_solution_is_refused_naming_it),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
