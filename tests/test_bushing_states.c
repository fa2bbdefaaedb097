/*
 * The bushing's internal states (docs/interface.md §3.8), in the core:
 * - no state: the state equation's force and partials are the FIESUB form's,
 *   bit for bit;
 * - every partial (d stated and d output by d states and d inputs) against
 *   central differences, at points that vary every input and state, for
 *   friction, damped and undamped mounts, rubber filters and limits alone
 *   and all together;
 * - friction integrated with a turning body: it sticks below the breakaway
 *   torque mu_s N r_B (slip rate to zero, bristles at T / (sigma0 r_B N)),
 *   slips above it at mu_d, floors at the preload torque, and grows with the
 *   normal force when a mount limit is in contact;
 * - a mount: very stiff, the force is the stateless one to 1e-6; a static
 *   load splits the deflection in the ratio of the stiffnesses, with damping
 *   and without (both integrated to rest), and at once in a direction without
 *   rate terms;
 * - the series mount's dynamic stiffness against the two-spring-damper closed
 *   form from 1 to 1e5 rad/s: damped, undamped, and rotational in series with
 *   friction (the node's inertia in the closed form);
 * - a rotational mount in series with friction has one answer: the rates do
 *   not jump when an unrelated state moves by 1e-10, and the file in metres
 *   gives the millimetre file's rates;
 * - the rubber filter's steady response to a sine: gain w / sqrt(R^2 + w^2),
 *   phase atan(R / w).
 */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"
#include "usrsub/core/bushing_states.h"
#include "usrsub/core/lugre_friction.h"
#include "usrsub/readers/bushing_reader.h"
#include "usrsub/readers/mount_limits_reader.h"
#include "usrsub/readers/units.h"

static const char header[] =
    "[HEADER]\nFILE_TYPE = 'gbs'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\nFORCE = 'newton'\n"
    "MASS = 'kg'\nTIME = 'second'\n";

/* A bushing read from a whole file's text, in a model of the given units
 * (NULL: none declared); fails the test when it is refused. */
static usrsub_bushing *read_bushing(const char *name, const char *text, const double *model)
{
    usrsub_bushing *b;
    usrsub_read_report report = {0};
    usrsub_message msg;
    if (usrsub_bushing_read(test_write_file(name, text), model, &b, &report, &msg) != 0)
        fail_msg("%s", msg.text);
    return b;
}

/* A bushing from its text after [UNITS]. */
static usrsub_bushing *bushing(const char *name, const char *body)
{
    char text[8192];
    snprintf(text, sizeof text, "%s%s", header, body);
    return read_bushing(name, text, NULL);
}

/* Mount limits with the given sides; every other side is written inactive. */
static usrsub_mount_limits *limits(const char *name, const char *sides)
{
    char text[4096];
    int n = snprintf(text, sizeof text,
                     "[HEADER]\nFILE_TYPE = 'gbi'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\n"
                     "FORCE = 'newton'\nMASS = 'kg'\nTIME = 'second'\n[MOUNT_LIMITS]\n%s", sides);
    static const char *const kinds[2] = {"TRA", "ROT"}, *const axes[3] = {"X", "Y", "Z"},
                             *const ends[2] = {"POS", "NEG"};
    for (int k = 0; k < 12; ++k) {
        char side[64];
        snprintf(side, sizeof side, "IMPACT_PARAMETERS_%s_%s_%s", kinds[k / 6], axes[k / 2 % 3],
                 ends[k % 2]);
        if (strstr(sides, side) == NULL)
            n += snprintf(text + n, sizeof text - (size_t)n, "%s = 0 1 0 0 0\n", side);
    }
    usrsub_mount_limits *m;
    usrsub_read_report report = {0};
    usrsub_message msg;
    if (usrsub_mount_limits_read(test_write_file(name, text), NULL, &m, &report, &msg) != 0)
        fail_msg("%s", msg.text);
    return m;
}

/* a nonlinear coupled bushing, damped, with every direction active */
static const char base_body[] =
    "[GLOBAL]\nCOUPLING = 'CYLINDRICAL'\n[DIRECTIONS]\n(ACTIVITY)\n"
    "{ formulation FX FY FZ TX TY TZ }\n'SPLINE_STIFFNESS' 1 1 0 0 0 0\n"
    "'CONSTANT_STIFFNESS' 0 0 1 1 1 1\n'CONSTANT_DAMPING' 1 1 %d 1 1 %d\n"
    "'RUBBER_DAMPING' 0 0 %d 0 0 %d\n"
    "[SPLINE_STIFFNESS_FX]\n(SPLINE_DATA)\n{ disp force }\n-4 -9200\n-2 -3000\n0 0\n2 3000\n4 9200\n"
    "[SPLINE_STIFFNESS_FY]\n(SPLINE_DATA)\n{ disp force }\n-4 -9000\n-2 -2800\n0 0\n2 2900\n4 9400\n"
    "[CONSTANT_STIFFNESS_FZ]\nK = 800\n[CONSTANT_STIFFNESS_TX]\nK = 4e5\n"
    "[CONSTANT_STIFFNESS_TY]\nK = 3e5\n[CONSTANT_STIFFNESS_TZ]\nK = 2e5\n"
    "[CONSTANT_DAMPING_FX]\nC = 2.5\n[CONSTANT_DAMPING_FY]\nC = 3\n[CONSTANT_DAMPING_FZ]\nC = 1.5\n"
    "[CONSTANT_DAMPING_TX]\nC = 40\n[CONSTANT_DAMPING_TY]\nC = 50\n[CONSTANT_DAMPING_TZ]\nC = 30\n"
    "[PRELOAD_OFFSET_SCALE]\n{ direction P Q H V }\nFX 10 0.1 1.1 0.9\nTZ 50 0.01 1 1.2\n";

static const char rubber_blocks[] =
    "[RUBBER_DAMPING_FZ]\nNPRELOADS = 1\n(PRELOAD_1)\nPRELOAD = 0\nR = 30\nK0 = 400\nK1 = 0\n"
    "K2 = 0\nC0 = 2\nC1 = 0\nC2 = 0\nP0 = 1\nP1 = 0\nP2 = 1\nQ0 = 1\nQ1 = 0\nQ2 = 1\n"
    "[RUBBER_DAMPING_TZ]\nNPRELOADS = 1\n(PRELOAD_1)\nR = 5\nRMIN = 12\nK0 = 1e5\nC0 = 300\n";

