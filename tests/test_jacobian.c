/*
 * The Jacobian of the dynamics (sim/jacobian/) from the elements' own
 * partials, against differences of the whole right-hand side, entry by
 * entry: on the bundled models and chains, a third party's field, the
 * routines' rows, jointed bodies, state equations; a GFOSUB twin that
 * disagrees with its element set aside; non-finite partials named.
 */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "model_runs.h"
#include "sim/jacobian/jacobian.h"
#include "sim_support.h"
#include "test_support.h"

static void compare_jacobians(model *m, double t, const double *y, const char *what,
                              hx_partials_source expected)
{
    hx_jacobian jac;
    hx_message msg;
    assert_int_equal(hx_jacobian_init(&jac, &m->d, &msg), 0);
    for (int k = 0; k < jac.nf; ++k)
        assert_int_equal(jac.source[k], expected);
    hx_jacobian_free(&jac);
    long outside = 0;
    const double worst = jacobian_against_differences(&m->d, t, y, what, &outside);
    assert_int_equal(outside, 0);
    assert_true(worst < 1e-6);
}

/* The Jacobian of a model after t_end of DOPRI5, against differences,
 * every force element's partials from the expected source. */
static void jacobian_after(const char *path, double t_end, const char *what,
                           hx_partials_source expected)
{
    model m;
    open_model(&m, path);
    double *y = model_state(&m);
    hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-8, t_end, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    compare_jacobians(&m, t_end, y, what, expected);
    free(y);
    close_model(&m);
}

/* Rolled by the engine torque, mounts in their limits. */
static void jacobian_equals_differences_on_the_powertrain(void **state)
{
    (void)state;
    jacobian_after(EXAMPLES_DIR "/powertrain.xml", 0.6, "powertrain.xml at t = 0.6 s",
                   HX_PARTIALS_TWIN);
}

/* A third party's FIESUB that fills dfddis only when dflag is set and never
 * writes dfdvel (tests/user_libraries/tp_habits_field.c): the Newton matrix
 * asks for them so, and equals the differences. */
static void jacobian_asks_a_field_for_its_partials(void **state)
{
    (void)state;
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    jacobian_after(USER_LIBRARIES_DIR "/tp_habits_field.xml", 0.01,
                   "tp_habits_field.xml at t = 0.01 s", HX_PARTIALS_FIESUB);
}

/* A Control_Diff's row (DIFSUB differenced in what it reads) and a driven
 * joint's rows (zero: a function of time) (tests/user_libraries/tp_routines.c);
 * the OneBody force's partials by differences of the element alone. */
static void jacobian_has_the_routines_rows(void **state)
{
    (void)state;
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    jacobian_after(USER_LIBRARIES_DIR "/tp_routines.xml", 0.02, "tp_routines.xml at t = 0.02 s",
                   HX_PARTIALS_DIFFERENCES);
}

/* Elements with partials on jointed bodies: a revolute and a slider body
 * (one coordinate each) joined to each other both ways, a free body's I on
 * the revolute's J, an I on ground; then a GFOSUB twin with I on the slider
 * and J (its axes) on the revolute. Every body kind on either side of an
 * element, against differences. */
