/*
 * Couplers on joints between any bodies (docs/interface.md §2, docs/architecture.md,
 * the constraint system): a joint's coordinate (joint_coordinate.h), its row
 * against differences of the coordinate and its convective term against
 * second differences, with I on ground, J on ground and both moving; two
 * gears on revolutes to a carrier that turns against their closed form; a
 * coupled pair once on reduced joints and once on general ones; the analytic
 * Jacobian against differences and BDF against DOPRI5; the bundled
 * differential whose carrier turns against its closed form; the couplings
 * the reader refuses, with file:line; a Motion_Joint between two moving
 * bodies following MOTSUB's function, and the motions refused.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "frames/measures.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/joint_coordinate.h"
#include "sim_support.h"
#include "test_support.h"

/* A cylindrical joint (1) between bodies 2 and 3 with markers at odd places
 * and in odd axes; `where`: 0 between the bodies, 1 I on ground, 2 J on
 * ground; `more`: elements added. */
static const char *cylinder_model(int where, const char *more)
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
             "<Constraint_Joint id=\"1\" type=\"CYLINDRICAL\" i_marker_id=\"%d\" j_marker_id=\"%d\"/>\n"
             "<Constraint_Joint id=\"2\" type=\"SPHERICAL\" i_marker_id=\"30\" j_marker_id=\"20\"/>\n"
             "%s</Model></MotionSolve>\n",
             i, j, more);
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
        double *q = y + dof->q, *u = y + d->nq + dof->u, n = 0.0;
        for (int c = 0; c < 3; ++c)
            q[c] = 0.3 * sim_uniform();
        for (int c = 3; c < 7; ++c)
            q[c] = sim_uniform(), n += q[c] * q[c];
        for (int c = 3; c < 7; ++c)
            q[c] /= sqrt(n);
        for (int c = 0; c < 6; ++c)
            u[c] = 1.5 * sim_uniform();
    }
}

/* The coordinate after moving the positions by h along the velocities u
 * (constant: the quaternions by their exact increment). */
static double coordinate_along(const hx_dynamics *d, char freedom, const double *y,
                               const double *u, double h)
{
    double z[64], value;
    memcpy(z, y, sizeof(double) * (size_t)d->n);
    for (int k = 0; k < d->nu; ++k)
        z[d->nq + k] = h < 0.0 ? -u[k] : u[k];
    hx_bodies_advance_positions(d, z, fabs(h));
    hx_joint_coordinate_at(d, 0, freedom, z, &value, NULL, NULL);
    return value;
}

/* G's entry for velocity c of joint 0 (I's body's block, then J's). */
static double row_entry(const hx_dynamics *d, const double G[12], int c)
{
    const hx_joint *j = &d->m->joints[0];
    const int side[2] = {d->m->markers[j->i_marker].body, d->m->markers[j->j_marker].body};
    for (int s = 0; s < 2; ++s) {
        const hx_body_dof *dof = &d->dof[side[s]];
        if (dof->kind == HX_DOF_FREE && c >= dof->u && c < dof->u + 6)
            return G[6 * s + c - dof->u];
    }
    return 0.0;
}

static void coordinate_rows_against_differences(void **state)
{
    (void)state;
    srand(7);
    const char freedoms[2] = {'R', 'T'};
    for (int where = 0; where < 3; ++where) {
        sim_opened o;
        sim_open_text(&o, "cylinder.xml", cylinder_model(where, ""));
        const hx_dynamics *d = &o.d;
        assert_true(d->n <= 64);
        for (int f = 0; f < 2; ++f)
            for (int trial = 0; trial < 6; ++trial) {
                double y[64], e[32], G[12] = {0}, value, conv;
                random_state(d, y);
                hx_joint_coordinate_at(d, 0, freedoms[f], y, &value, G, &conv);
                const double h = 1e-6;
                double rate = 0.0;
                for (int c = 0; c < d->nu; ++c) { /* the row's column c: along u = e_c */
                    memset(e, 0, sizeof e);
                    e[c] = 1.0;
                    const double slope = (coordinate_along(d, freedoms[f], y, e, h) -
                                          coordinate_along(d, freedoms[f], y, e, -h)) / (2 * h);
                    assert_close(row_entry(d, G, c), slope, 0, 1e-8);
                    rate += row_entry(d, G, c) * y[d->nq + c];
                }
                /* with u constant, a_ddot = G u_dot + c = c; and a_dot = G u */
                const double h2 = 1e-4, *u = y + d->nq;
                const double plus = coordinate_along(d, freedoms[f], y, u, h2);
                const double minus = coordinate_along(d, freedoms[f], y, u, -h2);
                assert_close(rate, (plus - minus) / (2 * h2), 0, 1e-6);
                assert_close(conv, (plus - 2 * value + minus) / (h2 * h2), 0, 2e-5);
                assert_true(fabs(conv) > 1e-3); /* the term is there to be checked */
            }
        sim_close_opened(&o);
    }
}

