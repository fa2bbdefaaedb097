/*
 * The reader of the state-equation elements (docs/interface.md §7.10):
 * Force_StateEqn with each of its attributes, Reference_Array of each type
 * (numbers and ids as attributes or as text), Reference_Variable with every
 * measure, a minus and a number; the user routines that are not forces
 * (§7.12: Post_Request, USERSUB Reference_Variable, Control_Diff,
 * Motion_Joint) and a user Force_Vector_OneBody; and every error path, each
 * naming the element, its id, the attribute and the line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "session/session.h"
#include "host/state_inputs.h"
#include "model/model.h"
#include "sim_support.h"
#include "test_support.h"

/* A body (markers 20, 21) on ground (marker 10); variables, arrays and the
 * element in between. Line 1 is <MotionSolve><Model>; the bodies take lines
 * 2 to 6, so the first line of `parts` is line 7. */
static const char *model_text(const char *parts)
{
    static char text[8192];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"3\" pos_y=\"4\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"-1\"/>\n"
             "%s</Model></MotionSolve>\n", parts);
    return text;
}

static hx_model *read_parts(const char *name, const char *parts, hx_message *msg)
{
    return hx_model_read(test_write_file(name, model_text(parts)), NULL, msg);
}

/* The model is refused with a message holding every needle. */
#define expect_refused(name, parts, ...)                                                  \
    do {                                                                                  \
        hx_message msg_;                                                                  \
        hx_model *m_ = read_parts((name), (parts), &msg_);                                \
        if (m_ != NULL) {                                                                 \
            hx_model_free(m_);                                                            \
            fail_msg("%s was read; expected an error", (name));                           \
        }                                                                                 \
        assert_contains(msg_.text, __VA_ARGS__);                                          \
    } while (0)

#define VARIABLES                                                                         \
    "<Reference_Variable id=\"1\" type=\"EXPRESSION\" expr=\"DX(20,10,10)\"/>\n"         \
    "<Reference_Variable id=\"2\" type=\"expression\" expr=\" - VY( 20 , 10 , 10 , 10 )\"/>\n" \
    "<Reference_Variable id=\"3\" expr=\"AZ(20,10)\" label=\"twist\"/>\n"               \
    "<Reference_Variable id=\"4\" type=\"EXPRESSION\" expr=\"-2.5\"/>\n"

#define ELEMENT(attributes)                                                              \
    "<Force_StateEqn id=\"7\" type=\"USERSUB\" i_marker_id=\"20\" j_floating_marker_id=\"10\"" \
    " ref_marker_id=\"10\" usrsub_param_string=\"USER(1, 2)\" " attributes "/>\n"

static const char good[] =
    VARIABLES
    "<Reference_Array id=\"30\" type=\"U\" num_element=\"4\" variable_id=\"1, 2 3 4\"/>\n"
    "<Reference_Array id=\"31\" type=\"X\" num_element=\"3\"/>\n"
    "<Reference_Array id=\"32\" type=\"IC\" num_element=\"3\" label=\"states at t = 0\">\n"
    "  0.5, -1.25\n  3e-3\n</Reference_Array>\n"
    "<Reference_Array id=\"33\" type=\"Y\" num_element=\"6\"></Reference_Array>\n"
    "<Reference_Array id=\"34\" type=\"U\" num_element=\"2\"> 3 1 </Reference_Array>\n"
    ELEMENT("x_array_id=\"31\" u_array_id=\"30\" ic_array_id=\"32\" num_state=\"3\""
            " is_static_hold=\"TRUE\" label=\"bushing\" usrsub_dll_name=\"NULL\""
            " usrsub_fnc_name=\"MY_YFO\" usrsub_der1_name=\"MY_XX\" usrsub_der2_name=\"MY_XU\""
            " usrsub_der3_name=\"MY_YX\" usrsub_der4_name=\"MY_YU\"");

