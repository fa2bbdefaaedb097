/*
 * General constraints (Constraint_General, GCON; docs/interface.md §7.16,
 * sim/dynamics/expression_rows.c): each row's G against differences of phi
 * along each velocity and its gamma against second differences along the
 * motion, at random states of two moving bodies, for displacements (a K
 * marker on a moving body), a rotation (by differences of the measure) and
 * time; a pendulum held by DM(20,10) - 1 against its closed-form period; two
 * free bodies held by a distance keeping their momentum; a time-dependent
 * GCON followed to 1e-10; the Jacobian BDF builds against differences; the
 * expressions and models refused, with file:line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraints.h"
#include "sim_support.h"
#include "test_support.h"

/* Two free bodies, no joint, markers at odd places and in odd axes; `more`:
 * the general constraints. */
static const char *two_bodies(const char *gravity, const char *more)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"%s\" grav_z=\"0\"/>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Reference_Marker id=\"11\" body_id=\"1\" pos_x=\"0.3\" psi=\"0.4\" theta=\"1.1\" phi=\"-0.2\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1.5\" inertia_xx=\"0.2\" inertia_yy=\"0.3\" inertia_zz=\"0.25\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"0.5\" pos_y=\"-0.1\" pos_z=\"0.2\" psi=\"1.3\" theta=\"0.8\" phi=\"-0.4\"/>\n"
             "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"2\" inertia_xx=\"0.4\" inertia_yy=\"0.3\" inertia_zz=\"0.2\"/>\n"
             "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"1.2\" pos_z=\"0.3\" psi=\"-0.3\" theta=\"0.6\" phi=\"0.2\"/>\n"
             "<Reference_Marker id=\"31\" body_id=\"3\" pos_x=\"1.4\" pos_y=\"0.4\" psi=\"0.9\" theta=\"-0.5\" phi=\"1.2\"/>\n"
             "%s</Model></MotionSolve>\n",
             gravity, more);
    return text;
}

/* A displacement between the bodies, one with K on a moving body, ground
 * and time; rotations (AZ analytic, PSI, INCANG and ORIENT's Euler parameter
 * by differences of the measure). */
#define MIXED_GCONS                                                                          \
    "<Constraint_General id=\"1\" expr=\"DM(21,31) - 0.7\"/>\n"                              \
    "<Constraint_General id=\"2\" expr=\"DX(21,31,30) + 0.3*DY(20,11)**2 - 0.05*SIN(TIME)\"/>\n" \
    "<Constraint_General id=\"3\" expr=\"0.5*AZ(21,30) + 0.2*PSI(31,20) + 0.1*INCANG(20,31,21) + DZ(20)*COS(2*TIME) + 0.3*ORIENT(27,2,21,30)\"/>\n"

static void random_state(const hx_dynamics *d, double *y)
{
    memset(y, 0, sizeof(double) * (size_t)d->n);
    for (int b = 0; b < d->m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        if (dof->kind != HX_DOF_FREE)
            continue;
        double *q = y + dof->q, *u = y + d->nq + dof->u, n = 0.0;
        for (int c = 0; c < 3; ++c)
            q[c] = 0.5 * sim_uniform() + (b == 2 ? 1.0 : 0.0);
        for (int c = 3; c < 7; ++c)
            q[c] = sim_uniform(), n += q[c] * q[c];
        for (int c = 3; c < 7; ++c)
            q[c] /= sqrt(n);
        for (int c = 0; c < 6; ++c)
            u[c] = 1.5 * sim_uniform();
    }
}

/* phi of every row at time t, the positions moved by h along velocities u
 * (held: a free body's centre straight, its quaternion by the exact increment). */
static void phi_along(sim_opened *o, double t, const double *y, const double *u, double h,
                      double *phi, double *G)
{
    const hx_dynamics *d = &o->d;
    double z[64];
    memcpy(z, y, sizeof(double) * (size_t)d->n);
    for (int k = 0; k < d->nu; ++k)
        z[d->nq + k] = h < 0.0 ? -u[k] : u[k];
    hx_bodies_advance_positions(d, z, fabs(h));
    if (hx_constraints_rows(d, &o->dd, t + h, z, phi, G, NULL) != 0)
        fail_msg("%s", o->dd.message);
}

/* G's entry of row i for velocity c (0 where the row has no block). */
static double row_entry(const hx_dynamics *d, const double *G, int i, int c)
{
    const hx_constraint_row *r = &d->rows[i];
    for (int b = 0; b < r->nblocks; ++b)
        if (c >= r->u[b] && c < r->u[b] + r->width[b])
            return G[(size_t)d->row_values * (size_t)i + (size_t)(r->slot[b] + c - r->u[b])];
    return 0.0;
}