static const char jointed_model[] =
    "<MotionSolve><Model>\n"
    "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\""
    " time_unit=\"SECOND\"/>\n"
    "<Reference_String id=\"401\" string=\"%s/flex_coupled.gfj\"/>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"10\" body_id=\"1\" pos_x=\"5\" pos_y=\"3\" a00=\"0.8\" a01=\"-0.6\""
    " a02=\"0\" a10=\"0.6\" a11=\"0.8\" a12=\"0\" a20=\"0\" a21=\"0\" a22=\"1\"/>\n"
    "<Reference_Marker id=\"11\" body_id=\"1\" pos_y=\"40\" a00=\"0\" a10=\"1\" a20=\"0\""
    " a01=\"0\" a11=\"0\" a21=\"1\" a02=\"1\" a12=\"0\" a22=\"0\"/>\n"
    "<Reference_Marker id=\"12\" body_id=\"1\" pos_x=\"2\" pos_z=\"1\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"2000\" inertia_yy=\"2500\""
    " inertia_zz=\"3000\" w_ic_z=\"2\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"40\" pos_y=\"-30\" pos_z=\"3\"/>\n"
    "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"5\" pos_y=\"3\" a00=\"0.8\" a01=\"-0.6\""
    " a02=\"0\" a10=\"0.6\" a11=\"0.8\" a12=\"0\" a20=\"0\" a21=\"0\" a22=\"1\"/>\n"
    "<Reference_Marker id=\"22\" body_id=\"2\" pos_x=\"30\" pos_y=\"20\" pos_z=\"2\"/>\n"
    "<Reference_Marker id=\"23\" body_id=\"2\" pos_x=\"-20\" pos_y=\"10\" pos_z=\"-2\"/>\n"
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"4\" inertia_xx=\"800\" inertia_yy=\"1000\""
    " inertia_zz=\"1200\" v_ic_z=\"30\"/>\n"
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"10\" pos_y=\"40\" pos_z=\"4\"/>\n"
    "<Reference_Marker id=\"31\" body_id=\"3\" pos_y=\"40\" a00=\"0\" a10=\"1\" a20=\"0\""
    " a01=\"0\" a11=\"0\" a21=\"1\" a02=\"1\" a12=\"0\" a22=\"0\"/>\n"
    "<Reference_Marker id=\"32\" body_id=\"3\" pos_x=\"31\" pos_y=\"20.5\" pos_z=\"2.3\"/>\n"
    "<Reference_Marker id=\"33\" body_id=\"3\" pos_x=\"-19\" pos_y=\"10.5\" pos_z=\"-1.5\"/>\n"
    "<Body_Rigid id=\"4\" cg_id=\"40\" mass=\"3\" inertia_xx=\"3000\" inertia_yy=\"4000\""
    " inertia_zz=\"5000\" v_ic_x=\"5\" v_ic_y=\"-3\" v_ic_z=\"2\" w_ic_x=\"0.2\""
    " w_ic_y=\"-0.3\" w_ic_z=\"0.25\"/>\n"
    "<Reference_Marker id=\"40\" body_id=\"4\" pos_x=\"30\" pos_y=\"21\" pos_z=\"1.5\"/>\n"
    "<Reference_Marker id=\"41\" body_id=\"4\" pos_x=\"30.8\" pos_y=\"20.5\" pos_z=\"2.3\""
    " a00=\"0.998300856485\" a01=\"-0.051137192285\" a02=\"-0.027935416720\""
    " a10=\"0.049956680331\" a11=\"0.997891416697\" a12=\"-0.041437308954\""
    " a20=\"0.029995500202\" a21=\"0.039971340336\" a22=\"0.998750500335\"/>\n"
    "<Reference_Marker id=\"42\" body_id=\"4\" pos_x=\"2.5\" pos_y=\"0.4\" pos_z=\"1.2\"/>\n"
    "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
    "<Constraint_Joint id=\"2\" type=\"TRANSLATIONAL\" i_marker_id=\"31\" j_marker_id=\"11\"/>\n"
    "%s</Model></MotionSolve>\n";

static void jacobian_on_jointed_bodies_with_partials(void **state)
{
    (void)state;
    static const char fields[] =
        "<Force_Field id=\"1\" i_marker_id=\"22\" j_marker_id=\"32\""
        " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n"
        "<Force_Field id=\"2\" i_marker_id=\"33\" j_marker_id=\"23\""
        " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n"
        "<Force_Field id=\"3\" i_marker_id=\"41\" j_marker_id=\"22\""
        " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n"
        "<Force_Field id=\"4\" i_marker_id=\"12\" j_marker_id=\"42\""
        " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n";
    static const char twin[] =
        "<Force_Vector_TwoBody id=\"11\" type=\"ForceAndTorque\" i_marker_id=\"32\""
        " j_floating_marker_id=\"22\" ref_marker_id=\"22\""
        " usrsub_param_string=\"USER(3, 32, 22, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n";
    static char text[8192];
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1); /* libusrsub.so is built there too */
    snprintf(text, sizeof text, jointed_model, EXAMPLES_DIR, fields);
    jacobian_after(test_write_file("jointed_fields.xml", text), 0.05,
                   "jointed bodies, four Force_Fields, at t = 0.05 s", HX_PARTIALS_FIESUB);
    snprintf(text, sizeof text, jointed_model, EXAMPLES_DIR, twin);
    jacobian_after(test_write_file("jointed_twin.xml", text), 0.05,
                   "jointed bodies, a GFOSUB twin, at t = 0.05 s", HX_PARTIALS_TWIN);
}

