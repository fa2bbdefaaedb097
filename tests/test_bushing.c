/*
 * The bushing law (docs/interface.md §3.2, §3.3): each characteristic against hand
 * values, the cubic's fit conditions, the coupled force's signs on every
 * half-axis with rates, spherical isotropy, the seed's coupling numbers,
 * behaviour at r = 0, preload/offset/scale, and the 6x6 partials against
 * central differences.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bushing_support.h"
#include "test_support.h"

static double g_of(const usrsub_bushing *b, int k, double q)
{
    double slope;
    return usrsub_characteristic(&b->dir[k], q, &slope);
}

static void constant_characteristic(void **state)
{
    (void)state;
    usrsub_bushing b;
    bushing_init(&b, USRSUB_UNCOUPLED);
    bushing_constant(&b, 2, 800.0);
    double slope;
    assert_close(usrsub_characteristic(&b.dir[2], 0.5, &slope), 400.0, 0, 0);
    assert_close(slope, 800.0, 0, 0);
}

static void spline_characteristic(void **state)
{
    (void)state;
    const double x[] = {-4, -2, 0, 2, 4}, y[] = {-9200, -3000, 0, 3000, 9200};
    usrsub_bushing b;
    bushing_init(&b, USRSUB_UNCOUPLED);
    bushing_spline(&b, 0, 5, x, y);
    for (int i = 0; i < 5; ++i)
        assert_close(g_of(&b, 0, x[i]), y[i], 0, 1e-10);
    /* odd data: the curve is odd; linear beyond the table with the end slope */
    assert_close(g_of(&b, 0, -1.3), -g_of(&b, 0, 1.3), 0, 1e-10);
    double s4;
    const double v4 = usrsub_characteristic(&b.dir[0], 4.0, &s4);
    assert_close(g_of(&b, 0, 6.0), v4 + 2.0 * s4, 1e-14, 0);
    bushing_release(&b);
}

static void cubic_characteristic_fit(void **state)
{
    (void)state;
    /* the vendor documentation's example points */
    usrsub_cubic_characteristic c = {.en = -0.2, .ens = 2e5, .rn = -0.1, .rnf = -3e4, .o = 0,
                                     .of = 0, .os = 2e4, .rp = 0.1, .rpf = 3e4, .ep = 0.2,
                                     .eps = 2e5};
    usrsub_message msg;
    assert_int_equal(usrsub_cubic_fit(&c, &msg), 0);
    assert_close(c.c2p, 3.975e6, 1e-12, 0);
    assert_close(c.c3p, -1.175e7, 1e-12, 0);
    assert_close(c.c2n, -3.975e6, 1e-12, 0);
    usrsub_bushing_direction d = {.stiffness = USRSUB_STIFFNESS_CUBIC, .cubic = c};
    double s;
    /* passes through O (OF, slope OS), RP (RPF), RN (RNF); slope EPS at EP */
    assert_close(usrsub_characteristic(&d, 0.0, &s), 0.0, 0, 1e-12);
    assert_close(s, 2e4, 1e-12, 0);
    assert_close(usrsub_characteristic(&d, 0.1, &s), 3e4, 1e-12, 0);
    assert_close(usrsub_characteristic(&d, -0.1, &s), -3e4, 1e-12, 0);
    assert_close(usrsub_characteristic(&d, 0.2, &s), 69000.0, 1e-12, 0);
    assert_close(s, 2e5, 1e-12, 0);
    assert_close(usrsub_characteristic(&d, -0.2, &s), -69000.0, 1e-12, 0);
    assert_close(s, 2e5, 1e-12, 0);
    /* linear beyond EP and EN, continuous in value and slope */
    assert_close(usrsub_characteristic(&d, 0.3, &s), 89000.0, 1e-12, 0);
    assert_close(s, 2e5, 0, 0);
    double s_in;
    usrsub_characteristic(&d, 0.2 - 1e-9, &s_in);
    assert_close(s_in, 2e5, 1e-6, 0);
    /* 100 u + u^3 is represented exactly */
    usrsub_bushing b;
    bushing_init(&b, USRSUB_UNCOUPLED);
    bushing_cubic(&b, 0, 100.0, 1.0);
    for (double u = -10.0; u <= 10.0; u += 0.37)
        assert_close(g_of(&b, 0, u), 100 * u + u * u * u, 1e-13, 1e-12);
    /* bad points are refused */
    usrsub_cubic_characteristic bad = c;
    bad.rp = 0.25;
    assert_int_equal(usrsub_cubic_fit(&bad, &msg), -1);
    assert_contains(msg.text, "EN < RN < O < RP < EP");
}

