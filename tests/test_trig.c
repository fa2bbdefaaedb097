/* usrsub_atan2 and usrsub_sincos against the C library: atan2 within 3 units
 * in the last place (and nearly always within 1), sincos within 2, over all
 * quadrants and magnitudes; the C library's answers for zeros, infinities
 * and NaN. */
#define _GNU_SOURCE
#include <float.h>
#include <math.h>
#include <stdint.h>

#include "test_support.h"
#include "usrsub/core/trig.h"

static double ulps(double a, double b)
{
    if (a == b)
        return 0.0;
    const double unit = nextafter(fabs(b), INFINITY) - fabs(b);
    return fabs(a - b) / unit;
}

static uint64_t state = 88172645463325252ull;
static double random_unit(void) /* in [0, 1) */
{
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return (double)(state >> 11) / 9007199254740992.0;
}

static void atan2_within_three_ulps(void **state_)
{
    (void)state_;
    double worst = 0.0;
    int within_one = 0;
    const int samples = 2000000;
    for (int k = 0; k < samples; ++k) {
        const double y = (random_unit() - 0.5) * pow(10.0, 12.0 * random_unit() - 6.0);
        const double x = (random_unit() - 0.5) * pow(10.0, 12.0 * random_unit() - 6.0);
        const double e = ulps(usrsub_atan2(y, x), atan2(y, x));
        worst = fmax(worst, e);
        within_one += e <= 1.0;
    }
    assert_true(within_one > 0.999 * samples);
    /* the reduction's seams: t = tan(pi/12), 1, and the axes' neighbourhoods */
    const double seams[] = {0.2679491924311227, 1.0, 1e-300, 1e300, 0.5773502691896258};
    for (size_t s = 0; s < sizeof seams / sizeof seams[0]; ++s)
        for (int k = -50; k <= 50; ++k) {
            const double t = seams[s] * (1.0 + k * DBL_EPSILON);
            worst = fmax(worst, ulps(usrsub_atan2(t, 1.0), atan2(t, 1.0)));
            worst = fmax(worst, ulps(usrsub_atan2(-1.0, -t), atan2(-1.0, -t)));
        }
    print_message("usrsub_atan2: worst error %.2f ulp, %.4f%% within 1 ulp\n", worst,
                  100.0 * within_one / samples);
    assert_true(worst <= 3.0);
}

static void atan2_special_values(void **state_)
{
    (void)state_;
    const double v[] = {0.0, -0.0, 1.0, -1.0, INFINITY, -INFINITY, 3e-310, -3e-310};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; ++i)
        for (size_t j = 0; j < sizeof v / sizeof v[0]; ++j) {
            const double a = usrsub_atan2(v[i], v[j]), b = atan2(v[i], v[j]);
            assert_true(a == b || ulps(a, b) <= 2.0);
            assert_int_equal(signbit(a), signbit(b));
        }
    assert_true(isnan(usrsub_atan2(NAN, 1.0)));
    assert_true(isnan(usrsub_atan2(1.0, NAN)));
}

static void sincos_within_two_ulps(void **state_)
{
    (void)state_;
    double worst = 0.0;
    for (int k = 0; k < 2000000; ++k) {
        const double x = (random_unit() - 0.5) * 2.0 * (k % 4 == 0 ? 1e5 : k % 4 == 1 ? 10.0 : M_PI);
        double s, c, ls, lc;
        usrsub_sincos(x, &s, &c);
        sincos(x, &ls, &lc);
        /* in units in the last place of the result, at least 1.1e-16 (1 ulp of 0.5..1) */
        worst = fmax(worst, fabs(s - ls) / fmax(nextafter(fabs(ls), INFINITY) - fabs(ls), 1.1e-16));
        worst = fmax(worst, fabs(c - lc) / fmax(nextafter(fabs(lc), INFINITY) - fabs(lc), 1.1e-16));
    }
    /* next to the multiples of pi/2, where the reduction matters most */
    for (int n = -2000; n <= 2000; ++n)
        for (int k = -3; k <= 3; ++k) {
            const double x = n * 1.5707963267948966 + k * 1e-9;
            double s, c, ls, lc;
            usrsub_sincos(x, &s, &c);
            sincos(x, &ls, &lc);
            assert_close(s, ls, 4.5e-16, 1.2e-16);
            assert_close(c, lc, 4.5e-16, 1.2e-16);
        }
    print_message("usrsub_sincos: worst error %.2f ulp\n", worst);
    assert_true(worst <= 2.0);
}

static void sincos_outside_the_fast_range(void **state_)
{
    (void)state_;
    const double x[] = {1e6, -3e9, 1e300, INFINITY, NAN};
    for (size_t i = 0; i < sizeof x / sizeof x[0]; ++i) {
        double s, c, ls, lc;
        usrsub_sincos(x[i], &s, &c);
        sincos(x[i], &ls, &lc);
        assert_true((s == ls && c == lc) || (isnan(s) && isnan(ls)));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(atan2_within_three_ulps),
        cmocka_unit_test(atan2_special_values),
        cmocka_unit_test(sincos_within_two_ulps),
        cmocka_unit_test(sincos_outside_the_fast_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
