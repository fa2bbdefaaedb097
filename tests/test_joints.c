/*
 * Joints between any two bodies in the equations of motion (docs/architecture.md,
 * the constraint system): each joint type's rows of G in the state's velocity
 * coordinates against differences of phi, and gamma against the second
 * difference of phi along a motion with constant velocities, with I on
 * ground, J on ground and between moving bodies; pendulums on a revolute
 * and a spherical joint against their small-angle period; the bundled
 * four-bar and slider-crank against their closed-form kinematics, with
 * DOPRI5 and BDF (constraint residuals, energy); the errors of joints the
 * harness does not run and of RACK_PINION's and SCREW's values. The primitives (Constraint_Jprim) are in the first;
 * their motions in test_joint_primitives.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraints.h"
#include "sim_support.h"
#include "test_support.h"

#define NTYPES 17
static const char *const type_names[NTYPES] = {
    "FIXED",   "REVOLUTE", "TRANSLATIONAL", "CYLINDRICAL", "SPHERICAL",     "UNIVERSAL",
    "HOOKE",   "PLANAR",   "CONSTANT_VELOCITY", "RACK_PINION", "SCREW",
    "ATPOINT", "INLINE",   "INPLANE",       "ORIENTATION",
    "PARALLEL_AXES", "PERPENDICULAR"};
static const int type_rows[NTYPES] = {6, 5, 5, 4, 3, 4, 4, 3, 4, 1, 1, 3, 2, 1, 3, 2, 1};

/* Two bodies (2, 3) with markers at odd places and in odd axes; the joint's
 * I and J markers chosen by `where`: 0 between the bodies, 1 I on ground, 2
 * J on ground (with body 3 hung from body 2 by a spherical joint, so that a
 * revolute or translational joint is not body 2's only one: not reduced). */
static const char *two_body_model(const char *type, int where)
{
    static char text[4096];
    const int i = where == 1 ? 11 : 21, j = where == 2 ? 12 : 31;
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"11\" body_id=\"1\" pos_x=\"0.3\" psi=\"0.4\" theta=\"1.1\" phi=\"-0.2\"/>\n"
             "<Reference_Marker id=\"12\" body_id=\"1\" pos_y=\"-0.2\" psi=\"-0.7\" theta=\"0.5\" phi=\"0.9\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1.5\" inertia_xx=\"0.2\" inertia_yy=\"0.3\" inertia_zz=\"0.25\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.1\" pos_y=\"0.2\" psi=\"0.3\" theta=\"0.2\" phi=\"0.1\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"0.5\" pos_y=\"-0.1\" pos_z=\"0.2\" psi=\"1.3\" theta=\"0.8\" phi=\"-0.4\"/>\n"
             "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"2\" inertia_xx=\"0.4\" inertia_yy=\"0.3\" inertia_zz=\"0.2\"/>\n"
             "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"-0.4\" pos_z=\"0.3\" psi=\"-0.3\" theta=\"0.6\" phi=\"0.2\"/>\n"
             "<Reference_Marker id=\"31\" body_id=\"3\" pos_x=\"0.2\" pos_y=\"0.4\" psi=\"0.9\" theta=\"-0.5\" phi=\"1.2\"/>\n"
             "<Constraint_%s id=\"1\" type=\"%s\" i_marker_id=\"%d\" j_marker_id=\"%d\""
             " pitch_diameter=\"0.3\" pitch=\"-0.25\"/>\n"
             "%s</Model></MotionSolve>\n",
             hx_joint_type_is_primitive((enum hx_joint_type)hx_joint_type_from_name(type)) ? "Jprim"
                                                                                      : "Joint",
             type, i, j,
             where == 2 ? "<Constraint_Joint id=\"2\" type=\"SPHERICAL\" i_marker_id=\"31\""
                          " j_marker_id=\"21\"/>\n" : "");
    return text;
}

/* A random state of the free bodies: positions, unit quaternions, velocities. */
static void random_state(const hx_dynamics *d, double *y)
{
    memset(y, 0, sizeof(double) * (size_t)d->n);
    for (int b = 0; b < d->m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        if (dof->kind != HX_DOF_FREE)
            continue;
        double *q = y + dof->q, *u = y + d->nq + dof->u;
        for (int c = 0; c < 3; ++c)
            q[c] = sim_uniform();
        double n = 0.0;
        for (int c = 3; c < 7; ++c)
            q[c] = sim_uniform(), n += q[c] * q[c];
        for (int c = 3; c < 7; ++c)
            q[c] /= sqrt(n);
        for (int c = 0; c < 6; ++c)
            u[c] = 1.5 * sim_uniform();
    }
}

