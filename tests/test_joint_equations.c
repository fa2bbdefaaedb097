/*
 * The equations of each joint type (sim/dynamics/joint_equations.c): their
 * number; at random assembled states phi = 0 and every free relative motion
 * (with any rigid motion of the pair) leaves phi_dot = G w = 0 while G keeps
 * full rank; G against central differences of phi at random unassembled
 * states; gamma against the second difference of phi along a motion with
 * constant twists (there w_dot = 0, so phi_ddot = -gamma). Each with I on
 * ground (static), J on ground and both moving. RACKPIN's and SCREW's law
 * from the markers at t = 0 and their equation, turns and wrap, by hand.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/linalg.h"
#include "base/vecmath.h"
#include "sim/dynamics/joint_equations.h"
#include "test_support.h"

#define NTYPES 17
static const enum hx_joint_type types[NTYPES] = {
    HX_JOINT_FIXED,     HX_JOINT_REVOLUTE,  HX_JOINT_TRANSLATIONAL, HX_JOINT_CYLINDRICAL,
    HX_JOINT_SPHERICAL, HX_JOINT_UNIVERSAL, HX_JOINT_HOOKE,         HX_JOINT_PLANAR,
    HX_JOINT_CONVEL,    HX_JOINT_RACKPIN,   HX_JOINT_SCREW,
    HX_JOINT_ATPOINT,   HX_JOINT_INLINE,    HX_JOINT_INPLANE,       HX_JOINT_ORIENTATION,
    HX_JOINT_PARALLEL_AXES, HX_JOINT_PERPENDICULAR};
/* RACKPIN's and SCREW's law in the sampled tests: s - 0.1 = 0.3 (theta - 0.2) */
static const hx_joint_law law = {0.3, 0.1, 0.2};
enum { BOTH_MOVE, I_STATIC, J_STATIC };

static double uniform(void)
{
    return 2.0 * rand() / (double)RAND_MAX - 1.0;
}

static void random_vector(double v[3], double size)
{
    v3_set(v, size * uniform(), size * uniform(), size * uniform());
}

static void random_rotation(double R[9])
{
    double q[4] = {uniform(), uniform(), uniform(), uniform()};
    quat_normalize(q);
    quat_to_matrix(R, q);
}

static void rotation(double R[9], int axis, double angle)
{
    double a[3] = {0, 0, 0};
    a[axis] = 1.0;
    m3_axis_angle(R, a, angle);
}

/* A pair of bodies and their markers. */
typedef struct pair {
    hx_frame fi, fj;
    double si[3], sj[3], Ai[9], Aj[9];
} pair;

static void eval(enum hx_joint_type type, const pair *p, double *phi, double *G, double *gamma)
{
    const hx_joint_side i = {&p->fi, p->si, p->Ai}, j = {&p->fj, p->sj, p->Aj};
    hx_joint_equations_eval(type, &law, &i, &j, phi, G, gamma);
}

static void column(const double R[9], int k, double a[3])
{
    v3_set(a, R[k], R[3 + k], R[6 + k]);
}

/* A random assembled state: J's marker anywhere, I's marker from it by the
 * type's free motions (Q its turn, d its offset in J's marker axes). */