/* The coordinate check and bench sample a coupler's joint at (frames/measures.h):
 * a cylindrical joint with I turned 0.3 rad about J's z and 0.5 along it
 * gives 0.3 for freedom R and 0.5 for T (its own coordinate, with no freedom
 * named, the translation). */
static void cylinder_coordinate_by_freedom(void **state)
{
    (void)state;
    sim_opened o;
    sim_open_text(&o, "turned.xml",
              "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
              "<Reference_Marker id=\"11\" body_id=\"1\"/>\n"
              "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
              " inertia_zz=\"1\"/>\n"
              "<Reference_Marker id=\"20\" body_id=\"2\" pos_z=\"0.5\"/>\n"
              "<Reference_Marker id=\"21\" body_id=\"2\" pos_z=\"0.5\" psi=\"0.3\"/>\n"
              "<Constraint_Joint id=\"1\" type=\"CYLINDRICAL\" i_marker_id=\"21\""
              " j_marker_id=\"11\"/>\n</Model></MotionSolve>\n");
    assert_close(hx_joint_coordinate(&o.s.frames, 0, 'R'), 0.3, 0, 1e-14);
    assert_close(hx_joint_coordinate(&o.s.frames, 0, 'T'), 0.5, 0, 1e-14);
    assert_close(hx_joint_coordinate(&o.s.frames, 0, 0), 0.5, 0, 1e-14);
    sim_close_opened(&o);
}

/* A coupler of the cylinder's rotation and a revolute (3) from body 3 to
 * ground: phi = a_1 + 2 a_3, its row (36 values: up to 6 bodies) against
 * differences of phi and gamma against its second difference along a
 * motion with constant velocities, at states near the model's (the
 * rotations unwrapped against it). */