/* The constraint system's blocks group by group (coupler_blocks.c): three
 * groups of bodies that no constraint row joins. A: a differential's carrier
 * on a revolute to ground, its two side gears on revolutes to it (joints
 * between moving bodies: none of the three is reduced, the carrier's joint
 * not being its only one), a coupler of the gears' joints (between moving
 * bodies), and one of the left gear's joint with the reduced revolute of a
 * pendulum, itself coupled to a second pendulum on a reduced revolute;
 * B: a double pendulum of free bodies on spherical joints, swinging; D: two
 * pendulums on reduced revolutes coupled alone (the couplers' former
 * arithmetic). Force_Fields join B's lower body to A's left gear, A's first
 * pendulum to A's right gear and D's first pendulum to B's lower body, so
 * each group's rows reach columns of another group, which P must not mix.
 * Sizes differ (A 20 velocities and 43 columns, B 12 and 26, D 2 and 4), so
 * the stage's differences, which move a column of every group at once, run
 * past the shorter groups. */
static const char grouped_model[] =
    "<MotionSolve><Model>\n"
    "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\""
    " time_unit=\"SECOND\"/>\n"
    "<Force_Gravity grav_x=\"0\" grav_y=\"0\" grav_z=\"-9810\"/>\n"
    "<Reference_String id=\"401\" string=\"%s/flex_coupled.gfj\"/>\n"
    "<Body_Ground id=\"1\"/>\n"