static void assembled(enum hx_joint_type type, pair *p)
{
    double Q[9], A[9], B[9], d[3] = {0, 0, 0};
    const double a = 3.0 * uniform(), b = 3.0 * uniform();
    m3_identity(Q);
    switch (type) {
    case HX_JOINT_FIXED:
        break;
    case HX_JOINT_REVOLUTE:
        rotation(Q, 2, a);
        break;
    case HX_JOINT_TRANSLATIONAL:
        d[2] = b;
        break;
    case HX_JOINT_CYLINDRICAL:
        rotation(Q, 2, a), d[2] = b;
        break;
    case HX_JOINT_SPHERICAL:
        random_rotation(Q);
        break;
    case HX_JOINT_UNIVERSAL: /* about z_J, then z_I off z_J by a right angle, then about z_I */
        rotation(A, 2, a), rotation(B, 0, M_PI / 2), m3_mul(Q, A, B);
        rotation(A, 2, b), m3_mul(B, Q, A), m3_copy(Q, B);
        break;
    case HX_JOINT_HOOKE: /* about y_J, then about x_I */
        rotation(A, 1, a), rotation(B, 0, b), m3_mul(Q, A, B);
        break;
    case HX_JOINT_PLANAR:
        rotation(Q, 2, a), d[0] = b, d[1] = uniform();
        break;
    case HX_JOINT_CONVEL: { /* z_I away from z_J: half a turn about x_J, then a bend about n */
        const double n[3] = {cos(a), sin(a), 0.0};
        rotation(A, 0, M_PI), m3_axis_angle(B, n, 0.5 * b), m3_mul(Q, A, B);
        break;
    }
    case HX_JOINT_RACKPIN: /* any turn (x_I, y_I not near normal to z_J: theta is
                            * defined); the travel -d_z = s by the law at theta(Q) */
        do
            random_rotation(Q);
        while (Q[6] * Q[6] + Q[7] * Q[7] < 0.25);
        random_vector(d, 2.0);
        d[2] = -(law.s0 + law.ratio * (atan2(-Q[7], Q[6]) - law.theta0));
        break;
    case HX_JOINT_SCREW: /* any turn (x_I not near z_J); d_z = s by the law at theta(Q) */
        do
            random_rotation(Q);
        while (Q[0] * Q[0] + Q[3] * Q[3] < 0.25);
        random_vector(d, 2.0);
        d[2] = law.s0 + law.ratio * (atan2(Q[3], Q[0]) - law.theta0);
        break;
    case HX_JOINT_ATPOINT:
        random_rotation(Q);
        break;
    case HX_JOINT_INLINE:
        random_rotation(Q), d[2] = b;
        break;
    case HX_JOINT_INPLANE:
        random_rotation(Q), d[0] = b, d[1] = uniform();
        break;
    case HX_JOINT_ORIENTATION:
        random_vector(d, 2.0);
        break;
    case HX_JOINT_PARALLEL_AXES:
        rotation(Q, 2, a), random_vector(d, 2.0);
        break;
    case HX_JOINT_PERPENDICULAR: /* as UNIVERSAL's turns, the origins anywhere */
        rotation(A, 2, a), rotation(B, 0, M_PI / 2), m3_mul(Q, A, B);
        rotation(A, 2, b), m3_mul(B, Q, A), m3_copy(Q, B);
        random_vector(d, 2.0);
        break;
    }
    random_rotation(p->fj.R), random_vector(p->fj.p, 2.0);
    random_rotation(p->Ai), random_rotation(p->Aj);
    random_vector(p->si, 1.0), random_vector(p->sj, 1.0);
    /* J's marker in the world, I's marker from it, then I's body */
    double MJ[9], xj[3], MI[9], xi[3], off[3], rs[3];
    m3_mul(MJ, p->fj.R, p->Aj);
    m3_apply(xj, p->fj.R, p->sj), v3_add(xj, xj, p->fj.p);
    m3_mul(MI, MJ, Q);
    m3_apply(off, MJ, d), v3_add(xi, xj, off);
    m3_mult(p->fi.R, MI, p->Ai); /* R_I A_I = MI */
    m3_apply(rs, p->fi.R, p->si), v3_sub(p->fi.p, xi, rs);
}

/* The free relative twist of I on J at I's marker: angular velocity, and the
 * marker's velocity (world). */