static void coupler_row_against_differences(void **state)
{
    (void)state;
    srand(11);
    static const char more[] =
        "<Reference_Marker id=\"32\" body_id=\"3\" pos_z=\"0.5\" psi=\"0.2\"/>\n"
        "<Reference_Marker id=\"14\" body_id=\"1\" pos_z=\"0.5\" psi=\"-0.3\"/>\n"
        "<Constraint_Joint id=\"3\" type=\"REVOLUTE\" i_marker_id=\"32\" j_marker_id=\"14\"/>\n"
        "<Constraint_Coupler id=\"1\" joint1_id=\"1\" freedom_1=\"R\" joint2_id=\"3\""
        " coefficients=\"1, 2\"/>\n";
    for (int where = 0; where < 3; ++where) {
        sim_opened o;
        sim_open_text(&o, "cylinder_coupler.xml", cylinder_model(where, more));
        const hx_dynamics *d = &o.d;
        assert_int_equal(d->row_values, 36);
        assert_int_equal(d->rows[0].nblocks, where == 1 ? 1 : 2); /* body 3, and body 2 */
        double y0[64], y[64], e[32], *G = calloc(36 * (size_t)d->nrows, sizeof(double));
        double phi[32], gamma[32], plus[32], minus[32], mid[32], Gs[36 * 32];
        assert_non_null(G);
        assert_true(d->n <= 64 && d->nrows <= 32);
        assert_int_equal(hx_dynamics_model_state(d, &o.dd, y0), 0);
        for (int trial = 0; trial < 5; ++trial) {
            memcpy(y, y0, sizeof y0);
            for (int b = 0; b < d->m->nbodies; ++b) {
                const hx_body_dof *dof = &d->dof[b];
                if (dof->kind != HX_DOF_FREE)
                    continue;
                double n = 0.0;
                for (int c = 0; c < 7; ++c)
                    y[dof->q + c] += 0.2 * sim_uniform();
                for (int c = 3; c < 7; ++c)
                    n += y[dof->q + c] * y[dof->q + c];
                for (int c = 3; c < 7; ++c)
                    y[dof->q + c] /= sqrt(n);
                for (int c = 0; c < 6; ++c)
                    y[d->nq + dof->u + c] = 1.5 * sim_uniform();
            }
            assert_int_equal(hx_constraints_rows(d, &o.dd, 0.0, y, phi, G, gamma), 0);
            const double h = 1e-6;
            for (int c = 0; c < d->nu; ++c) {
                memset(e, 0, sizeof e);
                e[c] = 1.0;
                double z[64];
                for (int side = 0; side < 2; ++side) {
                    memcpy(z, y, sizeof z);
                    for (int k = 0; k < d->nu; ++k)
                        z[d->nq + k] = side ? -e[k] : e[k];
                    hx_bodies_advance_positions(d, z, h);
                    assert_int_equal(hx_constraints_rows(d, &o.dd, 0.0, z, side ? minus : plus,
                                                         Gs, NULL), 0);
                }
                assert_int_equal(hx_constraints_rows(d, &o.dd, 0.0, y, phi, G, gamma), 0);
                double g = 0.0;
                const hx_constraint_row *row = &d->rows[0];
                for (int b = 0; b < row->nblocks; ++b)
                    if (c >= row->u[b] && c < row->u[b] + row->width[b])
                        g = G[row->slot[b] + c - row->u[b]];
                assert_close(g, (plus[0] - minus[0]) / (2 * h), 0, 1e-8);
            }
            const double h2 = 1e-4;
            double z[64];
            for (int side = 0; side < 3; ++side) {
                memcpy(z, y, sizeof z);
                for (int k = 0; k < d->nu; ++k)
                    z[d->nq + k] = side == 1 ? -y[d->nq + k] : y[d->nq + k];
                hx_bodies_advance_positions(d, z, side == 2 ? 0.0 : h2);
                double *out = side == 0 ? plus : side == 1 ? minus : mid;
                assert_int_equal(hx_constraints_rows(d, &o.dd, 0.0, z, out, Gs, NULL), 0);
            }
            assert_close(-gamma[0], (plus[0] - 2 * mid[0] + minus[0]) / (h2 * h2), 0, 2e-5);
        }
        free(G);
        sim_close_opened(&o);
    }
}

/* A carrier (body 2) on a revolute to ground about z at the origin, gears A
 * (3) at x = +d and B (4) at x = -d on revolutes to it about z, coupled as
 * phi_A + r phi_B = 0 (their angles relative to the carrier); torques Tc on
 * the carrier and Ta on gear A, both about z from ground. With `gravity`,
 * gravity along -y and the carrier's centre off its axis (its accelerations
 * then depend on the state: the Jacobian's check). */