/* Cylindrical, nonlinear and anisotropic, damped. */
static void nonlinear_damped(usrsub_bushing *b, int coupling)
{
    bushing_init(b, coupling);
    bushing_cubic(b, 0, 100.0, 1.0);
    bushing_cubic(b, 1, 150.0, 0.5);
    bushing_cubic(b, 2, 80.0, 2.0);
    bushing_damping(b, 0, 3.0);
    bushing_damping(b, 1, 7.0);
    bushing_damping(b, 2, 5.0);
    bushing_constant(b, 3, 1e4);
    bushing_constant(b, 4, 2e4);
    bushing_cubic(b, 5, 3e3, 500.0);
    bushing_damping(b, 3, 20.0);
    bushing_damping(b, 4, 30.0);
    usrsub_bushing_prepare(b);
}

static void coupled_equals_uncoupled_on_every_half_axis(void **state)
{
    (void)state;
    usrsub_bushing cyl, unc;
    nonlinear_damped(&cyl, USRSUB_CYLINDRICAL);
    nonlinear_damped(&unc, USRSUB_UNCOUPLED);
    const int axes[2] = {0, 1};
    for (int a = 0; a < 2; ++a)
        for (int sign = -1; sign <= 1; sign += 2)
            for (int rate = 0; rate < 3; ++rate) {
                double d[6] = {0}, v[6] = {0}, Fc[6], Fu[6];
                const int k = axes[a], other = 1 - k;
                d[k] = sign * 2.5;
                if (rate == 1)
                    v[k] = -4.0; /* radial */
                if (rate == 2)
                    v[k] = 3.0, v[other] = -6.0; /* radial and tangential */
                usrsub_bushing_force(&cyl, d, v, Fc, NULL, NULL);
                usrsub_bushing_force(&unc, d, v, Fu, NULL, NULL);
                for (int i = 0; i < 6; ++i)
                    assert_close(Fc[i], Fu[i], 1e-13, 1e-12);
                /* and it is G_k(d, v) = -(g(d) + c v) */
                assert_close(Fc[k], -(g_of(&unc, k, d[k]) + unc.dir[k].c * v[k]), 1e-13, 1e-12);
            }
    /* rotations: the same for the (ax, ay) group */
    for (int sign = -1; sign <= 1; sign += 2) {
        double d[6] = {0, 0, 0, sign * 0.01, 0, 0}, v[6] = {0, 0, 0, 0.2, -0.1, 0}, Fc[6], Fu[6];
        usrsub_bushing_force(&cyl, d, v, Fc, NULL, NULL);
        usrsub_bushing_force(&unc, d, v, Fu, NULL, NULL);
        for (int i = 0; i < 6; ++i)
            assert_close(Fc[i], Fu[i], 1e-13, 1e-12);
    }
}

static void spherical_isotropic_force_is_radial(void **state)
{
    (void)state;
    usrsub_bushing b;
    bushing_init(&b, USRSUB_SPHERICAL);
    for (int k = 0; k < 3; ++k)
        bushing_cubic(&b, k, 100.0, 1.0);
    usrsub_bushing_prepare(&b);
    unsigned seed = 7;
    for (int trial = 0; trial < 200; ++trial) {
        double d[6] = {0}, v[6] = {0}, F[6], r = 0.0;
        for (int i = 0; i < 3; ++i) {
            seed = seed * 1103515245u + 12345u;
            d[i] = ((seed >> 8) % 2001) / 100.0 - 10.0;
            r += d[i] * d[i];
        }
        r = sqrt(r);
        if (r < 1e-6 || r > 10.0)
            continue;
        usrsub_bushing_force(&b, d, v, F, NULL, NULL);
        const double G = 100 * r + r * r * r;
        for (int i = 0; i < 3; ++i)
            assert_close(F[i], -G * d[i] / r, 1e-12, 1e-10);
    }
}

static void seed_example_one(void **state)
{
    (void)state;
    usrsub_bushing cyl, unc;
    bushing_init(&cyl, USRSUB_CYLINDRICAL);
    bushing_init(&unc, USRSUB_UNCOUPLED);
    for (int k = 0; k < 2; ++k) {
        bushing_cubic(&cyl, k, 100.0, 1.0);
        bushing_cubic(&unc, k, 100.0, 1.0);
    }
    usrsub_bushing_prepare(&cyl);
    usrsub_bushing_prepare(&unc);
    for (int i = 0; i < 64; ++i) {
        const double th = 2 * M_PI * i / 64.0;
        double d[6] = {5 * cos(th), 5 * sin(th), 0, 0, 0, 0}, v[6] = {0}, F[6];
        usrsub_bushing_force(&cyl, d, v, F, NULL, NULL);
        assert_close(hypot(F[0], F[1]), 625.0, 1e-13, 0); /* |F| = g(5) whatever the angle */
        assert_close(F[0] * d[1] - F[1] * d[0], 0.0, 0, 1e-9); /* along the deformation */
    }
    double d[6] = {5 / sqrt(2.0), 5 / sqrt(2.0), 0, 0, 0, 0}, v[6] = {0}, F[6];
    usrsub_bushing_force(&unc, d, v, F, NULL, NULL);
    assert_close(hypot(F[0], F[1]), 562.5, 1e-13, 0); /* uncoupled falls at 45 degrees */
}