static void free_motion(enum hx_joint_type type, const pair *p, double w[3], double v[3])
{
    double MI[9], MJ[9], xj[3], yj[3], zj[3], xi[3], yi[3], zi[3], n[3], t[3];
    m3_mul(MI, p->fi.R, p->Ai), m3_mul(MJ, p->fj.R, p->Aj);
    column(MJ, 0, xj), column(MJ, 1, yj), column(MJ, 2, zj), column(MI, 0, xi), column(MI, 2, zi);
    column(MI, 1, yi);
    const double a = uniform(), b = uniform();
    v3_set(w, 0, 0, 0), v3_set(v, 0, 0, 0);
    switch (type) {
    case HX_JOINT_FIXED:
        break;
    case HX_JOINT_REVOLUTE:
        v3_scale(w, zj, a);
        break;
    case HX_JOINT_TRANSLATIONAL:
        v3_scale(v, zj, b);
        break;
    case HX_JOINT_CYLINDRICAL:
        v3_scale(w, zj, a), v3_scale(v, zj, b);
        break;
    case HX_JOINT_SPHERICAL:
        random_vector(w, 1.0);
        break;
    case HX_JOINT_UNIVERSAL:
        v3_scale(w, zj, a), v3_axpy(w, b, zi);
        break;
    case HX_JOINT_HOOKE:
        v3_scale(w, yj, a), v3_axpy(w, b, xi);
        break;
    case HX_JOINT_PLANAR:
        v3_scale(w, zj, a), v3_scale(v, xj, b), v3_axpy(v, uniform(), yj);
        break;
    case HX_JOINT_CONVEL: /* both shafts turning alike (z_I + z_J), and the bend about n */
        v3_cross(n, zi, zj), v3_scale(n, n, 1.0 / v3_norm(n));
        v3_add(w, zi, zj), v3_scale(w, w, a), v3_axpy(w, b, n);
        break;
    case HX_JOINT_RACKPIN: { /* theta = atan2(-y_I.z_J, x_I.z_J); s_dot = -v.z_J */
        random_vector(w, 1.0), random_vector(v, 1.0);
        const double A = -v3_dot(yi, zj), B = v3_dot(xi, zj);
        v3_cross(t, w, yi);
        const double Ad = -v3_dot(t, zj);
        v3_cross(t, w, xi);
        const double Bd = v3_dot(t, zj), thetadot = (B * Ad - A * Bd) / (A * A + B * B);
        v3_axpy(v, -v3_dot(v, zj) - law.ratio * thetadot, zj);
        break;
    }
    case HX_JOINT_SCREW: { /* theta = atan2(x_I.y_J, x_I.x_J); s_dot = v.z_J */
        random_vector(w, 1.0), random_vector(v, 1.0);
        const double A = v3_dot(xi, yj), B = v3_dot(xi, xj);
        v3_cross(t, w, xi);
        const double Ad = v3_dot(t, yj), Bd = v3_dot(t, xj);
        const double thetadot = (B * Ad - A * Bd) / (A * A + B * B);
        v3_axpy(v, -v3_dot(v, zj) + law.ratio * thetadot, zj);
        break;
    }
    case HX_JOINT_ATPOINT:
        random_vector(w, 1.0);
        break;
    case HX_JOINT_INLINE:
        random_vector(w, 1.0), v3_scale(v, zj, b);
        break;
    case HX_JOINT_INPLANE:
        random_vector(w, 1.0), v3_scale(v, xj, b), v3_axpy(v, uniform(), yj);
        break;
    case HX_JOINT_ORIENTATION:
        random_vector(v, 1.0);
        break;
    case HX_JOINT_PARALLEL_AXES:
        v3_scale(w, zj, a), random_vector(v, 1.0);
        break;
    case HX_JOINT_PERPENDICULAR:
        v3_scale(w, zj, a), v3_axpy(w, b, zi), random_vector(v, 1.0);
        break;
    }
}

/* A body's twist from a screw (W, velocity V0 of the world's origin). */
static void set_twist(hx_frame *f, const double W[3], const double V0[3])
{
    double wp[3];
    v3_copy(f->w, W);
    v3_cross(wp, W, f->p);
    v3_add(f->v, V0, wp);
}

static void twist_of(const hx_frame *f, double G12[12], int side, double *w12)
{
    (void)G12;
    v3_copy(w12 + 6 * side, f->v), v3_copy(w12 + 6 * side + 3, f->w);
}

static double row_times(const double *G, int row, const double *w12)
{
    double s = 0.0;
    for (int c = 0; c < 12; ++c)
        s += G[12 * row + c] * w12[c];
    return s;
}

static void equation_counts(void **state)
{
    (void)state;
    const int expected[NTYPES] = {6, 5, 5, 4, 3, 4, 4, 3, 4, 1, 1, 3, 2, 1, 3, 2, 1};
    for (int k = 0; k < NTYPES; ++k)
        assert_int_equal(hx_joint_equations_count(types[k]), expected[k]);
}

/* The rows that are lengths (constraints.c scales them by the model's length):
 * a row is a length when moving I's body by h along a world axis changes it
 * by about h somewhere, an axes' product when no translation changes it. */