#define CARRIER_R 2.5
#define CARRIER_D 0.5
static const char *carrier_model(const char *coupler, int gravity)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\" %s/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Reference_Marker id=\"13\" body_id=\"1\" pos_x=\"%g\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"3\" inertia_xx=\"0.5\" inertia_yy=\"0.6\" inertia_zz=\"0.7\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" %s/>\n"
             "<Reference_Marker id=\"23\" body_id=\"2\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"%g\"/>\n"
             "<Reference_Marker id=\"22\" body_id=\"2\" pos_x=\"%g\"/>\n"
             "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1.2\" inertia_xx=\"0.2\" inertia_yy=\"0.2\" inertia_zz=\"0.15\"/>\n"
             "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"%g\"/>\n"
             "<Body_Rigid id=\"4\" cg_id=\"40\" mass=\"0.8\" inertia_xx=\"0.1\" inertia_yy=\"0.1\" inertia_zz=\"0.05\"/>\n"
             "<Reference_Marker id=\"40\" body_id=\"4\" pos_x=\"%g\"/>\n"
             "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"23\" j_marker_id=\"10\"/>\n"
             "<Constraint_Joint id=\"2\" type=\"REVOLUTE\" i_marker_id=\"30\" j_marker_id=\"21\"/>\n"
             "<Constraint_Joint id=\"3\" type=\"REVOLUTE\" i_marker_id=\"40\" j_marker_id=\"22\"/>\n"
             "<Force_Scalar_TwoBody id=\"1\" type=\"TORQUE\" i_marker_id=\"23\" j_marker_id=\"10\" val=\"2\"/>\n"
             "<Force_Scalar_TwoBody id=\"2\" type=\"TORQUE\" i_marker_id=\"30\" j_marker_id=\"13\" val=\"0.3\"/>\n"
             "%s</Model></MotionSolve>\n",
             gravity ? "label=\"ground\"/><Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"" : "",
             CARRIER_D, gravity ? "pos_x=\"0.1\" pos_y=\"0.05\"" : "", CARRIER_D, -CARRIER_D,
             CARRIER_D, -CARRIER_D, coupler);
    return text;
}
#define CARRIER_COUPLER                                                                         \
    "<Constraint_Coupler id=\"1\" joint1_id=\"2\" freedom_1=\"R\" joint2_id=\"3\" freedom_2=\"R\"" \
    " coefficients=\"1, 2.5\"/>\n"

/* Joint k's coordinate at a path row. */
static double coordinate_at(const sim *s, int row, int joint)
{
    double value;
    hx_joint_coordinate_at(&s->dynamics, joint, s->dynamics.m->couplers[0].freedom[0],
                           s->path.y + (size_t)row * (size_t)s->path.n, &value, NULL, NULL);
    return value;
}

static void gears_on_a_turning_carrier(void **state)
{
    (void)state;
    /* Carrier angle th, gear B's angle relative to it p (gear A's is -r p).
     * T = 1/2 [(Ic + (mA + mB) d^2) th'^2 + IA (th' - r p')^2 + IB (th' + p')^2]:
     *   M = [Ic + (mA + mB) d^2 + IA + IB,  IB - r IA;  IB - r IA,  r^2 IA + IB];
     * Tc on the carrier works on th, Ta on gear A (absolute angle th - r p):
     *   Q = (Tc + Ta, -r Ta). Constant: from rest th = a t^2 / 2, p = b t^2 / 2,
     * (a, b) = M^-1 Q. With Ic 0.7, mA 1.2, mB 0.8, d 0.5, IA 0.15, IB 0.05,
     * r 2.5, Tc 2, Ta 0.3: M = [1.4, -0.325; -0.325, 0.9875], Q = (2.3, -0.75),
     * det = 1.4 * 0.9875 - 0.325^2 = 1.276875, a = (0.9875 * 2.3 - 0.325 * 0.75)
     * / det, b = (1.4 * -0.75 + 0.325 * 2.3) / det. */
    const double r = CARRIER_R, det = 1.4 * 0.9875 - 0.325 * 0.325;
    const double a = (0.9875 * 2.3 - 0.325 * 0.75) / det, b = (1.4 * -0.75 + 0.325 * 2.3) / det;
    sim s;
    sim_run(&s, test_write_file("carrier.xml", carrier_model(CARRIER_COUPLER, 0)),
            HX_METHOD_DOPRI5, 1e-11, 1.0, 0.05);
    assert_int_equal(s.dynamics.m->couplers[0].freedom[0], 'R');
    assert_int_equal(s.dynamics.rows[0].nblocks, 3); /* the carrier and the two gears */
    for (int row = 0; row < s.path.rows; ++row) {
        const double t = s.path.t[row];
        const double th = coordinate_at(&s, row, 0), pa = coordinate_at(&s, row, 1),
                     pb = coordinate_at(&s, row, 2);
        assert_close(pa, -r * pb, 1e-12, 1e-9);
        assert_close(th, 0.5 * a * t * t, 1e-12, 1e-8);
        assert_close(pb, 0.5 * b * t * t, 1e-12, 1e-8);
    }
    assert_true(s.path.t[s.path.rows - 1] > 0.99);
    assert_true(s.result.max_phi <= 1e-9);
    sim_close(&s);
}

