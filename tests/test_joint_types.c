/*
 * CONVEL, RACKPIN and SCREW in motion (docs/interface.md §7.14): two shafts
 * on revolutes bent by b at a CONVEL turn at one speed, on a HOOKE at the
 * cross's ratio; a rack pushed by gravity drives its pinion, a nut falls on
 * its screw, both at the accelerations of their effective masses worked by
 * hand. And the readers: Constraint_Joint's pitch_diameter and pitch and
 * JOINT's PD= and PITCH= give the same joints; a missing or bad value is an
 * error naming the file and line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "sim_support.h"
#include "test_support.h"

/* Input shaft body 2 along Z below the origin (its revolute at its centre
 * (0, 0, -1)), output shaft body 3 along a = (0, sin b, cos b) above it
 * (Rx(-b): theta = -b), both spun at 2 about their axes; the joint at the
 * origin: J = 21 on the input (z_J = -Z, pointing down its shaft, x_J = X),
 * I = 31 on the output (z_I = a, x_I = X): x_I . y_J + y_I . x_J = 0 and
 * x_I . y_J = 0 (the cross's pins X and -Y). */
static const char *shafts(const char *type, double b)
{
    static char text[4096];
    const double s = sin(b), c = cos(b);
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"12\" body_id=\"1\" pos_z=\"-1\"/>\n"
             "<Reference_Marker id=\"13\" body_id=\"1\" pos_y=\"%.17g\" pos_z=\"%.17g\""
             " theta=\"%.17g\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
             " inertia_zz=\"0.5\" w_ic_z=\"2\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_z=\"-1\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\" theta=\"3.1415926535897931\"/>\n"
             "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
             " inertia_zz=\"0.3\" w_ic_y=\"%.17g\" w_ic_z=\"%.17g\"/>\n"
             "<Reference_Marker id=\"30\" body_id=\"3\" pos_y=\"%.17g\" pos_z=\"%.17g\""
             " theta=\"%.17g\"/>\n"
             "<Reference_Marker id=\"31\" body_id=\"3\" theta=\"%.17g\"/>\n"
             "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"20\" j_marker_id=\"12\"/>\n"
             "<Constraint_Joint id=\"2\" type=\"REVOLUTE\" i_marker_id=\"30\" j_marker_id=\"13\"/>\n"
             "<Constraint_Joint id=\"3\" type=\"%s\" i_marker_id=\"31\" j_marker_id=\"21\"/>\n"
             "</Model></MotionSolve>\n",
             s, c, -b, 2 * s, 2 * c, s, c, -b, -b, type);
    return text;
}

static void convel_is_homokinetic_where_hooke_is_not(void **state)
{
    (void)state;
    const double b = 0.5;
    for (int k = 0; k < 2; ++k) {
        sim s;
        sim_run(&s, test_write_file("shafts.xml", shafts(k == 0 ? "CONVEL" : "HOOKE", b)),
                HX_METHOD_DOPRI5, 1e-11, 4.0, 0.05);
        assert_int_equal(s.dynamics.nrows, 14); /* 5 + 5 + 4 */
        const int q2 = s.dynamics.dof[1].q, u2 = s.dynamics.nq + s.dynamics.dof[1].u;
        const int u3 = s.dynamics.nq + s.dynamics.dof[2].u;
        double lo = 1e9, hi = -1e9;
        for (int r = 0; r < s.path.rows; ++r) {
            /* the spins about the shafts (body axes z), the input's angle
             * about Z from its quaternion (scalar first) */
            const double w_in = sim_state(&s, r, u2 + 5), w_out = sim_state(&s, r, u3 + 5);
            const double a = 2.0 * atan2(sim_state(&s, r, q2 + 6), sim_state(&s, r, q2 + 3));
            const double ratio = w_out / w_in;
            lo = fmin(lo, ratio), hi = fmax(hi, ratio);
            if (k == 0) {
                assert_close(ratio, 1.0, 0, 1e-8);
            } else {
                /* the cross: tan a_out = tan a / cos b from the input's pin in
                 * the shafts' plane (a = 0), so w_out / w_in = cos b /
                 * (1 - sin^2 b cos^2 a): 1 / cos b at a = 0, cos b a quarter on */
                const double ca = cos(a), sb = sin(b);
                assert_close(ratio, cos(b) / (1.0 - sb * sb * ca * ca), 0, 1e-8);
            }
        }
        if (k == 1) { /* the cross's ratio swings between cos b and 1 / cos b */
            assert_true(lo < cos(b) + 1e-3 && hi > 1.0 / cos(b) - 1e-3);
        }
        assert_true(s.result.max_phi <= 1e-10);
        assert_true(s.result.energy_error_max <= 1e-8 * s.result.energy_scale);
        sim_close(&s);
    }
}

