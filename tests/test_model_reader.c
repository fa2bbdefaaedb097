/*
 * The model reader against hand-worked values: the marker orientation forms
 * (direction cosines, 3-1-3 Euler angles, Euler parameters; yaw/pitch/roll
 * and mixed forms refused), rm_id, a Body_Rigid that is the ground, lprf_id,
 * products of inertia (the Adams convention: the tensor's off-diagonal
 * entries are -inertia_xy, ...) in the tensor and in the first angular
 * acceleration of a free body, elements the harness does not simulate, and
 * a folder given as the model. Every error names the file and the line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "session/session.h"
#include "model/model.h"
#include "model/xml_schema.h"
#include "sim/dynamics/dynamics.h"
#include "test_support.h"

#define HEAD "<MotionSolve><Model>\n"
#define TAIL "</Model></MotionSolve>\n"

/* Reads xml written to the temporary folder as name; warnings to the
 * stream given (may be NULL). */
static hx_model *read_text(const char *name, const char *xml, FILE *warnings, hx_message *msg)
{
    return hx_model_read(test_write_file(name, xml), warnings, msg);
}

static hx_model *read_ok(const char *name, const char *xml)
{
    hx_message msg;
    hx_model *m = read_text(name, xml, NULL, &msg);
    if (m == NULL)
        fail_msg("%s: %s", name, msg.text);
    return m;
}

/* The model is refused with a message holding every needle. */
#define expect_error(name, xml, ...)                                                      \
    do {                                                                                  \
        hx_message msg_;                                                                  \
        hx_model *m_ = read_text((name), (xml), NULL, &msg_);                             \
        if (m_ != NULL) {                                                                 \
            hx_model_free(m_);                                                            \
            fail_msg("%s was read; expected an error", (name));                           \
        }                                                                                 \
        assert_contains(msg_.text, __VA_ARGS__);                                          \
    } while (0)

static const hx_marker *marker(const hx_model *m, int id)
{
    const int k = hx_model_marker(m, id);
    if (k < 0)
        fail_msg("no marker %d", id);
    return &m->markers[k];
}

/* R0 (row-major) against the expected matrix, entry by entry. */
static void assert_matrix(const double *R, const double expected[9], double tol)
{
    for (int k = 0; k < 9; ++k)
        assert_close(R[k], expected[k], 0.0, tol);
}

