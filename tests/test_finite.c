/*
 * The entries' finiteness check (usrsub/entries/finite.h), on the bits and
 * two lanes at a time: a NaN or an infinity at every position of arrays of
 * odd and even lengths is found, contiguous and strided; the largest finite
 * value, subnormals and signed zeros pass.
 */
#include <float.h>
#include <math.h>

#include "finite.h"
#include "test_support.h"

static void every_position_of_every_length(void **state)
{
    (void)state;
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    for (int n = 1; n <= 73; ++n)
        for (int at = 0; at < n; ++at)
            for (int b = 0; b < 3; ++b) {
                double v[73];
                for (int k = 0; k < n; ++k)
                    v[k] = k % 4 == 0 ? DBL_MAX : k % 4 == 1 ? -DBL_MIN / 8 : k % 4 == 2 ? -0.0 : 1.5;
                assert_true(usrsub_finite_all(v, n));
                v[at] = bad[b];
                assert_false(usrsub_finite_all(v, n));
            }
}

static void strided_values_only(void **state)
{
    (void)state;
    double v[12];
    for (int k = 0; k < 12; ++k)
        v[k] = k;
    v[5] = NAN; /* between the strided entries 0, 3, 6, 9 */
    assert_true(usrsub_finite_all_strided(v, 4, 3));
    v[6] = -INFINITY;
    assert_false(usrsub_finite_all_strided(v, 4, 3));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_position_of_every_length),
        cmocka_unit_test(strided_values_only),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