static void length_rows_are_the_translation_dependent_ones(void **state)
{
    (void)state;
    srand(14);
    for (int k = 0; k < NTYPES; ++k) {
        pair p;
        memset(&p, 0, sizeof p);
        assembled(types[k], &p);
        const int n = hx_joint_equations_count(types[k]);
        double phi[6], G[72];
        eval(types[k], &p, phi, G, NULL);
        for (int e = 0; e < n; ++e) {
            /* G's columns of v_I: zero for an axes' product, a unit vector for a length */
            const double along = sqrt(G[12 * e] * G[12 * e] + G[12 * e + 1] * G[12 * e + 1] +
                                      G[12 * e + 2] * G[12 * e + 2]);
            assert_int_equal(hx_joint_equation_is_length(types[k], e), along > 0.5);
        }
    }
}

static void assembled_states_hold_and_free_motions_are_free(void **state)
{
    (void)state;
    srand(11);
    for (int k = 0; k < NTYPES; ++k)
        for (int c = BOTH_MOVE; c <= J_STATIC; ++c)
            for (int trial = 0; trial < 20; ++trial) {
                pair p;
                memset(&p, 0, sizeof p);
                assembled(types[k], &p);
                const int n = hx_joint_equations_count(types[k]);
                double phi[6], G[72], w12[12], wr[3], vr[3], xi[3], V0[3], W[3], zero[3] = {0, 0, 0};
                eval(types[k], &p, phi, G, NULL);
                for (int e = 0; e < n; ++e)
                    assert_close(phi[e], 0.0, 0, 1e-12);
                free_motion(types[k], &p, wr, vr);
                /* the relative screw: velocity of the world's origin */
                m3_apply(xi, p.fi.R, p.si), v3_add(xi, xi, p.fi.p);
                double rel0[3], wx[3];
                v3_cross(wx, wr, xi), v3_sub(rel0, vr, wx);
                random_vector(W, 1.0), random_vector(V0, 1.0);
                if (c == J_STATIC)
                    v3_set(W, 0, 0, 0), v3_set(V0, 0, 0, 0);
                if (c == I_STATIC)
                    v3_scale(W, wr, -1.0), v3_scale(V0, rel0, -1.0);
                double Wi[3], Vi[3];
                v3_add(Wi, W, wr), v3_add(Vi, V0, rel0);
                set_twist(&p.fj, W, V0);
                set_twist(&p.fi, Wi, Vi);
                if (c == I_STATIC) { /* exactly at rest, as the ground is */
                    set_twist(&p.fi, zero, zero);
                }
                twist_of(&p.fi, G, 0, w12), twist_of(&p.fj, G, 1, w12);
                for (int e = 0; e < n; ++e)
                    assert_close(row_times(G, e, w12), 0.0, 0, 1e-12);
                /* full rank: G G^T is regular */
                double A[36], rhs[6] = {1, 1, 1, 1, 1, 1};
                for (int a = 0; a < n; ++a)
                    for (int b = 0; b < n; ++b) {
                        double s = 0.0;
                        for (int col = 0; col < 12; ++col)
                            s += G[12 * a + col] * G[12 * b + col];
                        A[a * n + b] = s;
                    }
                assert_int_equal(hx_solve(n, A, rhs), 0);
                for (int e = 0; e < n; ++e)
                    assert_true(fabs(rhs[e]) < 1e6);
            }
}

/* Moves a body by h along its column c of the 6 (translation, then turn about
 * a world axis through its centre). */
static void move(hx_frame *f, int c, double h)
{
    if (c < 3) {
        f->p[c] += h;
        return;
    }
    double Rot[9], R[9];
    rotation(Rot, c - 3, h);
    m3_mul(R, Rot, f->R);
    m3_copy(f->R, R);
}

static void jacobian_against_differences(void **state)
{
    (void)state;
    srand(12);
    for (int k = 0; k < NTYPES; ++k)
        for (int trial = 0; trial < 20; ++trial) {
            pair p;
            memset(&p, 0, sizeof p);
            assembled(types[k], &p);
            /* off the joint: nothing of G may rely on phi = 0 */
            for (int a = 0; a < 3; ++a)
                p.fi.p[a] += 0.3 * uniform();
            move(&p.fi, 3 + trial % 3, 0.4 * uniform());
            const int n = hx_joint_equations_count(types[k]);
            double phi[6], G[72], plus[6], minus[6];
            eval(types[k], &p, phi, G, NULL);
            const double h = 1e-6;
            for (int side = 0; side < 2; ++side)
                for (int c = 0; c < 6; ++c) {
                    pair q = p;
                    move(side ? &q.fj : &q.fi, c, h);
                    eval(types[k], &q, plus, NULL, NULL);
                    q = p;
                    move(side ? &q.fj : &q.fi, c, -h);
                    eval(types[k], &q, minus, NULL, NULL);
                    for (int e = 0; e < n; ++e)
                        assert_close(G[12 * e + 6 * side + c], (plus[e] - minus[e]) / (2 * h), 0,
                                     1e-8);
                }
        }
}

