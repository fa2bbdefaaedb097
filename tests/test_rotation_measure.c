/*
 * The rotation-vector measure (docs/interface.md §3.7) in motion: a free body
 * tumbling in 3-D on a linear bushing, and on a flexible joint with a fully
 * populated symmetric K, keeps its energy to the integrator's accuracy with
 * the rotation vector (the error falls 16-fold when RK4's step halves),
 * where the projection angles, which are not a conservative measure of a 3-D
 * rotation, drift by orders of magnitude more at the same steps. check
 * passes on both measures (the FIESUB partials of the rotation map against
 * differences, the GFOSUB form's dependencies).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sim_support.h"
#include "test_support.h"

static const char *bushing_file(const char *measure)
{
    char text[2048], name[64];
    snprintf(text, sizeof text,
             "[HEADER]\nFILE_TYPE = 'gbs'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\n"
             "FORCE = 'newton'\nMASS = 'kg'\nTIME = 'second'\n[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n"
             "ROTATION_MEASURE = '%s'\n[DIRECTIONS]\n(ACTIVITY)\n"
             "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 1 1 1 1 1 1\n"
             "[CONSTANT_STIFFNESS_FX]\nK = 10\n[CONSTANT_STIFFNESS_FY]\nK = 15\n"
             "[CONSTANT_STIFFNESS_FZ]\nK = 20\n[CONSTANT_STIFFNESS_TX]\nK = 40\n"
             "[CONSTANT_STIFFNESS_TY]\nK = 60\n[CONSTANT_STIFFNESS_TZ]\nK = 50\n",
             measure);
    snprintf(name, sizeof name, "tumble_%s.gbs", measure);
    return test_write_file(name, text);
}

/* a symmetric positive definite K that couples every rotation with the others
 * and with the translations */
static const char *joint_file(const char *measure)
{
    char text[2048], name[64];
    snprintf(text, sizeof text,
             "[HEADER]\nFILE_TYPE = 'gfj'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\n"
             "FORCE = 'newton'\nMASS = 'kg'\nTIME = 'second'\n[GLOBAL]\nROTATION_MEASURE = '%s'\n"
             "[STIFFNESS]\n(MATRIX)\n{ x y z ax ay az }\n"
             "10 1 0 0.2 0 0\n1 15 0 0 -0.3 0\n0 0 20 0 0 0.1\n"
             "0.2 0 0 40 5 -3\n0 -0.3 0 5 60 4\n0 0 0.1 -3 4 50\n",
             measure);
    snprintf(name, sizeof name, "tumble_%s.gfj", measure);
    return test_write_file(name, text);
}

/* A 2 kg body, no gravity, spun about all three axes on the element. */
static const char *tumble_model(const char *name, const char *file, const char *entry)
{
    char xml[4096];
    snprintf(xml, sizeof xml,
             "<MotionSolve><Model>\n"
             "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>\n"
             "<Reference_String id=\"1\" string=\"%s\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"2000\" inertia_yy=\"3000\""
             " inertia_zz=\"4000\" v_ic_x=\"5\" v_ic_y=\"-3\" w_ic_x=\"2.5\" w_ic_y=\"-2\" w_ic_z=\"2.2\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "<Force_Vector_TwoBody id=\"1\" type=\"ForceAndTorque\" i_marker_id=\"20\" j_floating_marker_id=\"10\""
             " ref_marker_id=\"10\" usrsub_param_string=\"USER(20, 10, 1)\" usrsub_fnc_name=\"%s\""
             " usrsub_dll_name=\"%s\"/>\n"
             "</Model></MotionSolve>\n",
             file, entry, USRSUB_LIBRARY);
    return test_write_file(name, xml);
}

/* Largest relative energy error of 4 s of RK4 at step h, and the largest
 * rotation the body reached (rad). */
static double energy_error(const char *model, double h, double *largest_angle)
{
    sim s;
    sim_run(&s, model, HX_METHOD_RK4, h, 4.0, 0.01);
    const double e = s.result.energy_error_max / s.result.energy_scale;
    *largest_angle = 0.0;
    for (int r = 0; r < s.path.rows; ++r) {
        /* the body's Euler parameters: the angle is 2 acos(e0) */
        const double e0 = fabs(sim_state(&s, r, 3));
        *largest_angle = fmax(*largest_angle, 2.0 * acos(fmin(1.0, e0)));
    }
    sim_close(&s);
    return e;
}

