/*
 * The joint primitives in motion (docs/interface.md §7.14): a point mass on
 * INLINE slides down its tilted line and on INPLANE down its tilted plane as
 * worked by hand, whatever it spins; ORIENTATION with INLINE is a slider that
 * keeps its orientation while the line pushes off its centre; ATPOINT moves
 * as SPHERICAL, ATPOINT with PERPENDICULAR as UNIVERSAL, ATPOINT with
 * PARALLEL_AXES as the reduced REVOLUTE. And the readers: Constraint_Jprim
 * and JPRIM (any unique prefix of its word) give the same model; a word
 * that is not a primitive, none or two, is an error naming the file and line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "sim_support.h"
#include "test_support.h"

/* A ground (marker 10 at the origin with attributes G), a body 2 of mass
 * 1.5 with its centre marker 20 at cm (world axes), its extra attributes B,
 * its other markers M (Reference_Marker elements) and the joints J. Gravity
 * -9.81 along y. */
static const char *model(const char *G, const double cm[3], const char *B, const char *M,
                         const char *J)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\" %s/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1.5\" inertia_xx=\"0.2\" inertia_yy=\"0.3\""
             " inertia_zz=\"0.25\" %s/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"%.17g\" pos_y=\"%.17g\""
             " pos_z=\"%.17g\"/>\n%s\n%s\n</Model></MotionSolve>\n",
             G, B, cm[0], cm[1], cm[2], M, J);
    return text;
}

/* Axes z = (0.6, -0.8, 0), x = (0.8, 0.6, 0), y = (0, 0, 1): R = Rz(psi)
 * Rx(theta) Rz(0) with sin psi = 0.6, cos psi = 0.8, theta = pi/2 (§7.4:
 * z = (sin psi sin theta, -cos psi sin theta, cos theta)). */
static const char *tilted(void)
{
    static char text[128];
    snprintf(text, sizeof text, "psi=\"%.17g\" theta=\"1.5707963267948966\"", atan2(0.6, 0.8));
    return text;
}

#define PRIM(id, type, i)                                                                  \
    "<Constraint_Jprim id=\"" #id "\" type=\"" type "\" i_marker_id=\"" #i "\""              \
    " j_marker_id=\"10\"/>\n"

static void point_mass_slides_on_inline_and_inplane(void **state)
{
    (void)state;
    /* INLINE, the centre (its marker 20) on 10's z axis z = (0.6, -0.8, 0) at
     * s0 = 0.5: the line's force is normal to it and acts at the centre, so
     * the spin (w_ic) stays out of it and s'' = g . z = 9.81 * 0.8 = 7.848:
     * s(t) = 0.5 + 0.3 t + 3.924 t^2 (v_ic = 0.3 z), the centre s z. */
    const double c1[3] = {0.3, -0.4, 0.0};
    sim s;
    sim_run(&s, test_write_file("inline.xml",
                                model(tilted(), c1,
                                      "v_ic_x=\"0.18\" v_ic_y=\"-0.24\" w_ic_x=\"1\" w_ic_y=\"2\""
                                      " w_ic_z=\"-3\"", "", PRIM(1, "INLINE", 20))),
            HX_METHOD_DOPRI5, 1e-11, 1.0, 0.05);
    assert_int_equal(s.dynamics.nrows, 2);
    int q = s.dynamics.dof[1].q;
    const int u = s.dynamics.nq + s.dynamics.dof[1].u;
    double spin = 0.0;
    for (int r = 0; r < s.path.rows; ++r) {
        const double t = s.path.t[r], sl = 0.5 + 0.3 * t + 3.924 * t * t;
        assert_close(sim_state(&s, r, q), 0.6 * sl, 0, 1e-9);
        assert_close(sim_state(&s, r, q + 1), -0.8 * sl, 0, 1e-9);
        assert_close(sim_state(&s, r, q + 2), 0.0, 0, 1e-9);
        spin = fmax(spin, fabs(sim_state(&s, r, u + 3)) + fabs(sim_state(&s, r, u + 5)));
    }
    assert_true(spin > 1.0); /* it keeps turning: nothing holds its axes */
    assert_true(s.result.max_phi <= 1e-10);
    sim_close(&s);

    /* INPLANE, 10's x-y plane (normal n = z above) through the origin; the
     * centre starts at 0.5 x + 0.2 y = (0.4, 0.3, 0.2) moving at 0.5 along
     * y = (0, 0, 1); the plane takes g's normal part (g . n) n, g . n =
     * -9.81 * -0.8 = 7.848, leaving a = (0, -9.81, 0) - 7.848 (0.6, -0.8, 0)
     * = (-4.7088, -3.5316, 0): x = 0.4 - 2.3544 t^2,
     * y = 0.3 - 1.7658 t^2, z = 0.2 + 0.5 t. */
    const double c2[3] = {0.4, 0.3, 0.2};
    sim_run(&s, test_write_file("inplane.xml",
                                model(tilted(), c2,
                                      "v_ic_z=\"0.5\" w_ic_x=\"-2\" w_ic_y=\"0.5\" w_ic_z=\"1\"", "",
                                      PRIM(1, "INPLANE", 20))),
            HX_METHOD_DOPRI5, 1e-11, 1.0, 0.05);
    assert_int_equal(s.dynamics.nrows, 1);
    q = s.dynamics.dof[1].q;
    for (int r = 0; r < s.path.rows; ++r) {
        const double t = s.path.t[r];
        assert_close(sim_state(&s, r, q), 0.4 - 2.3544 * t * t, 0, 1e-9);
        assert_close(sim_state(&s, r, q + 1), 0.3 - 1.7658 * t * t, 0, 1e-9);
        assert_close(sim_state(&s, r, q + 2), 0.2 + 0.5 * t, 0, 1e-9);
    }
    assert_true(s.result.max_phi <= 1e-10);
    sim_close(&s);
}