static const char friction_block[] =
    "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\nMU_DYNAMIC = 0.3\nEFFECT = 'STICTION'\n"
    "TRANSITION_VELOCITY = 20\nBRISTLE_STIFFNESS = 100\nBRISTLE_DAMPING = 0.02\n"
    "SLIP_DAMPING = 0.001\nBALL_RADIUS = 10\nPRELOAD_TORQUE = 500\n";

static const char mount_block[] =
    "[MOUNT_STIFFNESS]\n{ direction K C }\nFX 20000 5\nFY 15000 0\nTX 2e6 100\nTZ 3e6 0\n";

static const char friction_block_with_mounts[] =
    "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\nMU_DYNAMIC = 0.3\n"
    "TRANSITION_VELOCITY = 20\nBRISTLE_STIFFNESS = 100\nBRISTLE_DAMPING = 0.02\n"
    "SLIP_DAMPING = 0.001\nBALL_RADIUS = 10\nPRELOAD_TORQUE = 500\n"
    "[MOUNT_STIFFNESS]\n{ direction K C }\nFX 20000 5\nFY 15000 0\nTX 2e6 100\nTZ 3e6 0\n";

static usrsub_bushing *base_bushing(const char *name, int rubber, const char *extra)
{
    char body[8192];
    snprintf(body, sizeof body, base_body, !rubber, !rubber, rubber, rubber);
    snprintf(body + strlen(body), sizeof body - strlen(body), "%s%s", rubber ? rubber_blocks : "",
             extra);
    return bushing(name, body);
}

static const char limit_sides[] =
    "IMPACT_PARAMETERS_TRA_X_POS = 500 2 10 0.5 0.5\nIMPACT_PARAMETERS_TRA_X_NEG = 500 2 10 0.5 0.5\n"
    "IMPACT_PARAMETERS_TRA_Z_POS = 2000 1.5 20 0.5 0.2\nIMPACT_PARAMETERS_TRA_Z_NEG = 2000 1.5 20 0.5 0.2\n"
    "IMPACT_PARAMETERS_ROT_Y_POS = 1e6 2 100 0.01 0.01\nIMPACT_PARAMETERS_ROT_Y_NEG = 1e6 2 100 0.01 0.01\n";

static void eval(const usrsub_bushing *b, const usrsub_mount_limits *m,
                 const usrsub_state_layout *l, const double u[12], const double *x,
                 double *xdot, double y[6], usrsub_state_partials *p)
{
    usrsub_message msg;
    if (usrsub_bushing_states_eval(b, m, l, u, x, xdot, y, p, &msg) != 0)
        fail_msg("%s", msg.text);
}

static void without_states_it_is_the_fiesub_force(void **state)
{
    (void)state;
    usrsub_bushing *b = base_bushing("plain.gbs", 0, "");
    usrsub_mount_limits *m = limits("plain.gbi", limit_sides);
    usrsub_state_layout l;
    usrsub_bushing_state_layout(b, &l);
    assert_int_equal(l.n, 0);
    assert_false(b->has_states);
    const double u[12] = {0.8, -0.4, 0.35, 0.004, -0.012, 0.02, 12, -7, 3, 0.4, -0.25, 0.6};
    double y[6], F[6], dFdd[36], dFdv[36];
    usrsub_state_partials p;
    eval(b, m, &l, u, NULL, NULL, y, &p);
    usrsub_bushing_force(b, u, u + 6, F, dFdd, dFdv);
    usrsub_mount_limits_add(m, u, u + 6, F, dFdd, dFdv);
    for (int i = 0; i < 6; ++i) {
        assert_true(y[i] == F[i]);
        for (int j = 0; j < 6; ++j) {
            assert_true(p.dy_du[i + 6 * j] == dFdd[i + 6 * j]);
            assert_true(p.dy_du[i + 6 * (6 + j)] == dFdv[i + 6 * j]);
        }
    }
    usrsub_bushing_free(b);
    usrsub_mount_limits_free(m);
}

/* Every partial against central differences at a point (u, x); returns the
 * worst relative error (against the column's size). */
static double partials_error(const usrsub_bushing *b, const usrsub_mount_limits *m,
                             const double u0[12], const double *x0)
{
    usrsub_state_layout l;
    usrsub_bushing_state_layout(b, &l);
    const int n = l.n, rows = n + 6;
    usrsub_state_partials p;
    double xdot[USRSUB_MAX_STATES], y[6];
    eval(b, m, &l, u0, x0, xdot, y, &p);
    double worst = 0.0;
    for (int j = 0; j < 12 + n; ++j) {
        double u[12], x[USRSUB_MAX_STATES], plus[USRSUB_MAX_STATES + 6], minus[USRSUB_MAX_STATES + 6];
        memcpy(u, u0, sizeof u);
        memcpy(x, x0, sizeof(double) * (size_t)n);
        double *at = j < 12 ? &u[j] : &x[j - 12];
        const double h = 1e-6 * fmax(1e-3, fabs(*at)), mid = *at;
        *at = mid + h;
        eval(b, m, &l, u, x, plus, plus + n, NULL);
        *at = mid - h;
        eval(b, m, &l, u, x, minus, minus + n, NULL);
        double size = 1e-9;
        for (int i = 0; i < rows; ++i)
            size = fmax(size, fabs(plus[i] - minus[i]) / (2.0 * h));
        for (int i = 0; i < rows; ++i) {
            const double fd = (plus[i] - minus[i]) / (2.0 * h);
            double exact;
            if (i < n)
                exact = j < 12 ? p.dxdot_du[i + n * j] : p.dxdot_dx[i + n * (j - 12)];
            else
                exact = j < 12 ? p.dy_du[i - n + 6 * j] : p.dy_dx[i - n + 6 * (j - 12)];
            const double e = fabs(exact - fd) / size;
            if (e > worst)
                worst = e;
            if (e > 1e-5)
                printf("    d out %d / d in %d: exact %.10g, differences %.10g\n", i, j, exact, fd);
        }
    }
    return worst;
}