static void tumbles(const char *what, const char *vector_model, const char *angles_model)
{
    double angle_v, angle_p, unused;
    const double v1 = energy_error(vector_model, 2e-3, &angle_v);
    const double v2 = energy_error(vector_model, 1e-3, &unused);
    const double p1 = energy_error(angles_model, 2e-3, &angle_p);
    const double p2 = energy_error(angles_model, 1e-3, &unused);
    printf("%s, 4 s of RK4, largest rotation %.2f rad: relative energy error\n"
           "  rotation vector:   %.3g (h = 2 ms), %.3g (h = 1 ms), ratio %.1f\n"
           "  projection angles: %.3g (h = 2 ms), %.3g (h = 1 ms), ratio %.1f\n",
           what, angle_v, v1, v2, v1 / v2, p1, p2, p1 / p2);
    assert_true(angle_v > 0.5 && angle_p > 0.5); /* a large 3-D rotation */
    assert_true(v1 / v2 > 10.0);                 /* the integrator's fourth order */
    assert_true(v2 < 1e-7);
    assert_true(p2 > 1e3 * v2);                  /* the measure's own drift */
    assert_true(p1 / p2 < 2.0);                  /* which no step size removes */
}

static void a_tumbling_body_keeps_its_energy_on_a_bushing(void **state)
{
    (void)state;
    tumbles("linear bushing",
            tumble_model("tumble_bv.xml", bushing_file("ROTATION_VECTOR"), "ABM_BUSHING"),
            tumble_model("tumble_bp.xml", bushing_file("PROJECTION_ANGLES"), "ABM_BUSHING"));
}

static void a_tumbling_body_keeps_its_energy_on_a_flexible_joint(void **state)
{
    (void)state;
    tumbles("flexible joint with a full K",
            tumble_model("tumble_jv.xml", joint_file("ROTATION_VECTOR"), "FLEX_JOINT"),
            tumble_model("tumble_jp.xml", joint_file("PROJECTION_ANGLES"), "FLEX_JOINT"));
}

static void check_passes_with_the_rotation_vector(void **state)
{
    (void)state;
    char xml[4096];
    snprintf(xml, sizeof xml,
             "<MotionSolve><Model>\n"
             "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>\n"
             "<Reference_String id=\"1\" string=\"%s\"/><Reference_String id=\"2\" string=\"%s\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"2000\" inertia_yy=\"3000\""
             " inertia_zz=\"4000\" w_ic_x=\"0.6\" w_ic_y=\"-0.5\" w_ic_z=\"0.7\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.4\" psi=\"0.3\" theta=\"0.5\" phi=\"-0.2\"/>\n"
             "<Force_Vector_TwoBody id=\"1\" type=\"ForceAndTorque\" i_marker_id=\"20\" j_floating_marker_id=\"10\""
             " ref_marker_id=\"10\" usrsub_param_string=\"USER(20, 10, 1)\" usrsub_fnc_name=\"ABM_BUSHING\""
             " usrsub_dll_name=\"%s\"/>\n"
             "<Force_Field id=\"2\" i_marker_id=\"20\" j_marker_id=\"10\" usrsub_param_string=\"USER(1)\""
             " usrsub_fnc_name=\"ABM_BUSHING_FIELD\" usrsub_dll_name=\"%s\"/>\n"
             "<Force_Vector_TwoBody id=\"3\" type=\"ForceAndTorque\" i_marker_id=\"20\" j_floating_marker_id=\"10\""
             " ref_marker_id=\"10\" usrsub_param_string=\"USER(20, 10, 2)\" usrsub_fnc_name=\"FLEX_JOINT\""
             " usrsub_dll_name=\"%s\"/>\n"
             "<Force_Field id=\"4\" i_marker_id=\"20\" j_marker_id=\"10\" usrsub_param_string=\"USER(2)\""
             " usrsub_fnc_name=\"FLEX_JOINT_FIELD\" usrsub_dll_name=\"%s\"/>\n"
             "</Model></MotionSolve>\n",
             bushing_file("ROTATION_VECTOR"), joint_file("ROTATION_VECTOR"), USRSUB_LIBRARY,
             USRSUB_LIBRARY, USRSUB_LIBRARY, USRSUB_LIBRARY);
    assert_int_equal(sim_check(test_write_file("vector_check.xml", xml)), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_tumbling_body_keeps_its_energy_on_a_bushing),
        cmocka_unit_test(a_tumbling_body_keeps_its_energy_on_a_flexible_joint),
        cmocka_unit_test(check_passes_with_the_rotation_vector),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