#define AXIS_Y " a00=\"1\" a10=\"0\" a20=\"0\" a01=\"0\" a11=\"0\" a21=\"-1\" a02=\"0\" a12=\"1\" a22=\"0\""
    "<Reference_Marker id=\"11\" body_id=\"1\"" AXIS_Y "/>\n"
    "<Reference_Marker id=\"111\" body_id=\"1\" pos_y=\"-200\" pos_z=\"100\"/>\n"
    "<Reference_Marker id=\"211\" body_id=\"1\" pos_x=\"500\"" AXIS_Y "/>\n"
    "<Reference_Marker id=\"212\" body_id=\"1\" pos_x=\"800\"" AXIS_Y "/>\n"
    /* A */
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"8\" inertia_xx=\"2e4\" inertia_yy=\"4e4\""
    " inertia_zz=\"2e4\" w_ic_y=\"2\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_z=\"-20\"/>\n"
    "<Reference_Marker id=\"21\" body_id=\"2\"" AXIS_Y "/>\n"
    "<Reference_Marker id=\"22\" body_id=\"2\" pos_y=\"-50\"" AXIS_Y "/>\n"
    "<Reference_Marker id=\"23\" body_id=\"2\" pos_y=\"50\"" AXIS_Y "/>\n"
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"3\" inertia_xx=\"6e3\" inertia_yy=\"1e4\""
    " inertia_zz=\"6e3\" w_ic_y=\"2\"/>\n"
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"5\" pos_y=\"-50\"/>\n"
    "<Reference_Marker id=\"31\" body_id=\"3\" pos_y=\"-50\"" AXIS_Y "/>\n"
    "<Reference_Marker id=\"33\" body_id=\"3\" pos_y=\"-100\" pos_z=\"-50\"/>\n"
    "<Body_Rigid id=\"4\" cg_id=\"40\" mass=\"4\" inertia_xx=\"8e3\" inertia_yy=\"1.5e4\""
    " inertia_zz=\"8e3\" w_ic_y=\"2\"/>\n"
    "<Reference_Marker id=\"40\" body_id=\"4\" pos_x=\"-4\" pos_y=\"50\" pos_z=\"3\"/>\n"
    "<Reference_Marker id=\"41\" body_id=\"4\" pos_y=\"50\"" AXIS_Y "/>\n"
    "<Reference_Marker id=\"42\" body_id=\"4\" pos_x=\"250\" pos_y=\"50\"/>\n"
    "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"11\"/>\n"
    "<Constraint_Joint id=\"2\" type=\"REVOLUTE\" i_marker_id=\"31\" j_marker_id=\"22\"/>\n"
    "<Constraint_Joint id=\"3\" type=\"REVOLUTE\" i_marker_id=\"41\" j_marker_id=\"23\"/>\n"
    "<Constraint_Coupler id=\"4\" joint1_id=\"2\" freedom_1=\"R\" joint2_id=\"3\""
    " freedom_2=\"R\" coefficients=\"1, 1\"/>\n"
    "<Constraint_Coupler id=\"5\" joint1_id=\"2\" freedom_1=\"R\" joint2_id=\"22\""
    " freedom_2=\"R\" coefficients=\"1, -2\"/>\n"
    "<Force_Scalar_TwoBody id=\"1\" type=\"TORQUE\" i_marker_id=\"21\" j_marker_id=\"11\""
    " val=\"1000\"/>\n"
    /* B */
    "<Body_Rigid id=\"12\" cg_id=\"120\" mass=\"1\" inertia_xx=\"2e3\" inertia_yy=\"2.5e3\""
    " inertia_zz=\"1.5e3\" w_ic_x=\"1\"/>\n"
    "<Reference_Marker id=\"120\" body_id=\"12\" pos_x=\"10\" pos_y=\"-200\" pos_z=\"50\"/>\n"
    "<Reference_Marker id=\"121\" body_id=\"12\" pos_y=\"-200\" pos_z=\"100\"/>\n"
    "<Reference_Marker id=\"122\" body_id=\"12\" pos_y=\"-200\"/>\n"
    "<Body_Rigid id=\"13\" cg_id=\"130\" mass=\"2\" inertia_xx=\"3e3\" inertia_yy=\"2e3\""
    " inertia_zz=\"4e3\" v_ic_x=\"100\" w_ic_z=\"1.5\"/>\n"
    "<Reference_Marker id=\"130\" body_id=\"13\" pos_y=\"-190\" pos_z=\"-50\"/>\n"
    "<Reference_Marker id=\"131\" body_id=\"13\" pos_y=\"-200\"/>\n"
    "<Reference_Marker id=\"132\" body_id=\"13\" pos_y=\"-100\" pos_z=\"-50\"/>\n"
    "<Constraint_Joint id=\"11\" type=\"SPHERICAL\" i_marker_id=\"121\" j_marker_id=\"111\"/>\n"
    "<Constraint_Joint id=\"12\" type=\"SPHERICAL\" i_marker_id=\"131\" j_marker_id=\"122\"/>\n"
    /* C */
    "<Body_Rigid id=\"22\" cg_id=\"220\" mass=\"1\" inertia_xx=\"3400\" inertia_yy=\"3400\""
    " inertia_zz=\"100\" w_ic_y=\"3\"/>\n"
    "<Reference_Marker id=\"220\" body_id=\"22\" pos_x=\"500\" pos_z=\"-200\"/>\n"
    "<Reference_Marker id=\"221\" body_id=\"22\" pos_x=\"500\"" AXIS_Y "/>\n"
    "<Reference_Marker id=\"222\" body_id=\"22\" pos_x=\"250\" pos_y=\"50\"/>\n"
    "<Body_Rigid id=\"23\" cg_id=\"230\" mass=\"2\" inertia_xx=\"15000\" inertia_yy=\"15000\""
    " inertia_zz=\"200\"/>\n"
    "<Reference_Marker id=\"230\" body_id=\"23\" pos_x=\"800\" pos_z=\"-300\"/>\n"
    "<Reference_Marker id=\"231\" body_id=\"23\" pos_x=\"800\"" AXIS_Y "/>\n"
    "<Constraint_Joint id=\"21\" type=\"REVOLUTE\" i_marker_id=\"221\" j_marker_id=\"211\"/>\n"
    "<Constraint_Joint id=\"22\" type=\"REVOLUTE\" i_marker_id=\"231\" j_marker_id=\"212\"/>\n"
    "<Constraint_Coupler id=\"23\" joint1_id=\"21\" freedom_1=\"R\" joint2_id=\"22\""
    " freedom_2=\"R\" coefficients=\"10, 15\"/>\n"
    /* D */
    "<Reference_Marker id=\"311\" body_id=\"1\" pos_x=\"1100\"" AXIS_Y "/>\n"
    "<Reference_Marker id=\"312\" body_id=\"1\" pos_x=\"1400\"" AXIS_Y "/>\n"
    "<Body_Rigid id=\"32\" cg_id=\"320\" mass=\"1.5\" inertia_xx=\"3000\" inertia_yy=\"3000\""
    " inertia_zz=\"100\" w_ic_y=\"-2\"/>\n"
    "<Reference_Marker id=\"320\" body_id=\"32\" pos_x=\"1150\" pos_z=\"-200\"/>\n"
    "<Reference_Marker id=\"321\" body_id=\"32\" pos_x=\"1100\"" AXIS_Y "/>\n"
    "<Reference_Marker id=\"322\" body_id=\"32\" pos_x=\"600\" pos_y=\"-150\" pos_z=\"-50\"/>\n"
    "<Body_Rigid id=\"33\" cg_id=\"330\" mass=\"2.5\" inertia_xx=\"12000\" inertia_yy=\"12000\""
    " inertia_zz=\"300\"/>\n"
    "<Reference_Marker id=\"330\" body_id=\"33\" pos_x=\"1400\" pos_z=\"-250\"/>\n"
    "<Reference_Marker id=\"331\" body_id=\"33\" pos_x=\"1400\"" AXIS_Y "/>\n"
    "<Constraint_Joint id=\"31\" type=\"REVOLUTE\" i_marker_id=\"321\" j_marker_id=\"311\"/>\n"
    "<Constraint_Joint id=\"32\" type=\"REVOLUTE\" i_marker_id=\"331\" j_marker_id=\"312\"/>\n"
    "<Constraint_Coupler id=\"33\" joint1_id=\"31\" freedom_1=\"R\" joint2_id=\"32\""
    " freedom_2=\"R\" coefficients=\"3, -4\"/>\n"
    "<Reference_Marker id=\"133\" body_id=\"13\" pos_x=\"600\" pos_y=\"-150\" pos_z=\"-50\"/>\n"