/* The pair at time t of a motion with constant twists (from p at t = 0). */
static pair at_time(const pair *p, double t)
{
    pair q = *p;
    hx_frame *f[2] = {&q.fi, &q.fj};
    for (int s = 0; s < 2; ++s) {
        v3_axpy(f[s]->p, t, f[s]->v);
        const double wn = v3_norm(f[s]->w);
        if (wn > 0.0) {
            double axis[3], Rot[9], R[9];
            v3_scale(axis, f[s]->w, 1.0 / wn);
            m3_axis_angle(Rot, axis, wn * t);
            m3_mul(R, Rot, f[s]->R);
            m3_copy(f[s]->R, R);
        }
    }
    return q;
}

static void gamma_against_second_differences(void **state)
{
    (void)state;
    srand(13);
    for (int k = 0; k < NTYPES; ++k)
        for (int c = BOTH_MOVE; c <= J_STATIC; ++c)
            for (int trial = 0; trial < 10; ++trial) {
                pair p;
                memset(&p, 0, sizeof p);
                assembled(types[k], &p);
                p.fi.p[0] += 0.2 * uniform(); /* off the joint */
                if (c != I_STATIC)
                    random_vector(p.fi.v, 1.0), random_vector(p.fi.w, 1.5);
                if (c != J_STATIC)
                    random_vector(p.fj.v, 1.0), random_vector(p.fj.w, 1.5);
                const int n = hx_joint_equations_count(types[k]);
                double phi[6], G[72], gamma[6], plus[6], minus[6], w12[12];
                eval(types[k], &p, phi, G, gamma);
                const double h = 1e-4;
                pair q = at_time(&p, h);
                eval(types[k], &q, plus, NULL, NULL);
                q = at_time(&p, -h);
                eval(types[k], &q, minus, NULL, NULL);
                twist_of(&p.fi, G, 0, w12), twist_of(&p.fj, G, 1, w12);
                for (int e = 0; e < n; ++e) {
                    /* phi_dot = G w; phi_ddot = G w_dot - gamma = -gamma */
                    assert_close(row_times(G, e, w12), (plus[e] - minus[e]) / (2 * h), 0, 1e-7);
                    assert_close(-gamma[e], (plus[e] - 2 * phi[e] + minus[e]) / (h * h), 0, 2e-5);
                }
            }
}

/* phi of a one-row joint with I's and J's markers at these world poses. */
static double one_row(enum hx_joint_type type, const hx_joint_law *l, const double xi[3],
                      const double Ri[9], const double xj[3], const double Rj[9])
{
    hx_frame world;
    memset(&world, 0, sizeof world);
    m3_identity(world.R);
    const hx_joint_side i = {&world, xi, Ri}, j = {&world, xj, Rj};
    double phi[6];
    hx_joint_equations_eval(type, l, &i, &j, phi, NULL, NULL);
    return phi[0];
}