/* phi after moving the positions by h along the velocities u (q's rate is
 * N(q) u, quaternions by their exact increment: u is constant on it; a
 * negative h as -u over |h|, the increment taking positive steps only). */
static void phi_along(sim_opened *o, const double *y, const double *u, double h, double *phi)
{
    const hx_dynamics *d = &o->d;
    double *z = malloc(sizeof(double) * (size_t)d->n), *G = malloc(sizeof(double) * 12 * (size_t)d->nrows);
    assert_non_null(z), assert_non_null(G);
    memcpy(z, y, sizeof(double) * (size_t)d->n);
    for (int k = 0; k < d->nu; ++k)
        z[d->nq + k] = h < 0.0 ? -u[k] : u[k];
    hx_bodies_advance_positions(d, z, fabs(h));
    assert_int_equal(hx_constraints_rows(d, &o->dd, 0.0, z, phi, G, NULL), 0);
    free(z), free(G);
}

static void constraint_rows_against_differences(void **state)
{
    (void)state;
    srand(21);
    for (int k = 0; k < NTYPES; ++k)
        for (int where = 0; where < 3; ++where) {
            sim_opened o;
            sim_open_text(&o, "two_bodies.xml", two_body_model(type_names[k], where));
            const hx_dynamics *d = &o.d;
            assert_int_equal(d->nrows, type_rows[k] + (where == 2 ? 3 : 0));
            for (int r = 0; r < type_rows[k]; ++r) /* the ground has no columns */
                assert_int_equal(d->rows[r].nblocks, where == 0 ? 2 : 1);
            double y[64], e[32], phi[16], G[12 * 16], gamma[16], plus[16], minus[16], mid[16];
            assert_true(d->n <= 64 && d->nu <= 32 && d->nrows <= 16);
            for (int trial = 0; trial < 5; ++trial) {
                random_state(d, y);
                assert_int_equal(hx_constraints_rows(d, &o.dd, 0.0, y, phi, G, gamma), 0);
                const double h = 1e-6;
                for (int c = 0; c < d->nu; ++c) { /* G's column c: d phi along u = e_c */
                    memset(e, 0, sizeof e);
                    e[c] = 1.0;
                    phi_along(&o, y, e, h, plus);
                    phi_along(&o, y, e, -h, minus);
                    for (int r = 0; r < d->nrows; ++r) {
                        double g = 0.0;
                        for (int b = 0; b < d->rows[r].nblocks; ++b) {
                            const hx_constraint_row *row = &d->rows[r];
                            if (c >= row->u[b] && c < row->u[b] + row->width[b])
                                g = G[12 * r + row->slot[b] + c - row->u[b]];
                        }
                        assert_close(g, (plus[r] - minus[r]) / (2 * h), 0, 1e-8);
                    }
                }
                /* with u constant, phi_ddot = G udot - gamma = -gamma */
                const double h2 = 1e-4;
                phi_along(&o, y, y + d->nq, h2, plus);
                phi_along(&o, y, y + d->nq, -h2, minus);
                phi_along(&o, y, y + d->nq, 0.0, mid);
                for (int r = 0; r < d->nrows; ++r)
                    assert_close(-gamma[r], (plus[r] - 2 * mid[r] + minus[r]) / (h2 * h2), 0, 2e-5);
            }
            sim_close_opened(&o);
        }
}

/* A pendulum: centre of mass L below the pivot at the origin, started at
 * angle a0 from hanging at rest; the joint's I marker on ground when
 * `i_on_ground` (a general joint), else J (the body's only joint to ground:
 * the reduced coordinate for a revolute). */
static const char *pendulum(const char *type, int i_on_ground, double a0)
{
    static char text[2048];
    const double L = 0.8, x = L * sin(a0), y = -L * cos(a0);
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1.2\" inertia_xx=\"1e-6\" inertia_yy=\"1e-6\""
             " inertia_zz=\"1e-6\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"%.17g\" pos_y=\"%.17g\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
             "<Constraint_Joint id=\"1\" type=\"%s\" i_marker_id=\"%d\" j_marker_id=\"%d\"/>\n"
             "</Model></MotionSolve>\n",
             x, y, type, i_on_ground ? 10 : 21, i_on_ground ? 21 : 10);
    return text;
}