/* Two pendulums on revolutes to ground, coupled 10 a1 + 15 a2 = 0: once
 * reduced (J on ground), once with I and J swapped (general joints: each
 * coordinate is minus the reduced one, the relation the same). */
static const char *pair_model(int swapped)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"0\" grav_z=\"-9.81\"/>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"11\" body_id=\"1\" a00=\"1\" a10=\"0\" a20=\"0\" a01=\"0\" a11=\"0\" a21=\"-1\" a02=\"0\" a12=\"1\" a22=\"0\"/>\n"
             "<Reference_Marker id=\"12\" body_id=\"1\" pos_x=\"0.5\" a00=\"1\" a10=\"0\" a20=\"0\" a01=\"0\" a11=\"0\" a21=\"-1\" a02=\"0\" a12=\"1\" a22=\"0\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1.0\" inertia_xx=\"0.0034\" inertia_yy=\"0.0034\" inertia_zz=\"0.0001\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_z=\"-0.2\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\" a00=\"1\" a10=\"0\" a20=\"0\" a01=\"0\" a11=\"0\" a21=\"-1\" a02=\"0\" a12=\"1\" a22=\"0\"/>\n"
             "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"2.0\" inertia_xx=\"0.015\" inertia_yy=\"0.015\" inertia_zz=\"0.0002\"/>\n"
             "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"0.5\" pos_z=\"-0.3\"/>\n"
             "<Reference_Marker id=\"31\" body_id=\"3\" pos_x=\"0.5\" a00=\"1\" a10=\"0\" a20=\"0\" a01=\"0\" a11=\"0\" a21=\"-1\" a02=\"0\" a12=\"1\" a22=\"0\"/>\n"
             "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"%d\" j_marker_id=\"%d\"/>\n"
             "<Constraint_Joint id=\"2\" type=\"REVOLUTE\" i_marker_id=\"%d\" j_marker_id=\"%d\"/>\n"
             "<Constraint_Coupler id=\"1\" joint1_id=\"1\" joint2_id=\"2\" coefficients=\"10, 15\"/>\n"
             "<Force_Scalar_TwoBody id=\"1\" type=\"TORQUE\" i_marker_id=\"21\" j_marker_id=\"11\" val=\"0.5\"/>\n"
             "</Model></MotionSolve>\n",
             swapped ? 11 : 21, swapped ? 21 : 11, swapped ? 12 : 31, swapped ? 31 : 12);
    return text;
}

static void reduced_and_general_pairs_agree(void **state)
{
    (void)state;
    sim reduced, general;
    sim_run(&reduced, test_write_file("pair_reduced.xml", pair_model(0)), HX_METHOD_DOPRI5,
            1e-11, 1.0, 0.05);
    sim_run(&general, test_write_file("pair_general.xml", pair_model(1)), HX_METHOD_DOPRI5,
            1e-11, 1.0, 0.05);
    assert_int_equal(reduced.dynamics.nrows, 1);
    assert_int_equal(general.dynamics.nrows, 11); /* the coupler and two revolutes' five */
    assert_int_equal(reduced.path.rows, general.path.rows);
    double largest = 0.0;
    for (int row = 0; row < reduced.path.rows; ++row)
        for (int joint = 0; joint < 2; ++joint) {
            const double q = sim_state(&reduced, row, reduced.dynamics.dof[1 + joint].q);
            assert_close(-coordinate_at(&general, row, joint), q, 0, 1e-8);
            largest = fmax(largest, fabs(q));
        }
    assert_true(largest > 0.1); /* the pendulums swung */
    sim_close(&reduced);
    sim_close(&general);
}