static void rows_against_differences(void **state)
{
    (void)state;
    srand(11);
    sim_opened o;
    sim_open_text(&o, "gcon_mixed.xml", two_bodies("0", MIXED_GCONS));
    const hx_dynamics *d = &o.d;
    assert_int_equal(d->nrows, 3);
    assert_int_equal(d->gcon_first, 0);
    assert_true(d->n <= 64);
    double worst_G = 0.0, worst_gamma = 0.0, worst_rate = 0.0;
    for (int trial = 0; trial < 8; ++trial) {
        double y[64], phi[3], G[3 * 36], gamma[3], plus[3], minus[3], zero[3], scratch[3 * 36];
        random_state(d, y);
        const double t = 2.0 * sim_uniform();
        if (hx_constraints_rows(d, &o.dd, t, y, phi, G, gamma) != 0)
            fail_msg("%s", o.dd.message);
        /* G column by column: phi along one velocity, time held */
        for (int c = 0; c < d->nu; ++c) {
            double e[32] = {0};
            e[c] = 1.0;
            const double h = 1e-6;
            double z[64];
            memcpy(z, y, sizeof(double) * (size_t)d->n);
            for (int k = 0; k < d->nu; ++k)
                z[d->nq + k] = e[k];
            double zp[64], zm[64];
            memcpy(zp, z, sizeof zp);
            memcpy(zm, z, sizeof zm);
            hx_bodies_advance_positions(d, zp, h);
            for (int k = 0; k < d->nu; ++k)
                zm[d->nq + k] = -e[k];
            hx_bodies_advance_positions(d, zm, h);
            if (hx_constraints_rows(d, &o.dd, t, zp, plus, scratch, NULL) != 0 ||
                hx_constraints_rows(d, &o.dd, t, zm, minus, scratch, NULL) != 0)
                fail_msg("%s", o.dd.message);
            for (int i = 0; i < 3; ++i) {
                const double fd = (plus[i] - minus[i]) / (2.0 * h), g = row_entry(d, G, i, c);
                worst_G = fmax(worst_G, fabs(fd - g) / fmax(1.0, fabs(g)));
            }
        }
        /* phidot = G u + df/dt and gamma = -phi'' along the motion with u held, in time too */
        const double *u = y + d->nq;
        const double h1 = 1e-6, h2 = 1e-4;
        phi_along(&o, t, y, u, h1, plus, scratch);
        phi_along(&o, t, y, u, -h1, minus, scratch);
        /* the residual of the velocity level, |G u + df/dt| (constraints.h), is |phi'| */
        double largest = 0.0, phi_max, phidot_max;
        for (int i = 0; i < 3; ++i)
            largest = fmax(largest, fabs((plus[i] - minus[i]) / (2.0 * h1)));
        if (hx_constraints_residuals(d, &o.dd, t, y, &phi_max, &phidot_max) != 0)
            fail_msg("%s", o.dd.message);
        worst_rate = fmax(worst_rate, fabs(phidot_max - largest) / fmax(1.0, largest));
        phi_along(&o, t, y, u, h2, plus, scratch);
        phi_along(&o, t, y, u, -h2, minus, scratch);
        phi_along(&o, t, y, u, 0.0, zero, scratch);
        for (int i = 0; i < 3; ++i) {
            const double second = (plus[i] - 2.0 * zero[i] + minus[i]) / (h2 * h2);
            worst_gamma = fmax(worst_gamma, fabs(second + gamma[i]) / fmax(1.0, fabs(gamma[i])));
        }
    }
    printf("  G against differences %.3g, G u + df/dt %.3g, gamma against second differences"
           " %.3g\n", worst_G, worst_rate, worst_gamma);
    assert_true(worst_rate < 1e-7);
    assert_true(worst_G < 1e-7);
    assert_true(worst_gamma < 1e-5);
    sim_close_opened(&o);
}

/* The bundled pendulum released from rest at 0.5 rad: back where it started
 * after its period T = 4 sqrt(L/g) K(sin 0.25), K by the arithmetic-geometric
 * mean (K(k) = pi / (2 AGM(1, sqrt(1 - k^2)))); with DOPRI5 and BDF. */
