/*
 * Static equilibrium (sim/simulation/equilibrium.h; docs/harness.md, static
 * equilibrium): models whose equilibria are worked by hand, each started away
 * from it: a mass on a vertical spring, a pendulum at 60 degrees on a
 * reduced REVOLUTE and on a SPHERICAL (rows), one started above the
 * horizontal, two masses hung in a chain of springs, a bar on a torsion
 * spring against gravity, a pendulum on a stiff spring not yet loaded (a
 * direction of no stiffness at the start); the refusals (a falling part named, no
 * convergence); SIMULATE/STATIC in a command file and run --static (the
 * equilibrium the CSV's first row, the dynamic run after it at rest).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim/simulation/equilibrium.h"
#include "sim_support.h"
#include "test_support.h"

/* SI units, gravity -9.81 along y; the parts after it. */
#define HEAD                                                                                    \
    "equilibrium test\nUNITS/\n, FORCE = NEWTON\n, MASS = KILOGRAM\n, LENGTH = METER\n"          \
    ", TIME = SECOND\nACCGRAV/\n, IGRAV = 0\n, JGRAV = -9.81\n, KGRAV = 0\n"                     \
    "PART/1, GROUND\nMARKER/10, PART = 1\n"

/* m = 2 kg on a spring of k = 400 N/m and free length 1 m from the ground's
 * origin, started at its free length: it settles m g / k = 19.62 / 400 =
 * 0.04905 m lower, at y = -1.04905. */
static const char spring[] = HEAD
    "PART/2, MASS = 2, CM = 20, IP = 0.1, 0.1, 0.1\n"
    "MARKER/20, PART = 2, QP = 0, -1, 0\n"
    "SFORCE/1, TRANSLATION, I = 20, J = 10, FUNCTION = -400*(DM(20,10) - 1)\n"
    "END\n";

/* A pendulum of 1 kg, its centre 0.5 m from the pivot at the origin,
 * started at 60 degrees (or 120: cm y = +0.25) from hanging. */
static const char *pendulum(const char *joint, int above)
{
    static char text[1024];
    snprintf(text, sizeof text, HEAD
             "PART/2, MASS = 1, CM = 20, IP = 0.01, 0.02, 0.03\n"
             "MARKER/20, PART = 2, QP = 0.4330127018922193, %s, 0\n"
             "MARKER/21, PART = 2\n"
             "JOINT/1, %s, I = 21, J = 10\n"
             "END\n", above ? "0.25" : "-0.25", joint);
    return text;
}

/* Two masses in a chain of springs: PART/2 (2 kg) on k1 = 300 N/m of free
 * length 1 from the origin, PART/3 (1 kg) on k2 = 200 N/m of free length 0.8
 * from PART/2, started aside (x 0.3, z 0.1). Hanging straight: spring 1
 * carries both weights, 3 * 9.81 = 29.43 N, stretched 29.43 / 300 = 0.0981:
 * y2 = -1.0981; spring 2 the lower one's, 9.81 / 200 = 0.04905: y3 = y2 -
 * 0.84905 = -1.94715; x = z = 0. */
static const char chain[] = HEAD
    "PART/2, MASS = 2, CM = 20, IP = 0.1, 0.1, 0.1\n"
    "MARKER/20, PART = 2, QP = 0, -1, 0\n"
    "PART/3, MASS = 1, CM = 30, IP = 0.1, 0.1, 0.1\n"
    "MARKER/30, PART = 3, QP = 0.3, -1.8, 0.1\n"
    "SFORCE/1, TRANSLATION, I = 20, J = 10, FUNCTION = -300*(DM(20,10) - 1)\n"
    "SFORCE/2, TRANSLATION, I = 30, J = 20, FUNCTION = -200*(DM(30,20) - 0.8)\n"
    "END\n";

/* A bar of 1 kg and length L = 1 hinged at its end to ground (reduced
 * REVOLUTE about z), horizontal along x at the spring's free angle, on a
 * torsion spring k = 10 N m/rad. It sags by phi (AZ = -phi) where the
 * spring's torque k phi meets gravity's m g L/2 cos phi = 4.905 cos phi:
 * f(phi) = 10 phi - 4.905 cos phi, f' = 10 + 4.905 sin phi; Newton from 0.4:
 *   f(0.4) = 4 - 4.905 * 0.921061 = -0.517804, f' = 11.910097: phi = 0.443476
 *   f = 4.434761 - 4.905 * 0.903266 = 0.004243, f' = 12.104647: phi = 0.4431256
 *   f = 2.7e-7, f' = 12.103093: phi = 0.44312552849 (cos phi = 0.903416). */