static void analytic_jacobian_and_bdf(void **state)
{
    (void)state;
    sim dopri, bdf;
    const char *path = test_write_file("carrier_bdf.xml", carrier_model(CARRIER_COUPLER, 1));
    sim_run(&dopri, path, HX_METHOD_DOPRI5, 1e-11, 0.5, 0.05);
    const int last = dopri.path.rows - 1;
    long outside = 0;
    const double worst = jacobian_against_differences(
        &dopri.dynamics, dopri.path.t[last], dopri.path.y + (size_t)last * (size_t)dopri.path.n,
        "carrier", &outside);
    assert_true(worst < 1e-6);
    assert_int_equal(outside, 0);
    sim_run(&bdf, path, HX_METHOD_BDF, 1e-9, 0.5, 0.05);
    assert_int_equal(bdf.path.rows, dopri.path.rows);
    for (int joint = 0; joint < 3; ++joint)
        assert_close(coordinate_at(&bdf, last, joint), coordinate_at(&dopri, last, joint), 0,
                     1e-5);
    sim_close(&dopri);
    sim_close(&bdf);
}

/* The carrier's gear A driven against the carrier by SWING (a sin(w t):
 * tests/user_libraries/tp_routines.c) instead of the coupler: a row of the
 * constraint system between two moving bodies, the carrier turning under
 * its torque. */
#define SWING_MOTION                                                                          \
    "<Motion_Joint id=\"6\" type=\"USERSUB\" val_type=\"D\" joint_id=\"2\" motion_type=\"R\"" \
    " usrsub_param_string=\"USER(5, 3)\" usrsub_fnc_name=\"SWING\""                          \
    " usrsub_dll_name=\"libtp_routines.so\"/>\n"

static void motion_between_moving_bodies_follows_its_function(void **state)
{
    (void)state;
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    const char *path = test_write_file("carrier_motion.xml", carrier_model(SWING_MOTION, 1));
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 2; ++k) {
        sim s;
        sim_run(&s, path, methods[k], k == 0 ? 1e-10 : 1e-8, 2.0, 0.05);
        assert_int_equal(s.dynamics.nmotions, 1);
        double turned = 0.0, wide = 0.0;
        for (int row = 0; row < s.path.rows; ++row) {
            /* relative to the carrier: AZ of gear A's marker against the carrier's,
             * 5 sin(3 t), past pi (the row unwraps against f): the angle in (-pi,
             * pi] is f's, to a whole turn */
            const double t = s.path.t[row], f = 5.0 * sin(3.0 * t);
            double a;
            hx_joint_coordinate_near(&s.dynamics, 1, 'R', s.path.y + (size_t)row * (size_t)s.path.n,
                                     0.0, &a, NULL, NULL);
            assert_close(remainder(a - f, 2.0 * M_PI), 0.0, 0, 1e-9);
            wide = fmax(wide, fabs(f));
            hx_frame carrier;
            hx_bodies_frame(&s.dynamics, 1, s.path.y + (size_t)row * (size_t)s.path.n, &carrier);
            turned = fmax(turned, fabs(carrier.w[2]));
        }
        assert_true(turned > 1.0); /* the carrier turned: both bodies move */
        assert_true(wide > 4.0);
        assert_true(s.path.t[s.path.rows - 1] > 1.99);
        if (k == 0) {
            const int last = s.path.rows - 1;
            /* the accelerations hold the motion: (alpha_A - alpha_C) . z = f''(t) =
             * -45 sin(3 t), each alpha = R udot's angular part (body axes) */
            const double t = s.path.t[last], *y = s.path.y + (size_t)last * (size_t)s.path.n;
            double *ydot = calloc((size_t)s.dynamics.n, sizeof(double)), alpha[2][3];
            assert_non_null(ydot);
            assert_int_equal(hx_dynamics_rhs(&s.dynamics, &s.data, t, y, ydot), 0);
            for (int b = 0; b < 2; ++b) {
                hx_frame f;
                hx_bodies_frame(&s.dynamics, 2 - b, y, &f);
                m3_apply(alpha[b], f.R, ydot + s.dynamics.nq + s.dynamics.dof[2 - b].u + 3);
            }
            assert_close(alpha[0][2] - alpha[1][2], -45.0 * sin(3.0 * t), 0, 1e-7);
            free(ydot);
            long outside = 0;
            const double worst = jacobian_against_differences(
                &s.dynamics, s.path.t[last], s.path.y + (size_t)last * (size_t)s.path.n,
                "carrier with a motion", &outside);
            assert_true(worst < 1e-6);
            assert_int_equal(outside, 0);
        }
        sim_close(&s);
    }
}

