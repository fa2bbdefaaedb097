/*
 * The joints' reactions (docs/interface.md §7.14, reactions; sim/dynamics/reactions.h):
 * pendulums hanging at rest and passing the bottom on a reduced REVOLUTE, on
 * the same REVOLUTE with ground as I (rows) and on a SPHERICAL, in SI and in
 * millimetres (ucf = 1000); a chain of three links carrying the links below;
 * a bar on a SPHERICAL and an INLINE or INPLANE primitive by moments; a
 * cantilever's torque; JOINT()/JPRIM() on J (jflag 1) and in a turned rm;
 * JOINT() in a Post_Request equal to the CSV's columns; JOINT() in a general
 * constraint refused with its place.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expr/evaluate.h"
#include "model/expr/expr.h"
#include "model_runs.h"
#include "sim/dynamics/reactions.h"
#include "sim/simulation/requests.h"
#include "sim_support.h"
#include "test_support.h"

#define G 9.81
#define TOL 1e-9

/* The six reactions of a Constraint_Joint (or, primitive, a Constraint_Jprim) by id. */
static const double *of(const evaluated *e, int id, int primitive)
{
    const hx_model *m = e->m.session.model;
    const int k = primitive ? hx_model_primitive(m, id) : hx_model_joint(m, id);
    assert_true(k >= 0);
    return e->r + 6 * k;
}


static void expect_six(const double *got, double fx, double fy, double fz, double tx, double ty,
                       double tz, double tol)
{
    const double want[6] = {fx, fy, fz, tx, ty, tz};
    for (int c = 0; c < 6; ++c)
        assert_close(got[c], want[c], 0, tol);
}

/* A pendulum: ground marker 10 at the origin; body 2 of mass 2 with its centre
 * (marker 20) at (0, -L, 0), marker 21 on it at the origin; gravity -g y in the
 * model's units (UNITS: a Param_Unit, or ""); turning at w about z (v_ic the
 * centre's w z x (0, -L, 0) = (w L, 0, 0)); the joint J. */
static const char *pendulum(const char *units, double L, double g, double w, const char *J)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n%s"
             "<Force_Gravity grav_x=\"0\" grav_y=\"%.17g\" grav_z=\"0\"/>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.3\" inertia_yy=\"0.2\""
             " inertia_zz=\"0.4\" v_ic_x=\"%.17g\" w_ic_z=\"%.17g\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_y=\"%.17g\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\"/>\n%s\n</Model></MotionSolve>\n",
             units, -g, w * L, w, -L, J);
    return text;
}

#define MM "<Param_Unit length_unit=\"MILLIMETER\" force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\"" \
           " time_unit=\"SECOND\"/>\n"
#define JOINT_IJ(type, i, j) \
    "<Constraint_Joint id=\"1\" type=\"" type "\" i_marker_id=\"" #i "\" j_marker_id=\"" #j "\"/>"

static void pendulum_at_rest_carries_its_weight(void **state)
{
    (void)state;
    /* at rest straight down the joint holds m g = 2 * 9.81 = 19.62 up, on the
     * body (I), at I: no torque (the weight's line passes through I) */
    evaluated e;
    evaluate_text(&e, "rest.xml", pendulum("", 1.5, G, 0.0, JOINT_IJ("REVOLUTE", 21, 10)));
    assert_int_equal(e.m.d.joint_row[0], -1); /* reduced */
    expect_six(of(&e, 1, 0), 0, 19.62, 0, 0, 0, 0, TOL);
    release(&e);
    /* in mm: L = 1500 mm, g = 9810 mm/s^2, ucf = 1000: m g / ucf = 2 * 9810 / 1000
     * = 19.62 N, the torque in N mm */
    evaluate_text(&e, "rest_mm.xml", pendulum(MM, 1500, 9810, 0.0, JOINT_IJ("REVOLUTE", 21, 10)));
    assert_close(e.m.d.ucf, 1000, 1e-15, 0);
    expect_six(of(&e, 1, 0), 0, 19.62, 0, 0, 0, 0, 1e-6);
    release(&e);
    /* the same on a SPHERICAL (rows) in mm: the multipliers are forces already */
    evaluate_text(&e, "rest_mm_s.xml", pendulum(MM, 1500, 9810, 0.0, JOINT_IJ("SPHERICAL", 21, 10)));
    assert_true(e.m.d.joint_row[0] >= 0);
    expect_six(of(&e, 1, 0), 0, 19.62, 0, 0, 0, 0, 1e-6);
    release(&e);
}