static const char torsion[] = HEAD
    "PART/2, MASS = 1, CM = 20, IP = 0.01, 0.08, 0.08\n"
    "MARKER/20, PART = 2, QP = 0.5, 0, 0\n"
    "MARKER/21, PART = 2\n"
    "JOINT/1, REVOLUTE, I = 21, J = 10\n"
    "SFORCE/1, ROTATION, I = 21, J = 10, FUNCTION = -10*AZ(21,10)\n"
    "END\n";

typedef struct solved {
    hx_session s;
    hx_dynamics d;
    hx_dynamics_data dd;
    double y[64];
    hx_equilibrium_result result;
    int status;
    hx_message msg;
} solved;

/* The model's initial state (assembled) moved to its equilibrium. */
static void solve(solved *o, const char *name, const char *text)
{
    memset(o, 0, sizeof *o);
    hx_message msg;
    if (hx_session_open(&o->s, test_write_file(name, text), stderr, &msg) != 0 ||
        hx_dynamics_init(&o->d, &o->s, &msg) != 0 ||
        hx_dynamics_data_init(&o->dd, &o->d, &msg) != 0)
        fail_msg("%s", msg.text);
    assert_true(o->d.n <= 64);
    assert_int_equal(hx_dynamics_initial_state(&o->d, &o->dd, o->y), 0);
    o->status = hx_equilibrium_solve(&o->d, &o->dd, NULL, 0.0, o->y, &o->result, &o->msg);
}

static void done(solved *o)
{
    hx_dynamics_data_free(&o->dd);
    hx_dynamics_free(&o->d);
    hx_session_close(&o->s);
}

/* The centre of part `index` (its position in the model's parts). */
static const double *centre(const solved *o, int index)
{
    assert_int_equal(o->d.dof[index].kind, HX_DOF_FREE);
    return o->y + o->d.dof[index].q;
}

static void converged(const solved *o)
{
    if (o->status != 0)
        fail_msg("%s", o->msg.text);
    assert_true(o->result.iterations >= 1); /* it started away from the equilibrium */
    assert_true(o->result.residual <= HX_EQUILIBRIUM_TOLERANCE);
    for (int k = 0; k < o->d.nu; ++k) /* at rest */
        assert_true(o->y[o->d.nq + k] == 0.0);
}

static void mass_on_a_spring_settles_m_g_over_k_below(void **state)
{
    (void)state;
    solved o;
    solve(&o, "eq_spring.adm", spring);
    converged(&o);
    const double *p = centre(&o, 1);
    assert_float_equal(p[1], -1.04905, 1e-12);
    assert_true(o.result.iterations <= 2); /* linear: one Newton step (one more: rounding) */
    assert_float_equal(p[0], 0.0, 1e-12);
    assert_float_equal(p[2], 0.0, 1e-12);
    done(&o);
}

/* The same in mm (ucf 1000, the model's length 1000 mm, a turn's 1): k = 0.4
 * N/mm settles 19.62 / 0.4 = 49.05 mm lower, at y = -1049.05 mm. */
static const char spring_mm[] =
    "equilibrium test\nUNITS/\n, FORCE = NEWTON\n, MASS = KILOGRAM\n, LENGTH = MILLIMETER\n"
    ", TIME = SECOND\nACCGRAV/\n, IGRAV = 0\n, JGRAV = -9810\n, KGRAV = 0\n"
    "PART/1, GROUND\nMARKER/10, PART = 1\n"
    "PART/2, MASS = 2, CM = 20, IP = 100, 100, 100\n"
    "MARKER/20, PART = 2, QP = 0, -1000, 0\n"
    "SFORCE/1, TRANSLATION, I = 20, J = 10, FUNCTION = -0.4*(DM(20,10) - 1000)\n"
    "END\n";

static void mass_on_a_spring_in_mm(void **state)
{
    (void)state;
    solved o;
    solve(&o, "eq_spring_mm.adm", spring_mm);
    converged(&o);
    const double *p = centre(&o, 1);
    assert_float_equal(p[1], -1049.05, 1e-9);
    assert_float_equal(p[0], 0.0, 1e-9);
    assert_true(o.result.iterations <= 2); /* the step in mm, not in the system's units */
    assert_float_equal(o.result.force_scale, 19.62, 1e-12); /* the weight, in N */
    done(&o);
}