/* The motions the reader refuses on joints between bodies, each at its line. */
static void refused_motions(void **state)
{
    (void)state;
    static const struct {
        const char *name, *joint, *motion, *what;
    } cases[] = {
        {"motion_sphere.xml", "SPHERICAL",
         "<Motion_Joint id=\"6\" type=\"USERSUB\" joint_id=\"2\" usrsub_param_string=\"USER(1, 1)\""
         " usrsub_fnc_name=\"SWING\" usrsub_dll_name=\"libtp_routines.so\"/>\n",
         "joint 2 is SPHERICAL, which has no coordinate"},
        {"motion_cylinder.xml", "CYLINDRICAL",
         "<Motion_Joint id=\"6\" type=\"USERSUB\" joint_id=\"2\" usrsub_param_string=\"USER(1, 1)\""
         " usrsub_fnc_name=\"SWING\" usrsub_dll_name=\"libtp_routines.so\"/>\n",
         "joint 2 is cylindrical: motion_type must say"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char text[4096], rest[4096];
        snprintf(text, sizeof text, "%s", carrier_model(cases[k].motion, 0));
        char *at = strstr(text, "type=\"REVOLUTE\" i_marker_id=\"30\"");
        assert_non_null(at);
        snprintf(rest, sizeof rest, "type=\"%s\" i_marker_id=\"30\"%s", cases[k].joint,
                 at + strlen("type=\"REVOLUTE\" i_marker_id=\"30\""));
        snprintf(at, sizeof text - (size_t)(at - text), "%s", rest);
        hx_message msg;
        hx_model *m = hx_model_read(test_write_file(cases[k].name, text), NULL, &msg);
        if (m != NULL) {
            hx_model_free(m);
            fail_msg("%s was read; expected an error", cases[k].name);
        }
        char where[64];
        snprintf(where, sizeof where, "%s:19:", cases[k].name);
        assert_contains(msg.text, where, "Motion_Joint 6", cases[k].what);
    }
}

/* A body's angular velocity about world y at a path row. */
static double spin_y(const sim *s, int row, int body)
{
    hx_frame f;
    hx_bodies_frame(&s->dynamics, body, s->path.y + (size_t)row * (size_t)s->path.n, &f);
    return f.w[1];
}

static void differential_carrier_splits_torque_equally(void **state)
{
    (void)state;
    /* harness/examples/differential_carrier.xml (mm, kg, s, N: ucf 1000): the
     * side gears' angles to the carrier p_L + p_R = 0, so w_L + w_R = 2 w_C;
     * IL aL = ucf l, IR aR = ucf l, IC aC = ucf (tau - 2 l) (l the coupler's
     * torque on each side gear), aL + aR = 2 aC:
     *   l = 2 tau / IC / (1/IL + 1/IR + 4/IC); IL 1e4, IR 1.5e4, IC 4e4, tau 1000:
     *   1/IL + 1/IR + 4/IC = 2.6667e-4, l = 0.05 / 2.6667e-4 = 187.5 N mm,
     *   aL = 18.75, aR = 12.5, aC = 15.625 rad/s^2 (aL + aR = 31.25 = 2 aC).
     * Run to t = 5, the side gears turn (aL - aC) t^2 / 2 = 1.5625 t^2 = 39.1 rad
     * (6.2 turns) against the carrier, either way: the run goes on past 3 rad. */
    const double IL = 1e4, IR = 1.5e4, IC = 4e4, tau = 1000.0, ucf = 1000.0;
    const double l = 2 * tau / IC / (1 / IL + 1 / IR + 4 / IC);
    assert_close(l, 187.5, 1e-12, 0);
    sim s;
    sim_run(&s, "differential_carrier.xml", HX_METHOD_DOPRI5, 1e-10, 5.0, 0.1);
    for (int row = 0; row < s.path.rows; ++row) {
        const double t = s.path.t[row];
        const double wc = spin_y(&s, row, 1), wl = spin_y(&s, row, 2), wr = spin_y(&s, row, 3);
        assert_close(wl + wr, 2.0 * wc, 1e-12, 1e-9);
        assert_close(wc, ucf * (tau - 2 * l) / IC * t, 1e-12, 1e-8);
        assert_close(wl, ucf * l / IL * t, 1e-12, 1e-8);
        assert_close(wr, ucf * l / IR * t, 1e-12, 1e-8);
    }
    const int last = s.path.rows - 1;
    assert_true(s.path.t[last] > 5.0 - 1e-9);
    assert_true(0.5 * (ucf * l / IL - ucf * (tau - 2 * l) / IC) * 25.0 > 6 * 2 * M_PI);
    const double *y = s.path.y + (size_t)last * (size_t)s.path.n;
    sim_evaluate(&s, 5.0, y);
    const double left = hx_constraints_coupler_force(&s.dynamics, &s.data, 5.0, y, 0, 0);
    const double right = hx_constraints_coupler_force(&s.dynamics, &s.data, 5.0, y, 0, 1);
    assert_close(left, l, 1e-10, 0);
    assert_close(right, l, 1e-10, 0);
    sim_close(&s);
}

/* The couplings the reader refuses, each at its line. */
static void refused_couplings(void **state)
{
    (void)state;
    static const struct {
        const char *name, *joint, *coupler, *where, *what;
    } cases[] = {
        {"coupler_freedom.xml", "REVOLUTE",
         "<Constraint_Coupler id=\"7\" joint1_id=\"2\" freedom_1=\"T\" joint2_id=\"3\" coefficients=\"1, 1\"/>\n",
         "coupler_freedom.xml:19:", "freedom_1 is \"T\" but joint 2 is revolute"},
        {"coupler_cylinder.xml", "CYLINDRICAL",
         "<Constraint_Coupler id=\"7\" joint1_id=\"2\" joint2_id=\"3\" coefficients=\"1, 1\"/>\n",
         "coupler_cylinder.xml:19:", "joint 2 is cylindrical: freedom_1 must say"},
        {"coupler_sphere.xml", "SPHERICAL",
         "<Constraint_Coupler id=\"7\" joint1_id=\"3\" joint2_id=\"2\" coefficients=\"1, 1\"/>\n",
         "coupler_sphere.xml:19:", "joint 2 is SPHERICAL, which has no coordinate"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char text[4096], joint[256];
        snprintf(joint, sizeof joint, "type=\"%s\" i_marker_id=\"30\"", cases[k].joint);
        snprintf(text, sizeof text, "%s", carrier_model(cases[k].coupler, 0));
        char *at = strstr(text, "type=\"REVOLUTE\" i_marker_id=\"30\"");
        assert_non_null(at);
        char rest[4096];
        snprintf(rest, sizeof rest, "%s%s", joint, at + strlen("type=\"REVOLUTE\" i_marker_id=\"30\""));
        snprintf(at, sizeof text - (size_t)(at - text), "%s", rest);
        hx_message msg;
        hx_model *m = hx_model_read(test_write_file(cases[k].name, text), NULL, &msg);
        if (m != NULL) {
            hx_model_free(m);
            fail_msg("%s was read; expected an error", cases[k].name);
        }
        assert_contains(msg.text, cases[k].where, "Constraint_Coupler 7", cases[k].what);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(coordinate_rows_against_differences),
        cmocka_unit_test(cylinder_coordinate_by_freedom),
        cmocka_unit_test(coupler_row_against_differences),
        cmocka_unit_test(gears_on_a_turning_carrier),
        cmocka_unit_test(reduced_and_general_pairs_agree),
        cmocka_unit_test(analytic_jacobian_and_bdf),
        cmocka_unit_test(differential_carrier_splits_torque_equally),
        cmocka_unit_test(refused_couplings),
        cmocka_unit_test(motion_between_moving_bodies_follows_its_function),
        cmocka_unit_test(refused_motions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