static void screw_and_rackpin_by_hand(void **state)
{
    (void)state;
    /* SCREW, PITCH 0.5: k = 0.5 / (2 pi) per radian. At t = 0 I is 0.125
     * up J's z and turned a quarter: s0 = 0.125, theta0 = pi / 2. */
    hx_joint screw = {.type = HX_JOINT_SCREW, .pitch = 0.5};
    hx_marker mi = {.pos0 = {0, 0, 0.125}}, mj = {.pos0 = {0, 0, 0}};
    rotation(mi.R0, 2, M_PI / 2), m3_identity(mj.R0);
    hx_joint_law l;
    hx_joint_equations_law(&screw, &mi, &mj, &l);
    assert_close(l.ratio, 0.5 / (2 * M_PI), 1e-15, 0);
    assert_close(l.s0, 0.125, 0, 1e-15);
    assert_close(l.theta0, M_PI / 2, 1e-15, 0);
    double R[9], x[3] = {0, 0, 0.25};
    rotation(R, 2, M_PI); /* a quarter turn more: 0.125 further up */
    assert_close(one_row(HX_JOINT_SCREW, &l, x, R, mj.pos0, mj.R0), 0.0, 0, 1e-15);
    x[2] = 0.125; /* turned, not moved: k pi / 2 = 0.125 short */
    assert_close(one_row(HX_JOINT_SCREW, &l, x, R, mj.pos0, mj.R0), -0.125, 0, 1e-15);
    x[2] = 0.125 + 3 * 0.5; /* three turns on: the same place of the thread */
    assert_close(one_row(HX_JOINT_SCREW, &l, x, mi.R0, mj.pos0, mj.R0), 0.0, 0, 1e-14);
    x[2] = 0.125 + 0.3; /* 0.3 up, not turned: 0.3 - 0.5, the nearest turn's thread */
    assert_close(one_row(HX_JOINT_SCREW, &l, x, mi.R0, mj.pos0, mj.R0), -0.2, 0, 1e-15);
    /* RACKPIN, PD 0.2: k = 0.1. The pinion I at the origin (z_I = Z); the
     * rack J 0.1 below it along X (z_J = X, x_J = Y, y_J = Z), x_I along z_J:
     * s0 = 0, theta0 = 0. The pinion's point in contact, (0, -0.1, 0), moves
     * at w Z x (0, -0.1, 0) = (0.1 w, 0, 0): a quarter turn takes the rack
     * 0.1 pi / 2 along +X. */
    hx_joint rackpin = {.type = HX_JOINT_RACKPIN, .pitch_diameter = 0.2};
    hx_marker pinion = {.pos0 = {0, 0, 0}}, rack = {.pos0 = {0, -0.1, 0}};
    const double Rrack[9] = {0, 0, 1, 1, 0, 0, 0, 1, 0};
    m3_identity(pinion.R0), m3_copy(rack.R0, Rrack);
    hx_joint_equations_law(&rackpin, &pinion, &rack, &l);
    assert_close(l.ratio, 0.1, 1e-15, 0);
    assert_close(l.s0, 0.0, 0, 1e-15);
    assert_close(l.theta0, 0.0, 0, 1e-15);
    rotation(R, 2, M_PI / 2);
    double xr[3] = {0.1 * M_PI / 2, -0.1, 0};
    assert_close(one_row(HX_JOINT_RACKPIN, &l, pinion.pos0, R, xr, Rrack), 0.0, 0, 1e-15);
    assert_close(one_row(HX_JOINT_RACKPIN, &l, pinion.pos0, R, rack.pos0, Rrack),
                 -0.1 * M_PI / 2, 0, 1e-15);
    /* a turn undefined (the screw's x_I along z_J): finite, the angle's row 0 */
    double G[12], gamma[1], phi[1];
    hx_frame world;
    memset(&world, 0, sizeof world);
    m3_identity(world.R);
    const double down[9] = {0, 0, 1, 0, 1, 0, -1, 0, 0}; /* x_I = -Z exactly */
    const hx_joint_side si = {&world, x, down}, sj = {&world, mj.pos0, mj.R0};
    hx_joint_equations_eval(HX_JOINT_SCREW, &l, &si, &sj, phi, G, gamma);
    assert_true(isfinite(phi[0]) && isfinite(gamma[0]));
    for (int c = 0; c < 12; ++c)
        assert_true(isfinite(G[c]) && (c == 2 || c == 8 || G[c] == 0.0)); /* s: v_I, v_J along z */
    /* the other types have no law */
    hx_joint revolute = {.type = HX_JOINT_REVOLUTE, .pitch = 3};
    hx_joint_equations_law(&revolute, &mi, &mj, &l);
    assert_true(l.ratio == 0.0 && l.s0 == 0.0 && l.theta0 == 0.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(equation_counts),
        cmocka_unit_test(length_rows_are_the_translation_dependent_ones),
        cmocka_unit_test(assembled_states_hold_and_free_motions_are_free),
        cmocka_unit_test(jacobian_against_differences),
        cmocka_unit_test(gamma_against_second_differences),
        cmocka_unit_test(screw_and_rackpin_by_hand),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