static void pendulum_at_the_bottom_pulls_by_its_speed(void **state)
{
    (void)state;
    /* w = 2 rad/s, L = 1.5: the centre's acceleration w^2 L = 6 toward the
     * pivot (up), none along the path (no torque about the pivot):
     * F = m (g + w^2 L) = 2 (9.81 + 6) = 31.62 up on the body */
    evaluated e;
    evaluate_text(&e, "bottom.xml", pendulum("", 1.5, G, 2.0, JOINT_IJ("REVOLUTE", 21, 10)));
    assert_int_equal(e.m.d.joint_row[0], -1);
    expect_six(of(&e, 1, 0), 0, 31.62, 0, 0, 0, 0, TOL);
    release(&e);
    /* ground as I: rows, not reduced; what ground gets is the opposite */
    evaluate_text(&e, "bottom_ji.xml", pendulum("", 1.5, G, 2.0, JOINT_IJ("REVOLUTE", 10, 21)));
    assert_true(e.m.d.joint_row[0] >= 0);
    expect_six(of(&e, 1, 0), 0, -31.62, 0, 0, 0, 0, TOL);
    release(&e);
    /* a SPHERICAL: rows, the same force on the body */
    evaluate_text(&e, "bottom_s.xml", pendulum("", 1.5, G, 2.0, JOINT_IJ("SPHERICAL", 21, 10)));
    expect_six(of(&e, 1, 0), 0, 31.62, 0, 0, 0, 0, TOL);
    release(&e);
    /* in mm: 2 (9810 + 4 * 1500) / 1000 = 31.62 N */
    evaluate_text(&e, "bottom_mm.xml", pendulum(MM, 1500, 9810, 2.0, JOINT_IJ("REVOLUTE", 21, 10)));
    expect_six(of(&e, 1, 0), 0, 31.62, 0, 0, 0, 0, 1e-6);
    release(&e);
}

/* A pendulum off the bottom, its force and torque by hand: level (the centre
 * at r = (L, 0, c) = (1.5, 0, 0.4) from the hinge, off the hinge's plane by c),
 * turning at w = 2 about z, a product of inertia Ixz = 0.05 (the tensor's
 * entry -0.05, §7.8), a reduced REVOLUTE about z, m = 2, Izz = 0.4:
 *   alpha = -m g L / (Izz + m L^2) = -29.43 / 4.9 = -6.00612... (clockwise);
 *   m a_cm = m (alpha z x r - w^2 (L, 0, 0)) = (-12, 3 alpha, 0), W = (0, -19.62, 0):
 *   F = m a - W = (-12, 3 alpha + 19.62, 0) = (-12, 1.60163..., 0).
 * Moments about I (fixed): T = r x m a - r x W + I alpha + w x I w, with
 *   r x m a = (-1.2 alpha, -4.8, 4.5 alpha), -r x W = (-7.848, 0, 29.43),
 *   I alpha z = (-0.05 alpha, 0, 0.4 alpha), w z x I w z = w^2 z x (-0.05, 0, 0.4)
 *   = (0, -0.2, 0):
 *   T = (-1.25 alpha - 7.848, -5, 0): its z (the axis) sums to 0, as it must. */
static void pendulum_level_by_hand(void **state)
{
    (void)state;
    static char text[2048];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
             "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.3\" inertia_yy=\"0.2\""
             " inertia_zz=\"0.4\" inertia_xz=\"0.05\" w_ic_z=\"2\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1.5\" pos_z=\"0.4\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\"/>\n%s\n</Model></MotionSolve>\n",
             JOINT_IJ("REVOLUTE", 21, 10));
    evaluated e;
    evaluate_text(&e, "level.xml", text);
    const double alpha = -29.43 / 4.9;
    assert_close(e.ydot[e.m.d.nq], alpha, 0, TOL);
    expect_six(of(&e, 1, 0), -12, 3 * alpha + 19.62, 0, -1.25 * alpha - 7.848, -5, 0, TOL);
    release(&e);
}