/* Hand-written elementary rotations (row-major). */
static void rot_z(double a, double R[9])
{
    const double c = cos(a), s = sin(a);
    const double r[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
    memcpy(R, r, sizeof r);
}

static void rot_x(double a, double R[9])
{
    const double c = cos(a), s = sin(a);
    const double r[9] = {1, 0, 0, 0, c, -s, 0, s, c};
    memcpy(R, r, sizeof r);
}

static void multiply(const double A[9], const double B[9], double C[9])
{
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

/* ---- orientation forms ---------------------------------------------------------------- */

static void direction_cosines_are_the_marker_axes(void **state)
{
    (void)state;
    /* x axis (0,1,0), y axis (-1,0,0), z axis (0,0,1): column j is axis j */
    hx_model *m = read_ok("cosines.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\"\n"
        "  a00=\"0\" a10=\"1\" a20=\"0\" a01=\"-1\" a11=\"0\" a21=\"0\" a02=\"0\" a12=\"0\" a22=\"1\"/>\n"
        TAIL);
    const hx_marker *mk = marker(m, 10);
    const double expected[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    assert_matrix(mk->R0, expected, 1e-15);
    assert_close(mk->pos0[0], 1.0, 0, 0);
    assert_close(mk->pos0[1], 2.0, 0, 0);
    assert_close(mk->pos0[2], 3.0, 0, 0);
    hx_model_free(m);
}

static void euler_angles_worked_by_hand(void **state)
{
    (void)state;
    /* psi = pi/2, theta = pi/2, phi = 0: Rz(pi/2) Rx(pi/2) = [[0,0,1],[1,0,0],[0,1,0]]:
     * x axis (0,1,0), y axis (0,0,1), z axis (1,0,0) */
    hx_model *m = read_ok("euler_hand.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" psi=\"1.5707963267948966\""
        " theta=\"1.5707963267948966\" phi=\"0\"/>\n" TAIL);
    const hx_marker *mk = marker(m, 10);
    const double expected[9] = {0, 0, 1, 1, 0, 0, 0, 1, 0};
    assert_matrix(mk->R0, expected, 1e-15);
    hx_model_free(m);
}

static void euler_angles_are_body_fixed_313(void **state)
{
    (void)state;
    const double psi = 0.3, theta = 0.7, phi = -1.1;
    hx_model *m = read_ok("euler_general.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" psi=\"0.3\" theta=\"0.7\" phi=\"-1.1\"/>\n" TAIL);
    double Rz1[9], Rx[9], Rz2[9], tmp[9], expected[9];
    rot_z(psi, Rz1);
    rot_x(theta, Rx);
    rot_z(phi, Rz2);
    multiply(Rz1, Rx, tmp);
    multiply(tmp, Rz2, expected);
    assert_matrix(marker(m, 10)->R0, expected, 1e-15);
    hx_model_free(m);
}

static void euler_parameters(void **state)
{
    (void)state;
    /* a quarter turn about z: e0 = cos(pi/4), e3 = sin(pi/4) */
    hx_model *m = read_ok("parameters.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" e0=\"0.70710678118654752\" e1=\"0\" e2=\"0\""
        " e3=\"0.70710678118654752\"/>\n" TAIL);
    const double expected[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    assert_matrix(marker(m, 10)->R0, expected, 1e-15);
    hx_model_free(m);
    expect_error("parameters_not_unit.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" e0=\"1\" e1=\"0\" e2=\"0\" e3=\"1\"/>\n" TAIL,
        "parameters_not_unit.xml:3:", "Reference_Marker 10", "not of unit length");
}

static void yaw_pitch_roll_is_refused(void **state)
{
    (void)state;
    expect_error("ypr.xml",
        HEAD "<Body_Ground id=\"1\"/>\n\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" yaw=\"0.1\" pitch=\"0.2\" roll=\"0.3\"/>\n" TAIL,
        "ypr.xml:4:", "Reference_Marker 10", "yaw/pitch/roll", "not documented");
}

static void two_forms_at_once_are_refused(void **state)
{
    (void)state;
    expect_error("two_forms.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" psi=\"0.1\" a00=\"1\"/>\n" TAIL,
        "two_forms.xml:3:", "Reference_Marker 10", "more than one orientation form");
}

static void unknown_marker_attributes_are_errors(void **state)
{
    (void)state;
    static const char *const names[] = {"qp_x", "zp_x", "node_id", "usrsub_param_string"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k) {
        char xml[512], file[64], where[80], what[128];
        snprintf(xml, sizeof xml,
                 HEAD "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\""
                 " %s=\"1\"/>\n" TAIL, names[k]);
        snprintf(file, sizeof file, "unknown_%s.xml", names[k]);
        snprintf(where, sizeof where, "%s:3:", file);
        snprintf(what, sizeof what, "attribute %s is not one the harness reads", names[k]);
        expect_error(file, xml, where, "Reference_Marker 10", what);
    }
}

static void rm_id_places_a_marker_in_another_markers_frame(void **state)
{
    (void)state;
    /* marker 30 at (1,2,3) turned a quarter about z; marker 31 at (1,0,0) in 30's frame,
     * turned a further quarter about z: world (1,2,3) + Rz(pi/2) (1,0,0) = (1,3,3),
     * orientation Rz(pi) = diag(-1,-1,1). 31 comes first: order does not matter. */
    hx_model *m = read_ok("rm_id.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"31\" body_id=\"1\" rm_id=\"30\" pos_x=\"1\" psi=\"1.5707963267948966\"/>\n"
        "<Reference_Marker id=\"30\" body_id=\"1\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\""
        " psi=\"1.5707963267948966\"/>\n" TAIL);
    const hx_marker *mk = marker(m, 31);
    assert_close(mk->pos0[0], 1.0, 0, 1e-15);
    assert_close(mk->pos0[1], 3.0, 0, 1e-15);
    assert_close(mk->pos0[2], 3.0, 0, 1e-15);
    const double expected[9] = {-1, 0, 0, 0, -1, 0, 0, 0, 1};
    assert_matrix(mk->R0, expected, 1e-15);
    hx_model_free(m);
    expect_error("rm_id_missing.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"31\" body_id=\"1\" rm_id=\"99\"/>\n" TAIL,
        "rm_id_missing.xml:3:", "Reference_Marker 31", "rm_id 99");
}

/* ---- ground, lprf_id ------------------------------------------------------------------------ */

static void isground_makes_a_body_the_ground(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    const char *path = test_write_file("isground.xml",
        HEAD "<Body_Rigid id=\"1\" isground=\"TRUE\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" pos_x=\"5\" pos_y=\"-2\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\"/>\n" TAIL);
    assert_int_equal(hx_session_open(&s, path, stderr, &msg), 0);
    const hx_model *m = s.model;
    assert_int_equal(m->ground, hx_model_body(m, 1));
    assert_true(m->bodies[m->ground].is_ground);
    assert_false(m->bodies[hx_model_body(m, 2)].is_ground);
    const hx_marker *mk = marker(m, 10);
    assert_int_equal(mk->body, m->ground);
    assert_close(mk->pos0[0], 5.0, 0, 0);
    assert_close(mk->pos0[1], -2.0, 0, 0);
    /* the dynamics: the ground does not move, the other body is free (7 positions) */
    hx_dynamics d;
    assert_int_equal(hx_dynamics_init(&d, &s, &msg), 0);
    assert_int_equal(d.dof[m->ground].kind, HX_DOF_GROUND);
    assert_int_equal(d.dof[hx_model_body(m, 2)].kind, HX_DOF_FREE);
    assert_int_equal(d.nq, 7);
    hx_dynamics_free(&d);
    hx_session_close(&s);
}

static void a_second_ground_names_both_lines(void **state)
{
    (void)state;
    expect_error("two_grounds.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" isground=\"TRUE\"/>\n" TAIL,
        "two_grounds.xml:3:", "Body_Rigid 2", "already has a ground body (line 2)");
    expect_error("two_isground.xml",
        HEAD "<Body_Rigid id=\"1\" isground=\"TRUE\"/>\n\n"
        "<Body_Rigid id=\"2\" isground=\"true\"/>\n" TAIL,
        "two_isground.xml:4:", "Body_Rigid 2", "already has a ground body (line 2)");
}

static void lprf_id_must_be_the_world_frame(void **state)
{
    (void)state;
    hx_model *m = read_ok("lprf_world.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"5\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" lprf_id=\"5\" mass=\"1\" inertia_xx=\"1\""
        " inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\"/>\n" TAIL);
    assert_close(marker(m, 20)->pos0[0], 1.0, 0, 0); /* read as written, in the world */
    hx_model_free(m);
    /* moved */
    expect_error("lprf_moved.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"5\" body_id=\"1\" pos_z=\"0.5\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" lprf_id=\"5\" mass=\"1\" inertia_xx=\"1\""
        " inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\"/>\n" TAIL,
        "lprf_moved.xml:4:", "Body_Rigid 2", "lprf_id 5", "other than the world");
    /* turned, at the origin */
    expect_error("lprf_turned.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" lprf_id=\"21\" mass=\"1\" inertia_xx=\"1\""
        " inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
        "<Reference_Marker id=\"21\" body_id=\"2\" psi=\"0.1\"/>\n" TAIL,
        "lprf_turned.xml:3:", "Body_Rigid 2", "lprf_id 21", "other than the world");
    expect_error("lprf_missing.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" lprf_id=\"77\" mass=\"1\" inertia_xx=\"1\""
        " inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\"/>\n" TAIL,
        "lprf_missing.xml:3:", "Body_Rigid 2", "lprf_id 77");
}

/* ---- products of inertia ---------------------------------------------------------------------- */

static void products_of_inertia_enter_with_a_minus_sign(void **state)
{
    (void)state;
    /* inertia_xy = 0.5 = +integral of x y dm: the tensor's (x,y) entries are -0.5 */
    hx_model *m = read_ok("products.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"2\" inertia_yy=\"3\""
        " inertia_zz=\"4\" inertia_xy=\"0.5\" inertia_yz=\"0.25\" inertia_xz=\"-0.125\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\"/>\n" TAIL);
    const double expected[9] = {2, -0.5, 0.125, -0.5, 3, -0.25, 0.125, -0.25, 4};
    assert_matrix(m->bodies[hx_model_body(m, 2)].inertia, expected, 0.0);
    hx_model_free(m);
}

static void inertia_moves_from_the_im_marker_to_the_cm(void **state)
{
    (void)state;
    /* mass 2; given about the IM marker at the origin: Ixx 20, Iyy 10, Izz 25, Ixy 5
     * (tensor [[20,-5,0],[-5,10,0],[0,0,25]]); cm at d = (1,2,0):
     * m (|d|^2 1 - d d^T) = 2 [[4,-2,0],[-2,1,0],[0,0,5]], so about the cm
     * [[12,-1,0],[-1,8,0],[0,0,15]] (Ixy at the cm = 5 - m x y = 1) */
    hx_model *m = read_ok("parallel_axes.xml",
        HEAD "<Body_Ground id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" im_id=\"21\" mass=\"2\" inertia_xx=\"20\""
        " inertia_yy=\"10\" inertia_zz=\"25\" inertia_xy=\"5\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\" pos_y=\"2\"/>\n"
        "<Reference_Marker id=\"21\" body_id=\"2\"/>\n" TAIL);
    const double expected[9] = {12, -1, 0, -1, 8, 0, 0, 0, 15};
    assert_matrix(m->bodies[hx_model_body(m, 2)].inertia, expected, 1e-13);
    hx_model_free(m);
}

/* The first angular acceleration of a free body at rest (no gravity) under a
 * constant torque of 5.75 about world x, in body axes. */
static void first_angular_acceleration(const char *name, const char *cg_orientation,
                                       const double expected[3])
{
    char xml[2048];
    snprintf(xml, sizeof xml,
             HEAD "<Body_Ground id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"2\" inertia_yy=\"3\""
             " inertia_zz=\"4\" inertia_xy=\"0.5\" w_ic_x=\"0\" w_ic_y=\"0\" w_ic_z=\"0\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" %s/>\n"
             "<Force_Vector_OneBody id=\"7\" marker_id=\"20\" tx_expression=\"5.75\"/>\n" TAIL,
             cg_orientation);
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, test_write_file(name, xml), stderr, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_dynamics d;
    hx_dynamics_data dd;
    if (hx_dynamics_init(&d, &s, &msg) != 0 || hx_dynamics_data_init(&dd, &d, &msg) != 0)
        fail_msg("%s", msg.text);
    double *y = calloc((size_t)d.n, sizeof(double)), *ydot = calloc((size_t)d.n, sizeof(double));
    assert_non_null(y);
    assert_non_null(ydot);
    assert_int_equal(hx_dynamics_initial_state(&d, &dd, y), 0);
    assert_int_equal(hx_dynamics_rhs(&d, &dd, 0.0, y, ydot), 0);
    const hx_body_dof *dof = &d.dof[hx_model_body(s.model, 2)];
    assert_int_equal(dof->kind, HX_DOF_FREE);
    const double *udot = ydot + d.nq + dof->u;
    for (int k = 0; k < 3; ++k) {
        assert_close(udot[k], 0.0, 0, 1e-15);           /* no force: v dot = 0 */
        assert_close(udot[3 + k], expected[k], 0, 1e-13); /* body-axis angular acceleration */
    }
    free(y);
    free(ydot);
    hx_dynamics_data_free(&dd);
    hx_dynamics_free(&d);
    hx_session_close(&s);
}

static void torque_on_a_body_with_a_product_of_inertia(void **state)
{
    (void)state;
    /* I = [[2,-0.5,0],[-0.5,3,0],[0,0,4]], det of the xy block 6 - 0.25 = 5.75, so
     * I^-1 = [[3,0.5,0],[0.5,2,0],[0,0,5.75/4]] / 5.75.
     * Body axes = world axes: T = (5.75,0,0), I^-1 T = (3, 0.5, 0). */
    const double aligned[3] = {3.0, 0.5, 0.0};
    first_angular_acceleration("torque_aligned.xml", "", aligned);
    /* Body turned a quarter about z: body x = world y, body y = -world x, so
     * T = (0,-5.75,0) in body axes and I^-1 T = (-0.5, -2, 0). */
    const double turned[3] = {-0.5, -2.0, 0.0};
    first_angular_acceleration("torque_turned.xml", "psi=\"1.5707963267948966\"", turned);
}

/* ---- elements not simulated, output-only elements, folders ------------------------------------- */

static const char *const free_body =
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\"/>\n";

/* The text a model's reading wrote to its warnings stream. */
static char *warnings_of(const char *name, const char *xml, hx_model **model)
{
    char *text = NULL;
    size_t size = 0;
    FILE *warnings = open_memstream(&text, &size);
    assert_non_null(warnings);
    hx_message msg;
    *model = read_text(name, xml, warnings, &msg);
    fclose(warnings);
    if (*model == NULL)
        fail_msg("%s", msg.text);
    return text;
}

static void unsimulated_elements_are_read_and_refused_by_the_dynamics(void **state)
{
    (void)state;
    char xml[2048];
    snprintf(xml, sizeof xml, HEAD "%s"
             "<Control_StateEqn id=\"5\" num_state=\"1\"/>\n" TAIL, free_body);
    hx_model *m;
    char *warnings = warnings_of("motion.xml", xml, &m);
    assert_contains(warnings, "motion.xml:6:", "warning", "Control_StateEqn id=5", "run and bench refuse");
    assert_int_equal(m->nunsimulated, 1);
    assert_contains(m->unsimulated, "Control_StateEqn 5", "line 6");
    free(warnings);
    hx_model_free(m);
    hx_session s;
    hx_message msg;
    assert_int_equal(hx_session_open(&s, test_write_file("motion.xml", xml), NULL, &msg), 0);
    hx_dynamics d;
    assert_int_equal(hx_dynamics_init(&d, &s, &msg), -1);
    assert_contains(msg.text, "Control_StateEqn 5", "does not simulate");
    if (d.dof != NULL)
        hx_dynamics_free(&d);
    hx_session_close(&s);
}

static void output_only_elements_are_skipped_silently(void **state)
{
    (void)state;
    char xml[2048];
    snprintf(xml, sizeof xml, HEAD "%s"
             "<Post_Request id=\"1\" type=\"EXPRESSION\" expr2=\"DX(20)\"/>\n"
             "<Post_Graphic id=\"2\" type=\"Sphere\" cm_id=\"20\" radius=\"1\"/>\n"
             "<Param_Simulation sim_type=\"TRANSIENT\"/>\n"
             "<Param_Transient integrator_type=\"VSTIFF_DASPK\"/>\n"
             "<Simulate analysis_type=\"Transient\" end_time=\"1\"/>\n" TAIL, free_body);
    hx_model *m;
    char *warnings = warnings_of("outputs.xml", xml, &m);
    assert_true(warnings == NULL || warnings[0] == '\0');
    assert_int_equal(m->nwarnings, 0);
    assert_int_equal(m->nunsimulated, 0);
    assert_int_equal(m->nrequests, 1); /* read, output only (docs/interface.md §7.13) */
    free(warnings);
    hx_model_free(m);
}

static void a_folder_is_not_malformed_xml(void **state)
{
    (void)state;
    hx_message msg;
    assert_null(hx_model_read(test_temp_dir(), NULL, &msg));
    assert_contains(msg.text, test_temp_dir(), "is a folder");
    assert_null(strstr(msg.text, "malformed"));
}

/* Every element description within the readers' room (an attribute past
 * HX_MAX_ATTRS would be read as unknown, and a dataset's twin of it lost). */
static void every_description_fits_the_readers(void **state)
{
    (void)state;
    for (int k = 0; k < hx_element_spec_count; ++k) {
        int n = 0;
        while (hx_element_specs[k].attrs != NULL && hx_element_specs[k].attrs[n].name != NULL)
            ++n;
        if (n >= HX_MAX_ATTRS)
            fail_msg("%s: %d attributes, the readers hold %d", hx_element_specs[k].name, n,
                     HX_MAX_ATTRS - 1);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(direction_cosines_are_the_marker_axes),
        cmocka_unit_test(euler_angles_worked_by_hand),
        cmocka_unit_test(euler_angles_are_body_fixed_313),
        cmocka_unit_test(euler_parameters),
        cmocka_unit_test(yaw_pitch_roll_is_refused),
        cmocka_unit_test(two_forms_at_once_are_refused),
        cmocka_unit_test(unknown_marker_attributes_are_errors),
        cmocka_unit_test(rm_id_places_a_marker_in_another_markers_frame),
        cmocka_unit_test(isground_makes_a_body_the_ground),
        cmocka_unit_test(a_second_ground_names_both_lines),
        cmocka_unit_test(lprf_id_must_be_the_world_frame),
        cmocka_unit_test(products_of_inertia_enter_with_a_minus_sign),
        cmocka_unit_test(inertia_moves_from_the_im_marker_to_the_cm),
        cmocka_unit_test(torque_on_a_body_with_a_product_of_inertia),
        cmocka_unit_test(unsimulated_elements_are_read_and_refused_by_the_dynamics),
        cmocka_unit_test(output_only_elements_are_skipped_silently),
        cmocka_unit_test(a_folder_is_not_malformed_xml),
        cmocka_unit_test(every_description_fits_the_readers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