static void every_partial_against_differences(void **state)
{
    (void)state;
    usrsub_mount_limits *m = limits("fd.gbi", limit_sides);
    const char *names[5] = {"friction", "mounts", "rubber", "all, limits in contact", "all, sliding"};
    usrsub_bushing *bs[5] = {
        base_bushing("fd_friction.gbs", 0, friction_block),
        base_bushing("fd_mount.gbs", 0, mount_block),
        base_bushing("fd_rubber.gbs", 1, ""),
        base_bushing("fd_all.gbs", 1, friction_block_with_mounts),
        NULL};
    bs[4] = bs[3];
    for (int c = 0; c < 5; ++c) {
        usrsub_state_layout l;
        usrsub_bushing_state_layout(bs[c], &l);
        /* every input and state its own value; case 3 in contact in x, z and ay */
        double u[12] = {0.8, -0.4, 0.35, 0.004, -0.012, 0.02, 12, -7, 3, 0.4, -0.25, 0.6};
        if (c == 3)
            u[0] = 0.9, u[2] = 0.45, u[4] = 0.017;
        if (c == 4)
            u[9] = 3.0, u[10] = -2.0, u[11] = 1.5;
        double x[USRSUB_MAX_STATES];
        for (int i = 0; i < l.n; ++i)
            x[i] = 0.01 * (i + 1) * (i % 2 ? -1.0 : 1.0);
        const double worst = partials_error(bs[c], c >= 3 ? m : NULL, u, x);
        printf("  %-24s %2d states: worst partial off by %.2g of its column\n", names[c], l.n, worst);
        assert_true(worst < 1e-6);
    }
    for (int c = 0; c < 4; ++c)
        usrsub_bushing_free(bs[c]);
    usrsub_mount_limits_free(m);
}

/* The friction law's own partials against differences (lugre_friction.h): in
 * each branch of the torque, in the blend between them, and at rest (z = w =
 * 0, no preload torque: the joint torque's slope, not zero). */
static double friction_error(const usrsub_friction *f, const double F[3], const double z[3],
                             const double w[3])
{
    double tau[3], zdot[3];
    usrsub_friction_partials p;
    usrsub_friction_eval(f, F, z, w, tau, zdot, &p);
    double worst = 0.0;
    for (int j = 0; j < 9; ++j) {
        double in[9], plus[6], minus[6];
        memcpy(in, F, 3 * sizeof(double)), memcpy(in + 3, z, 3 * sizeof(double));
        memcpy(in + 6, w, 3 * sizeof(double));
        const double h = 1e-6 * fmax(1e-3, fabs(in[j])), mid = in[j];
        in[j] = mid + h;
        usrsub_friction_eval(f, in, in + 3, in + 6, plus, plus + 3, NULL);
        in[j] = mid - h;
        usrsub_friction_eval(f, in, in + 3, in + 6, minus, minus + 3, NULL);
        const double *exact_tau = j < 3 ? p.dtau_dF : j < 6 ? p.dtau_dz : p.dtau_dw;
        double size = 1e-12;
        for (int i = 0; i < 6; ++i)
            size = fmax(size, fabs(plus[i] - minus[i]) / (2 * h));
        for (int i = 0; i < 6; ++i) {
            const double fd = (plus[i] - minus[i]) / (2 * h);
            double exact = i < 3 ? exact_tau[i + 3 * (j % 3)] : 0.0;
            if (i >= 3)
                exact = j < 3 ? 0.0 : j < 6 ? p.dzdot_dz[i - 3 + 3 * (j - 3)] : p.dzdot_dw[i - 3 + 3 * (j - 6)];
            worst = fmax(worst, fabs(exact - fd) / size);
        }
    }
    return worst;
}

static void friction_partials_in_every_branch(void **state)
{
    (void)state;
    usrsub_friction f = {1, 0.5, 0.3, 5.0, 100.0, 0.02, 0.001, 10.0, 0.0, 1};
    const double F[3] = {10, -20, 100}, zero[3] = {0, 0, 0};
    /* at rest without a preload torque */
    double tau[3], zdot[3];
    usrsub_friction_partials p;
    usrsub_friction_eval(&f, F, zero, zero, tau, zdot, &p);
    assert_true(p.dtau_dz[0] < -1e4); /* -sigma0 r_B |F| (1 - n_x^2): the bristles' stiffness */
    const double e_rest = friction_error(&f, F, zero, (const double[3]){1e-9, 0, 0});
    /* joint branch, preload branch, and in the blend (|tj| = |tp| with mu not
     * perpendicular to F_N) */
    const double z1[3] = {0.002, -0.001, 0.0015}, w1[3] = {0.3, -0.2, 0.1};
    f.preload_torque = 50.0;
    const double e_joint = friction_error(&f, F, z1, w1);
    f.preload_torque = 5e4;
    const double e_preload = friction_error(&f, F, z1, w1);
    double worst_blend = 0.0, joint_only[3], preload_only[3];
    int in_band = 0;
    f.preload_torque = 0.0;
    usrsub_friction_eval(&f, F, z1, w1, joint_only, zdot, NULL);
    for (double T = 300.0; T <= 800.0; T += 10.0) {
        f.preload_torque = T;
        usrsub_friction_eval(&f, F, z1, w1, tau, zdot, NULL);
        usrsub_friction_eval(&f, zero, z1, w1, preload_only, zdot, NULL); /* no load: tau_pre */
        in_band += tau[0] != joint_only[0] && tau[0] != preload_only[0];
        worst_blend = fmax(worst_blend, friction_error(&f, F, z1, w1));
    }
    assert_true(in_band >= 2); /* the sweep crosses the blend */
    printf("  friction partials: at rest %.2g, joint %.2g, preload %.2g, across the blend %.2g"
           " (%d of 51 preload torques inside it)\n", e_rest, e_joint, e_preload, worst_blend,
           in_band);
    assert_true(e_rest < 1e-6 && e_joint < 1e-6 && e_preload < 1e-6 && worst_blend < 1e-5);
}

/* The mounts' balance is solved at every state of a wide random sample (the
 * bristles within LuGre's bound mu_s / sigma0, deformations and rates of
 * every direction, twice the range too), across the friction's blend, and
 * with a mount far stiffer than its damping (K 1e15, C 1e-3). */
