/*
 * The bushing examples: the seed's three coupling examples driven by the rig
 * (FIESUB and GFOSUB forms), a 100 kg body on four linear bushings oscillating
 * at its analytic natural frequency, and check on every bushing example.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sim_support.h"
#include "test_support.h"

/* rig CSV columns */
enum { T = 0, X = 1, Y = 2, FX = 13, FY = 14, RESIDUAL = 25 };
#define OMEGA "6.283185307179586"

static void rig(const char *csv_name, const char *const *args, csv_table *t)
{
    char csv[512];
    snprintf(csv, sizeof csv, "%s/%s", test_temp_dir(), csv_name);
    assert_int_equal(sim_rig("bushing_coupling.xml", csv, args), 0);
    csv_read(csv, t);
    assert_true(t->rows > 100);
}

static void example_one_rotating_deflection(void **state)
{
    (void)state;
    for (int form = 0; form < 2; ++form) {
        csv_table coupled, uncoupled;
        const char *c_args[] = {"--element", form ? "11" : "1", "--circle", "5," OMEGA, "--end", "1",
                                "--step", "0.005", NULL};
        const char *u_args[] = {"--element", form ? "12" : "2", "--circle", "5," OMEGA, "--end", "1",
                                "--step", "0.005", NULL};
        rig("ex1_coupled.csv", c_args, &coupled);
        rig("ex1_uncoupled.csv", u_args, &uncoupled);
        double umin = 1e300, umax = 0.0;
        for (int r = 0; r < coupled.rows; ++r) {
            /* coupled: |F| = g(5) = 625 all the way round, so Fy against Fx is a circle */
            assert_close(hypot(csv_at(&coupled, r, FX), csv_at(&coupled, r, FY)), 625.0, 1e-12, 0);
            const double fu = hypot(csv_at(&uncoupled, r, FX), csv_at(&uncoupled, r, FY));
            umin = fmin(umin, fu), umax = fmax(umax, fu);
        }
        /* uncoupled: 625 on the axes, down to 562.5 at 45 degrees (t = 0.125) */
        assert_close(umax, 625.0, 1e-12, 0);
        assert_close(umin, 562.5, 1e-12, 0);
        assert_close(hypot(csv_at(&uncoupled, 25, FX), csv_at(&uncoupled, 25, FY)), 562.5, 1e-12, 0);
        csv_free(&coupled);
        csv_free(&uncoupled);
    }
}

static void example_two_rotating_force(void **state)
{
    (void)state;
    /* the radius that balances 125: r^3 + 100 r = 125 */
    double r = 1.2;
    for (int k = 0; k < 50; ++k)
        r -= (r * r * r + 100 * r - 125) / (3 * r * r + 100);
    printf("root of r^3 + 100 r = 125: %.10f\n", r);
    for (int form = 0; form < 2; ++form) {
        csv_table t;
        const char *args[] = {"--element", form ? "11" : "1", "--force-circle", "125," OMEGA,
                              "--end", "1", "--step", "0.005", NULL};
        rig("ex2.csv", args, &t);
        for (int row = 0; row < t.rows; ++row) {
            assert_close(hypot(csv_at(&t, row, X), csv_at(&t, row, Y)), r, 1e-10, 0);
            assert_true(csv_at(&t, row, RESIDUAL) < 1e-8);
        }
        assert_close(r, 1.2313309, 0, 1e-7);
        csv_free(&t);
    }
}

static void example_three_anisotropic(void **state)
{
    (void)state;
    csv_table t;
    const char *args[] = {"--element", "3", "--force-circle", "125," OMEGA, "--end", "1",
                          "--step", "0.002", NULL};
    rig("ex3.csv", args, &t);
    double rmin = 1e300, rmax = 0.0, max_turn = 0.0;
    for (int row = 0; row < t.rows; ++row) {
        const double r = hypot(csv_at(&t, row, X), csv_at(&t, row, Y));
        rmin = fmin(rmin, r), rmax = fmax(rmax, r);
        if (row >= 2) { /* smooth: the path turns little between samples */
            const double ax = csv_at(&t, row - 1, X) - csv_at(&t, row - 2, X);
            const double ay = csv_at(&t, row - 1, Y) - csv_at(&t, row - 2, Y);
            const double bx = csv_at(&t, row, X) - csv_at(&t, row - 1, X);
            const double by = csv_at(&t, row, Y) - csv_at(&t, row - 1, Y);
            max_turn = fmax(max_turn, fabs(atan2(ax * by - ay * bx, ax * bx + ay * by)));
        }
    }
    const int last = t.rows - 1;
    assert_close(csv_at(&t, last, X), csv_at(&t, 0, X), 0, 1e-9); /* closed */
    assert_close(csv_at(&t, last, Y), csv_at(&t, 0, Y), 0, 1e-9);
    assert_true(rmax / rmin > 1.5);                                /* not a circle */
    assert_true(max_turn < 0.1);                                   /* smooth */
    printf("anisotropic bushing: radius from %.6f to %.6f, largest turn %.3g rad per sample\n",
           rmin, rmax, max_turn);
    csv_free(&t);
}

static void body_on_four_bushings_natural_frequency(void **state)
{
    (void)state;
    sim s;
    sim_run(&s, "bushing_mount.xml", HX_METHOD_RK4, 1e-4, 1.0, 1e-4);
    const int z = s.dynamics.dof[1].q + 2; /* body 2 is the second body */
    /* minima of z, located by a parabola through three samples */
    double first = -1.0, last = -1.0;
    int count = 0;
    for (int r = 1; r + 1 < s.path.rows; ++r) {
        const double a = sim_state(&s, r - 1, z), b = sim_state(&s, r, z), c = sim_state(&s, r + 1, z);
        if (b < a && b <= c) {
            const double offset = 0.5 * (a - c) / (a - 2 * b + c);
            const double t = s.path.t[r] + offset * 1e-4;
            if (first < 0.0)
                first = t;
            last = t;
            ++count;
        }
    }
    const double period = (last - first) / (count - 1);
    const double omega = sqrt(4.0 * 100.0 * 1000.0 / 100.0); /* sqrt(4 k ucf / m) */
    printf("100 kg on four bushings: period %.7f s, analytic %.7f s (%d periods)\n", period,
           2 * M_PI / omega, count - 1);
    assert_true(count >= 9);
    assert_close(period, 2 * M_PI / omega, 1e-3, 0);
    /* a conservative run: energy kept to the integrator's accuracy */
    assert_true(s.result.energy_error_max < 1e-6 * s.result.energy_scale);
    sim_close(&s);
}

static void check_passes_on_every_bushing_example(void **state)
{
    (void)state;
    assert_int_equal(sim_check("bushing_coupling.xml"), 0);
    assert_int_equal(sim_check("bench_bushing.xml"), 0);
    assert_int_equal(sim_check("bushing_mount.xml"), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(example_one_rotating_deflection),
        cmocka_unit_test(example_two_rotating_force),
        cmocka_unit_test(example_three_anisotropic),
        cmocka_unit_test(body_on_four_bushings_natural_frequency),
        cmocka_unit_test(check_passes_on_every_bushing_example),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