static void orientation_and_inline_make_a_slider(void **state)
{
    (void)state;
    /* Marker 21 (0.1, 0, 0.05 from the centre, 10's axes) on 10's tilted z
     * axis at s0 = 0.5: the line's normal force at 21 would turn the body,
     * ORIENTATION holds it; the centre slides as the point mass above from
     * rest, cm(t) = cm0 + 3.924 t^2 z, and the quaternion stays. */
    char marker[256];
    snprintf(marker, sizeof marker,
             "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"0.3\" pos_y=\"-0.4\" %s/>",
             tilted());
    const double cm[3] = {0.4, -0.4, 0.05};
    sim s;
    sim_run(&s, test_write_file("slider.xml",
                                model(tilted(), cm, "", marker,
                                      PRIM(1, "ORIENTATION", 21) PRIM(2, "INLINE", 21))),
            HX_METHOD_DOPRI5, 1e-11, 1.0, 0.05);
    assert_int_equal(s.dynamics.nrows, 5);
    const int q = s.dynamics.dof[1].q;
    for (int r = 0; r < s.path.rows; ++r) {
        const double t = s.path.t[r], ds = 3.924 * t * t;
        assert_close(sim_state(&s, r, q), 0.4 + 0.6 * ds, 0, 1e-9);
        assert_close(sim_state(&s, r, q + 1), -0.4 - 0.8 * ds, 0, 1e-9);
        assert_close(sim_state(&s, r, q + 2), 0.05, 0, 1e-9);
        for (int c = 3; c < 7; ++c)
            assert_close(sim_state(&s, r, q + c), sim_state(&s, 0, q + c), 0, 1e-9);
    }
    assert_true(s.result.max_phi <= 1e-10);
    sim_close(&s);
}

/* Two runs of one pendulum (the centre at cm, spun by w_ic, marker 21 at
 * the origin with axes A) on joints J1 and on J2: the same states. */
static void same_motion(const char *A, const char *J1, const char *J2, int rows, double tol)
{
    const double cm[3] = {0.3, -0.7, 0.2};
    char marker[256];
    snprintf(marker, sizeof marker, "<Reference_Marker id=\"21\" body_id=\"2\" %s/>", A);
    const char *B = "w_ic_x=\"0.5\" w_ic_y=\"1\" w_ic_z=\"-0.3\"";
    sim a, b;
    sim_run(&a, test_write_file("a.xml", model("", cm, B, marker, J1)), HX_METHOD_DOPRI5, 1e-11,
            2.0, 0.05);
    sim_run(&b, test_write_file("b.xml", model("", cm, B, marker, J2)), HX_METHOD_DOPRI5, 1e-11,
            2.0, 0.05);
    assert_int_equal(a.dynamics.nrows, rows);
    assert_int_equal(b.dynamics.nrows, rows);
    assert_int_equal(a.path.rows, b.path.rows);
    const int q = a.dynamics.dof[1].q;
    double moved = 0.0;
    for (int r = 0; r < a.path.rows; ++r)
        for (int c = 0; c < 7; ++c) {
            assert_close(sim_state(&a, r, q + c), sim_state(&b, r, q + c), 0, tol);
            moved = fmax(moved, fabs(sim_state(&a, r, q + c) - sim_state(&a, 0, q + c)));
        }
    assert_true(moved > 0.1);
    assert_true(a.result.max_phi <= 1e-10 && b.result.max_phi <= 1e-10);
    sim_close(&a);
    sim_close(&b);
}

static void primitives_make_the_joints(void **state)
{
    (void)state;
    /* ATPOINT is SPHERICAL's three rows */
    same_motion("", PRIM(1, "ATPOINT", 21),
                "<Constraint_Joint id=\"1\" type=\"SPHERICAL\" i_marker_id=\"21\" j_marker_id=\"10\"/>",
                3, 1e-12);
    /* ATPOINT and PERPENDICULAR are UNIVERSAL: z_21 = (0, -1, 0) across z_10 */
    same_motion("theta=\"1.5707963267948966\"", PRIM(1, "ATPOINT", 21) PRIM(2, "PERPENDICULAR", 21),
                "<Constraint_Joint id=\"1\" type=\"UNIVERSAL\" i_marker_id=\"21\" j_marker_id=\"10\"/>",
                4, 1e-9);
    /* ATPOINT and PARALLEL_AXES are REVOLUTE (between free bodies' rows: I on
     * the body, J on ground, but not reduced, as a JPRIM is a second joint) */
    same_motion("", PRIM(1, "ATPOINT", 21) PRIM(2, "PARALLEL_AXES", 21),
                "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"10\" j_marker_id=\"21\"/>",
                5, 1e-9);
}