/* A block of mass 4 on a TRANSLATIONAL along x to ground (reduced), its centre
 * 0.5 ahead of its I marker, gravity (-3, -9.81, 0): it slides at a = (-3, 0, 0)
 * and the joint holds m a - W = (0, 4 * 9.81, 0) = (0, 39.24, 0) and, about I,
 * r x (m a - W) = (0.5, 0, 0) x (0, 39.24, 0) = (0, 0, 19.62). */
static void slider_holds_its_weight_and_moment(void **state)
{
    (void)state;
    static const char *const text =
        "<MotionSolve><Model>\n"
        "<Force_Gravity grav_x=\"-3\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
        "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" psi=\"1.5707963267948966\""
        " theta=\"1.5707963267948966\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"4\" inertia_xx=\"0.1\" inertia_yy=\"1.5\""
        " inertia_zz=\"1.5\" v_ic_x=\"0.7\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.5\"/>\n"
        "<Reference_Marker id=\"21\" body_id=\"2\" psi=\"1.5707963267948966\""
        " theta=\"1.5707963267948966\"/>\n"
        "<Constraint_Joint id=\"1\" type=\"TRANSLATIONAL\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "</Model></MotionSolve>\n";
    evaluated e;
    evaluate_text(&e, "slider.xml", text);
    assert_int_equal(e.m.d.joint_row[0], -1);
    assert_close(e.ydot[e.m.d.nq], -3.0, 0, TOL); /* along J's z = x */
    expect_six(of(&e, 1, 0), 0, 39.24, 0, 0, 0, 19.62, TOL);
    release(&e);
}

/* Three links of 1 hanging from the origin, masses 1, 2, 3 (top down), joined
 * top to bottom by a REVOLUTE, a SPHERICAL and a REVOLUTE (none reduced: the
 * top link has two joints): joint k holds the links from k down, (1+2+3) g =
 * 58.86, (2+3) g = 49.05, 3 g = 29.43, up on its I (the lower link). */
static void chain_carries_the_links_below(void **state)
{
    (void)state;
    static const char *const text =
        "<MotionSolve><Model>\n"
        "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
        "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""
        " inertia_zz=\"0.1\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_y=\"-0.5\"/>\n"
        "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
        "<Reference_Marker id=\"22\" body_id=\"2\" pos_y=\"-1\"/>\n"
        "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""
        " inertia_zz=\"0.1\"/>\n"
        "<Reference_Marker id=\"30\" body_id=\"3\" pos_y=\"-1.5\"/>\n"
        "<Reference_Marker id=\"31\" body_id=\"3\" pos_y=\"-1\"/>\n"
        "<Reference_Marker id=\"32\" body_id=\"3\" pos_y=\"-2\"/>\n"
        "<Body_Rigid id=\"4\" cg_id=\"40\" mass=\"3\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""
        " inertia_zz=\"0.1\"/>\n"
        "<Reference_Marker id=\"40\" body_id=\"4\" pos_y=\"-2.5\"/>\n"
        "<Reference_Marker id=\"41\" body_id=\"4\" pos_y=\"-2\"/>\n"
        "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "<Constraint_Joint id=\"2\" type=\"SPHERICAL\" i_marker_id=\"31\" j_marker_id=\"22\"/>\n"
        "<Constraint_Joint id=\"3\" type=\"REVOLUTE\" i_marker_id=\"41\" j_marker_id=\"32\"/>\n"
        "</Model></MotionSolve>\n";
    evaluated e;
    evaluate_text(&e, "chain.xml", text);
    for (int k = 0; k < 3; ++k)
        assert_true(e.m.d.joint_row[k] >= 0);
    expect_six(of(&e, 1, 0), 0, 58.86, 0, 0, 0, 0, TOL);
    expect_six(of(&e, 2, 0), 0, 49.05, 0, 0, 0, 0, TOL);
    expect_six(of(&e, 3, 0), 0, 29.43, 0, 0, 0, 0, TOL);
    /* on J (the link above, at J): the links below pull it down */
    assert_close(output(&e, "JOINT(2, 1, 3, 0)"), -49.05, 0, TOL);
    assert_close(output(&e, "JOINT(2, 0, 1, 0)"), 49.05, 0, TOL);
    release(&e);
}

/* A bar of mass 4 along x, its centre at x = 0.5, on a SPHERICAL at x = 0 and
 * the primitive P at x = 2 (its I marker 22; its J marker 11 on ground at
 * (JX, 0, 0) with the angles JA). Vertical: R1 + R2 = m g = 39.24; moments
 * about x = 0: R2 * 2 = m g * 0.5, R2 = 9.81, R1 = 29.43. */
