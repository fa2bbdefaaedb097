/*
 * The bushing at rest with the harness as host: its torque against the law
 * at the exact projection angles at tilts from 1e-15 to 1e-3 rad with J
 * turned arbitrarily in ground (the harness's own Euler split keeps psi + phi
 * exact; the library does not rely on it either); the harness's Euler angles
 * keep their sum exact at every tilt; and a free body on a bushing in exactly
 * planar motion runs 10^5 steps with its torque on the law at every output.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "host/invoke.h"
#include "session/session.h"
#include "rest_scenario.h"
#include "sim_support.h"
#include "frames/measures.h"
#include "test_support.h"

static const char *marker(char *text, size_t size, int id, int body, const double R[9])
{
    snprintf(text, size,
             "<Reference_Marker id=\"%d\" body_id=\"%d\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\""
             " a00=\"%.17g\" a01=\"%.17g\" a02=\"%.17g\" a10=\"%.17g\" a11=\"%.17g\" a12=\"%.17g\""
             " a20=\"%.17g\" a21=\"%.17g\" a22=\"%.17g\"/>\n",
             id, body, R[0], R[1], R[2], R[3], R[4], R[5], R[6], R[7], R[8]);
    return text;
}

static void torque_at_rest_with_the_harness(void **state)
{
    (void)state;
    const char *gbs = test_write_file("rest_h.gbs", rest_gbs);
    double worst = 0.0, worst_sum = 0.0;
    for (int k = 0; k < 4; ++k)
        for (double tilt = 1e-15; tilt <= 1.001e-3; tilt *= 10.0) {
            double RJ[9], Rrel[9], RI[9], exact[3];
            rest_case(k, tilt, RJ, Rrel);
            rest_mul(RJ, Rrel, RI);
            rest_exact_angles(tilt, exact);
            char mj[512], mi[512], xml[4096];
            snprintf(xml, sizeof xml,
                     "<MotionSolve><Model>\n"
                     "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>\n"
                     "<Reference_String id=\"1\" string=\"%s\"/>\n"
                     "<Body_Ground id=\"1\"/>%s"
                     "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n%s"
                     "<Force_Vector_TwoBody id=\"1\" type=\"ForceAndTorque\" i_marker_id=\"20\" j_floating_marker_id=\"10\""
                     " ref_marker_id=\"10\" usrsub_param_string=\"USER(20, 10, 1)\" usrsub_fnc_name=\"ABM_BUSHING\""
                     " usrsub_dll_name=\"%s\"/>\n"
                     "<Force_Field id=\"2\" i_marker_id=\"20\" j_marker_id=\"10\" usrsub_param_string=\"USER(1)\""
                     " usrsub_fnc_name=\"ABM_BUSHING_FIELD\" usrsub_dll_name=\"%s\"/>\n"
                     "</Model></MotionSolve>\n",
                     gbs, marker(mj, sizeof mj, 10, 1, RJ), marker(mi, sizeof mi, 20, 2, RI),
                     USRSUB_LIBRARY, USRSUB_LIBRARY);
            hx_session s;
            hx_message msg;
            if (hx_session_open(&s, test_write_file("rest.xml", xml), stderr, &msg) != 0)
                fail_msg("%s", msg.text);
            double T[6], Tref[6], dfd[36], dfv[36];
            hx_invoke_force(&s.bindings.items[0], &s.frames, 0, 0, T, NULL);
            const double disp[6] = {0, 0, 0, exact[0], exact[1], exact[2]}, velo[6] = {0};
            hx_invoke_field(&s.bindings.items[1], &s.frames, disp, velo, 0, 0, Tref, dfd, dfv, NULL);
            const double size = sqrt(Tref[3] * Tref[3] + Tref[4] * Tref[4] + Tref[5] * Tref[5]);
            for (int i = 3; i < 6; ++i)
                worst = fmax(worst, fabs(T[i] - Tref[i]) / size);
            /* the harness's own Euler angles: psi + phi is the twist at every tilt */
            double e[3];
            hx_relative_euler313(&s.frames.markers[hx_model_marker(s.model, 20)],
                                 &s.frames.markers[hx_model_marker(s.model, 10)], e);
            worst_sum = fmax(worst_sum, fabs(remainder(e[0] + e[2] - exact[2], 2 * M_PI)));
            hx_session_close(&s);
        }
    printf("harness host: torque within %.3g relative, psi + phi within %.3g rad\n", worst,
           worst_sum);
    assert_true(worst < 1e-10);
    assert_true(worst_sum < 1e-14);
}

static void planar_motion_without_a_torque_spike(void **state)
{
    (void)state;
    /* a 1 kg body turning in the plane on a torsion bushing: its I and J z axes
     * stay parallel for the whole run; every output's torque must be the law's */
    const char *gbs = test_write_file("planar_rest.gbs", rest_gbs);
    char xml[4096];
    snprintf(xml, sizeof xml,
             "<MotionSolve><Model>\n"
             "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>\n"
             "<Reference_String id=\"1\" string=\"%s\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"100\" inertia_yy=\"100\" inertia_zz=\"100\""
             " w_ic_z=\"30\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "<Force_Vector_TwoBody id=\"1\" type=\"ForceAndTorque\" i_marker_id=\"20\" j_floating_marker_id=\"10\""
             " ref_marker_id=\"10\" usrsub_param_string=\"USER(20, 10, 1)\" usrsub_fnc_name=\"ABM_BUSHING\""
             " usrsub_dll_name=\"%s\"/>\n"
             "</Model></MotionSolve>\n", gbs, USRSUB_LIBRARY);
    const char *model = test_write_file("planar_rest.xml", xml);
    char csv[512];
    snprintf(csv, sizeof csv, "%s/planar_rest.csv", test_temp_dir());
    const char *args[] = {"--end", "1", "--integrator", "rk4", "--step", "1e-5",
                          "--output-interval", "1e-4", "--quiet", NULL};
    assert_int_equal(sim_run_csv(model, csv, args), 0);
    csv_table t;
    csv_read(csv, &t);
    const int az = csv_column(csv, "force1.daz"), tz = csv_column(csv, "force1.tz");
    const int ax = csv_column(csv, "force1.dax"), tx = csv_column(csv, "force1.tx");
    assert_true(az > 0 && tz > 0 && ax > 0 && tx > 0);
    double worst = 0.0, largest = 0.0;
    for (int r = 0; r < t.rows; ++r) {
        /* world z is J's z: the torque on I about z is -k AZ */
        worst = fmax(worst, fabs(csv_at(&t, r, tz) + 1e5 * csv_at(&t, r, az)));
        worst = fmax(worst, fabs(csv_at(&t, r, tx)));
        largest = fmax(largest, fabs(csv_at(&t, r, tz)));
    }
    printf("planar run: %d outputs of 10^5 steps, torque off the law by at most %.3g of %.3g\n",
           t.rows, worst, largest);
    assert_true(t.rows > 10000);
    assert_true(largest > 1e3); /* it does twist */
    assert_true(worst < 1e-9 * largest);
    csv_free(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(torque_at_rest_with_the_harness),
        cmocka_unit_test(planar_motion_without_a_torque_spike),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