/* The period from the upward zero crossings of the swing's x (linear
 * interpolation between output rows). */
static double measured_period(const sim *s, int xq)
{
    double first = -1.0, last = -1.0;
    int crossings = 0;
    for (int r = 1; r < s->path.rows; ++r) {
        const double x0 = sim_state(s, r - 1, xq), x1 = sim_state(s, r, xq);
        if (x0 < 0.0 && x1 >= 0.0) {
            const double t = s->path.t[r - 1] + (s->path.t[r] - s->path.t[r - 1]) * (-x0) / (x1 - x0);
            if (first < 0.0)
                first = t;
            last = t;
            crossings++;
        }
    }
    assert_true(crossings >= 3);
    return (last - first) / (crossings - 1);
}

static void pendulums_swing_at_their_period(void **state)
{
    (void)state;
    /* Small angles: I_pivot phi'' = -m g L phi, I_pivot = I_c + m L^2, so
     * T = 2 pi sqrt(I_pivot / (m g L)) -> 2 pi sqrt(L / g) as I_c -> 0 (here
     * I_c = 1e-6: 1.3e-6 relative); an amplitude a0 lengthens it by
     * (1 + a0^2 / 16): 6e-6 at a0 = 0.01, the tolerance's scale. */
    const double L = 0.8, g = 9.81, m = 1.2, Ic = 1e-6, a0 = 0.01;
    const double T = 2.0 * M_PI * sqrt((Ic + m * L * L) / (m * g * L)) * (1.0 + a0 * a0 / 16.0);
    const char *types[2] = {"REVOLUTE", "SPHERICAL"};
    for (int k = 0; k < 2; ++k) {
        sim s;
        sim_run(&s, test_write_file("pendulum.xml", pendulum(types[k], 1, a0)), HX_METHOD_DOPRI5,
                1e-11, 3.2 * T, 0.002);
        assert_int_equal(s.dynamics.nrows, k == 0 ? 5 : 3);
        const int xq = s.dynamics.dof[1].q; /* the body's centre x */
        assert_close(measured_period(&s, xq), T, 2e-5, 0);
        assert_true(s.result.max_phi <= 1e-10 * L);
        assert_true(s.result.max_phidot <= 1e-10 * L);
        assert_true(s.result.energy_error_max <= 1e-9 * s.result.energy_scale);
        sim_close(&s);
    }
}

/* The same revolute pendulum, reduced (J on ground) and Cartesian (I on
 * ground), at a large swing: one motion. */
static void cartesian_revolute_follows_the_reduced_one(void **state)
{
    (void)state;
    sim reduced, cartesian;
    sim_run(&reduced, test_write_file("reduced.xml", pendulum("REVOLUTE", 0, 1.2)),
            HX_METHOD_DOPRI5, 1e-11, 2.0, 0.05);
    sim_run(&cartesian, test_write_file("cartesian.xml", pendulum("REVOLUTE", 1, 1.2)),
            HX_METHOD_DOPRI5, 1e-11, 2.0, 0.05);
    assert_int_equal(reduced.dynamics.nrows, 0);
    assert_int_equal(cartesian.dynamics.nrows, 5);
    assert_int_equal(reduced.path.rows, cartesian.path.rows);
    const int xq = cartesian.dynamics.dof[1].q;
    for (int r = 0; r < reduced.path.rows; ++r) {
        /* the reduced coordinate is AZ(I, J) of the body's marker against
         * ground's; the Cartesian one's centre at L (sin a, -cos a) */
        const double a = 1.2 + sim_state(&reduced, r, reduced.dynamics.dof[1].q); /* 0 at t = 0 */
        assert_close(sim_state(&cartesian, r, xq), 0.8 * sin(a), 0, 1e-8);
        assert_close(sim_state(&cartesian, r, xq + 1), -0.8 * cos(a), 0, 1e-8);
    }
    sim_close(&reduced);
    sim_close(&cartesian);
}

/* The four-bar's rocker from its crank (harness/examples/four_bar.xml):
 * C where the circles about B (radius b) and D (radius c) meet, on the branch
 * left of BD; the rates from vB + w3 x (C - B) = w4 x (C - D). */