static const char *bar(const char *P, double jx, const char *ja)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
             "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Reference_Marker id=\"11\" body_id=\"1\" pos_x=\"%.17g\" %s/>\n"
             "<Reference_Marker id=\"12\" body_id=\"1\" psi=\"%.17g\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"4\" inertia_xx=\"0.1\" inertia_yy=\"1.5\""
             " inertia_zz=\"1.5\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.5\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
             "<Reference_Marker id=\"22\" body_id=\"2\" pos_x=\"2\"/>\n"
             "<Constraint_Joint id=\"1\" type=\"SPHERICAL\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
             "<Constraint_Jprim id=\"1\" type=\"%s\" i_marker_id=\"22\" j_marker_id=\"11\"/>\n"
             "</Model></MotionSolve>\n",
             jx, ja, atan2(0.6, 0.8), P);
    return text;
}

static void bar_on_two_supports_by_moments(void **state)
{
    (void)state;
    /* INLINE along x (J's z = x: psi = theta = 90 degrees), J at x = 3: I is
     * 1 behind J along the line */
    evaluated e;
    evaluate_text(&e, "inline.xml", bar("INLINE", 3.0, "psi=\"1.5707963267948966\""
                                        " theta=\"1.5707963267948966\""));
    expect_six(of(&e, 1, 0), 0, 29.43, 0, 0, 0, 0, TOL);
    expect_six(of(&e, 1, 1), 0, 9.81, 0, 0, 0, 0, TOL);
    /* JPRIM on J at J: -F, and -(d x F) with d = x_I - x_J = (-1, 0, 0):
     * -((-1, 0, 0) x (0, 9.81, 0)) = -(0, 0, -9.81) = (0, 0, 9.81) */
    assert_close(output(&e, "JPRIM(1, 1, 3, 0)"), -9.81, 0, TOL);
    assert_close(output(&e, "JPRIM(1, 1, 8, 0)"), 9.81, 0, TOL);
    assert_close(output(&e, "JPRIM(1, 1, 5, 0)"), 9.81, 0, TOL);
    assert_close(output(&e, "JPRIM(1, 0, 5, 0)"), 0.0, 0, TOL);
    /* in marker 12's axes (turned about z: x = (0.8, 0.6, 0), y = (-0.6, 0.8, 0)):
     * F = (0, 9.81, 0) has x 0.6 * 9.81 = 5.886 and y 0.8 * 9.81 = 7.848 */
    assert_close(output(&e, "JPRIM(1, 0, 2, 12)"), 5.886, 0, TOL);
    assert_close(output(&e, "JPRIM(1, 0, 3, 12)"), 7.848, 0, TOL);
    assert_close(output(&e, "JPRIM(1, 0, 4, 12)"), 0.0, 0, TOL);
    assert_close(output(&e, "JPRIM(1, 0, 1, 12)"), 9.81, 0, TOL);
    /* the torque on J in 12's axes: (0, 0, 9.81) stays along z */
    assert_close(output(&e, "JPRIM(1, 1, 8, 12)"), 9.81, 0, TOL);
    assert_close(output(&e, "JPRIM(1, 1, 6, 12)"), 0.0, 0, TOL);
    assert_close(output(&e, "JOINT(1, 0, 3, 0)"), 29.43, 0, TOL);
    release(&e);
    /* INPLANE: J's z along y (theta = 90 degrees: z = (0, -1, 0)), J at x = 2 */
    evaluate_text(&e, "inplane.xml", bar("INPLANE", 2.0, "theta=\"1.5707963267948966\""));
    expect_six(of(&e, 1, 0), 0, 29.43, 0, 0, 0, 0, TOL);
    expect_six(of(&e, 1, 1), 0, 9.81, 0, 0, 0, 0, TOL);
    release(&e);
}

/* A cantilever: the bar above FIXED to ground at x = 0 (I 21 on the bar, J 10):
 * F = (0, m g, 0) = (0, 39.24, 0); its weight's moment about I is
 * (0.5, 0, 0) x (0, -39.24, 0) = (0, 0, -19.62), held by T = (0, 0, 19.62).
 * On J at J (the same point): the opposites; in marker 12's axes the torque
 * stays along z, the force (0, -39.24, 0) has x -0.6 * 39.24 = -23.544. */