static void pendulum_hangs_down(void **state)
{
    (void)state;
    for (int above = 0; above <= 1; ++above) {
        /* reduced: the joint coordinate turns by -60 (or -120) degrees */
        solved o;
        solve(&o, "eq_revolute.adm", pendulum("REVOLUTE", above));
        converged(&o);
        assert_int_equal(o.d.dof[1].kind, HX_DOF_REVOLUTE);
        assert_float_equal(o.y[o.d.dof[1].q], (above ? -2.0 : -1.0) * M_PI / 3.0, 1e-10);
        done(&o);
        /* rows: a free part held by the SPHERICAL's three, its centre under the pivot */
        solve(&o, "eq_spherical.adm", pendulum("SPHERICAL", above));
        converged(&o);
        assert_int_equal(o.d.nrows, 3);
        const double *p = centre(&o, 1);
        assert_float_equal(p[0], 0.0, 1e-10);
        assert_float_equal(p[1], -0.5, 1e-10);
        assert_float_equal(p[2], 0.0, 1e-10);
        done(&o);
    }
}

static void chain_of_springs_hangs_straight(void **state)
{
    (void)state;
    solved o;
    solve(&o, "eq_chain.adm", chain);
    converged(&o);
    const double *p2 = centre(&o, 1), *p3 = centre(&o, 2);
    assert_float_equal(p2[1], -1.0981, 1e-10);
    assert_float_equal(p3[1], -1.94715, 1e-10);
    for (int c = 0; c < 3; c += 2) {
        assert_float_equal(p2[c], 0.0, 1e-10);
        assert_float_equal(p3[c], 0.0, 1e-10);
    }
    done(&o);
}

static void torsion_spring_against_gravity(void **state)
{
    (void)state;
    solved o;
    solve(&o, "eq_torsion.adm", torsion);
    converged(&o);
    assert_float_equal(o.y[o.d.dof[1].q], -0.44312552849, 1e-10);
    done(&o);
}

/* The pendulum hung on a stiff spring at its pivot (k = 1e7 N/m each way, a
 * VFORCE), started hanging with the spring unloaded: at the start its turn
 * about the pivot has no stiffness at all (the spring's pull on the moved
 * pivot and its moment about the centre cancel; gravity's share comes with
 * the load), the Newton matrix singular but for R. It sags m g / k =
 * 9.81e-7 and does not turn. */
static void pendulum_on_a_stiff_unloaded_spring(void **state)
{
    (void)state;
    solved o;
    solve(&o, "eq_stiff.adm", HEAD
          "MARKER/11, PART = 1\n"
          "PART/2, MASS = 1, CM = 20, IP = 0.01, 0.02, 0.03\n"
          "MARKER/20, PART = 2, QP = 0, -0.5, 0\n"
          "MARKER/21, PART = 2\n"
          "VFORCE/1, I = 21, JFLOAT = 11, RM = 10, FX = -1E7*DX(21,10)\\"
          "FY = -1E7*DY(21,10)\\FZ = -1E7*DZ(21,10)\n"
          "END\n");
    converged(&o);
    const double *p = centre(&o, 1);
    assert_float_equal(p[1], -0.5 - 9.81e-7, 1e-13);
    assert_float_equal(p[0], 0.0, 1e-13);
    assert_float_equal(p[3], 1.0, 1e-12); /* not turned */
    done(&o);
}

static void a_falling_part_is_refused_by_name(void **state)
{
    (void)state;
    /* the chain without its lower spring: PART/2 hangs, PART/3 falls */
    char text[2048];
    snprintf(text, sizeof text, "%s", chain);
    char *second = strstr(text, "SFORCE/2");
    assert_non_null(second);
    strcpy(second, "END\n");
    solved o;
    solve(&o, "eq_falling.adm", text);
    assert_int_equal(o.status, -1);
    assert_contains(o.msg.text, "no static equilibrium: nothing holds PART/3 against its load",
                    "unbalanced force 9.81");
    done(&o);
}