static void pendulum_period(void **state)
{
    (void)state;
    const double k = sin(0.25);
    double a = 1.0, b = sqrt(1.0 - k * k);
    for (int i = 0; i < 8; ++i) {
        const double next = 0.5 * (a + b);
        b = sqrt(a * b), a = next;
    }
    const double T = 4.0 * sqrt(1.0 / 9.81) * M_PI / (2.0 * a); /* 2.0378679 s */
    assert_true(fabs(T - 2.0378679) < 1e-6);
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    const double bound[2] = {1e-9, 1e-5}; /* DOPRI5 at rtol 1e-10, BDF at its default 1e-6 */
    for (int m = 0; m < 2; ++m) {
        sim s;
        sim_run(&s, "gcon_pendulum.xml", methods[m], 1e-10, T, T / 4.0);
        const int last = s.path.rows - 1, q = s.dynamics.dof[1].q, u = s.dynamics.nq;
        assert_true(fabs(s.path.t[last] - T) < 1e-12);
        /* a quarter period in: through the bottom (x = 0), at the speed energy gives */
        const double speed = sqrt(2.0 * 9.81 * (1.0 - cos(0.5)));
        const double x0 = sim_state(&s, 0, q), y0 = sim_state(&s, 0, q + 1);
        printf("  %s: after T, x %.3g y %.3g off; vx %.3g; at T/4 x %.3g, speed %.3g off\n",
               m == 0 ? "dopri5" : "bdf", sim_state(&s, last, q) - x0,
               sim_state(&s, last, q + 1) - y0, sim_state(&s, last, u),
               sim_state(&s, 1, q), fabs(sim_state(&s, 1, u)) - speed);
        assert_true(fabs(sim_state(&s, last, q) - x0) < bound[m]);
        assert_true(fabs(sim_state(&s, last, q + 1) - y0) < bound[m]);
        assert_true(fabs(sim_state(&s, last, u)) < 100.0 * bound[m]);
        assert_true(fabs(sim_state(&s, 1, q)) < 100.0 * bound[m]);
        assert_true(fabs(fabs(sim_state(&s, 1, u)) - speed) < 100.0 * bound[m]);
        sim_close(&s);
    }
}

/* Two free bodies held by a distance between markers off their centres and
 * nothing else: the constraint's forces on the two are equal and opposite,
 * so the momentum stays what it was (after the assembly's projection), and
 * the distance stays 0.9. */
static void two_moving_bodies_keep_momentum(void **state)
{
    (void)state;
    static const char gcon[] =
        "<Constraint_General id=\"4\" expr=\"DM(21,31) - 0.9\"/>\n";
    char text[4096];
    snprintf(text, sizeof text, "%s", two_bodies("0", gcon));
    /* initial velocities: apart and turning */
    char *at = strstr(text, "inertia_zz=\"0.25\"");
    assert_non_null(at);
    char rest[4096];
    snprintf(rest, sizeof rest, "inertia_zz=\"0.25\" v_ic_y=\"1\" v_ic_z=\"0.2\" w_ic_x=\"2\"%s",
             at + strlen("inertia_zz=\"0.25\""));
    snprintf(at, sizeof text - (size_t)(at - text), "%s", rest);
    at = strstr(text, "inertia_zz=\"0.2\"");
    assert_non_null(at);
    snprintf(rest, sizeof rest, "inertia_zz=\"0.2\" v_ic_y=\"-1\" v_ic_z=\"0.3\" w_ic_z=\"-3\"%s",
             at + strlen("inertia_zz=\"0.2\""));
    snprintf(at, sizeof text - (size_t)(at - text), "%s", rest);
    sim s;
    sim_run(&s, test_write_file("gcon_pair.xml", text), HX_METHOD_DOPRI5, 1e-10, 2.0, 0.05);
    const hx_dynamics *d = &s.dynamics;
    const int u2 = d->nq + d->dof[1].u, u3 = d->nq + d->dof[2].u;
    double p0[3], worst_p = 0.0, worst_phi = 0.0, travel = 0.0;
    for (int r = 0; r < s.path.rows; ++r) {
        const double *y = s.path.y + (size_t)r * (size_t)s.path.n;
        double phi, phidot;
        if (hx_constraints_residuals(d, &s.data, s.path.t[r], y, &phi, &phidot) != 0)
            fail_msg("%s", s.data.message);
        worst_phi = fmax(worst_phi, fmax(phi, phidot));
        for (int c = 0; c < 3; ++c) {
            const double p = 1.5 * y[u2 + c] + 2.0 * y[u3 + c];
            if (r == 0)
                p0[c] = p;
            worst_p = fmax(worst_p, fabs(p - p0[c]));
        }
        travel = fmax(travel, fabs(y[u2 + 1] - s.path.y[u2 + 1]));
    }
    printf("  momentum kept to %.3g, |phi|, |phidot| %.3g, a body's velocity changed by %.3g\n",
           worst_p, worst_phi, travel);
    assert_true(travel > 0.1); /* the constraint acted */
    assert_true(worst_p < 1e-10);
    assert_true(worst_phi < 1e-10);
    sim_close(&s);
}