static void cantilever_torque_and_its_transfer(void **state)
{
    (void)state;
    static const char *const text =
        "<MotionSolve><Model>\n"
        "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
        "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Reference_Marker id=\"12\" body_id=\"1\" psi=\"0.64350110879328437\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"4\" inertia_xx=\"0.1\" inertia_yy=\"1.5\""
        " inertia_zz=\"1.5\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.5\"/>\n"
        "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
        "<Constraint_Joint id=\"7\" type=\"FIXED\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "</Model></MotionSolve>\n";
    evaluated e;
    evaluate_text(&e, "cantilever.xml", text);
    expect_six(of(&e, 7, 0), 0, 39.24, 0, 0, 0, 19.62, TOL);
    assert_close(output(&e, "JOINT(7, 1, 8, 0)"), -19.62, 0, TOL);
    assert_close(output(&e, "JOINT(7, 1, 2, 12)"), -23.544, 0, TOL);
    assert_close(output(&e, "JOINT(7, 1, 3, 12)"), -0.8 * 39.24, 0, TOL);
    assert_close(output(&e, "JOINT(7, 0, 8, 12)"), 19.62, 0, TOL);
    release(&e);
}

/* A Post_Request reading JOINT() of the swinging pendulum (ground as I, rows)
 * writes what the CSV's joint columns hold, row by row, while it swings. */
static void request_equals_the_csv_columns(void **state)
{
    (void)state;
    char joint[256];
    snprintf(joint, sizeof joint, "%s\n<Post_Request id=\"5\" type=\"EXPRESSION\""
             " expr1=\"JOINT(1,0,1,0)\" expr2=\"JOINT(1,0,2,0)\" expr3=\"JOINT(1,0,3,0)\""
             " expr4=\"JOINT(1,0,4,0)\" expr6=\"JOINT(1,1,6,0)\"/>", JOINT_IJ("REVOLUTE", 10, 21));
    const char *path = test_write_file("request.xml", pendulum("", 1.5, G, 2.0, joint));
    char csv[512];
    snprintf(csv, sizeof csv, "%s.csv", path);
    assert_int_equal(sim_run_csv(path, csv, (const char *const[]){"--end", "0.5", "--quiet",
                                                                    NULL}), 0);
    csv_table t;
    csv_read(csv, &t);
    const int fx = csv_column(csv, "joint1.fx"), fy = csv_column(csv, "joint1.fy"),
              fz = csv_column(csv, "joint1.fz"), tx = csv_column(csv, "joint1.tx"),
              r1 = csv_column(csv, "request5.1"), phidot = csv_column(csv, "phidot");
    assert_true(fx > phidot && phidot > r1 && r1 > 0);
    assert_int_equal(csv_column(csv, "joint1.tz"), t.columns - 1); /* the last column */
    assert_true(t.rows > 5);
    double swing = 0.0;
    for (int r = 0; r < t.rows; ++r) {
        const double F[3] = {csv_at(&t, r, fx), csv_at(&t, r, fy), csv_at(&t, r, fz)};
        const double tol = 1e-12 * (1 + fabs(F[1]));
        assert_close(csv_at(&t, r, r1), sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]), 0, tol);
        for (int c = 0; c < 3; ++c)
            assert_close(csv_at(&t, r, r1 + 1 + c), F[c], 0, tol);
        /* on J (the body) at J, which is I's place: the torque's opposite */
        assert_close(csv_at(&t, r, r1 + 5), -csv_at(&t, r, tx), 0, tol);
        swing = fmax(swing, fabs(F[0]));
    }
    assert_true(swing > 1.0); /* it moved off the bottom: the values change */
    /* the first row by hand: the swapped pendulum at the bottom, -31.62 on ground */
    assert_close(csv_at(&t, 0, fy), -31.62, 0, 1e-9);
    csv_free(&t);
}