static void the_mounts_balance_is_solved_everywhere(void **state)
{
    (void)state;
    usrsub_bushing *all = base_bushing("wide_all.gbs", 1, friction_block_with_mounts);
    usrsub_bushing *blend = bushing("wide_switch.gbs",
        "[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
        "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 1 1 1 1 1 1\n"
        "[CONSTANT_STIFFNESS_FX]\nK = 1000\n[CONSTANT_STIFFNESS_FY]\nK = 1000\n"
        "[CONSTANT_STIFFNESS_FZ]\nK = 1000\n[CONSTANT_STIFFNESS_TX]\nK = 1e4\n"
        "[CONSTANT_STIFFNESS_TY]\nK = 1e4\n[CONSTANT_STIFFNESS_TZ]\nK = 1e4\n"
        "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.3\nMU_DYNAMIC = 0.2\nTRANSITION_VELOCITY = 10\n"
        "BRISTLE_STIFFNESS = 100\nSLIP_DAMPING = 0.05\nBALL_RADIUS = 10\nPRELOAD_TORQUE = 300\n"
        "[MOUNT_STIFFNESS]\n{ direction K C }\nTX 1e5 10\n");
    usrsub_bushing *stiff = base_bushing("wide_stiff.gbs", 0,
        "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\nMU_DYNAMIC = 0.3\nTRANSITION_VELOCITY = 20\n"
        "BRISTLE_STIFFNESS = 100\nBRISTLE_DAMPING = 0.02\nBALL_RADIUS = 10\n"
        "[MOUNT_STIFFNESS]\n{ direction K C }\nFX 1e15 1e-3\nTX 1e15 1e-3\n");
    usrsub_bushing *const bushings[3] = {all, blend, stiff};
    unsigned seed = 12345;
    int failures = 0, samples = 0;
    for (int c = 0; c < 3; ++c) {
        usrsub_state_layout l;
        usrsub_bushing_state_layout(bushings[c], &l);
        for (int t = 0; t < 4000; ++t) {
            const double range = t < 2000 ? 1.0 : 2.0;
            double u[12], x[USRSUB_MAX_STATES], xdot[USRSUB_MAX_STATES], y[6];
            for (int i = 0; i < 12; ++i) {
                seed = seed * 1664525u + 1013904223u;
                const double r = range * ((seed >> 8) / 8388608.0 - 1.0);
                u[i] = r * (i < 3 ? 1.5 : i < 6 ? 0.02 : i < 9 ? 20.0 : 0.5);
            }
            if (c == 1)
                u[2] = -0.3; /* pressed: a normal force of 300 N */
            for (int i = 0; i < l.n; ++i) {
                seed = seed * 1664525u + 1013904223u;
                x[i] = range * ((seed >> 8) / 8388608.0 - 1.0) * (i < l.friction ? 0.0015 : 0.02);
            }
            usrsub_message msg;
            ++samples;
            if (usrsub_bushing_states_eval(bushings[c], NULL, &l, u, x, xdot, y, NULL, &msg) != 0) {
                if (failures++ < 3)
                    printf("    %s\n", msg.text);
            }
        }
    }
    printf("  the mounts' balance: %d of %d sampled states without a solution\n", failures,
           samples);
    assert_int_equal(failures, 0);
    for (int c = 0; c < 3; ++c)
        usrsub_bushing_free(bushings[c]);
}

/* ---- friction on a turning body ----------------------------------------------------- */

/* A body of inertia 1000 kg mm^2 turning about x, pressed along z by a
 * 1000 N/mm spring compressed 2 mm (N = 2000 N), with torque T about x: its
 * angular velocity after t seconds of RK4, and the bristle deflection. */
typedef struct spin {
    const usrsub_bushing *b;
    const usrsub_mount_limits *m;
    usrsub_state_layout l;
    double torque, press;
} spin;

static void spin_rates(const spin *s, const double y[5], double dy[5])
{
    /* y = (z0, z1, z2, angle, w) */
    double u[12] = {0, 0, -s->press, y[3], 0, 0, 0, 0, 0, y[4], 0, 0}, out[6];
    eval(s->b, s->m, &s->l, u, y, dy, out, NULL);
    dy[3] = y[4];
    dy[4] = (s->torque + out[3]) * 1e3 / 1000.0; /* N mm -> kg mm^2/s^2, over the inertia */
}

/* RK4 at step h: the bristles stiffen as the slip rate grows (their rate is
 * r_B |w| sigma0 / g), so fast slips want short runs and steps */