#undef AXIS_Y
    /* across the groups */
    "<Force_Field id=\"1\" i_marker_id=\"132\" j_marker_id=\"33\""
    " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n"
    "<Force_Field id=\"2\" i_marker_id=\"222\" j_marker_id=\"42\""
    " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n"
    "<Force_Field id=\"3\" i_marker_id=\"322\" j_marker_id=\"133\""
    " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n"
    "</Model></MotionSolve>\n";

/* The index of the body of id `id`, and the y column of its first position. */
static int body_index(const model *m, int id)
{
    for (int b = 0; b < m->d.m->nbodies; ++b)
        if (m->d.m->bodies[b].id == id)
            return b;
    fail_msg("no body %d", id);
    return -1;
}

static int first_column(const model *m, int id)
{
    return m->d.dof[body_index(m, id)].q;
}

static void jacobian_of_constraint_groups(void **state)
{
    (void)state;
    static char text[16384];
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1); /* libusrsub.so is built there too */
    snprintf(text, sizeof text, grouped_model, EXAMPLES_DIR);
    const char *path = test_write_file("constraint_groups.xml", text);
    model m;
    open_model(&m, path);
    hx_jacobian jac;
    hx_message msg;
    assert_int_equal(hx_jacobian_init(&jac, &m.d, &msg), 0);
    /* the groups as the comment above counts them, in the order of their first
     * rows (the couplers' rows come first: A, D, then B's joints) */
    assert_int_equal(jac.ngroups, 3);
    for (int g = 0; g < 3; ++g) {
        static const int velocities[3] = {20, 2, 12}, columns[3] = {43, 4, 26};
        assert_int_equal(jac.group_start[g + 1] - jac.group_start[g], velocities[g]);
        assert_int_equal(jac.group_column_start[g + 1] - jac.group_column_start[g], columns[g]);
    }
    /* B's rows reach A's left gear and D's first pendulum (Force_Fields), not
     * A's pendulums; D's rows reach B's lower body, not A's gears */
    const int row_b = m.d.nq + m.d.dof[body_index(&m, 13)].u;
    const int row_d = m.d.nq + m.d.dof[body_index(&m, 33)].u;
    assert_true(hx_sparsity_find(&jac.pattern, row_b, first_column(&m, 3)) >= 0);
    assert_true(hx_sparsity_find(&jac.pattern, row_b, first_column(&m, 32)) >= 0);
    assert_true(hx_sparsity_find(&jac.pattern, row_b, first_column(&m, 22)) < 0);
    assert_true(hx_sparsity_find(&jac.pattern, row_d, first_column(&m, 13)) >= 0);
    assert_true(hx_sparsity_find(&jac.pattern, row_d, first_column(&m, 3)) < 0);
    hx_jacobian_free(&jac);
    close_model(&m);
    /* swinging and turning: every row and column of the groups against differences */
    jacobian_after(path, 0.05, "three constraint groups at t = 0.05 s", HX_PARTIALS_FIESUB);
}