static void four_bar_closed_form(double t2, double w2, double *t4, double *w4)
{
    const double a = 0.1, b = 0.35, c = 0.3, d = 0.3;
    const double B[2] = {a * cos(t2), a * sin(t2)}, BD[2] = {d - B[0], -B[1]};
    const double e = hypot(BD[0], BD[1]), l = (b * b - c * c + e * e) / (2 * e);
    const double h = sqrt(b * b - l * l), ux = BD[0] / e, uy = BD[1] / e;
    const double C[2] = {B[0] + l * ux - h * uy, B[1] + l * uy + h * ux};
    *t4 = atan2(C[1], C[0] - d);
    const double vB[2] = {-w2 * B[1], w2 * B[0]}, r3[2] = {C[0] - B[0], C[1] - B[1]},
                 r4[2] = {C[0] - d, C[1]};
    /* w3 (-r3y, r3x) - w4 (-r4y, r4x) = -vB */
    const double M00 = -r3[1], M01 = r4[1], M10 = r3[0], M11 = -r4[0];
    const double det = M00 * M11 - M01 * M10;
    *w4 = (M00 * -vB[1] - M10 * -vB[0]) / det;
}

static void check_four_bar(const sim *s)
{
    const hx_dynamics *d = &s->dynamics;
    const hx_body_dof *crank = &d->dof[1], *rocker = &d->dof[3];
    for (int r = 0; r < s->path.rows; ++r) {
        /* the bars' centres are at their middles: the crank's angle from
         * its centre, the rocker's from its centre about D */
        const double t2 = atan2(sim_state(s, r, crank->q + 1), sim_state(s, r, crank->q));
        const double w2 = sim_state(s, r, d->nq + crank->u + 5); /* body z = world z */
        double t4, w4;
        four_bar_closed_form(t2, w2, &t4, &w4);
        const double sim_t4 = atan2(sim_state(s, r, rocker->q + 1), sim_state(s, r, rocker->q) - 0.3);
        assert_close(sim_t4, t4, 0, 1e-9);
        assert_close(sim_state(s, r, d->nq + rocker->u + 5), w4, 0, 1e-8);
    }
    assert_true(s->result.max_phi <= 1e-10 * 0.35);
    assert_true(s->result.max_phidot <= 1e-10);
}

static void four_bar_kinematics(void **state)
{
    (void)state;
    sim s;
    sim_run(&s, "four_bar.xml", HX_METHOD_DOPRI5, 1e-10, 2.0, 0.01);
    assert_int_equal(s.dynamics.nrows, 17);
    check_four_bar(&s);
    assert_true(s.result.energy_error_max <= 1e-8 * s.result.energy_scale);
    sim_close(&s);
    sim_run(&s, "four_bar.xml", HX_METHOD_BDF, 1e-4, 0.5, 0.01);
    check_four_bar(&s);
    assert_true(s.result.energy_error_max <= 1e-4 * s.result.energy_scale);
    sim_close(&s);
}

/* The slider's x and velocity from the crank's angle and rate: B at
 * r cos t + sqrt(l^2 - r^2 sin^2 t). */
static void check_slider_crank(const sim *s)
{
    const hx_dynamics *d = &s->dynamics;
    const hx_body_dof *crank = &d->dof[1], *slider = &d->dof[3];
    const double r = 0.1, l = 0.4;
    for (int row = 0; row < s->path.rows; ++row) {
        const double t = atan2(sim_state(s, row, crank->q + 1), sim_state(s, row, crank->q));
        const double w = sim_state(s, row, d->nq + crank->u + 5);
        const double root = sqrt(l * l - r * r * sin(t) * sin(t));
        const double x = r * cos(t) + root;
        const double v = -r * w * sin(t) - r * r * sin(t) * cos(t) * w / root;
        assert_close(sim_state(s, row, slider->q), x, 0, 1e-9);
        assert_close(sim_state(s, row, d->nq + slider->u), v, 0, 1e-8);
        assert_close(sim_state(s, row, slider->q + 1), 0.0, 0, 1e-10);
    }
    assert_true(s->result.max_phi <= 1e-10 * 0.5);
    assert_true(s->result.max_phidot <= 1e-10);
}

static void slider_crank_kinematics(void **state)
{
    (void)state;
    sim s;
    sim_run(&s, "slider_crank.xml", HX_METHOD_DOPRI5, 1e-10, 2.0, 0.01);
    assert_int_equal(s.dynamics.nrows, 17);
    check_slider_crank(&s);
    assert_true(s.result.energy_error_max <= 1e-8 * s.result.energy_scale);
    sim_close(&s);
    sim_run(&s, "slider_crank.xml", HX_METHOD_BDF, 1e-4, 0.5, 0.01);
    check_slider_crank(&s);
    sim_close(&s);
}