static void no_convergence_names_the_part(void **state)
{
    (void)state;
    /* the spring pulls 5 to 15 N up, the weight is 19.62 N down: no equilibrium, and
     * the pull's slope (50 cos(10 DM)) is no zero direction to tell it by */
    char text[2048];
    snprintf(text, sizeof text, "%s", spring);
    char *law = strstr(text, "FUNCTION = ");
    assert_non_null(law);
    strcpy(law, "FUNCTION = -(10 + 5*SIN(10*DM(20,10)))\nEND\n");
    solved o;
    solve(&o, "eq_wobble.adm", text);
    assert_int_equal(o.status, -1);
    char expected[128];
    snprintf(expected, sizeof expected, "no static equilibrium found in %d Newton iterations",
             HX_EQUILIBRIUM_ITERATIONS);
    assert_contains(o.msg.text, expected, "the largest on PART/2 (force ");
    done(&o);
}

/* The values of column `name` of a CSV, rows of them. */
static void column_values(const char *csv, const char *name, const csv_table *t, double *out)
{
    const int c = csv_column(csv, name);
    assert_true(c >= 0);
    for (int r = 0; r < t->rows; ++r)
        out[r] = csv_at(t, r, c);
}

static void command_file_static_then_dynamic_stays_at_rest(void **state)
{
    (void)state;
    /* the SPHERICAL pendulum at 60 degrees, its command file beside it */
    test_write_file("eq_acf.acf", "eq_acf\n\nSIMULATE/STATIC\n"
                                  "SIMULATE/DYNAMIC, END=0.5, STEPS=10\nSTOP\n");
    const char *model = test_write_file("eq_acf.adm", pendulum("SPHERICAL", 0));
    char csv[512];
    snprintf(csv, sizeof csv, "%s/eq_acf.csv", test_temp_dir());
    assert_int_equal(sim_run_csv(model, csv, (const char *const[]){"--quiet", NULL}), 0);
    csv_table t;
    csv_read(csv, &t);
    assert_int_equal(t.rows, 11);
    double v[16];
    column_values(csv, "body2.y", &t, v);
    for (int r = 0; r < t.rows; ++r) /* the first row the equilibrium, the rest at it */
        assert_float_equal(v[r], -0.5, 1e-10);
    const char *speeds[] = {"body2.vx", "body2.vy", "body2.vz", "body2.wx", "body2.wy", "body2.wz"};
    for (int k = 0; k < 6; ++k) {
        column_values(csv, speeds[k], &t, v);
        for (int r = 0; r < t.rows; ++r)
            assert_true(fabs(v[r]) < 1e-9);
    }
    csv_free(&t);
    /* a SIMULATE/STATIC between segments: its row at the time reached, after the row
     * that ended the segment before */
    test_write_file("eq_acf.acf", "eq_acf\n\nSIMULATE/DYNAMIC, END=0.2, STEPS=2\n"
                                  "SIMULATE/STATIC\nSIMULATE/DYNAMIC, END=0.4, STEPS=2\n");
    assert_int_equal(sim_run_csv(model, csv, (const char *const[]){"--quiet", NULL}), 0);
    csv_read(csv, &t);
    assert_int_equal(t.rows, 6);
    double time[8], x[8];
    column_values(csv, "t", &t, time);
    column_values(csv, "body2.x", &t, x);
    assert_float_equal(time[2], 0.2, 1e-12);
    assert_float_equal(time[3], 0.2, 1e-12);
    assert_true(x[2] > 0.1);                 /* swinging: still well aside at 0.2 s */
    assert_float_equal(x[3], 0.0, 1e-10);    /* the equilibrium */
    assert_float_equal(x[5], 0.0, 1e-9);
    csv_free(&t);
    /* a SIMULATE/STATIC last: the run is that equilibrium alone, one row */
    test_write_file("eq_acf.acf", "eq_acf\n\nSIMULATE/STATIC\nSTOP\n");
    assert_int_equal(sim_run_csv(model, csv, (const char *const[]){"--quiet", NULL}), 0);
    csv_read(csv, &t);
    assert_int_equal(t.rows, 1);
    column_values(csv, "body2.x", &t, x);
    assert_float_equal(x[0], 0.0, 1e-10);
    csv_free(&t);
}

/* SIMULATE/STATIC, then ACCGRAV, then SIMULATE/DYNAMIC: the equilibrium is the one
 * under the gravity before the ACCGRAV (the spring's, y = -1.04905), and the dynamics
 * the new gravity's: with none, the spring (k = 400, m = 2: w = sqrt(200)) swings about
 * its free length, y = -1 - 0.04905 cos(w t); y(0.1) = -1.0076490. An ACCGRAV before the
 * STATIC: the equilibrium under the new gravity, 2 * 19.62 / 400 = 0.0981 below, at
 * -1.0981. */