static void spin_run(const spin *s, double t, double h, double y[5])
{
    for (double time = 0.0; time < t; time += h) {
        double k1[5], k2[5], k3[5], k4[5], tmp[5];
        spin_rates(s, y, k1);
        for (int i = 0; i < 5; ++i) tmp[i] = y[i] + 0.5 * h * k1[i];
        spin_rates(s, tmp, k2);
        for (int i = 0; i < 5; ++i) tmp[i] = y[i] + 0.5 * h * k2[i];
        spin_rates(s, tmp, k3);
        for (int i = 0; i < 5; ++i) tmp[i] = y[i] + h * k3[i];
        spin_rates(s, tmp, k4);
        for (int i = 0; i < 5; ++i)
            y[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
}

static const char spin_body[] =
    "[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
    "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 0 0 1 0 0 0\n"
    "[CONSTANT_STIFFNESS_FZ]\nK = 1000\n"
    "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\nMU_DYNAMIC = 0.3\nEFFECT = 'STICTION'\n"
    "TRANSITION_VELOCITY = 5\nBRISTLE_STIFFNESS = 100\nBRISTLE_DAMPING = 0.5\n"
    "SLIP_DAMPING = 0\nBALL_RADIUS = 10\nPRELOAD_TORQUE = %g\n";

static void friction_sticks_slips_and_floors(void **state)
{
    (void)state;
    char body[2048];
    snprintf(body, sizeof body, spin_body, 0.0);
    usrsub_bushing *b = bushing("spin.gbs", body);
    spin s = {b, NULL, {0}, 0.0, 2.0};
    usrsub_bushing_state_layout(b, &s.l);
    assert_int_equal(s.l.n, 3);
    const double N = 2000.0, rB = 10.0, breakaway = 0.5 * N * rB; /* 10 000 N mm */

    /* below the breakaway torque: the body stops and the bristles hold it */
    s.torque = 0.8 * breakaway;
    double y[5] = {0, 0, 0, 0, 0};
    spin_run(&s, 0.2, 1e-5, y);
    const double z_expected = s.torque / (100.0 * rB * N);
    printf("  stick at 0.8 breakaway: slip rate %.3g rad/s, bristles %.6g mm (expected %.6g)\n",
           y[4], y[0], z_expected);
    assert_true(fabs(y[4]) < 1e-6);
    assert_close(y[0], z_expected, 1e-6, 0);

    /* above it: it slides, at mu_d once fast: the acceleration is (T - mu_d N r_B) / I */
    s.torque = 1.5 * breakaway;
    double z[5] = {0, 0, 0, 0, 0};
    spin_run(&s, 0.005, 2e-6, z);
    double rates[5];
    spin_rates(&s, z, rates);
    const double expected = (s.torque - 0.3 * N * rB) * 1e3 / 1000.0;
    printf("  slip at 1.5 breakaway: w = %.4g rad/s, dw/dt %.6g (expected %.6g at mu_d)\n", z[4],
           rates[4], expected);
    assert_true(z[4] > 20.0); /* r_B w far above the transition velocity */
    assert_close(rates[4], expected, 1e-6, 0);
    usrsub_bushing_free(b);

    /* no normal force: the preload torque's floor, (T_pre / mu_s) mu, so
     * T_pre mu_d / mu_s in fast sliding */
    snprintf(body, sizeof body, spin_body, 800.0);
    b = bushing("spin_pre.gbs", body);
    spin p = {b, NULL, {0}, 3000.0, 0.0};
    usrsub_bushing_state_layout(b, &p.l);
    double w[5] = {0, 0, 0, 0, 0};
    spin_run(&p, 0.005, 2e-6, w);
    spin_rates(&p, w, rates);
    printf("  preload floor: sliding torque %.6g N mm (expected %.6g)\n", 3000.0 - rates[4],
           800.0 * 0.3 / 0.5);
    assert_close(3000.0 - rates[4], 800.0 * 0.3 / 0.5, 1e-6, 0);

    /* a z limit in contact presses harder: the sliding torque grows with N */
    usrsub_bushing_free(b);
    snprintf(body, sizeof body, spin_body, 0.0);
    b = bushing("spin_limit.gbs", body);
    usrsub_mount_limits *m = limits("spin.gbi", "IMPACT_PARAMETERS_TRA_Z_NEG = 3000 1 0 0 1.5\n"
                                                "IMPACT_PARAMETERS_TRA_Z_POS = 3000 1 0 0 1.5\n");
    spin free_spin = {b, NULL, {0}, 0.0, 2.0}, limited = {b, m, {0}, 0.0, 2.0};
    usrsub_bushing_state_layout(b, &free_spin.l);
    usrsub_bushing_state_layout(b, &limited.l);
    double torque[2];
    for (int k = 0; k < 2; ++k) {
        spin *sp = k ? &limited : &free_spin;
        /* spinning fast with the bristles at their sliding deflection */
        double yy[5] = {0.3 / 100.0, 0, 0, 0, 500.0}, dy[5];
        spin_rates(sp, yy, dy);
        torque[k] = -dy[4];
    }
    /* the limit adds 3000 N/mm * (2 - 1.5) mm to the 2000 N of the spring */
    printf("  sliding torque %.6g N mm free, %.6g with the z limit in contact\n", torque[0],
           torque[1]);
    assert_close(torque[1] / torque[0], 3500.0 / 2000.0, 1e-9, 0);
    usrsub_mount_limits_free(m);
    usrsub_bushing_free(b);
}

/* ---- the mount ------------------------------------------------------------------------ */

static const char mount_body[] =
    "[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
    "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 1 1 1 1 1 1\n"
    "'CONSTANT_DAMPING' 1 1 1 1 1 1\n"
    "[CONSTANT_STIFFNESS_FX]\nK = 1000\n[CONSTANT_STIFFNESS_FY]\nK = 1000\n[CONSTANT_STIFFNESS_FZ]\nK = 800\n"
    "[CONSTANT_STIFFNESS_TX]\nK = 4e5\n[CONSTANT_STIFFNESS_TY]\nK = 3e5\n[CONSTANT_STIFFNESS_TZ]\nK = 2e5\n"
    "[CONSTANT_DAMPING_FX]\nC = 2\n[CONSTANT_DAMPING_FY]\nC = 2\n[CONSTANT_DAMPING_FZ]\nC = 2\n"
    "[CONSTANT_DAMPING_TX]\nC = 20\n[CONSTANT_DAMPING_TY]\nC = 20\n[CONSTANT_DAMPING_TZ]\nC = 20\n"
    "[MOUNT_STIFFNESS]\n{ direction K C }\nFX %g %g\nFY %g 0\n";

static void a_mount_splits_the_deflection(void **state)
{
    (void)state;
    char body[4096];
    /* very stiff mounts: the stateless force to 1e-6 once they have settled */
    snprintf(body, sizeof body, mount_body, 1e12, 1.0, 1e12);
    usrsub_bushing *b = bushing("stiff_mount.gbs", body);
    char plain[4096];
    snprintf(plain, sizeof plain, "%.*s", (int)(strstr(mount_body, "[MOUNT") - mount_body), mount_body);
    usrsub_bushing *p = bushing("no_mount.gbs", plain);
    usrsub_state_layout l, lp;
    usrsub_bushing_state_layout(b, &l);
    usrsub_bushing_state_layout(p, &lp);
    /* both balanced: the damped x mount, and the undamped y mount, whose
     * direction has the bushing's damping (a series spring capping it) */
    assert_int_equal(l.n, 2);
    assert_int_equal(l.nmount, 2);
    assert_int_equal(l.nfollow, 0);
    const double u[12] = {0.8, -0.4, 0.35, 0.004, -0.012, 0.02, 12, -7, 3, 0.4, -0.25, 0.6};
    double y[6], y0[6], xdot[2];
    eval(p, NULL, &lp, u, NULL, NULL, y0, NULL);
    /* where the fast states have settled: K s = -F */
    double x[2] = {-y0[0] / 1e12, -y0[1] / 1e12};
    eval(b, NULL, &l, u, x, xdot, y, NULL);
    printf("  mounts of 1e12 N/mm: force off the stateless one by %.2g (x) and %.2g (y)"
           " relative\n", fabs(y[0] / y0[0] - 1), fabs(y[1] / y0[1] - 1));
    for (int i = 0; i < 6; ++i)
        assert_close(y[i], y0[i], 1e-6, 1e-9);
    usrsub_bushing_free(b);

    /* a static load: mount 2000 N/mm in series with the bushing's 1000 N/mm: a
     * deflection of 3 mm puts 1 mm in the mount and 2 in the bushing, with
     * the mount's damping (time constant (2 + 50) / 3000 s) and without
     * (2 / 3000 s) */
    snprintf(body, sizeof body, mount_body, 2000.0, 50.0, 2000.0);
    b = bushing("soft_mount.gbs", body);
    usrsub_bushing_state_layout(b, &l);
    const double still[12] = {3.0, 3.0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    double s[2] = {0.0, 0.0};
    for (int k = 0; k < 200000; ++k) {
        eval(b, NULL, &l, still, s, xdot, y, NULL);
        s[0] += 1e-5 * xdot[0], s[1] += 1e-5 * xdot[1];
    }
    eval(b, NULL, &l, still, s, xdot, y, NULL);
    printf("  3 mm across mount (2000 N/mm) and bushing (1000): mounts %.9f and %.9f mm,"
           " forces %.6g and %.6g N\n", s[0], s[1], y[0], y[1]);
    for (int k = 0; k < 2; ++k) {
        assert_close(s[k], 1.0, 1e-9, 0);
        assert_close(y[k], -2000.0, 1e-9, 0);
    }
    usrsub_bushing_free(b);

    /* an undamped mount where the rubber's C0 is the direction's only rate
     * term: balanced; with C0 = 0 it follows */
    static const char rubber_mount[] =
        "[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
        "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 0 1 0 0 0 0\n"
        "'RUBBER_DAMPING' 0 1 0 0 0 0\n[CONSTANT_STIFFNESS_FY]\nK = 1000\n"
        "[RUBBER_DAMPING_FY]\nNPRELOADS = 1\n(PRELOAD_1)\nR = 30\nK0 = 400\nC0 = %g\n"
        "[MOUNT_STIFFNESS]\n{ direction K C }\nFY 2000 0\n";
    for (int damped = 0; damped < 2; ++damped) {
        snprintf(body, sizeof body, rubber_mount, damped ? 2.0 : 0.0);
        b = bushing(damped ? "rubber_mount.gbs" : "rubber_k_mount.gbs", body);
        usrsub_bushing_state_layout(b, &l);
        assert_int_equal(l.nmount, damped);
        assert_int_equal(l.nfollow, !damped);
        assert_int_equal(l.n, 1 + damped);
        const double ur[12] = {0, 0.4, 0, 0, 0, 0, 0, -3.0, 0, 0, 0, 0};
        const double xr[2] = {0.05, -0.02};
        const double worst = partials_error(b, NULL, ur, xr);
        assert_true(worst < 1e-6);
        usrsub_bushing_free(b);
    }

    /* a direction without rate terms: the undamped mount follows at once */
    b = bushing("elastic_mount.gbs",
                "[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
                "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 1 0 0 0 0 0\n"
                "[CONSTANT_STIFFNESS_FX]\nK = 1000\n"
                "[MOUNT_STIFFNESS]\n{ direction K C }\nFX 2000 0\n");
    usrsub_bushing_state_layout(b, &l);
    assert_int_equal(l.n, 0);
    assert_int_equal(l.nfollow, 1);
    eval(b, NULL, &l, still, NULL, NULL, y, NULL);
    assert_close(y[0], -2000.0, 1e-12, 0);
    usrsub_bushing_free(b);
    usrsub_bushing_free(p);
}

/* ---- the series mount against its closed form ----------------------------------------- */

/* The element's dynamic stiffness in direction k at frequency w, from its
 * state equation linearized with its own partials (checked against
 * differences above): deformation d_k e^{jwt} in, force on I out,
 * Z = -dy_k / dd_k. */
static double complex dynamic_stiffness(const usrsub_bushing *b, const usrsub_state_layout *l,
                                        int k, double w)
{
    const int n = l->n;
    const double u[12] = {0}, x[USRSUB_MAX_STATES] = {0};
    double xdot[USRSUB_MAX_STATES], y[6];
    usrsub_state_partials p;
    eval(b, NULL, l, u, x, xdot, y, &p);
    /* (jw I - A) dx = B du, du = e_k + jw e_{6+k}, by Gaussian elimination */
    double complex M[USRSUB_MAX_STATES][USRSUB_MAX_STATES + 1];
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j)
            M[i][j] = (i == j ? I * w : 0.0) - p.dxdot_dx[i + n * j];
        M[i][n] = p.dxdot_du[i + n * k] + I * w * p.dxdot_du[i + n * (6 + k)];
    }
    for (int c = 0; c < n; ++c) {
        int pivot = c;
        for (int r = c + 1; r < n; ++r)
            if (cabs(M[r][c]) > cabs(M[pivot][c]))
                pivot = r;
        for (int j = 0; j <= n; ++j) {
            const double complex t = M[c][j];
            M[c][j] = M[pivot][j], M[pivot][j] = t;
        }
        for (int r = 0; r < n; ++r)
            if (r != c) {
                const double complex f = M[r][c] / M[c][c];
                for (int j = c; j <= n; ++j)
                    M[r][j] -= f * M[c][j];
            }
    }
    double complex dy = p.dy_du[k + 6 * k] + I * w * p.dy_du[k + 6 * (6 + k)];
    for (int j = 0; j < n; ++j)
        dy += p.dy_dx[k + 6 * j] * M[j][n] / M[j][j];
    return -dy;
}

/* A bushing (k_b, c_b) in series with a mount (K, C) whose node carries J:
 * Z = Zb Zm / (Zb + Zm), Zb = k_b + jw c_b, Zm = K + jw C - J w^2. From 1 to
 * 1e5 rad/s: the damped mount, the undamped one (which caps the bushing's
 * damper at K), and the rotational one in series with friction (its node's
 * inertia K / 1e8 s^2; friction adds nothing at zero load and preload). */
static void the_series_mount_has_the_closed_form_stiffness(void **state)
{
    (void)state;
    usrsub_bushing *b = bushing("series.gbs",
        "[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
        "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 1 1 1 1 1 1\n"
        "'CONSTANT_DAMPING' 1 1 1 1 1 1\n"
        "[CONSTANT_STIFFNESS_FX]\nK = 1000\n[CONSTANT_STIFFNESS_FY]\nK = 1500\n"
        "[CONSTANT_STIFFNESS_FZ]\nK = 800\n[CONSTANT_STIFFNESS_TX]\nK = 4e5\n"
        "[CONSTANT_STIFFNESS_TY]\nK = 3e5\n[CONSTANT_STIFFNESS_TZ]\nK = 2e5\n"
        "[CONSTANT_DAMPING_FX]\nC = 2\n[CONSTANT_DAMPING_FY]\nC = 3\n[CONSTANT_DAMPING_FZ]\nC = 2\n"
        "[CONSTANT_DAMPING_TX]\nC = 20\n[CONSTANT_DAMPING_TY]\nC = 20\n[CONSTANT_DAMPING_TZ]\nC = 40\n"
        "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\nMU_DYNAMIC = 0.3\nTRANSITION_VELOCITY = 20\n"
        "BRISTLE_STIFFNESS = 100\nBRISTLE_DAMPING = 0.02\nBALL_RADIUS = 10\n"
        "[MOUNT_STIFFNESS]\n{ direction K C }\nFX 8000 0.5\nFY 8000 0\nTZ 3e5 10\n");
    usrsub_state_layout l;
    usrsub_bushing_state_layout(b, &l);
    assert_int_equal(l.nmount, 2);
    assert_int_equal(l.ninertial, 1);
    assert_int_equal(l.n, 3 + 2 + 2);
    static const struct {
        int k;
        double kb, cb, K, C, J;
        const char *name;
    } cases[3] = {{0, 1000, 2, 8000, 0.5, 0, "x, damped mount"},
                  {1, 1500, 3, 8000, 0, 0, "y, undamped mount"},
                  {5, 2e5, 40, 3e5, 10, 3e5 / 1e8, "tz, with friction"}};
    for (int c = 0; c < 3; ++c) {
        double worst = 0.0, high = 0.0;
        for (int e = 0; e <= 20; ++e) {
            const double w = pow(10.0, e / 4.0);
            const double complex Zb = cases[c].kb + I * w * cases[c].cb;
            const double complex Zm = cases[c].K + I * w * cases[c].C - cases[c].J * w * w;
            const double complex expected = Zb * Zm / (Zb + Zm);
            const double complex got = dynamic_stiffness(b, &l, cases[c].k, w);
            worst = fmax(worst, cabs(got - expected) / cabs(expected));
            high = cabs(got);
        }
        printf("  %-18s: dynamic stiffness off its closed form by %.2g from 1 to 1e5 rad/s;"
               " |Z(1e5)| %.6g (mount K %g)\n", cases[c].name, worst, high, cases[c].K);
        assert_true(worst < 1e-9);
    }
    /* the undamped mount caps the damper: at 1e5 rad/s the bushing alone
     * would be |1500 + 3e5 j| = 3e5 N/mm; in series with 8000 it stays below */
    assert_true(cabs(dynamic_stiffness(b, &l, 1, 1e5)) < 8000.0);
    usrsub_bushing_free(b);
}

/* ---- a rotational mount in series with friction: one answer ------------------------- */

/* The bushing of docs/sources.md §3.8's audit, written in a length unit of L mm (1:
 * mm, 1000: m): friction with the bristle damping that fades, a damped mount
 * about z of 2e5 N mm/rad and 10 N mm s/rad, a damped x mount. */
static usrsub_bushing *friction_mount_bushing(const char *name, double L, const double *model)
{
    char text[8192];
    snprintf(text, sizeof text,
             "[HEADER]\nFILE_TYPE = 'gbs'\n[UNITS]\nLENGTH = '%s'\nANGLE = 'radian'\n"
             "FORCE = 'newton'\nMASS = 'kg'\nTIME = 'second'\n"
             "[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
             "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 1 1 1 1 1 1\n"
             "'CONSTANT_DAMPING' 1 1 1 1 1 1\n"
             "[CONSTANT_STIFFNESS_FX]\nK = %.17g\n[CONSTANT_STIFFNESS_FY]\nK = %.17g\n"
             "[CONSTANT_STIFFNESS_FZ]\nK = %.17g\n[CONSTANT_STIFFNESS_TX]\nK = %.17g\n"
             "[CONSTANT_STIFFNESS_TY]\nK = %.17g\n[CONSTANT_STIFFNESS_TZ]\nK = %.17g\n"
             "[CONSTANT_DAMPING_FX]\nC = %.17g\n[CONSTANT_DAMPING_FY]\nC = %.17g\n"
             "[CONSTANT_DAMPING_FZ]\nC = %.17g\n[CONSTANT_DAMPING_TX]\nC = %.17g\n"
             "[CONSTANT_DAMPING_TY]\nC = %.17g\n[CONSTANT_DAMPING_TZ]\nC = %.17g\n"
             "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\nMU_DYNAMIC = 0.3\n"
             "TRANSITION_VELOCITY = %.17g\nBRISTLE_STIFFNESS = %.17g\nBRISTLE_DAMPING = %.17g\n"
             "SLIP_DAMPING = %.17g\nBALL_RADIUS = %.17g\nPRELOAD_TORQUE = %.17g\n"
             "[MOUNT_STIFFNESS]\n{ direction K C }\nFX %.17g %.17g\nTZ %.17g %.17g\n",
             L == 1.0 ? "mm" : "meter", 1000 * L, 1000 * L, 1000 * L, 1e5 / L, 1e5 / L, 1e5 / L,
             2 * L, 2 * L, 2 * L, 5 / L, 5 / L, 5 / L, 20 / L, 100 * L, 0.5 * L, 0.001 * L, 10 / L,
             500 / L, 8000 * L, 4 * L, 2e5 / L, 10 / L);
    return read_bushing(name, text, model);
}

/* At random states (the bristles within mu_s / sigma0, mount deflections and
 * rates, loads and slips of every direction), the rates do not jump when an
 * unrelated state (the x mount's deflection) moves by 1e-10 mm, and the file
 * written in metres gives the millimetre file's rates. */
static void a_rotational_mount_with_friction_has_one_answer(void **state)
{
    (void)state;
    const double model[USRSUB_UNIT_COUNT] = {1e-3, 1.0, 1.0, 1.0, 1.0}; /* mm N kg s rad */
    usrsub_bushing *mm = friction_mount_bushing("one_answer_mm.gbs", 1.0, model);
    usrsub_bushing *m = friction_mount_bushing("one_answer_m.gbs", 1000.0, model);
    usrsub_state_layout l, lm;
    usrsub_bushing_state_layout(mm, &l);
    usrsub_bushing_state_layout(m, &lm);
    assert_int_equal(l.ninertial, 1);
    assert_int_equal(l.n, 3 + 1 + 2); /* bristles, the x mount, the z mount's s and sdot */
    assert_int_equal(lm.n, l.n);
    static const double scale[6] = {0.005, 0.005, 0.005, 0.02, 0.01, 1.0};
    unsigned seed = 2026;
    double jump = 0.0, units = 0.0;
    for (int t = 0; t < 600; ++t) {
        double u[12], x[USRSUB_MAX_STATES];
        for (int i = 0; i < 12; ++i) {
            seed = seed * 1664525u + 1013904223u;
            const double r = (seed >> 8) / 8388608.0 - 1.0;
            u[i] = r * (i < 3 ? 1.0 : i < 6 ? 0.02 : i < 9 ? 20.0 : 2.0);
        }
        for (int i = 0; i < l.n; ++i) {
            seed = seed * 1664525u + 1013904223u;
            x[i] = ((seed >> 8) / 8388608.0 - 1.0) * scale[i];
        }
        double xdot[USRSUB_MAX_STATES], y[6], moved[USRSUB_MAX_STATES], ym[6];
        double other[USRSUB_MAX_STATES], yo[6];
        eval(mm, NULL, &l, u, x, xdot, y, NULL);
        x[3] += 1e-10;
        eval(mm, NULL, &l, u, x, moved, ym, NULL);
        x[3] -= 1e-10;
        eval(m, NULL, &lm, u, x, other, yo, NULL);
        for (int i = 0; i < l.n; ++i) {
            const double size = fabs(xdot[i]) + 1e-6;
            jump = fmax(jump, fabs(moved[i] - xdot[i]) / size);
            units = fmax(units, fabs(other[i] - xdot[i]) / size);
        }
        for (int i = 0; i < 6; ++i)
            units = fmax(units, fabs(yo[i] - y[i]) / (fabs(y[i]) + 1e-6));
    }
    printf("  600 random states: rates moved by %.2g (relative) for an x mount moved by"
           " 1e-10 mm; the file in metres off the one in mm by %.2g\n", jump, units);
    assert_true(jump < 1e-4);
    assert_true(units < 1e-9);
    /* the node's frequency is 1e4 rad/s in any time unit: J = K / 1e8 s^2 in a
     * model in seconds, K / 100 ms^2 in one in milliseconds */
    const double model_ms[USRSUB_UNIT_COUNT] = {1e-3, 1.0, 1.0, 1e-3, 1.0};
    usrsub_bushing *ms = friction_mount_bushing("one_answer_ms.gbs", 1.0, model_ms);
    assert_close(mm->dir[5].mount_inertia, 2e5 / 1e8, 1e-12, 0);
    assert_close(ms->dir[5].mount_inertia, 2e5 / 100.0, 1e-12, 0);
    usrsub_bushing_free(ms);
    usrsub_bushing_free(mm);
    usrsub_bushing_free(m);
}

/* ---- the rubber filter ---------------------------------------------------------------- */

static void the_rubber_filter_is_a_high_pass(void **state)
{
    (void)state;
    usrsub_bushing *b = base_bushing("filter.gbs", 1, "");
    usrsub_state_layout l;
    usrsub_bushing_state_layout(b, &l);
    assert_int_equal(l.n, 2); /* FZ (R = 30) and TZ (R = max(5, RMIN 12)) */
    assert_int_equal(l.rubber[0], 2);
    const double R = 30.0, w = 40.0, A = 0.2, h = 1e-5;
    double x[2] = {0, 0}, xdot[2], y[6], peak = 0.0, peak_time = 0.0;
    const double period = 2 * M_PI / w;
    for (double t = 0.0; t < 20 * period; t += h) {
        /* RK2 on the filter state, driven by X = A sin(w t) along z */
        double u[12] = {0, 0, A * sin(w * t), 0, 0, 0, 0, 0, A * w * cos(w * t), 0, 0, 0};
        eval(b, NULL, &l, u, x, xdot, y, NULL);
        double mid[2] = {x[0] + 0.5 * h * xdot[0], x[1] + 0.5 * h * xdot[1]};
        u[2] = A * sin(w * (t + 0.5 * h)), u[8] = A * w * cos(w * (t + 0.5 * h));
        eval(b, NULL, &l, u, mid, xdot, y, NULL);
        x[0] += h * xdot[0], x[1] += h * xdot[1];
        if (t > 19 * period && x[0] > peak)
            peak = x[0], peak_time = t + h;
    }
    const double gain = w / sqrt(R * R + w * w), lead = atan(R / w);
    /* X peaks at w t = pi/2 (mod 2 pi); x peaks lead earlier */
    double phase = fmod(M_PI / 2 - w * peak_time, 2 * M_PI);
    if (phase < -M_PI)
        phase += 2 * M_PI;
    printf("  rubber filter at w = %g, R = %g: gain %.6f (expected %.6f), lead %.5f rad"
           " (expected %.5f)\n", w, R, peak / A, gain, phase, lead);
    assert_close(peak / A, gain, 1e-4, 0);
    assert_close(phase, lead, 0, 2e-3);
    usrsub_bushing_free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(without_states_it_is_the_fiesub_force),
        cmocka_unit_test(every_partial_against_differences),
        cmocka_unit_test(friction_partials_in_every_branch),
        cmocka_unit_test(the_mounts_balance_is_solved_everywhere),
        cmocka_unit_test(friction_sticks_slips_and_floors),
        cmocka_unit_test(a_mount_splits_the_deflection),
        cmocka_unit_test(the_series_mount_has_the_closed_form_stiffness),
        cmocka_unit_test(a_rotational_mount_with_friction_has_one_answer),
        cmocka_unit_test(the_rubber_filter_is_a_high_pass),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