/* BDF's Jacobian on the joints' rows (differences over the coupled bodies)
 * against differences of the whole right-hand side. */
static void jacobian_of_the_linkages(void **state)
{
    (void)state;
    const char *models[2] = {"four_bar.xml", "slider_crank.xml"};
    for (int k = 0; k < 2; ++k) {
        sim s;
        sim_run(&s, models[k], HX_METHOD_DOPRI5, 1e-8, 0.3, 0.3);
        const int last = s.path.rows - 1;
        long outside = 0;
        const double worst = jacobian_against_differences(&s.dynamics, s.path.t[last],
                                                          s.path.y + last * s.path.n, models[k],
                                                          &outside);
        /* 2.4e-9 of a row on the four-bar; 2.2e-6 on the slider-crank, in the
         * slider's vertical acceleration: zero but for rounding (4e-9 by
         * differences), measured against 1e-5 of the matrix's largest entry */
        assert_true(worst < 1e-5);
        assert_int_equal(outside, 0);
        sim_close(&s);
    }
}

static void joints_the_harness_refuses(void **state)
{
    (void)state;
    static const struct {
        const char *joints;
        const char *needles[3];
    } cases[] = {
        {"<Constraint_Joint id=\"1\" type=\"GEAR\" i_marker_id=\"21\" j_marker_id=\"10\"/>",
         {"bad.xml:8:", "Constraint_Joint 1", "type \"GEAR\""}},
        /* a SCREW needs its pitch (not 0), a RACK_PINION its pitch diameter (> 0) */
        {"<Constraint_Joint id=\"1\" type=\"SCREW\" i_marker_id=\"21\" j_marker_id=\"10\"/>",
         {"bad.xml:8:", "Constraint_Joint 1", "a SCREW joint needs pitch"}},
        {"<Constraint_Joint id=\"1\" type=\"SCREW\" i_marker_id=\"21\" j_marker_id=\"10\""
         " pitch=\"0\"/>",
         {"bad.xml:8:", "Constraint_Joint 1", "pitch = 0: expected a pitch not 0"}},
        {"<Constraint_Joint id=\"1\" type=\"RACK_PINION\" i_marker_id=\"21\" j_marker_id=\"10\""
         " pitch=\"1\"/>",
         {"bad.xml:8:", "Constraint_Joint 1", "a RACK_PINION joint needs pitch_diameter"}},
        {"<Constraint_Joint id=\"1\" type=\"RACKPIN\" i_marker_id=\"21\" j_marker_id=\"10\""
         " pitch_diameter=\"-2\"/>",
         {"bad.xml:8:", "Constraint_Joint 1", "pitch_diameter = -2: expected a diameter > 0"}},
        /* their turn needs z_J across z_I (RACK_PINION), x_I across z_J (SCREW): 21 and 10
         * have the world's axes */
        {"<Constraint_Joint id=\"1\" type=\"RACKPIN\" i_marker_id=\"21\" j_marker_id=\"10\""
         " pitch_diameter=\"2\"/>",
         {"bad.xml:8:", "Constraint_Joint 1", "rack axis z_J must be across the pinion's axis"}},
        {"<Constraint_Joint id=\"1\" type=\"SCREW\" i_marker_id=\"21\" j_marker_id=\"10\""
         " pitch=\"2\"/>\n<Reference_Marker id=\"22\" body_id=\"2\" psi=\"1.5707963267948966\""
         " theta=\"1.5707963267948966\"/>\n"
         "<Constraint_Joint id=\"2\" type=\"SCREW\" i_marker_id=\"10\" j_marker_id=\"22\""
         " pitch=\"2\"/>",
         {"bad.xml:10:", "Constraint_Joint 2", "a SCREW's x_I must be across z_J"}},
        /* a primitive is a Constraint_Jprim's type, not a Constraint_Joint's, and back */
        {"<Constraint_Joint id=\"1\" type=\"INLINE\" i_marker_id=\"21\" j_marker_id=\"10\"/>",
         {"bad.xml:8:", "Constraint_Joint 1", "type \"INLINE\""}},
        {"<Constraint_Jprim id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>",
         {"bad.xml:8:", "Constraint_Jprim 1", "type \"REVOLUTE\""}},
        {"<Constraint_Jprim id=\"1\" type=\"INLINER\" i_marker_id=\"21\" j_marker_id=\"10\"/>",
         {"bad.xml:8:", "Constraint_Jprim 1", "ATPOINT, INLINE"}},
        {"<Constraint_Jprim id=\"1\" type=\"INLINE\" i_marker_id=\"21\" j_marker_id=\"20\"/>",
         {"bad.xml:8:", "Constraint_Jprim 1", "on the same body"}},
        {"<Constraint_Jprim id=\"1\" type=\"INLINE\" i_marker_id=\"21\" j_marker_id=\"10\"/>"
         "<Constraint_Jprim id=\"1\" type=\"INPLANE\" i_marker_id=\"21\" j_marker_id=\"10\"/>",
         {"bad.xml:8:", "Constraint_Jprim 1", "defined twice"}},
        /* a JPRIM's id is not a joint's: a coupler cannot name it */
        {"<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>"
         "<Constraint_Jprim id=\"2\" type=\"INPLANE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
         "<Constraint_Coupler id=\"1\" joint1_id=\"2\" freedom_1=\"R\" joint2_id=\"1\" freedom_2=\"R\""
         " coefficients=\"1,1\"/>",
         {"bad.xml:9:", "Constraint_Coupler 1", "joint1_id 2 is not a Constraint_Joint"}},
        {"<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"10\" j_marker_id=\"10\"/>",
         {"bad.xml:8:", "Constraint_Joint 1", "on the same body"}},
        {"<Constraint_Joint id=\"1\" type=\"SPHERICAL\" i_marker_id=\"21\" j_marker_id=\"10\"/>"
         "<Constraint_Joint id=\"2\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
         "<Constraint_Coupler id=\"1\" joint1_id=\"1\" freedom_1=\"R\" joint2_id=\"2\" freedom_2=\"R\""
         " coefficients=\"1,1\"/>",
         {"bad.xml:9:", "Constraint_Coupler 1", "joint 1 is SPHERICAL, which has no coordinate"}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char text[2048];
        snprintf(text, sizeof text,
                 "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
                 "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
                 "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
                 " inertia_zz=\"1\"/>\n"
                 "<Reference_Marker id=\"20\" body_id=\"2\" pos_y=\"-1\"/>\n"
                 "<Reference_Marker id=\"21\" body_id=\"2\"/>\n\n%s\n</Model></MotionSolve>\n",
                 cases[k].joints);
        hx_message msg;
        hx_model *m = hx_model_read(test_write_file("bad.xml", text), NULL, &msg);
        assert_null(m);
        assert_contains(msg.text, cases[k].needles[0], cases[k].needles[1], cases[k].needles[2]);
    }
    /* joints that cannot be met (two ball joints 1 apart on the body, 3 on
     * ground): the initial state's projection says so, naming the time */
    sim_opened o;
    sim_open_text(&o, "apart.xml",
              "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
              "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
              "<Reference_Marker id=\"11\" body_id=\"1\" pos_x=\"3\"/>\n"
              "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
              " inertia_zz=\"1\"/>\n"
              "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.5\"/>\n"
              "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
              "<Reference_Marker id=\"22\" body_id=\"2\" pos_x=\"1\"/>\n"
              "<Constraint_Joint id=\"1\" type=\"SPHERICAL\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
              "<Constraint_Joint id=\"2\" type=\"SPHERICAL\" i_marker_id=\"22\" j_marker_id=\"11\"/>\n"
              "</Model></MotionSolve>\n");
    double *y = calloc((size_t)o.d.n, sizeof(double));
    assert_non_null(y);
    hx_message msg;
    assert_int_equal(hx_dynamics_initial_y(&o.d, y, &msg), -1);
    /* G has rank 5 on the balls' line (the turn about it is free): joint
     * 2's row along the line is redundant at set-up and removed, and once
     * the others are met it is 2 off, the distance that cannot change
     * (tests/test_redundancy.c) */
    assert_contains(msg.text, "a redundant constraint is not consistent at t = 0",
                    "JOINT/2 SPHERICAL: equation 1 (x_I - x_J along x)", "the model locks");
    free(y);
    sim_close_opened(&o);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(constraint_rows_against_differences),
        cmocka_unit_test(pendulums_swing_at_their_period),
        cmocka_unit_test(cartesian_revolute_follows_the_reduced_one),
        cmocka_unit_test(four_bar_kinematics),
        cmocka_unit_test(slider_crank_kinematics),
        cmocka_unit_test(jacobian_of_the_linkages),
        cmocka_unit_test(joints_the_harness_refuses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