static void every_attribute_is_read(void **state)
{
    (void)state;
    hx_message msg;
    hx_model *m = read_parts("good.xml", good, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    assert_int_equal(m->nstateeqns, 1);
    const hx_stateeqn *f = &m->stateeqns[0];
    assert_int_equal(f->id, 7);
    assert_int_equal(f->line, 19);
    assert_int_equal(m->markers[f->i_marker].id, 20);
    assert_int_equal(m->markers[f->j_marker].id, 10);
    assert_int_equal(m->markers[f->ref_marker].id, 10);
    assert_int_equal(f->nstate, 3);
    assert_int_equal(f->static_hold, 1);
    const double ic[3] = {0.5, -1.25, 3e-3};
    for (int i = 0; i < 3; ++i)
        assert_true(f->initial[i] == ic[i]);
    assert_int_equal(f->ninput, 4);
    for (int i = 0; i < 4; ++i)
        assert_int_equal(m->variables[f->inputs[i]].id, i + 1);
    assert_int_equal(m->arrays[f->x_array].id, 31);
    assert_int_equal(m->arrays[f->u_array].id, 30);
    assert_int_equal(m->arrays[f->ic_array].id, 32);
    assert_null(f->user.dll_name);
    assert_string_equal(f->user.fnc_name, "MY_YFO");
    assert_string_equal(f->user.der1_name, "MY_XX");
    assert_string_equal(f->user.der2_name, "MY_XU");
    assert_string_equal(f->user.der3_name, "MY_YX");
    assert_string_equal(f->user.der4_name, "MY_YU");
    assert_int_equal(f->user.npar, 2);
    /* ids as text; a Y array read and unused */
    const hx_array *u2 = &m->arrays[hx_model_array(m, 34)];
    assert_int_equal(u2->count, 2);
    assert_int_equal(m->variables[u2->variables[0]].id, 3);
    assert_int_equal(m->arrays[hx_model_array(m, 33)].type, HX_ARRAY_Y);
    /* the markers an input reads are kept current by states */
    assert_true(m->markers[hx_model_marker(m, 20)].tracked);
    hx_model_free(m);
}

static void variables_are_measured_by_the_harness(void **state)
{
    (void)state;
    hx_message msg;
    hx_model *m = read_parts("measured.xml", good, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    hx_frames s;
    assert_int_equal(hx_frames_init(&s, m), 0);
    /* marker 20 at (3, 4, 0) of a body at rest: DX = 3, -VY = 0, AZ = 0, -2.5 */
    double u[4];
    assert_int_equal(hx_stateeqn_inputs(&s, 0, u), 0);
    assert_close(u[0], 3.0, 0, 1e-15);
    assert_close(u[1], 0.0, 0, 1e-15);
    assert_close(u[2], 0.0, 0, 1e-15);
    assert_close(u[3], -2.5, 0, 0);
    /* the body turned by 0.3 rad about z and moving at vy = 2: AZ = 0.3, -VY = -2 */
    s.bodies[1].v[1] = 2.0;
    const double c = cos(0.3), sn = sin(0.3);
    const double R[9] = {c, -sn, 0, sn, c, 0, 0, 0, 1};
    memcpy(s.bodies[1].R, R, sizeof R);
    hx_frames_update(&s);
    assert_int_equal(hx_stateeqn_inputs(&s, 0, u), 0);
    assert_close(u[1], -2.0, 0, 1e-12);
    assert_close(u[2], 0.3, 0, 1e-12);
    assert_true(hx_variable_is_angle(&m->variables[2]) && !hx_variable_is_angle(&m->variables[0]));
    hx_frames_free(&s);
    hx_model_free(m);
}

static void defaults_without_optional_attributes(void **state)
{
    (void)state;
    hx_message msg;
    hx_model *m = read_parts("defaults.xml",
                             "<Reference_Array id=\"31\" type=\"X\" num_element=\"2\"/>\n"
                             ELEMENT("x_array_id=\"31\" num_state=\"2\""), &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    const hx_stateeqn *f = &m->stateeqns[0];
    assert_int_equal(f->ninput, 0);
    assert_int_equal(f->u_array, -1);
    assert_int_equal(f->ic_array, -1);
    assert_true(f->initial[0] == 0.0 && f->initial[1] == 0.0);
    assert_int_equal(f->static_hold, 0);
    assert_null(f->user.fnc_name);
    assert_null(f->user.der4_name);
    hx_model_free(m);
}

/* ---- errors: Force_StateEqn ------------------------------------------------------------ */

#define X3 "<Reference_Array id=\"31\" type=\"X\" num_element=\"3\"/>\n"

static void stateeqn_errors_name_element_and_line(void **state)
{
    (void)state;
    expect_refused("type.xml", X3 "<Force_StateEqn id=\"7\" type=\"LINEAR\" x_array_id=\"31\""
                   " i_marker_id=\"20\" j_floating_marker_id=\"10\" ref_marker_id=\"10\"/>\n",
                   "type.xml:8:", "Force_StateEqn 7", "type \"LINEAR\"", "USERSUB");
    expect_refused("no_x.xml", X3 ELEMENT("num_state=\"3\""), "no_x.xml:8:", "Force_StateEqn 7",
                   "attribute x_array_id is missing");
    expect_refused("no_n.xml", X3 ELEMENT("x_array_id=\"31\""), "no_n.xml:8:", "Force_StateEqn 7",
                   "attribute num_state is missing");
    /* an input by an expression reads TIME and measures only (docs/interface.md §7.10):
     * another variable's value (VARVAL) is refused, naming the variable and what it reads */
    expect_refused("varval.xml",
                   "<Reference_Variable id=\"1\" expr=\"DX(20,10)\"/>\n"
                   "<Reference_Variable id=\"5\" expr=\"TIME + 2*VARVAL(1)\"/>\n"
                   "<Reference_Array id=\"30\" type=\"U\" num_element=\"1\" variable_id=\"5\"/>\n"
                   X3 ELEMENT("x_array_id=\"31\" u_array_id=\"30\" num_state=\"3\""),
                   "varval.xml:11:", "Force_StateEqn 7: its U array 30 names Reference_Variable 5",
                   "which reads VARVAL(1)", "TIME and measures only");
    expect_refused("neg.xml", X3 ELEMENT("x_array_id=\"31\" num_state=\"-1\""), "neg.xml:8:",
                   "num_state -1");
    expect_refused("unread.xml", X3 ELEMENT("x_array_id=\"31\" num_state=\"3\" y_array_id=\"4\""),
                   "unread.xml:8:", "Force_StateEqn 7", "attribute y_array_id is not one the"
                   " harness reads");
    expect_refused("x_len.xml", X3 ELEMENT("x_array_id=\"31\" num_state=\"2\""), "x_len.xml:8:",
                   "Force_StateEqn 7", "num_state is 2 but its X array 31 holds 3");
    expect_refused("ic_len.xml", X3 "<Reference_Array id=\"32\" type=\"IC\" num_element=\"2\">1 2"
                   "</Reference_Array>\n" ELEMENT("x_array_id=\"31\" ic_array_id=\"32\" num_state=\"3\""),
                   "ic_len.xml:9:", "Force_StateEqn 7", "num_state is 3 but its IC array 32 holds 2");
    expect_refused("no_array.xml", X3 ELEMENT("x_array_id=\"31\" u_array_id=\"40\" num_state=\"3\""),
                   "no_array.xml:8:", "Force_StateEqn 7", "u_array_id 40 is not a Reference_Array");
    expect_refused("wrong_type.xml", X3 ELEMENT("x_array_id=\"31\" ic_array_id=\"31\" num_state=\"3\""),
                   "wrong_type.xml:8:", "ic_array_id 31 is a Reference_Array of type X (line 7)",
                   "not IC");
    expect_refused("marker.xml", X3 "<Force_StateEqn id=\"7\" type=\"USERSUB\" x_array_id=\"31\""
                   " num_state=\"3\" i_marker_id=\"20\" j_floating_marker_id=\"99\""
                   " ref_marker_id=\"10\" usrsub_param_string=\"USER(1)\"/>\n", "marker.xml:8:",
                   "Force_StateEqn 7", "j_floating_marker_id 99 is not a Reference_Marker");
    expect_refused("same_body.xml", X3 "<Force_StateEqn id=\"7\" type=\"USERSUB\" x_array_id=\"31\""
                   " num_state=\"3\" i_marker_id=\"20\" j_floating_marker_id=\"21\""
                   " ref_marker_id=\"10\" usrsub_param_string=\"USER(1)\"/>\n",
                   "same_body.xml:8:", "Force_StateEqn 7", "same body");
    expect_refused("twice.xml", X3 ELEMENT("x_array_id=\"31\" num_state=\"3\"")
                   ELEMENT("x_array_id=\"31\" num_state=\"3\""), "twice.xml:9:",
                   "Force_StateEqn 7 is defined twice (line 8)");
    expect_refused("no_user.xml", X3 "<Force_StateEqn id=\"7\" type=\"USERSUB\" x_array_id=\"31\""
                   " num_state=\"3\" i_marker_id=\"20\" j_floating_marker_id=\"10\""
                   " ref_marker_id=\"10\"/>\n", "no_user.xml:8:", "Force_StateEqn 7",
                   "needs usrsub_param_string");
    expect_refused("hold.xml", X3 ELEMENT("x_array_id=\"31\" num_state=\"3\" is_static_hold=\"yes\""),
                   "hold.xml:8:", "Force_StateEqn 7", "is_static_hold", "TRUE or FALSE");
}

/* ---- errors: Reference_Array ------------------------------------------------------------ */

static void array_errors_name_element_and_line(void **state)
{
    (void)state;
    expect_refused("a_type.xml", "<Reference_Array id=\"5\" type=\"Z\" num_element=\"1\"/>\n",
                   "a_type.xml:7:", "Reference_Array 5", "type \"Z\"", "X, U, Y or IC");
    expect_refused("a_count.xml", VARIABLES "<Reference_Array id=\"5\" type=\"U\" num_element=\"3\""
                   " variable_id=\"1 2\"/>\n", "a_count.xml:11:", "Reference_Array 5",
                   "num_element is 3 but variable_id holds 2 ids");
    expect_refused("a_id.xml", VARIABLES "<Reference_Array id=\"5\" type=\"U\" num_element=\"2\""
                   " variable_id=\"1 x\"/>\n", "a_id.xml:11:", "Reference_Array 5",
                   "entry 2 (from 1) is not a positive integer id");
    expect_refused("a_var.xml", VARIABLES "<Reference_Array id=\"5\" type=\"U\" num_element=\"2\""
                   " variable_id=\"1 9\"/>\n", "a_var.xml:11:", "Reference_Array 5",
                   "variable 9 is not a Reference_Variable");
    expect_refused("a_none.xml", "<Reference_Array id=\"5\" type=\"U\" num_element=\"2\"/>\n",
                   "a_none.xml:7:", "Reference_Array 5 (type U): num_element is 2 but its data"
                   " holds 0 ids");
    expect_refused("a_ic.xml", "<Reference_Array id=\"5\" type=\"IC\" num_element=\"3\">1 2"
                   "</Reference_Array>\n", "a_ic.xml:7:", "Reference_Array 5 (type IC)",
                   "num_element is 3 but its data holds 2 numbers");
    expect_refused("a_nan.xml", "<Reference_Array id=\"5\" type=\"IC\" num_element=\"2\">\n1\nnan"
                   "</Reference_Array>\n", "a_nan.xml:7:", "Reference_Array 5 (type IC)",
                   "entry 2 (from 1) of its data is not a finite number");
    expect_refused("a_text.xml", "<Reference_Array id=\"5\" type=\"X\" num_element=\"1\">4"
                   "</Reference_Array>\n", "a_text.xml:7:", "Reference_Array 5 (type X)",
                   "not read");
    expect_refused("a_both.xml", VARIABLES "<Reference_Array id=\"5\" type=\"U\" num_element=\"1\""
                   " variable_id=\"1\">1</Reference_Array>\n", "a_both.xml:11:",
                   "Reference_Array 5 (type U)", "its ids are in variable_id");
    expect_refused("a_ids_ic.xml", "<Reference_Array id=\"5\" type=\"IC\" num_element=\"1\""
                   " variable_id=\"1\"/>\n", "a_ids_ic.xml:7:", "Reference_Array 5",
                   "variable_id belongs to type U arrays");
    expect_refused("a_user.xml", "<Reference_Array id=\"5\" type=\"U\" num_element=\"1\""
                   " usrsub_param_string=\"USER(1)\"/>\n", "a_user.xml:7:", "Reference_Array 5",
                   "computed by a user subroutine");
    expect_refused("a_twice.xml", "<Reference_Array id=\"5\" type=\"X\" num_element=\"1\"/>\n"
                   "<Reference_Array id=\"5\" type=\"X\" num_element=\"1\"/>\n", "a_twice.xml:8:",
                   "Reference_Array 5 is defined twice (line 7)");
    expect_refused("a_neg.xml", "<Reference_Array id=\"5\" type=\"X\" num_element=\"-2\"/>\n",
                   "a_neg.xml:7:", "Reference_Array 5", "num_element -2");
}

/* ---- errors: Reference_Variable ------------------------------------------------------------ */

static void variable_errors_name_element_attribute_and_line(void **state)
{
    (void)state;
    static const struct {
        const char *expr, *why;
    } refused[] = {
        {"DX(20,10,10,10)", "DX takes 1 to 3 arguments"},
        {"AX(20, 10, 10)", "AX takes 1 to 2 arguments"},
        {"DX(20;10)", "must be written as a whole number"},
        {"DX(a)", "must be written as a whole number"},
        {"DX", "DX is a function"},
        {"DX(0,10)", "its I marker is 0"},
        {"1.5e", "exponent has no digits"},
    };
    /* any expression is a variable now (docs/interface.md §7.10): these are
     * what the engine refuses, at the attribute's line */
    for (size_t k = 0; k < sizeof refused / sizeof refused[0]; ++k) {
        char parts[512];
        snprintf(parts, sizeof parts, "<Reference_Variable id=\"3\" type=\"EXPRESSION\""
                 " expr=\"%s\"/>\n", refused[k].expr);
        expect_refused("v_expr.xml", parts, "v_expr.xml:7:", "Reference_Variable 3", "expr",
                       refused[k].why);
    }
    expect_refused("v_self.xml", "<Reference_Variable id=\"3\" expr=\"VARVAL(3)\"/>\n",
                   "v_self.xml:7:", "a cycle of variables", "Reference_Variable 3 reads VARVAL(3)");
    expect_refused("v_marker.xml", "<Reference_Variable id=\"3\" expr=\"WZ(20,99,10)\"/>\n",
                   "v_marker.xml:7:", "Reference_Variable 3", "attribute expr names marker 99");
    expect_refused("v_function.xml", "<Reference_Variable id=\"3\" function=\"DX(20,10)\"/>\n",
                   "v_function.xml:7:", "Reference_Variable 3", "attribute function",
                   "expr");
    expect_refused("v_missing.xml", "<Reference_Variable id=\"3\" type=\"EXPRESSION\"/>\n",
                   "v_missing.xml:7:", "Reference_Variable 3", "attribute expr is missing");
    expect_refused("v_usersub.xml", "<Reference_Variable id=\"3\" type=\"USERSUB\""
                   " usrsub_param_string=\"USER(1)\"/>\n<Reference_Variable id=\"3\""
                   " expr=\"1\"/>\n", "v_usersub.xml:8:",
                   "Reference_Variable 3 is defined twice (line 7)");
    expect_refused("v_script.xml", "<Reference_Variable id=\"3\" type=\"SCRIPT\"/>\n",
                   "v_script.xml:7:", "Reference_Variable 3", "type \"SCRIPT\"",
                   "expected EXPRESSION or USERSUB");
    expect_refused("v_twice.xml", "<Reference_Variable id=\"3\" expr=\"1\"/>\n"
                   "<Reference_Variable id=\"3\" expr=\"2\"/>\n", "v_twice.xml:8:",
                   "Reference_Variable 3 is defined twice (line 7)");
    expect_refused("v_implicit.xml", "<Reference_Variable id=\"3\" expr=\"1\" is_implicit=\"true\"/>\n",
                   "v_implicit.xml:7:", "Reference_Variable 3", "attribute is_implicit is not one"
                   " the harness reads");
}

/* ---- the binding ------------------------------------------------------------------------------ */

/* ---- the user routines that are not forces ------------------------------------------------ */

#define JOINT                                                                             \
    "<Reference_Marker id=\"11\" body_id=\"1\" pos_x=\"3\" pos_y=\"4\"/>\n"               \
    "<Constraint_Joint id=\"6\" type=\"REVOLUTE\" i_marker_id=\"20\" j_marker_id=\"11\"/>\n"
#define USERLIB " usrsub_dll_name=\"lib.so\" usrsub_param_string=\"USER(1, 2)\""

static void routines_are_read_with_their_attributes(void **state)
{
    (void)state;
    hx_message msg;
    hx_model *m = read_parts("routines.xml", JOINT
        "<Post_Request id=\"8\"" USERLIB " comment=\"c\"/>\n"
        "<Post_Request id=\"9\" type=\"EXPRESSION\" expr1=\"DX(20,10)\"/>\n" /* the harness's own */
        "<Reference_Variable id=\"5\" type=\"USERSUB\"" USERLIB " usrsub_fnc_name=\"V\"/>\n"
        "<Control_Diff id=\"7\" type=\"USERSUB\" ic=\"0.5\" ic_dot=\"-2\" is_implicit=\"TRUE\""
        USERLIB "/>\n"
        "<Motion_Joint id=\"3\" type=\"USERSUB\" joint_id=\"6\" motion_type=\"R\" val_type=\"a\""
        " ic_disp=\"0.25\" ic_vel=\"4\"" USERLIB "/>\n"
        "<Force_Vector_OneBody id=\"4\" type=\"TorqueOnly\" marker_id=\"20\" ref_marker_id=\"21\""
        USERLIB "/>\n", &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    assert_int_equal(m->nroutines, 4);
    assert_int_equal(m->nrequests, 1); /* request 9, by expression, is not a routine */
    const int kinds[4] = {HX_ROUTINE_REQUEST, HX_ROUTINE_VARIABLE, HX_ROUTINE_DIFF,
                          HX_ROUTINE_MOTION};
    for (int k = 0; k < 4; ++k) {
        assert_int_equal(m->routines[k].kind, kinds[k]);
        assert_int_equal(m->routines[k].slot, 0);
        assert_int_equal(m->routines[k].user.npar, 2);
        assert_int_equal(m->nroutines_of[kinds[k]], 1);
    }
    assert_string_equal(m->routines[1].user.fnc_name, "V");
    const hx_routine *diff = &m->routines[2], *motion = &m->routines[3];
    assert_int_equal(diff->id, 7);
    assert_true(diff->ic[0] == 0.5 && diff->ic[1] == -2.0 && diff->implicit == 1);
    assert_int_equal(motion->joint, hx_model_joint(m, 6));
    assert_true(motion->val_type == 'A' && motion->motion_type == 'R');
    assert_true(motion->ic[0] == 0.25 && motion->ic[1] == 4.0);
    /* the one-body force: a user force element whose J is the ground's origin */
    assert_int_equal(m->nforces, 1);
    const hx_force *f = &m->forces[0];
    assert_true(f->one_body && f->part == HX_OUTPUT_TORQUE);
    assert_string_equal(hx_force_element_name(f), "Force_Vector_OneBody");
    assert_int_equal(m->markers[f->i_marker].id, 20);
    assert_int_equal(m->markers[f->ref_marker].id, 21);
    const hx_marker *ground_origin = &m->markers[f->j_marker];
    assert_int_equal(ground_origin->id, 0);
    assert_int_equal(ground_origin->body, m->ground);
    for (int i = 0; i < 3; ++i)
        assert_true(ground_origin->pos0[i] == 0.0);
    for (int i = 0; i < 9; ++i)
        assert_true(ground_origin->R0[i] == (i % 4 == 0 ? 1.0 : 0.0));
    hx_model_free(m);
}

static void routine_errors_name_element_and_line(void **state)
{
    (void)state;
    expect_refused("r_type.xml", "<Post_Request id=\"8\" type=\"EXPRESSION\"" USERLIB "/>\n",
                   "r_type.xml:7:", "Post_Request 8", "type \"EXPRESSION\"", "USERSUB");
    expect_refused("r_twice.xml", "<Post_Request id=\"8\"" USERLIB "/>\n<Post_Request id=\"8\""
                   USERLIB "/>\n", "r_twice.xml:8:", "Post_Request 8 is defined twice (line 7)");
    expect_refused("r_script.xml", "<Control_Diff id=\"7\" script_name=\"d.py\""
                   " usrsub_param_string=\"USER(1)\"/>\n", "r_script.xml:7:", "Control_Diff 7",
                   "script_name", "not scripts");
    expect_refused("r_dtype.xml", "<Control_Diff id=\"7\" type=\"EXPRESSION\" expr=\"1\""
                   USERLIB "/>\n", "r_dtype.xml:7:", "Control_Diff 7", "type EXPRESSION",
                   "no user routine");
    expect_refused("r_dexpr.xml", "<Control_Diff id=\"7\" type=\"USERSUB\" expr=\"1\""
                   USERLIB "/>\n", "r_dexpr.xml:7:", "Control_Diff 7", "takes no expr");
    expect_refused("r_vexpr.xml", "<Reference_Variable id=\"5\" type=\"USERSUB\" expr=\"1\""
                   USERLIB "/>\n", "r_vexpr.xml:7:", "Reference_Variable 5", "takes no expr");
    expect_refused("r_val.xml", JOINT "<Motion_Joint id=\"3\" joint_id=\"6\" val_type=\"X\""
                   USERLIB "/>\n", "r_val.xml:9:", "Motion_Joint 3", "val_type \"X\"",
                   "D, V or A");
    expect_refused("r_mtype.xml", JOINT "<Motion_Joint id=\"3\" joint_id=\"6\" motion_type=\"Q\""
                   USERLIB "/>\n", "r_mtype.xml:9:", "Motion_Joint 3", "motion_type \"Q\"");
    expect_refused("r_freedom.xml", JOINT "<Motion_Joint id=\"3\" joint_id=\"6\""
                   " motion_type=\"T\"" USERLIB "/>\n", "r_freedom.xml:9:", "Motion_Joint 3",
                   "motion_type T on joint 6, a revolute joint");
    expect_refused("r_nojoint.xml", "<Motion_Joint id=\"3\" joint_id=\"66\"" USERLIB "/>\n",
                   "r_nojoint.xml:7:", "Motion_Joint 3", "joint_id 66 is not a Constraint_Joint");
    expect_refused("r_nojointid.xml", "<Motion_Joint id=\"3\"" USERLIB "/>\n",
                   "r_nojointid.xml:7:", "Motion_Joint 3", "joint_id is missing");
    expect_refused("r_driven.xml", JOINT "<Motion_Joint id=\"3\" joint_id=\"6\"" USERLIB "/>\n"
                   "<Motion_Joint id=\"4\" joint_id=\"6\"" USERLIB "/>\n", "r_driven.xml:10:",
                   "Motion_Joint 4", "joint 6 is driven by Motion_Joint 3 too (line 9)");
    expect_refused("r_onebody.xml", "<Force_Vector_OneBody id=\"4\" type=\"Sideways\""
                   " marker_id=\"20\"" USERLIB "/>\n", "r_onebody.xml:7:",
                   "Force_Vector_OneBody 4", "type \"Sideways\"");
    expect_refused("r_onemarker.xml", "<Force_Vector_OneBody id=\"4\" type=\"ForceOnly\""
                   " marker_id=\"99\"" USERLIB "/>\n", "r_onemarker.xml:7:",
                   "Force_Vector_OneBody 4", "marker_id 99 is not a Reference_Marker");
    /* a user routine and a value of the element's own: neither is guessed */
    expect_refused("r_oneboth.xml", "<Force_Vector_OneBody id=\"4\" type=\"ForceOnly\""
                   " marker_id=\"20\" fy_expression=\"3\"" USERLIB "/>\n", "r_oneboth.xml:7:",
                   "Force_Vector_OneBody 4", "fy_expression = \"3\" and a user routine");
    expect_refused("r_scalarboth.xml", "<Force_Scalar_TwoBody id=\"5\" type=\"FORCE\""
                   " i_marker_id=\"20\" j_marker_id=\"10\" val=\"2\"" USERLIB "/>\n",
                   "r_scalarboth.xml:7:", "Force_Scalar_TwoBody 5",
                   "val = \"2\" and a user routine");
}

/* The model of `parts`, written as `name`, reads, and binding its routines
 * fails: the message in msg. */
static void expect_bind_fails(const char *name, const char *parts, hx_message *msg)
{
    hx_model *m = read_parts(name, parts, msg);
    if (m == NULL)
        fail_msg("%s", msg->text);
    hx_messages messages;
    hx_messages_init(&messages, NULL);
    hx_bindings bindings;
    assert_int_equal(hx_bind(m, &messages, &bindings, msg), -1);
    hx_bindings_free(&bindings);
    hx_messages_destroy(&messages);
    hx_model_free(m);
}

static void the_partial_routines_are_optional_unless_named(void **state)
{
    (void)state;
    /* the library's default names bind; a named routine that is missing is an error */
    char parts[2048];
    hx_message msg;
    snprintf(parts, sizeof parts, X3 ELEMENT("x_array_id=\"31\" num_state=\"3\""
             " usrsub_dll_name=\"%s\" usrsub_der2_name=\"NO_SUCH_XU\""), USRSUB_LIBRARY);
    expect_bind_fails("named.xml", parts, &msg);
    assert_contains(msg.text, "named.xml:8:", "Force_StateEqn 7", "'NO_SUCH_XU' not found");
    /* the probe library exports no state-equation entry at all: YFOSUB is needed */
    snprintf(parts, sizeof parts, X3 ELEMENT("x_array_id=\"31\" num_state=\"3\""
             " usrsub_dll_name=\"%s\""), HOSTPROBE_LIBRARY);
    expect_bind_fails("defaults_bind.xml", parts, &msg);
    assert_contains(msg.text, "Force_StateEqn 7", "'YFOSUB' not found");
}

/* A routine with its default name found in neither form: both lookups named. */
static void a_routine_in_neither_form_is_named(void **state)
{
    (void)state;
    char parts[1024];
    hx_message msg;
    snprintf(parts, sizeof parts, "<Post_Request id=\"8\" usrsub_param_string=\"USER(1)\""
             " usrsub_dll_name=\"%s\"/>\n", HOSTPROBE_LIBRARY);
    expect_bind_fails("neither.xml", parts, &msg);
    assert_contains(msg.text, "Post_Request 8", "function 'REQSUB' not found",
                    "(looked up REQSUB, reqsub_ and reqsub)",
                    "nor in the C-style form: function 'Reqsub' not found");
}

/* A U array of another length than the library's bushing takes: the
 * library reports it in the dependency pass, naming what it expects, and
 * the session does not open. */
static void a_wrong_input_count_is_the_librarys_to_report(void **state)
{
    (void)state;
    char parts[4096];
    snprintf(parts, sizeof parts,
             "<Reference_String id=\"301\" string=\"%s/suspension_bushing.gbs\"/>\n" VARIABLES
             "<Reference_Array id=\"30\" type=\"U\" num_element=\"4\" variable_id=\"1 2 3 4\"/>\n"
             "<Reference_Array id=\"31\" type=\"X\" num_element=\"5\"/>\n"
             "<Force_StateEqn id=\"7\" type=\"USERSUB\" i_marker_id=\"20\""
             " j_floating_marker_id=\"10\" ref_marker_id=\"10\" x_array_id=\"31\""
             " u_array_id=\"30\" num_state=\"5\" usrsub_param_string=\"USER(1, 301)\""
             " usrsub_dll_name=\"%s\"/>\n", EXAMPLES_DIR, USRSUB_LIBRARY);
    const char *path = test_write_file("inputs.xml", model_text(parts));
    expect_one_setup_error(path, (const char *const[]){"YFOSUB element 7", "12 inputs",
                                                       "ninput 4"});
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_attribute_is_read),
        cmocka_unit_test(variables_are_measured_by_the_harness),
        cmocka_unit_test(defaults_without_optional_attributes),
        cmocka_unit_test(stateeqn_errors_name_element_and_line),
        cmocka_unit_test(array_errors_name_element_and_line),
        cmocka_unit_test(variable_errors_name_element_attribute_and_line),
        cmocka_unit_test(routines_are_read_with_their_attributes),
        cmocka_unit_test(routine_errors_name_element_and_line),
        cmocka_unit_test(the_partial_routines_are_optional_unless_named),
        cmocka_unit_test(a_routine_in_neither_form_is_named),
        cmocka_unit_test(a_wrong_input_count_is_the_librarys_to_report),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