/* The y of a model with Force_StateEqn states, a Control_Diff state after
 * them and loads (suspension_bushing.xml with tp_routines.c's LAG on the arm's
 * angle): every block where the layout puts it, against differences, during
 * the torque ramp. */
static void jacobian_with_state_equations_diffs_and_loads(void **state)
{
    (void)state;
    FILE *f = fopen(EXAMPLES_DIR "/suspension_bushing.xml", "r");
    assert_non_null(f);
    static char text[16384], changed[17408];
    const size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    /* the property files by absolute path: the variant is written elsewhere */
    const char *gbs = strstr(text, "string=\"suspension_bushing.gbs\"");
    const char *gbi = strstr(text, "string=\"suspension_bushing.gbi\"");
    const char *end = strstr(text, "</Model>");
    assert_true(gbs != NULL && gbi != NULL && end != NULL && gbs < gbi && gbi < end);
    const int key = (int)strlen("string=\"suspension_bushing.gbs\"");
    snprintf(changed, sizeof changed,
             "%.*sstring=\"%s/suspension_bushing.gbs\"%.*sstring=\"%s/suspension_bushing.gbi\""
             "%.*s<Control_Diff id=\"7\" type=\"USERSUB\" ic=\"0.01\""
             " usrsub_param_string=\"USER(20, 10, 0.01)\" usrsub_fnc_name=\"LAG\""
             " usrsub_dll_name=\"libtp_routines.so\"/>\n%s",
             (int)(gbs - text), text, EXAMPLES_DIR, (int)(gbi - gbs) - key, gbs + key,
             EXAMPLES_DIR, (int)(end - gbi) - key, gbi + key, end);
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    jacobian_after(test_write_file("bushing_and_diff.xml", changed), 0.2,
                   "suspension_bushing.xml with a Control_Diff at t = 0.2 s",
                   HX_PARTIALS_FIESUB /* no force elements */);
}

/* An added mass on a spring (docs/interface.md §8.8): a body of 2 with
 * fz = -50 DZ - 3 VZ - 3 ACCZ, so z'' = (-50 z - 3 v - 2 g) / (2 + 3): the row
 * of z' holds -50 / 5 = -10 on z and -3 / 5 = -0.6 on v (the loop's share;
 * without it -25 and -1.5), by hand; and the whole matrix against
 * differences, nothing outside its pattern. */