/* A body driven by time: DX(20) - 0.1 SIN(TIME), DY(20) - 0.05 COS(2 TIME),
 * DZ(20), under gravity and turning: its centre follows the functions, the
 * residuals of phi and of G u + df/dt stay at 1e-10, and its acceleration
 * is the functions' second derivative (gamma's df/dt term). */
static void time_dependent(void **state)
{
    (void)state;
    static const char gcon[] =
        "<Constraint_General id=\"5\" expr=\"DX(20) - 0.1*SIN(TIME)\"/>\n"
        "<Constraint_General id=\"6\" expr=\"DY(20) - 0.05*COS(2*TIME)\"/>\n"
        "<Constraint_General id=\"7\" expr=\"DZ(20)\"/>\n";
    char text[4096];
    snprintf(text, sizeof text, "%s", two_bodies("-9.81", gcon));
    /* body 3 falls freely beside it; body 2 starts at y = 0.05 */
    char *at = strstr(text, "<Reference_Marker id=\"20\" body_id=\"2\"/>");
    assert_non_null(at);
    char rest[4096];
    snprintf(rest, sizeof rest, "<Reference_Marker id=\"20\" body_id=\"2\" pos_y=\"0.05\"/>%s",
             at + strlen("<Reference_Marker id=\"20\" body_id=\"2\"/>"));
    snprintf(at, sizeof text - (size_t)(at - text), "%s", rest);
    sim s;
    sim_run(&s, test_write_file("gcon_time.xml", text), HX_METHOD_DOPRI5, 1e-9, 3.0, 0.1);
    const hx_dynamics *d = &s.dynamics;
    const int q = d->dof[1].q, u = d->nq + d->dof[1].u;
    double worst_x = 0.0, worst_v = 0.0, worst_r = 0.0, worst_a = 0.0;
    double *ydot = malloc(sizeof(double) * (size_t)d->n);
    assert_non_null(ydot);
    for (int r = 0; r < s.path.rows; ++r) {
        const double t = s.path.t[r], *y = s.path.y + (size_t)r * (size_t)s.path.n;
        worst_x = fmax(worst_x, fabs(y[q] - 0.1 * sin(t)));
        worst_x = fmax(worst_x, fabs(y[q + 1] - 0.05 * cos(2.0 * t)));
        worst_v = fmax(worst_v, fabs(y[u] - 0.1 * cos(t)));
        worst_v = fmax(worst_v, fabs(y[u + 1] + 0.1 * sin(2.0 * t)));
        double phi, phidot;
        if (hx_constraints_residuals(d, &s.data, t, y, &phi, &phidot) != 0)
            fail_msg("%s", s.data.message);
        worst_r = fmax(worst_r, fmax(phi, phidot));
        if (hx_dynamics_rhs(d, &s.data, t, y, ydot) != 0)
            fail_msg("%s", s.data.message);
        worst_a = fmax(worst_a, fabs(ydot[u] + 0.1 * sin(t)));
        worst_a = fmax(worst_a, fabs(ydot[u + 1] + 0.2 * cos(2.0 * t)));
        worst_a = fmax(worst_a, fabs(ydot[u + 2]));
    }
    printf("  position %.3g, velocity %.3g, residuals %.3g, acceleration %.3g off\n", worst_x,
           worst_v, worst_r, worst_a);
    assert_true(worst_x < 1e-10);
    assert_true(worst_v < 1e-10);
    assert_true(worst_r < 1e-10);
    assert_true(worst_a < 1e-7);
    free(ydot);
    sim_close(&s);
}

/* The Jacobian BDF assembles (the constraint rows by differences of the
 * constraint stage, on the coupled bodies' columns) against differences of
 * the whole right-hand side: on measures whose rows are analytic (1.2e-7 of
 * a row), and with PSI and INCANG, whose rows are differences of the measure
 * (1.2e-6: the stage's differences see theirs). */
