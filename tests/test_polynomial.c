/* Polynomial value and derivatives. */
#include "test_support.h"
#include "usrsub/core/polynomial.h"

static void hand_values(void **state)
{
    (void)state;
    /* p = 1 - 2x + 3x^2 at x = 2: 1 - 4 + 12 = 9; p' = -2 + 6x = 10; p'' = 6 */
    usrsub_polynomial p = {2, {1, -2, 3}};
    usrsub_jet j = usrsub_polynomial_eval(&p, 2.0);
    assert_close(j.value, 9.0, 0, 1e-14);
    assert_close(j.d1, 10.0, 0, 1e-14);
    assert_close(j.d2, 6.0, 0, 1e-14);
    /* x^6 at x = -1.5: 11.390625; 6x^5 = -45.5625; 30x^4 = 151.875 */
    usrsub_polynomial q = {6, {0, 0, 0, 0, 0, 0, 1}};
    j = usrsub_polynomial_eval(&q, -1.5);
    assert_close(j.value, 11.390625, 1e-15, 0);
    assert_close(j.d1, -45.5625, 1e-15, 0);
    assert_close(j.d2, 151.875, 1e-15, 0);
}

static void constant(void **state)
{
    (void)state;
    usrsub_polynomial p = {0, {4.25}};
    usrsub_jet j = usrsub_polynomial_eval(&p, 123.0);
    assert_close(j.value, 4.25, 0, 0);
    assert_close(j.d1, 0.0, 0, 0);
    assert_close(j.d2, 0.0, 0, 0);
}

static void derivatives_match_finite_differences(void **state)
{
    (void)state;
    usrsub_polynomial p = {6, {0.3, -1.1, 0.7, 2.5, -0.4, 0.05, -0.02}};
    const double h = 1e-6;
    for (double x = -2.0; x <= 2.0; x += 0.37) {
        const usrsub_jet j = usrsub_polynomial_eval(&p, x);
        const double d1 = (usrsub_polynomial_eval(&p, x + h).value -
                           usrsub_polynomial_eval(&p, x - h).value) / (2 * h);
        const double d2 = (usrsub_polynomial_eval(&p, x + h).d1 -
                           usrsub_polynomial_eval(&p, x - h).d1) / (2 * h);
        assert_close(j.d1, d1, 1e-8, 1e-8);
        assert_close(j.d2, d2, 1e-8, 1e-8);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hand_values),
        cmocka_unit_test(constant),
        cmocka_unit_test(derivatives_match_finite_differences),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