static void jacobian_of_an_algebraic_loop(void **state)
{
    (void)state;
    model m;
    open_model(&m, test_write_file(
        "loop.xml",
        "<MotionSolve><Model>\n"
        "<Force_Gravity grav_x=\"0\" grav_y=\"0\" grav_z=\"-9.81\"/>\n"
        "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.2\""
        " inertia_zz=\"0.3\" v_ic_z=\"0.4\" w_ic_x=\"0.5\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_z=\"0.1\"/>\n"
        "<Force_Vector_OneBody id=\"5\" marker_id=\"20\""
        " fz_expression=\"-50*DZ(20) - 3*VZ(20) - 3*ACCZ(20)\"/>\n"
        "</Model></MotionSolve>\n"));
    double *y = model_state(&m);
    model_initial_state(&m, y);
    hx_jacobian jac;
    hx_message msg;
    assert_int_equal(hx_jacobian_init(&jac, &m.d, &msg), 0);
    double *values = calloc((size_t)jac.pattern.nnz, sizeof(double));
    assert_non_null(values);
    assert_int_equal(hx_jacobian_build(&jac, 0.0, y, NULL, values), 0);
    enum { Z = 2, VZ = 9 }; /* y = [p, q | v, w | works] */
    assert_close(values[hx_sparsity_find(&jac.pattern, VZ, Z)], -10.0, 0, 1e-6);
    assert_close(values[hx_sparsity_find(&jac.pattern, VZ, VZ)], -0.6, 0, 1e-6);
    free(values);
    hx_jacobian_free(&jac);
    long outside = 0;
    const double worst = jacobian_against_differences(&m.d, 0.0, y, "an added mass", &outside);
    assert_int_equal(outside, 0);
    assert_true(worst < 1e-6);
    free(y);
    close_model(&m);
}

/* Every bundled model the harness simulates, at a state it reaches (0.05 s
 * of DOPRI5 from the start: loads on, elements deformed), and chains of
 * bodies from scripts/chain_model.sh: the assembled matrix equals the
 * differences entry by entry, and no nonzero lies outside its sparsity. */
static void jacobian_equals_differences_on_every_model(void **state)
{
    (void)state;
    struct dirent **names;
    const int count = scandir(EXAMPLES_DIR, &names, is_model, alphasort);
    assert_true(count > 10);
    char paths[64][1024];
    int npaths = 0;
    for (int k = 0; k < count; ++k) {
        if (npaths < 60)
            snprintf(paths[npaths++], sizeof paths[0], "%s/%s", EXAMPLES_DIR, names[k]->d_name);
        free(names[k]);
    }
    free(names);
    static const int links[] = {2, 5};
    for (int k = 0; k < 2; ++k) {
        char command[2048];
        snprintf(paths[npaths], sizeof paths[0], "%s/chain_%d.xml", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp", links[k]);
        snprintf(command, sizeof command, "sh %s/chain_model.sh %d %s", SCRIPTS_DIR, links[k],
                 paths[npaths]);
        assert_int_equal(system(command), 0);
        ++npaths;
    }
    int compared = 0;
    for (int k = 0; k < npaths; ++k) {
        hx_session session;
        hx_dynamics d;
        hx_message msg;
        if (hx_session_open(&session, paths[k], stderr, &msg) != 0)
            fail_msg("%s: %s", paths[k], msg.text);
        const int simulated = hx_dynamics_init(&d, &session, &msg) == 0;
        hx_dynamics_free(&d);
        hx_session_close(&session);
        if (!simulated) /* check-only models */
            continue;
        model m;
        open_model(&m, paths[k]);
        double *y = model_state(&m);
        hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-8, 0.05, y);
        assert_int_equal(r.status, HX_INTEGRATION_OK);
        const char *name = strrchr(paths[k], '/') + 1;
        long outside = 0;
        const double worst = jacobian_against_differences(&m.d, 0.05, y, name, &outside);
        assert_int_equal(outside, 0);
        if (worst >= 1e-6)
            fail_msg("%s: the Jacobian differs from differences by %.2g of a row", name, worst);
        compared++;
        free(y);
        close_model(&m);
    }
    printf("%d models compared\n", compared);
    assert_true(compared >= 20);
}