/* The pinion body 2 at the origin on a revolute about Z (inertia_zz J =
 * 0.01), the rack body 3 0.1 below it on a translational along X (mass 2),
 * the RACK_PINION with PD = 0.2 between the pinion's centre marker 20 (x_I
 * = X = z_J) and the rack's 30 (z_J = X, x_J = Y: psi = theta = pi / 2);
 * gravity -9.81 along X. */
static const char rack_and_pinion[] =
    "<MotionSolve><Model>\n"
    "<Force_Gravity grav_x=\"-9.81\" grav_y=\"0\" grav_z=\"0\"/>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
    "<Reference_Marker id=\"11\" body_id=\"1\" pos_y=\"-0.1\" psi=\"1.5707963267948966\""
    " theta=\"1.5707963267948966\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"0.02\" inertia_yy=\"0.02\""
    " inertia_zz=\"0.01\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""
    " inertia_zz=\"0.1\"/>\n"
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_y=\"-0.1\" psi=\"1.5707963267948966\""
    " theta=\"1.5707963267948966\"/>\n"
    "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"20\" j_marker_id=\"10\"/>\n"
    "<Constraint_Joint id=\"2\" type=\"TRANSLATIONAL\" i_marker_id=\"30\" j_marker_id=\"11\"/>\n"
    "<Constraint_Joint id=\"3\" type=\"RACK_PINION\" i_marker_id=\"20\" j_marker_id=\"30\""
    " pitch_diameter=\"0.2\"/>\n"
    "</Model></MotionSolve>\n";

static void rack_drives_its_pinion(void **state)
{
    (void)state;
    /* s = the rack's travel along X = k theta, k = PD / 2 = 0.1: T = (m +
     * J / k^2) s'^2 / 2 with J / k^2 = 1, the load m g: s'' = 2 (-9.81) / 3
     * = -6.54, s = s'' t^2 / 2 and the pinion's spin theta' = s' / k. */
    sim s;
    sim_run(&s, test_write_file("rackpin.xml", rack_and_pinion), HX_METHOD_DOPRI5, 1e-11, 1.0,
            0.05);
    assert_int_equal(s.dynamics.nrows, 11);
    const double a = -6.54;
    const int q3 = s.dynamics.dof[2].q, u2 = s.dynamics.nq + s.dynamics.dof[1].u;
    for (int r = 0; r < s.path.rows; ++r) {
        const double t = s.path.t[r];
        assert_close(sim_state(&s, r, q3), 0.5 * a * t * t, 0, 1e-8);
        assert_close(sim_state(&s, r, u2 + 5), a * t / 0.1, 0, 1e-7);
    }
    assert_true(fabs(sim_state(&s, s.path.rows - 1, q3)) > 3.0);
    assert_true(s.result.max_phi <= 1e-10);
    sim_close(&s);
}

/* A nut body 2 (mass 1.5, inertia_zz J = 0.015) on a CYLINDRICAL along Z and
 * a SCREW of this pitch, gravity -9.81 along Z. */
static const char *nut(double pitch)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"0\" grav_z=\"-9.81\"/>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1.5\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""
             " inertia_zz=\"0.015\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "<Constraint_Joint id=\"1\" type=\"CYLINDRICAL\" i_marker_id=\"20\" j_marker_id=\"10\"/>\n"
             "<Constraint_Joint id=\"2\" type=\"SCREW\" i_marker_id=\"20\" j_marker_id=\"10\""
             " pitch=\"%.17g\"/>\n"
             "</Model></MotionSolve>\n",
             pitch);
    return text;
}

static void nut_falls_down_its_screw(void **state)
{
    (void)state;
    /* s = z = k theta, k = PITCH / (2 pi) = +-0.1: J / k^2 = 1.5 = m, so
     * z'' = m g / (m + J / k^2) = -4.905 and theta' = z' / k: a right-hand
     * thread (PITCH > 0) turns the falling nut clockwise seen from above. */
    for (int sign = -1; sign <= 1; sign += 2) {
        sim s;
        sim_run(&s, test_write_file("screw.xml", nut(sign * 0.2 * M_PI)), HX_METHOD_DOPRI5,
                1e-11, 1.0, 0.05);
        assert_int_equal(s.dynamics.nrows, 5);
        const double a = -4.905, k = sign * 0.1;
        const int q = s.dynamics.dof[1].q, u = s.dynamics.nq + s.dynamics.dof[1].u;
        for (int r = 0; r < s.path.rows; ++r) {
            const double t = s.path.t[r];
            assert_close(sim_state(&s, r, q + 2), 0.5 * a * t * t, 0, 1e-8);
            assert_close(sim_state(&s, r, u + 5), a * t / k, 0, 1e-7);
        }
        assert_true(s.result.max_phi <= 1e-10);
        sim_close(&s);
    }
}