static void finite_and_continuous_at_the_origin(void **state)
{
    (void)state;
    usrsub_bushing b;
    nonlinear_damped(&b, USRSUB_CYLINDRICAL);
    const double tiny[] = {0.0, 1e-300, 5e-324, 1e-12, 1e-9, 1.5e-9, 3e-9};
    for (size_t t = 0; t < sizeof tiny / sizeof tiny[0]; ++t) {
        double d[6] = {tiny[t], -tiny[t], 0, tiny[t], tiny[t], 0}, v[6] = {1, 2, 0, 0.1, 0.2, 0};
        double F[6], J[36], Jv[36];
        usrsub_bushing_force(&b, d, v, F, J, Jv);
        for (int i = 0; i < 36; ++i) {
            assert_true(isfinite(J[i]));
            assert_true(isfinite(Jv[i]));
        }
        for (int i = 0; i < 6; ++i)
            assert_true(isfinite(F[i]));
    }
    /* a path through the origin, across the blend [EPSILON, 2 EPSILON]: sampled
     * ten times finer, the largest jump between samples is ten times smaller,
     * as for a continuous force (a jump would stay the same) */
    double jumps[2];
    for (int fine = 0; fine < 2; ++fine) {
        const double step = fine ? 2e-13 : 2e-12;
        double prev[6] = {0}, max_jump = 0.0;
        for (int i = 0; i * step <= 8e-9; ++i) {
            const double s = -4e-9 + step * i;
            double d[6] = {s, 0.5 * s, 0, 0, 0, 0}, v[6] = {0.3, -0.2, 0, 0, 0, 0}, F[6];
            usrsub_bushing_force(&b, d, v, F, NULL, NULL);
            if (i > 0)
                for (int k = 0; k < 2; ++k)
                    max_jump = fmax(max_jump, fabs(F[k] - prev[k]));
            memcpy(prev, F, sizeof F);
        }
        jumps[fine] = max_jump;
    }
    assert_true(jumps[1] < 0.2 * jumps[0]);
    assert_true(jumps[0] < 0.01); /* of forces of order 1 */
}

static void preload_offset_and_scale(void **state)
{
    (void)state;
    usrsub_bushing b;
    bushing_init(&b, USRSUB_UNCOUPLED);
    bushing_constant(&b, 2, 800.0);
    bushing_damping(&b, 2, 1.5);
    usrsub_bushing_prepare(&b);
    double d[6] = {0, 0, 0.7, 0, 0, 0}, v[6] = {0, 0, 2.0, 0, 0, 0}, F[6];
    usrsub_bushing_force(&b, d, v, F, NULL, NULL);
    const double G = -(800.0 * 0.7 + 1.5 * 2.0);
    assert_close(F[2], G, 1e-15, 0);
    b.dir[2].preload = 50.0; /* a positive preload pulls I towards -z */
    usrsub_bushing_force(&b, d, v, F, NULL, NULL);
    assert_close(F[2], -50.0 + G, 1e-15, 0);
    b.dir[2].preload = 0.0, b.dir[2].offset = 0.2; /* q = d - Q */
    usrsub_bushing_force(&b, d, v, F, NULL, NULL);
    assert_close(F[2], -(800.0 * 0.5 + 1.5 * 2.0), 1e-15, 0);
    b.dir[2].offset = 0.0, b.dir[2].disp_scale = 0.9; /* q = H d, qdot = H v */
    usrsub_bushing_force(&b, d, v, F, NULL, NULL);
    assert_close(F[2], -(800.0 * 0.63 + 1.5 * 1.8), 1e-15, 0);
    b.dir[2].disp_scale = 1.0, b.dir[2].force_scale = 1.1; /* F = V G, not the preload */
    b.dir[2].preload = 50.0;
    usrsub_bushing_force(&b, d, v, F, NULL, NULL);
    assert_close(F[2], -50.0 + 1.1 * G, 1e-15, 0);
}