/* A FIESUB whose partials hold a NaN: the run stops with an error naming the
 * element and its partials, none of them in the Jacobian. */
static void non_finite_partials_stop_the_run_with_their_element(void **state)
{
    (void)state;
    const char *path = scaled_field_model(
        "nan_partials.xml", "<Force_Field id=\"7\" i_marker_id=\"20\" j_marker_id=\"10\""
                            " usrsub_param_string=\"USER(100, 0.2, 1e6, 2000, 1, 1)\""
                            " usrsub_dll_name=\"" SCALED_FIELD_LIBRARY "\"/>\n");
    model m;
    open_model(&m, path);
    double *y = model_state(&m);
    hx_simulation_result r = simulate(&m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, 1e-6, 0.1, y);
    printf("%s: %s\n", hx_status_text(r.status), r.message);
    assert_int_not_equal(r.status, HX_INTEGRATION_OK);
    assert_contains(r.message, "Force_Field 7 (", "returned a non-finite value among its partials");
    free(y);
    close_model(&m);
}

/* A GFOSUB element whose FIESUB twin agrees is linearized by the twin; one
 * whose twin does not is set aside for differences of the element alone, and
 * BDF still runs right. */
static void a_twin_that_disagrees_is_set_aside(void **state)
{
    (void)state;
    double *y[2];
    static const double scales[2] = {1.0, 2.0};
    hx_partials_source source[2];
    char description[2][1024], first[512] = "";
    for (int k = 0; k < 2; ++k) {
        char element[512], name[64];
        snprintf(element, sizeof element,
                 "<Force_Vector_TwoBody id=\"1\" type=\"ForceAndTorque\" i_marker_id=\"20\""
                 " j_floating_marker_id=\"10\" ref_marker_id=\"10\" usrsub_param_string=\"USER(20,"
                 " 10, 100, 0.2, 1e6, 2000, %g)\" usrsub_fnc_name=\"SCALED_SPRING\""
                 " usrsub_dll_name=\"" SCALED_FIELD_LIBRARY "\"/>\n", scales[k]);
        snprintf(name, sizeof name, "scaled_spring_%d.xml", k);
        const char *path = scaled_field_model(name, element);
        if (k == 0)
            snprintf(first, sizeof first, "%s", path);
        hx_simulation_result r;
        y[k] = bdf_on(path, 1e-8, 0.2, &r, &source[k], description[k]);
        assert_int_equal(r.status, HX_INTEGRATION_OK);
        printf("twin scaled by %g: %s\n", scales[k], description[k]);
    }
    assert_int_equal(source[0], HX_PARTIALS_TWIN);
    assert_int_equal(source[1], HX_PARTIALS_DIFFERENCES);
    assert_contains(description[1], "SCALED_SPRING_FIELD differs from it");
    model m;
    open_model(&m, first);
    double *y0 = model_state(&m);
    model_initial_state(&m, y0);
    assert_true(state_difference(&m.d, y[0], y[1], y0) < 1e-6);
    free(y0), free(y[0]), free(y[1]);
    close_model(&m);
}


int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(jacobian_equals_differences_on_the_powertrain),
        cmocka_unit_test(jacobian_equals_differences_on_every_model),
        cmocka_unit_test(jacobian_asks_a_field_for_its_partials),
        cmocka_unit_test(jacobian_has_the_routines_rows),
        cmocka_unit_test(jacobian_on_jointed_bodies_with_partials),
        cmocka_unit_test(jacobian_of_constraint_groups),
        cmocka_unit_test(jacobian_with_state_equations_diffs_and_loads),
        cmocka_unit_test(jacobian_of_an_algebraic_loop),
        cmocka_unit_test(non_finite_partials_stop_the_run_with_their_element),
        cmocka_unit_test(a_twin_that_disagrees_is_set_aside),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