static void joint_in_a_general_constraint_is_refused(void **state)
{
    (void)state;
    char text[2048];
    /* line 9: a general constraint. (A force or a
     * variable reads it as an algebraic loop's input: test_algebraic_loops.c) */
    snprintf(text, sizeof text, "%s", pendulum("", 1.5, G, 0.0, JOINT_IJ("REVOLUTE", 21, 10)
             "\n<Constraint_General id=\"4\" i_marker_id=\"20\""
             " expr=\"DX(20) - JOINT(1,0,3,0)\"/>"));
    sim_expect_parse_error("gcon.xml", text, (const char *const[]){"gcon.xml:9:", "JOINT(1,0,3,0)",
                 "algebraic loop", "Constraint_General", NULL});
    /* a variable's: its ids resolved all the same */
    snprintf(text, sizeof text, "%s", pendulum("", 1.5, G, 0.0, JOINT_IJ("REVOLUTE", 21, 10)
             "\n<Reference_Variable id=\"3\" expr=\"JPRIM(1,0,3,0)\"/>"));
    sim_expect_parse_error("variable.xml", text, (const char *const[]){"variable.xml:9:1",
                 "JPRIM(1,0,3,0)", "no Constraint_Jprim (JPRIM) 1", "Reference_Variable", NULL});
    /* in a request: an id the model lacks, a flag or component out of range */
    snprintf(text, sizeof text, "%s", pendulum("", 1.5, G, 0.0, JOINT_IJ("REVOLUTE", 21, 10)
             "\n<Post_Request id=\"5\" type=\"EXPRESSION\" expr2=\"JOINT(9,0,3,0)\"/>"));
    sim_expect_parse_error("noid.xml", text, (const char *const[]){"noid.xml:9:", "JOINT(9,0,3,0)",
                 "no Constraint_Joint (JOINT) 9", NULL});
    snprintf(text, sizeof text, "%s", pendulum("", 1.5, G, 0.0, JOINT_IJ("REVOLUTE", 21, 10)
             "\n<Post_Request id=\"5\" type=\"EXPRESSION\" expr2=\"JOINT(1,0,3,77)\"/>"));
    sim_expect_parse_error("norm.xml", text, (const char *const[]){"norm.xml:9:", "rm (argument 4)",
                 "77", NULL});
    snprintf(text, sizeof text, "%s", pendulum("", 1.5, G, 0.0, JOINT_IJ("REVOLUTE", 21, 10)
             "\n<Post_Request id=\"5\" type=\"EXPRESSION\" expr2=\"JOINT(1,2,3,0)\"/>"));
    sim_expect_parse_error("jflag.xml", text, (const char *const[]){"jflag.xml:9:", "jflag (argument 2)",
                 NULL});
    snprintf(text, sizeof text, "%s", pendulum("", 1.5, G, 0.0, JOINT_IJ("REVOLUTE", 21, 10)
             "\n<Post_Request id=\"5\" type=\"EXPRESSION\" expr2=\"JOINT(1,0,9,0)\"/>"));
    sim_expect_parse_error("comp.xml", text, (const char *const[]){"comp.xml:9:", "comp (argument 3)",
                 NULL});
}

/* Outside an output (no reactions given) JOINT is a fault naming itself. */
static void joint_without_reactions_is_a_fault(void **state)
{
    (void)state;
    evaluated e;
    evaluate_text(&e, "fault.xml", pendulum("", 1.5, G, 0.0, JOINT_IJ("REVOLUTE", 21, 10)));
    hx_message msg;
    hx_expr_program *p = hx_expr_parse("JOINT(1,0,3,0)", 14, NULL, &msg);
    assert_non_null(p);
    assert_int_equal(hx_expr_link_output(p, e.m.session.model, &msg), 0);
    const hx_expr_context c = {&e.m.data.frames, NULL, NULL};
    double value;
    hx_expr_fault fault;
    assert_int_equal(hx_expr_eval(p, &c, &value, &fault), -1);
    assert_int_equal(fault.kind, HX_EXPR_FAULT_INPUT);
    assert_string_equal(fault.function, "JOINT");
    hx_expr_free(p);
    release(&e);
}

/* The dataset's REQUEST reads JOINT() as the XML's Post_Request does: the
 * pendulum at the bottom (w = 2, L = 1.5, m = 2) holds 31.62 up on the part,
 * -31.62 on ground at J (the same point: no torque). An SFORCE that reads it
 * is refused with its place. */