static void static_then_accgrav_keeps_the_order_of_the_file(void **state)
{
    (void)state;
    const char *model = test_write_file("eq_grav.adm", spring);
    char csv[512];
    snprintf(csv, sizeof csv, "%s/eq_grav.csv", test_temp_dir());
    test_write_file("eq_grav.acf", "eq_grav\n\nSIMULATE/STATIC\nACCGRAV/JGRAV=0\n"
                                   "SIMULATE/DYNAMIC, END=0.5, STEPS=5\n");
    const char *const args[] = {"--quiet", "--rtol", "1e-10", "--atol", "1e-12", NULL};
    assert_int_equal(sim_run_csv(model, csv, args), 0);
    csv_table t;
    csv_read(csv, &t);
    assert_int_equal(t.rows, 6);
    double y[8];
    column_values(csv, "body2.y", &t, y);
    assert_float_equal(y[0], -1.04905, 1e-10);
    for (int r = 1; r < 6; ++r)
        assert_float_equal(y[r], -1.0 - 0.04905 * cos(sqrt(200.0) * 0.1 * r), 1e-8);
    csv_free(&t);
    test_write_file("eq_grav.acf", "eq_grav\n\nACCGRAV/JGRAV=-19.62\nSIMULATE/STATIC\n"
                                   "SIMULATE/DYNAMIC, END=0.2, STEPS=2\n");
    assert_int_equal(sim_run_csv(model, csv, args), 0);
    csv_read(csv, &t);
    assert_int_equal(t.rows, 3);
    column_values(csv, "body2.y", &t, y);
    for (int r = 0; r < 3; ++r)
        assert_float_equal(y[r], -1.0981, 1e-9);
    csv_free(&t);
}

/* A coupler on joints between moving bodies (differential_carrier.xml: its rows hold
 * 36 values, not 12) in the equilibrium's Newton system: driven by a torque and free to
 * turn, it has none, and says which part nothing holds. */
static void a_coupler_between_moving_bodies_in_the_equilibrium(void **state)
{
    (void)state;
    char csv[512];
    snprintf(csv, sizeof csv, "%s/eq_diff.csv", test_temp_dir());
    assert_int_not_equal(sim_run_csv("differential_carrier.xml", csv,
                                     (const char *const[]){"--static", "--quiet", "--end",
                                                           "0.1", NULL}),
                         0);
}

static void run_static_starts_from_the_equilibrium(void **state)
{
    (void)state;
    const char *model = test_write_file("eq_run.adm", spring);
    char csv[512];
    snprintf(csv, sizeof csv, "%s/eq_run.csv", test_temp_dir());
    assert_int_equal(sim_run_csv(model, csv, (const char *const[]){"--static", "--end", "0.5",
                                                                  "--quiet", NULL}), 0);
    csv_table t;
    csv_read(csv, &t);
    double y[1024], vy[1024];
    assert_true(t.rows > 2 && t.rows <= 1024);
    column_values(csv, "body2.y", &t, y);
    column_values(csv, "body2.vy", &t, vy);
    for (int r = 0; r < t.rows; ++r) {
        assert_float_equal(y[r], -1.04905, 1e-10);
        assert_true(fabs(vy[r]) < 1e-9);
    }
    csv_free(&t);
    /* without --static it oscillates about it from its free length */
    assert_int_equal(sim_run_csv(model, csv, (const char *const[]){"--end", "0.5", "--quiet",
                                                                  NULL}), 0);
    csv_read(csv, &t);
    column_values(csv, "body2.y", &t, y);
    assert_float_equal(y[0], -1.0, 1e-12);
    csv_free(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(mass_on_a_spring_settles_m_g_over_k_below),
        cmocka_unit_test(mass_on_a_spring_in_mm),
        cmocka_unit_test(pendulum_hangs_down),
        cmocka_unit_test(chain_of_springs_hangs_straight),
        cmocka_unit_test(torsion_spring_against_gravity),
        cmocka_unit_test(pendulum_on_a_stiff_unloaded_spring),
        cmocka_unit_test(a_falling_part_is_refused_by_name),
        cmocka_unit_test(no_convergence_names_the_part),
        cmocka_unit_test(command_file_static_then_dynamic_stays_at_rest),
        cmocka_unit_test(run_static_starts_from_the_equilibrium),
        cmocka_unit_test(static_then_accgrav_keeps_the_order_of_the_file),
        cmocka_unit_test(a_coupler_between_moving_bodies_in_the_equilibrium),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
