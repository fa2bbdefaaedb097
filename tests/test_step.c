/* STEP and STEP5: the contract's test vector, hand values, derivatives. */
#include <math.h>

#include "test_support.h"
#include "usrsub/core/step.h"

static void step_contract_vector(void **state)
{
    (void)state;
    /* docs/interface.md §3.6: STEP(x, 3,0, 4,1) at 2, 3, 3.5, 4, 5 gives 0, 0, 0.5, 1, 1. */
    const double x[] = {2, 3, 3.5, 4, 5}, expected[] = {0, 0, 0.5, 1, 1};
    for (int k = 0; k < 5; ++k)
        assert_close(usrsub_step(x[k], 3, 0, 4, 1).value, expected[k], 0, 1e-15);
}

static void step_hand_values(void **state)
{
    (void)state;
    /* a = 0.25: a^2 (3 - 2a) = 0.15625; 6a(1-a) = 1.125; 6(1-2a) = 3 */
    usrsub_jet j = usrsub_step(3.25, 3, 0, 4, 1);
    assert_close(j.value, 0.15625, 0, 1e-15);
    assert_close(j.d1, 1.125, 0, 1e-15);
    assert_close(j.d2, 3.0, 0, 1e-14);
    /* span 2, heights 2 -> -4: value 2 - 6*0.15625, slope -6*1.125/2, curvature -6*3/4 */
    j = usrsub_step(1.5, 1, 2, 3, -4);
    assert_close(j.value, 1.0625, 0, 1e-15);
    assert_close(j.d1, -3.375, 0, 1e-14);
    assert_close(j.d2, -4.5, 0, 1e-14);
}

static void step5_hand_values(void **state)
{
    (void)state;
    /* a = 0.25: a^3 (10 - 15a + 6a^2) = 0.103515625; 30 a^2 (1-a)^2 = 1.0546875;
     * 60 a (1-a)(1-2a) = 5.625 */
    usrsub_jet j = usrsub_step5(3.25, 3, 0, 4, 1);
    assert_close(j.value, 0.103515625, 0, 1e-15);
    assert_close(j.d1, 1.0546875, 0, 1e-14);
    assert_close(j.d2, 5.625, 0, 1e-13);
    assert_close(usrsub_step5(3.5, 3, 0, 4, 1).value, 0.5, 0, 1e-15);
    assert_close(usrsub_step5(2, 3, -1, 4, 1).value, -1.0, 0, 0);
    assert_close(usrsub_step5(7, 3, -1, 4, 1).value, 1.0, 0, 0);
}

typedef usrsub_jet step_fn(double, double, double, double, double);

static void check_derivatives(step_fn *f)
{
    const double h = 1e-6;
    for (double x = 1.05; x < 2.0; x += 0.0937) {
        const usrsub_jet j = f(x, 1, -0.5, 2, 3.5);
        const double d1 = (f(x + h, 1, -0.5, 2, 3.5).value - f(x - h, 1, -0.5, 2, 3.5).value) / (2 * h);
        const double d2 = (f(x + h, 1, -0.5, 2, 3.5).d1 - f(x - h, 1, -0.5, 2, 3.5).d1) / (2 * h);
        assert_close(j.d1, d1, 1e-7, 1e-7);
        assert_close(j.d2, d2, 1e-7, 1e-6);
    }
}

static void derivatives_match_finite_differences(void **state)
{
    (void)state;
    check_derivatives(usrsub_step);
    check_derivatives(usrsub_step5);
}

static void continuity_at_the_ends(void **state)
{
    (void)state;
    const double eps = 1e-9;
    /* STEP is C1: slope 0 at both ends; its curvature jumps to 6(h1-h0)/span^2. */
    assert_close(usrsub_step(3 + eps, 3, 0, 4, 1).value, 0.0, 0, 1e-15);
    assert_close(usrsub_step(3 + eps, 3, 0, 4, 1).d1, 0.0, 0, 1e-8);
    assert_close(usrsub_step(3 + eps, 3, 0, 4, 1).d2, 6.0, 1e-8, 0);
    assert_close(usrsub_step(4 - eps, 3, 0, 4, 1).d1, 0.0, 0, 1e-8);
    /* STEP5 is C2: curvature 0 at both ends. */
    assert_close(usrsub_step5(3 + eps, 3, 0, 4, 1).d2, 0.0, 0, 1e-7);
    assert_close(usrsub_step5(4 - eps, 3, 0, 4, 1).d2, 0.0, 0, 1e-7);
    assert_close(usrsub_step5(4 - eps, 3, 0, 4, 1).value, 1.0, 0, 1e-15);
}

static void zero_width_step_is_a_jump(void **state)
{
    (void)state;
    assert_close(usrsub_step(0.0, 0, 0, 0, 1).value, 0.0, 0, 0);
    assert_close(usrsub_step(1e-300, 0, 0, 0, 1).value, 1.0, 0, 0);
    assert_close(usrsub_step(1e-300, 0, 0, 0, 1).d1, 0.0, 0, 0);
    assert_true(isfinite(usrsub_step5(1e-300, 0, 0, 0, 1).d2));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(step_contract_vector),
        cmocka_unit_test(step_hand_values),
        cmocka_unit_test(step5_hand_values),
        cmocka_unit_test(derivatives_match_finite_differences),
        cmocka_unit_test(continuity_at_the_ends),
        cmocka_unit_test(zero_width_step_is_a_jump),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