static void dataset_request_and_force(void **state)
{
    (void)state;
    static const char *const head =
        "pendulum\n"
        "ACCGRAV/IGRAV = 0, JGRAV = -9.81, KGRAV = 0\n"
        "PART/1, GROUND\n"
        "MARKER/10, PART = 1\n"
        "PART/2, MASS = 2, CM = 20, IP = 0.3, 0.2, 0.4, WZ = 2\n"
        "MARKER/20, PART = 2, QP = 0, -1.5, 0\n"
        "MARKER/21, PART = 2\n"
        "JOINT/1, REVOLUTE, I = 21, J = 10\n";
    char text[2048];
    snprintf(text, sizeof text, "%sREQUEST/5, F2=JOINT(1,0,2,0)\\F3=JOINT(1,0,3,0)"
             "\\F4=JOINT(1,1,3,0)\\F8=JOINT(1,1,8,0)\nEND\n", head);
    evaluated e;
    evaluate_text(&e, "request.adm", text);
    double out[8];
    hx_message msg;
    const hx_expr_outputs given = {e.r, NULL, NULL, NULL, NULL};
    assert_int_equal(hx_requests_values(&e.m.data.frames, 0, NULL, &given, out, &msg), 0);
    assert_close(out[1], 0.0, 0, TOL);
    assert_close(out[2], 31.62, 0, TOL);
    assert_close(out[3], -31.62, 0, TOL);
    assert_close(out[7], 0.0, 0, TOL);
    /* without the reactions: the request's fault names it */
    assert_int_equal(hx_requests_values(&e.m.data.frames, 0, NULL, NULL, out, &msg), -1);
    assert_contains(msg.text, "request.adm:9:", "JOINT", "no joint reactions");
    release(&e);
    /* line 9: a general constraint may not read it (a force may: test_algebraic_loops.c) */
    snprintf(text, sizeof text, "%sGCON/4, I = 20, FUNCTION = DX(20) - JOINT(1,0,3,0)"
             "\nEND\n", head);
    sim_expect_parse_error("gcon.adm", text, (const char *const[]){"gcon.adm:9:", "GCON/4",
                 "JOINT(1,0,3,0)", "algebraic loop", NULL});
}

/* Bevel gears (the bundled example, mm and N: ucf 1000): two reduced revolutes
 * coupled, a torque on the first. Each gear's centre is on its axis, its axes
 * principal, its spin along one of them, so the joint holds the weight alone,
 * m g / ucf: 0.0123 * 9810 / 1000 = 0.120663 and 0.02775 * 9810 / 1000 =
 * 0.2722275 N up (z), and no torque: what the balance leaves about each axis,
 * the coupler's and the applied torque's share, is not the joint's. The rack
 * and pinion the same: the rack (2 kg, sliding along x, its I at its centre)
 * 2 * 9810 / 1000 = 19.62 N up and nothing along x, where the coupler pushes;
 * the pinion 0.5 * 9.81 = 4.905 N. */
static void coupled_gears_hold_their_weight_only(void **state)
{
    (void)state;
    evaluated e;
    evaluate_path(&e, EXAMPLES_DIR "/rack_pinion.xml");
    assert_true(fabs(e.m.data.lambda[0]) > 1e-6);
    expect_six(of(&e, 51, 0), 0, 0, 19.62, 0, 0, 0, 1e-12);
    expect_six(of(&e, 41, 0), 0, 0, 4.905, 0, 0, 0, 1e-12);
    release(&e);
    evaluate_path(&e, EXAMPLES_DIR "/bevel_gears.xml");
    assert_true(fabs(e.m.data.lambda[0]) > 1e-6); /* the coupler pushes */
    expect_six(of(&e, 1, 0), 0, 0, 0.120663, 0, 0, 0, 1e-12);
    expect_six(of(&e, 2, 0), 0, 0, 0.2722275, 0, 0, 0, 1e-12);
    release(&e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(pendulum_at_rest_carries_its_weight),
        cmocka_unit_test(pendulum_at_the_bottom_pulls_by_its_speed),
        cmocka_unit_test(pendulum_level_by_hand),
        cmocka_unit_test(slider_holds_its_weight_and_moment),
        cmocka_unit_test(chain_carries_the_links_below),
        cmocka_unit_test(bar_on_two_supports_by_moments),
        cmocka_unit_test(cantilever_torque_and_its_transfer),
        cmocka_unit_test(request_equals_the_csv_columns),
        cmocka_unit_test(joint_in_a_general_constraint_is_refused),
        cmocka_unit_test(joint_without_reactions_is_a_fault),
        cmocka_unit_test(dataset_request_and_force),
        cmocka_unit_test(coupled_gears_hold_their_weight_only),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