static void jacobian_covers_gcon(void **state)
{
    (void)state;
    static const char analytic[] =
        "<Constraint_General id=\"1\" expr=\"DM(21,31) - 0.7\"/>\n"
        "<Constraint_General id=\"2\" expr=\"DX(21,31,30) + 0.3*DY(20,11)**2 - 0.05*SIN(TIME)\"/>\n"
        "<Constraint_General id=\"3\" expr=\"0.5*AZ(21,30) + DZ(20)*COS(2*TIME)\"/>\n";
    const char *const sets[2] = {analytic, MIXED_GCONS};
    const double bound[2] = {1e-6, 1e-5};
    for (int k = 0; k < 2; ++k) {
        sim s;
        sim_run(&s, test_write_file("gcon_mixed_run.xml", two_bodies("-9.81", sets[k])),
                HX_METHOD_BDF, 1e-8, 0.2, 0.1);
        const int last = s.path.rows - 1;
        long outside = 0;
        const double worst = jacobian_against_differences(
            &s.dynamics, s.path.t[last], s.path.y + (size_t)last * (size_t)s.path.n,
            k == 0 ? "gcon, analytic rows" : "gcon, with differenced rotations", &outside);
        assert_true(worst < bound[k]);
        assert_int_equal(outside, 0);
        sim_close(&s);
    }
}

/* What is refused, each with its place. */
static void refusals(void **state)
{
    (void)state;
    static const struct {
        const char *name, *gcon, *where, *what;
    } cases[] = {
        {"gcon_velocity.xml", "<Constraint_General id=\"8\" expr=\"DM(21,31) + 0.1*VX(21)\"/>\n",
         "gcon_velocity.xml:12:17: Constraint_General 8: expr: VX(21)", "nonholonomic"},
        {"gcon_unknown.xml", "<Constraint_General id=\"8\" expr=\"DM(21,99) - 1\"/>\n",
         "gcon_unknown.xml:12:1: Constraint_General 8", "no Reference_Marker 99"},
        {"gcon_variable.xml", "<Constraint_General id=\"8\" expr=\"DM(21,31) - VARVAL(3)\"/>\n"
         "<Reference_Variable id=\"3\" type=\"EXPRESSION\" expr=\"DX(21)\"/>\n",
         "gcon_variable.xml:12:13: Constraint_General 8: expr: VARVAL(3)", "a variable"},
        {"gcon_user.xml", "<Constraint_General id=\"8\" expr=\"0\" usrsub_param_string=\"USER(1)\"/>\n",
         "gcon_user.xml:12:", "GCOSUB"},
        {"gcon_time.xml", "<Constraint_General id=\"8\" expr=\"TIME - 1\"/>\n",
         "gcon_time.xml:12:", "reads no marker"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        hx_message msg;
        hx_model *m = hx_model_read(test_write_file(cases[k].name, two_bodies("0", cases[k].gcon)),
                                    NULL, &msg);
        if (m != NULL) {
            hx_model_free(m);
            fail_msg("%s was read; expected an error", cases[k].name);
        }
        printf("  %s\n", msg.text);
        assert_contains(msg.text, cases[k].where, "Constraint_General 8", cases[k].what);
    }
    /* the dataset: the statement's line and the expression's column */
    static const char adm[] =
        "gcon refusal\n"
        "PART/1, GROUND\n"
        "MARKER/10, PART = 1\n"
        "PART/2, MASS = 1, CM = 20, IP = 1, 1, 1\n"
        "MARKER/20, PART = 2, QP = 1, 0, 0\n"
        "GCON/3, I = 20, FUNCTION = DM(20,10) - WZ(20)\n"
        "END\n";
    hx_message msg;
    hx_model *m = hx_model_read(test_write_file("gcon_velocity.adm", adm), NULL, &msg);
    assert_null(m);
    printf("  %s\n", msg.text);
    assert_contains(msg.text, "gcon_velocity.adm:6:40:", "GCON/3", "WZ(20)", "nonholonomic");
    /* on ground alone: the dynamics refuses it */
    hx_session session;
    hx_dynamics d;
    memset(&d, 0, sizeof d);
    static const char ground[] = "<Constraint_General id=\"9\" expr=\"DX(11,10) - 0.3\"/>\n";
    if (hx_session_open(&session, test_write_file("gcon_ground.xml", two_bodies("0", ground)),
                        stderr, &msg) != 0)
        fail_msg("%s", msg.text);
    assert_int_equal(hx_dynamics_init(&d, &session, &msg), -1);
    printf("  %s\n", msg.text);
    assert_contains(msg.text, "Constraint_General 9", "all on ground");
    hx_dynamics_free(&d);
    hx_session_close(&session);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rows_against_differences),
        cmocka_unit_test(pendulum_period),
        cmocka_unit_test(two_moving_bodies_keep_momentum),
        cmocka_unit_test(time_dependent),
        cmocka_unit_test(jacobian_covers_gcon),
        cmocka_unit_test(refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