#define HEAD "title\nPART/1, GROUND\nMARKER/10, PART=1\nPART/2, MASS=2, CM=20, IP=1,2,3\n" \
             "MARKER/20, PART=2\n"

/* JOINT's CONVEL, RACKPIN with PD= and SCREW with PITCH= are the XML's. */
static void dataset_and_xml_agree(void **state)
{
    (void)state;
    static const char xml[] =
        "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Reference_Marker id=\"11\" body_id=\"1\" psi=\"1.5707963267948966\""
        " theta=\"1.5707963267948966\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"2\""
        " inertia_zz=\"3\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
        "<Constraint_Joint id=\"1\" type=\"CONSTANT_VELOCITY\" i_marker_id=\"20\" j_marker_id=\"10\"/>\n"
        "<Constraint_Joint id=\"2\" type=\"RACK_PINION\" i_marker_id=\"20\" j_marker_id=\"11\""
        " pitch_diameter=\"0.25\"/>\n"
        "<Constraint_Joint id=\"3\" type=\"SCREW\" i_marker_id=\"20\" j_marker_id=\"10\""
        " pitch=\"-0.5\"/>\n"
        "</Model></MotionSolve>\n";
    /* marker 11: z along X (the rack across the pinion's z) */
    static const char adm[] = HEAD "MARKER/11, PART=1, REULER=1.5707963267948966,"
                                   " 1.5707963267948966, 0\n"
                                   "JOINT/1, CONVEL, I=20, J=10\n"
                                   "JOINT/2, RACKPIN, I=20, J=11, PD=0.25\n"
                                   "JOINT/3, SCREW, I=20, J=10, PITCH=-0.5\nEND\n";
    hx_model *x = sim_parse("p.xml", xml);
    hx_model *a = sim_parse("p.adm", adm);
    assert_int_equal(a->nunsimulated, 0);
    assert_int_equal(x->njoints, 3);
    assert_int_equal(a->njoints, 3);
    static const enum hx_joint_type types[3] = {HX_JOINT_CONVEL, HX_JOINT_RACKPIN, HX_JOINT_SCREW};
    static const double pd[3] = {0, 0.25, 0}, pitch[3] = {0, 0, -0.5};
    for (int id = 1; id <= 3; ++id) {
        const hx_joint *jx = &x->joints[hx_model_joint(x, id)], *ja = &a->joints[hx_model_joint(a, id)];
        assert_int_equal(jx->type, types[id - 1]);
        assert_int_equal(ja->type, types[id - 1]);
        assert_true(jx->pitch_diameter == pd[id - 1] && ja->pitch_diameter == pd[id - 1]);
        assert_true(jx->pitch == pitch[id - 1] && ja->pitch == pitch[id - 1]);
    }
    assert_string_equal(hx_joint_type_name(HX_JOINT_CONVEL), "CONSTANT_VELOCITY");
    assert_string_equal(hx_joint_type_name(HX_JOINT_RACKPIN), "RACK_PINION");
    hx_model_free(x);
    hx_model_free(a);
}

static void dataset_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        const char *needles[3];
    } cases[] = {
        {HEAD "JOINT/1, RACKPIN, I=20, J=10\nEND\n", {"p.adm:6:", "JOINT/1", "needs PD="}},
        {HEAD "JOINT/1, SCREW, I=20, J=10\nEND\n", {"p.adm:6:", "JOINT/1", "needs PITCH="}},
        {HEAD "JOINT/1, SCREW, I=20, J=10,\n, PITCH=0\nEND\n",
         {"p.adm:7:", "JOINT/1", "PITCH=0: expected a pitch not 0"}},
        {HEAD "JOINT/1, RACKPIN, I=20, J=10,\n, PD=-1\nEND\n",
         {"p.adm:7:", "JOINT/1", "PD=-1: expected a diameter > 0"}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        hx_message msg;
        hx_model *m = hx_model_parse(cases[k].text, strlen(cases[k].text), "p.adm", NULL, &msg);
        if (m != NULL) {
            hx_model_free(m);
            fail_msg("case %zu read; expected an error", k);
        }
        assert_contains(msg.text, cases[k].needles[0], cases[k].needles[1], cases[k].needles[2]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(convel_is_homokinetic_where_hooke_is_not),
        cmocka_unit_test(rack_drives_its_pinion),
        cmocka_unit_test(nut_falls_down_its_screw),
        cmocka_unit_test(dataset_and_xml_agree),
        cmocka_unit_test(dataset_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