static void inactive_directions_return_zero(void **state)
{
    (void)state;
    usrsub_bushing b;
    bushing_init(&b, USRSUB_CYLINDRICAL);
    bushing_cubic(&b, 0, 100.0, 1.0); /* only x: the group has one active member */
    b.dir[1].preload = 99.0;          /* an inactive direction ignores its preload */
    usrsub_bushing_prepare(&b);
    assert_int_equal(b.group_size[0], 0);
    double d[6] = {1, 2, 3, 0.1, 0.2, 0.3}, v[6] = {1, 1, 1, 1, 1, 1}, F[6], J[36], Jv[36];
    usrsub_bushing_force(&b, d, v, F, J, Jv);
    assert_close(F[0], -101.0, 1e-15, 0);
    for (int k = 1; k < 6; ++k)
        assert_close(F[k], 0.0, 0, 0);
    assert_false(b.uses_rotation);
    assert_false(b.uses_velocity);
}

/* dF/dd and dF/dv against central differences, column by column. */
static void compare_partials(const usrsub_bushing *b, const double *d0, const double *v0)
{
    double F[6], J[36], Jv[36];
    usrsub_bushing_force(b, d0, v0, F, J, Jv);
    for (int c = 0; c < 12; ++c) {
        double d[6], v[6], Fp[6], Fm[6];
        memcpy(d, d0, sizeof d);
        memcpy(v, v0, sizeof v);
        double *x = c < 6 ? &d[c] : &v[c - 6];
        /* steps scaled to each variable's typical size, not its current value */
        static const double typical[12] = {4, 4, 4, 0.05, 0.05, 0.05, 5, 5, 5, 0.3, 0.3, 0.3};
        const double h = 1e-6 * typical[c], x0 = *x;
        *x = x0 + h;
        usrsub_bushing_force(b, d, v, Fp, NULL, NULL);
        *x = x0 - h;
        usrsub_bushing_force(b, d, v, Fm, NULL, NULL);
        double scale = 0.0;
        for (int i = 0; i < 36; ++i)
            scale = fmax(scale, fmax(fabs(J[i]), fabs(Jv[i])));
        for (int i = 0; i < 6; ++i) {
            const double fd = (Fp[i] - Fm[i]) / (2 * h);
            const double an = c < 6 ? J[i + 6 * c] : Jv[i + 6 * (c - 6)];
            assert_close(an, fd, 2e-7, 1e-9 * scale);
        }
    }
}

static void partials_match_finite_differences(void **state)
{
    (void)state;
    const double sx[] = {-6, -3, -1, 0, 1, 3, 6}, sy[] = {-900, -320, -95, 0, 95, 320, 900};
    for (int coupling = USRSUB_UNCOUPLED; coupling <= USRSUB_SPHERICAL; ++coupling) {
        usrsub_bushing b;
        nonlinear_damped(&b, coupling);
        bushing_spline(&b, 1, 7, sx, sy);
        b.dir[0].offset = 0.1, b.dir[0].disp_scale = 0.95, b.dir[0].force_scale = 1.2;
        b.dir[1].preload = 12.0, b.dir[4].disp_scale = 1.1;
        b.group_epsilon[0] = 1e-3, b.group_epsilon[1] = 1e-4; /* a blend wide enough to difference */
        usrsub_bushing_prepare(&b);
        unsigned seed = 11u + (unsigned)coupling;
        for (int trial = 0; trial < 60; ++trial) {
            double d[6], v[6];
            for (int i = 0; i < 6; ++i) {
                seed = seed * 1103515245u + 12345u;
                const double u = ((seed >> 8) % 20001) / 10000.0 - 1.0;
                d[i] = (i < 3 ? 4.0 : 0.05) * u * (trial % 3 == 0 ? 1e-3 : 1.0);
                seed = seed * 1103515245u + 12345u;
                v[i] = (i < 3 ? 5.0 : 0.3) * (((seed >> 8) % 20001) / 10000.0 - 1.0);
            }
            compare_partials(&b, d, v);
        }
        bushing_release(&b);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(constant_characteristic),
        cmocka_unit_test(spline_characteristic),
        cmocka_unit_test(cubic_characteristic_fit),
        cmocka_unit_test(coupled_equals_uncoupled_on_every_half_axis),
        cmocka_unit_test(spherical_isotropic_force_is_radial),
        cmocka_unit_test(seed_example_one),
        cmocka_unit_test(finite_and_continuous_at_the_origin),
        cmocka_unit_test(preload_offset_and_scale),
        cmocka_unit_test(inactive_directions_return_zero),
        cmocka_unit_test(partials_match_finite_differences),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
