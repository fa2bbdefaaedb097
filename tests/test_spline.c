/* Natural cubic spline: interpolation, C2 continuity, natural ends, linear
 * extension, hand values, finite differences, input errors. */
#include <math.h>
#include <stdlib.h>

#include "test_support.h"
#include "usrsub/core/spline.h"

static usrsub_spline make(int n, const double *x, const double *y)
{
    usrsub_spline s;
    usrsub_message msg;
    if (usrsub_spline_init(&s, n, x, y, &msg) != 0)
        fail_msg("spline_init: %s", msg.text);
    return s;
}

static void hand_values(void **state)
{
    (void)state;
    /* Through (0,0) (1,1) (2,0): interior curvature M1 = -3, so on [0,1]
     * s = 1.5 t - 0.5 t^3, s(0.5) = 0.6875, s'(0.5) = 1.125, s''(0.5) = -1.5,
     * end slopes +-1.5, and the linear extension gives s(-1) = s(3) = -1.5. */
    const double x[] = {0, 1, 2}, y[] = {0, 1, 0};
    usrsub_spline s = make(3, x, y);
    usrsub_jet j = usrsub_spline_eval(&s, 0.5);
    assert_close(j.value, 0.6875, 0, 1e-15);
    assert_close(j.d1, 1.125, 0, 1e-15);
    assert_close(j.d2, -1.5, 0, 1e-15);
    assert_close(usrsub_spline_eval(&s, 1.5).value, 0.6875, 0, 1e-15);
    assert_close(usrsub_spline_eval(&s, 1.5).d1, -1.125, 0, 1e-15);
    assert_close(usrsub_spline_eval(&s, -1.0).value, -1.5, 0, 1e-15);
    assert_close(usrsub_spline_eval(&s, 3.0).value, -1.5, 0, 1e-15);
    assert_close(usrsub_spline_eval(&s, 3.0).d1, -1.5, 0, 1e-15);
    usrsub_spline_free(&s);
}

static void interpolates_points_and_reproduces_lines(void **state)
{
    (void)state;
    double x[12], y[12], ly[12];
    for (int k = 0; k < 12; ++k) {
        x[k] = k * 0.7 + 0.05 * (k % 3) - 1.3;
        y[k] = sin(x[k]) + 0.1 * k;
        ly[k] = 2.0 * x[k] - 1.0;
    }
    usrsub_spline s = make(12, x, y), line = make(12, x, ly);
    for (int k = 0; k < 12; ++k)
        assert_close(usrsub_spline_eval(&s, x[k]).value, y[k], 1e-14, 1e-14);
    for (double t = -5.0; t < 12.0; t += 0.31) {
        const usrsub_jet j = usrsub_spline_eval(&line, t);
        assert_close(j.value, 2.0 * t - 1.0, 1e-13, 1e-13);
        assert_close(j.d1, 2.0, 1e-12, 1e-12);
        assert_close(j.d2, 0.0, 0, 1e-11);
    }
    usrsub_spline_free(&s);
    usrsub_spline_free(&line);
}

static void c2_at_knots_and_natural_ends(void **state)
{
    (void)state;
    const double x[] = {-2, -1.2, 0, 0.5, 1.7, 3}, y[] = {3, -1, 0.5, 2, -0.7, 1};
    usrsub_spline s = make(6, x, y);
    const double eps = 1e-10;
    for (int k = 0; k < 6; ++k) {
        const usrsub_jet l = usrsub_spline_eval(&s, x[k] - eps);
        const usrsub_jet r = usrsub_spline_eval(&s, x[k] + eps);
        assert_close(l.value, r.value, 0, 1e-8);
        assert_close(l.d1, r.d1, 0, 1e-8);
        assert_close(l.d2, r.d2, 0, 1e-7);
    }
    /* natural: zero curvature at the end knots, so the linear extension is C2 */
    assert_close(usrsub_spline_eval(&s, x[0] + eps).d2, 0.0, 0, 1e-7);
    assert_close(usrsub_spline_eval(&s, x[5] - eps).d2, 0.0, 0, 1e-7);
    /* outside: a straight line with the end slope */
    const usrsub_jet end = usrsub_spline_eval(&s, 3.0);
    const usrsub_jet far = usrsub_spline_eval(&s, 13.0);
    assert_close(far.value, end.value + 10.0 * end.d1, 1e-14, 1e-12);
    assert_close(far.d1, end.d1, 0, 0);
    assert_close(far.d2, 0.0, 0, 0);
    usrsub_spline_free(&s);
}

static void derivatives_match_finite_differences(void **state)
{
    (void)state;
    const double x[] = {0, 0.4, 1.1, 1.5, 2.6, 3.0, 4.2}, y[] = {0, 0.3, -0.2, 1.4, 0.9, 2.2, 1.0};
    usrsub_spline s = make(7, x, y);
    const double h = 1e-6;
    for (double t = -1.013; t < 5.3; t += 0.0731) {
        const usrsub_jet j = usrsub_spline_eval(&s, t);
        const double d1 = (usrsub_spline_eval(&s, t + h).value - usrsub_spline_eval(&s, t - h).value) / (2 * h);
        const double d2 = (usrsub_spline_eval(&s, t + h).d1 - usrsub_spline_eval(&s, t - h).d1) / (2 * h);
        assert_close(j.d1, d1, 1e-7, 1e-7);
        assert_close(j.d2, d2, 1e-5, 1e-5); /* d2 is continuous but kinked at knots */
    }
    usrsub_spline_free(&s);
}