/* The same model as XML and as a dataset: the joints' ids, types, markers. */
static void dataset_and_xml_agree(void **state)
{
    (void)state;
    static const char xml[] =
        "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"2\""
        " inertia_zz=\"3\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
        "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
        "<Constraint_Jprim id=\"1\" type=\"ATPOINT\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "<Constraint_Jprim id=\"2\" type=\"INLINE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "<Constraint_Jprim id=\"3\" type=\"INPLANE\" i_marker_id=\"10\" j_marker_id=\"21\"/>\n"
        "<Constraint_Jprim id=\"4\" type=\"ORIENTATION\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "<Constraint_Jprim id=\"5\" type=\"PARALLEL_AXES\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "<Constraint_Jprim id=\"6\" type=\"PERPENDICULAR\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "<Constraint_Joint id=\"1\" type=\"SPHERICAL\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "</Model></MotionSolve>\n";
    /* the words by a unique prefix, in any case; JPRIM's ids apart from JOINT's */
    static const char adm[] = "title\nPART/1, GROUND\nMARKER/10, PART=1\n"
                              "PART/2, MASS=2, CM=20, IP=1,2,3\nMARKER/20, PART=2\n"
                              "MARKER/21, PART=2\n"
                              "JPRIM/1, I=21, J=10, AT\nJPRIM/2, INL, I=21, J=10\n"
                              "JPRIM/3, I=10, J=21, inp\nJPRIM/4, I=21, J=10, ORIENTATION\n"
                              "JPRIM/5, I=21, J=10, PA\nJPRIM/6, I=21, J=10, PE\n"
                              "JOINT/1, SPHERICAL, I=21, J=10\nEND\n";
    hx_model *x = sim_parse("p.xml", xml);
    hx_model *a = sim_parse("p.adm", adm);
    assert_int_equal(x->njoints, 7);
    assert_int_equal(a->njoints, 7);
    assert_int_equal(a->nunsimulated, 0);
    for (int k = 0; k < x->njoints; ++k) {
        const hx_joint *jx = &x->joints[k];
        const int primitive = hx_joint_type_is_primitive(jx->type);
        const int ka = primitive ? hx_model_primitive(a, jx->id) : hx_model_joint(a, jx->id);
        assert_true(ka >= 0);
        const hx_joint *ja = &a->joints[ka];
        assert_int_equal(ja->type, jx->type);
        assert_int_equal(a->markers[ja->i_marker].id, x->markers[jx->i_marker].id);
        assert_int_equal(a->markers[ja->j_marker].id, x->markers[jx->j_marker].id);
    }
    assert_int_equal(x->joints[hx_model_primitive(x, 3)].type, HX_JOINT_INPLANE);
    assert_int_equal(x->joints[hx_model_joint(x, 1)].type, HX_JOINT_SPHERICAL);
    hx_model_free(x);
    hx_model_free(a);
}

#define HEAD "title\nPART/1, GROUND\nMARKER/10, PART=1\nPART/2, MASS=2, CM=20, IP=1,2,3\n" \
             "MARKER/20, PART=2\n"

static void dataset_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        const char *needles[3];
    } cases[] = {
        {HEAD "JPRIM/1, I=20, J=10, INLIN3\nEND\n", {"p.adm:6:", "JPRIM/1", "INLIN3"}},
        {HEAD "JPRIM/1, I=20, J=10, IN\nEND\n", {"p.adm:6:", "JPRIM/1", "ambiguous"}},
        {HEAD "JPRIM/1, I=20, J=10\nEND\n", {"p.adm:6:", "JPRIM/1", "(0 given)"}},
        {HEAD "JPRIM/1, I=20, J=10, INLINE, INPLANE\nEND\n", {"p.adm:6:", "JPRIM/1", "(2 given)"}},
        {HEAD "JPRIM/1, I=20, INLINE\nEND\n", {"p.adm:6:", "JPRIM/1", "J"}},
        {HEAD "JPRIM/1, I=20, J=99, INLINE\nEND\n", {"p.adm:6:", "JPRIM/1", "99"}},
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
    /* a primitive's word on a JOINT: read, not simulated, pointing at JPRIM */
    static const char joint[] = HEAD "JOINT/1, INLINE, I=20, J=10\nEND\n";
    hx_model *m = sim_parse("p.adm", joint);
    assert_int_equal(m->nunsimulated, 1);
    assert_int_equal(m->njoints, 0);
    hx_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(point_mass_slides_on_inline_and_inplane),
        cmocka_unit_test(orientation_and_inline_make_a_slider),
        cmocka_unit_test(primitives_make_the_joints),
        cmocka_unit_test(dataset_and_xml_agree),
        cmocka_unit_test(dataset_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
