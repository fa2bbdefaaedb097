/*
 * What the harness makes of a force routine's own values
 * (hx_force_routine_load, sim/dynamics/element_forces.h): the routine's
 * values are judged by check as they are; turning them into a load (a
 * scalar's direction along J to I or about J's z, a VFOSUB's force or a
 * VTOSUB's torque in its slots) is the harness's own code, tested here
 * against values worked by hand.
 */
#include <math.h>
#include <stdio.h>

#include "sim/dynamics/element_forces.h"
#include "sim_support.h"
#include "test_support.h"

/* I (marker 20 on body 2) at (3, 4, 12) relative to J (marker 10 on ground,
 * at (1, 1, 1)): |r| = 13; J's z axis turned to (0, -1, 0) by a quarter turn
 * about x (a12 = -1: the z axis's world y). Elements in the model's order:
 * 1 SFOSUB force, 2 SFOSUB torque, 3 VFOSUB, 4 VTOSUB, 5 GFOSUB. */
static const char model[] =
    "<MotionSolve><Model>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"10\" body_id=\"1\" pos_x=\"1\" pos_y=\"1\" pos_z=\"1\"\n"
    "  a11=\"0\" a21=\"1\" a12=\"-1\" a22=\"0\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"4\" pos_y=\"5\" pos_z=\"13\"/>\n"
    "<Force_Scalar_TwoBody id=\"1\" type=\"FORCE\" i_marker_id=\"20\" j_marker_id=\"10\"\n"
    "  usrsub_param_string=\"USER()\" usrsub_dll_name=\"none.so\"/>\n"
    "<Force_Scalar_TwoBody id=\"2\" type=\"TORQUE\" i_marker_id=\"20\" j_marker_id=\"10\"\n"
    "  usrsub_param_string=\"USER()\" usrsub_dll_name=\"none.so\"/>\n"
    "<Force_Vector_TwoBody id=\"3\" type=\"ForceOnly\" i_marker_id=\"20\"\n"
    "  j_floating_marker_id=\"10\" ref_marker_id=\"10\" usrsub_param_string=\"USER()\"\n"
    "  usrsub_dll_name=\"none.so\"/>\n"
    "<Force_Vector_TwoBody id=\"4\" type=\"TorqueOnly\" i_marker_id=\"20\"\n"
    "  j_floating_marker_id=\"10\" ref_marker_id=\"10\" usrsub_param_string=\"USER()\"\n"
    "  usrsub_dll_name=\"none.so\"/>\n"
    "<Force_Vector_TwoBody id=\"5\" type=\"ForceAndTorque\" i_marker_id=\"20\"\n"
    "  j_floating_marker_id=\"10\" ref_marker_id=\"10\" usrsub_param_string=\"USER()\"\n"
    "  usrsub_dll_name=\"none.so\"/>\n"
    "</Model></MotionSolve>\n";

static void expect_load(const double load[6], const double want[6], const char *what)
{
    for (int k = 0; k < 6; ++k)
        if (fabs(load[k] - want[k]) > 1e-14 * (1.0 + fabs(want[k])))
            fail_msg("%s: load[%d] = %.17g, expected %.17g", what, k, load[k], want[k]);
}

static void a_scalar_force_acts_along_the_line_from_j_to_i(void **state)
{
    (void)state;
    host_model h;
    host_model_attach(&h, "routine_load.xml", model);
    double load[6];
    /* positive pushes I away from J: 26 N along (3, 4, 12) / 13 */
    hx_force_routine_load(h.model, &h.frames, 0, (const double[]){26.0}, load);
    expect_load(load, (const double[]){6.0, 8.0, 24.0, 0, 0, 0}, "SFOSUB force 26");
    hx_force_routine_load(h.model, &h.frames, 0, (const double[]){-13.0}, load);
    expect_load(load, (const double[]){-3.0, -4.0, -12.0, 0, 0, 0}, "SFOSUB force -13");
    /* where I and J meet the line has no direction: no force */
    hx_frames tmp;
    assert_int_equal(hx_frames_clone(&tmp, &h.frames), 0);
    tmp.bodies[1].p[0] = 1.0, tmp.bodies[1].p[1] = 1.0, tmp.bodies[1].p[2] = 1.0;
    hx_frames_update(&tmp);
    hx_force_routine_load(h.model, &tmp, 0, (const double[]){26.0}, load);
    expect_load(load, (const double[]){0, 0, 0, 0, 0, 0}, "SFOSUB force at I = J");
    hx_frames_free(&tmp);
    /* an unwritten value (NaN in check's probe) stays NaN */
    hx_force_routine_load(h.model, &h.frames, 0, (const double[]){NAN}, load);
    assert_true(isnan(load[0]));
    host_model_detach(&h);
}

static void a_scalar_torque_acts_about_js_z_axis(void **state)
{
    (void)state;
    host_model h;
    host_model_attach(&h, "routine_load.xml", model);
    double load[6];
    hx_force_routine_load(h.model, &h.frames, 1, (const double[]){5.0}, load);
    expect_load(load, (const double[]){0, 0, 0, 0.0, -5.0, 0.0}, "SFOSUB torque 5");
    host_model_detach(&h);
}

static void vector_routines_fill_their_own_part(void **state)
{
    (void)state;
    host_model h;
    host_model_attach(&h, "routine_load.xml", model);
    double load[6];
    hx_force_routine_load(h.model, &h.frames, 2, (const double[]){1.0, 2.0, 3.0}, load);
    expect_load(load, (const double[]){1.0, 2.0, 3.0, 0, 0, 0}, "VFOSUB");
    hx_force_routine_load(h.model, &h.frames, 3, (const double[]){1.0, 2.0, 3.0}, load);
    expect_load(load, (const double[]){0, 0, 0, 1.0, 2.0, 3.0}, "VTOSUB");
    hx_force_routine_load(h.model, &h.frames, 4, (const double[]){1, 2, 3, 4, 5, 6}, load);
    expect_load(load, (const double[]){1, 2, 3, 4, 5, 6}, "GFOSUB");
    /* the values a routine returns: 1, 1, 3, 3 and 6 */
    static const int count[5] = {1, 1, 3, 3, 6};
    for (int k = 0; k < 5; ++k)
        assert_int_equal(hx_force_routine_values(h.model->forces[k].part), count[k]);
    host_model_detach(&h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_scalar_force_acts_along_the_line_from_j_to_i),
        cmocka_unit_test(a_scalar_torque_acts_about_js_z_axis),
        cmocka_unit_test(vector_routines_fill_their_own_part),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