static void two_points_is_a_line(void **state)
{
    (void)state;
    const double x[] = {1, 3}, y[] = {2, 6};
    usrsub_spline s = make(2, x, y);
    assert_close(usrsub_spline_eval(&s, 2.0).value, 4.0, 0, 1e-15);
    assert_close(usrsub_spline_eval(&s, 10.0).value, 20.0, 0, 1e-13);
    assert_close(usrsub_spline_eval(&s, 2.0).d2, 0.0, 0, 1e-15);
    usrsub_spline_free(&s);
}

/* Equally spaced knots take the division path; its interval must be the one
 * the search would find, at knots and one rounding step either side. */
static void equally_spaced_knots_find_the_same_interval(void **state)
{
    (void)state;
    enum { N = 21 };
    double x[N], y[N], xu[N];
    for (int i = 0; i < N; ++i) {
        x[i] = -1.0 + 0.1 * i; /* 0.1 is not a binary number: spacings differ by rounding */
        y[i] = sin(3.0 * x[i]) + 0.2 * x[i] * x[i];
        xu[i] = x[i] + (i % 3 == 1 ? 1e-3 : 0.0); /* not equally spaced */
    }
    usrsub_spline u, searched, uneven;
    usrsub_message msg;
    assert_int_equal(usrsub_spline_init(&u, N, x, y, &msg), 0);
    assert_int_equal(usrsub_spline_init(&searched, N, x, y, &msg), 0);
    assert_int_equal(usrsub_spline_init(&uneven, N, xu, y, &msg), 0);
    assert_true(u.uniform);
    assert_false(uneven.uniform);
    searched.uniform = 0; /* the same spline through the bucket search */
    for (int i = 0; i < N; ++i)
        for (int side = -2; side <= 2; ++side) {
            double at = x[i];
            for (int k = 0; k < (side < 0 ? -side : side); ++k)
                at = nextafter(at, side < 0 ? -INFINITY : INFINITY);
            double s1, s2;
            const double v1 = usrsub_spline_value_slope(&u, at, &s1);
            const double v2 = usrsub_spline_value_slope(&searched, at, &s2);
            assert_true(v1 == v2 && s1 == s2); /* the same interval, bit for bit */
        }
    for (double at = -1.2; at < 1.2; at += 0.0137) {
        double s1, s2;
        assert_true(usrsub_spline_value_slope(&u, at, &s1) ==
                    usrsub_spline_value_slope(&searched, at, &s2));
        assert_true(s1 == s2);
    }
    usrsub_spline_free(&u);
    usrsub_spline_free(&searched);
    usrsub_spline_free(&uneven);
}

static void bad_input_is_named(void **state)
{
    (void)state;
    usrsub_spline s;
    usrsub_message msg;
    const double x[] = {0, 1, 1, 2}, y[] = {0, 1, 2, 3};
    assert_int_equal(usrsub_spline_init(&s, 1, x, y, &msg), -1);
    assert_contains(msg.text, "at least 2 points");
    assert_int_equal(usrsub_spline_init(&s, 4, x, y, &msg), -1);
    assert_contains(msg.text, "point 3", "strictly increasing");
    const double xd[] = {0, 2, 1}, yd[] = {0, 1, 2};
    assert_int_equal(usrsub_spline_init(&s, 3, xd, yd, &msg), -1);
    assert_contains(msg.text, "point 3");
    const double xn[] = {0, NAN, 2};
    assert_int_equal(usrsub_spline_init(&s, 3, xn, yd, &msg), -1);
    assert_contains(msg.text, "point 2", "not finite");
    /* Tables whose arithmetic overflows (found by fuzz_user_lists). */
    const double xw[] = {-1e308, 0, 1e308}, yw[] = {0, 1, 0};
    assert_int_equal(usrsub_spline_init(&s, 3, xw, yw, &msg), -1);
    assert_contains(msg.text, "too wide");
    const double xc[] = {0, 1e-320, 1}, yc[] = {0, 1, 2};
    assert_int_equal(usrsub_spline_init(&s, 3, xc, yc, &msg), -1);
    assert_contains(msg.text, "points 1 and 2", "too close");
    const double xs[] = {0, 1e-300, 2e-300}, ys[] = {0, 1e300, 0};
    assert_int_equal(usrsub_spline_init(&s, 3, xs, ys, &msg), -1);
    assert_contains(msg.text, "overflows");
}

static void extreme_arguments_find_an_interval(void **state)
{
    (void)state;
    /* Interval look-up must clamp its index before converting to int: a
     * huge quotient or a NaN argument is not undefined behaviour. */
    const double x[] = {0, 1e-100, 2e-100, 3e-100}, y[] = {0, 1, 4, 9};
    usrsub_spline s = make(4, x, y);
    assert_close(usrsub_spline_eval(&s, 2e-100).value, 4.0, 1e-12, 0);
    assert_true(isfinite(usrsub_spline_eval(&s, 2.999999999e-100).value));
    assert_true(isnan(usrsub_spline_eval(&s, NAN).value));
    usrsub_spline_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hand_values),
        cmocka_unit_test(interpolates_points_and_reproduces_lines),
        cmocka_unit_test(c2_at_knots_and_natural_ends),
        cmocka_unit_test(derivatives_match_finite_differences),
        cmocka_unit_test(two_points_is_a_line),
        cmocka_unit_test(equally_spaced_knots_find_the_same_interval),
        cmocka_unit_test(bad_input_is_named),
        cmocka_unit_test(extreme_arguments_find_an_interval),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
