/* The coupler core: each term code against hand values, the assembled
 * phi/gradient/Hessian against finite differences, and every USER-list error. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"
#include "usrsub/readers/coupler_reader.h"

/* Reference_String 100 -> the table file written by a test, 200 -> a missing file. */
static char table_path[512];
static int lookup(void *ctx, int id, char *text, int capacity)
{
    (void)ctx;
    if (id == 100)
        snprintf(text, (size_t)capacity, "%s", table_path);
    else if (id == 200)
        snprintf(text, (size_t)capacity, "%s/no-such-table.tbl", test_temp_dir());
    else
        return -1;
    return 0;
}

static usrsub_coupler decode(const double *par, int npar, int ndisp)
{
    usrsub_coupler c;
    usrsub_message msg;
    if (usrsub_coupler_decode(&c, par, npar, ndisp, lookup, NULL, &msg) != 0)
        fail_msg("decode: %s", msg.text);
    return c;
}

static const char *decode_error(const double *par, int npar, int ndisp)
{
    static usrsub_message msg;
    usrsub_coupler c;
    memset(&msg, 0, sizeof msg);
    assert_int_equal(usrsub_coupler_decode(&c, par, npar, ndisp, lookup, NULL, &msg), -1);
    return msg.text;
}

static void linear_and_polynomial_terms(void **state)
{
    (void)state;
    /* USER(1, 10, 2, 2, 1, -2, 3): G1 = 10 M1, G2 = 1 - 2 M2 + 3 M2^2 */
    const double par[] = {1, 10, 2, 2, 1, -2, 3};
    usrsub_coupler c = decode(par, 7, 2);
    const double m[2] = {0.5, 2.0};
    assert_close(usrsub_coupler_phi(&c, m), 5.0 + 9.0, 0, 1e-14);
    double g[2], h[4];
    usrsub_coupler_gradient(&c, m, g);
    assert_close(g[0], 10.0, 0, 0);
    assert_close(g[1], 10.0, 0, 1e-14); /* -2 + 6*2 */
    usrsub_coupler_hessian(&c, m, h);
    assert_close(h[0], 0.0, 0, 0);
    assert_close(h[3], 6.0, 0, 1e-14);
    assert_close(h[1], 0.0, 0, 0);
    assert_close(h[2], 0.0, 0, 0);
    usrsub_coupler_free(&c);
}

static void inline_spline_term(void **state)
{
    (void)state;
    /* code 3 through (0,0) (1,1) (2,0): s(0.5) = 0.6875, s' = 1.125, s'' = -1.5 */
    const double par[] = {3, 3, 0, 0, 1, 1, 2, 0, 1, 1};
    usrsub_coupler c = decode(par, 10, 2);
    const usrsub_jet j = usrsub_coupler_term_eval(&c.term[0], 0.5);
    assert_close(j.value, 0.6875, 0, 1e-15);
    assert_close(j.d1, 1.125, 0, 1e-15);
    assert_close(j.d2, -1.5, 0, 1e-15);
    double lo, hi;
    assert_int_equal(usrsub_coupler_term_range(&c.term[0], &lo, &hi), 1);
    assert_close(lo, 0.0, 0, 0);
    assert_close(hi, 2.0, 0, 0);
    assert_int_equal(usrsub_coupler_term_range(&c.term[1], &lo, &hi), 0);
    usrsub_coupler_free(&c);
}

static void table_file_term(void **state)
{
    (void)state;
    snprintf(table_path, sizeof table_path, "%s",
             test_write_file("table.tbl", "# a comment\n$ another\n\n0 0\n 1, 1\n\t2\t0\n"));
    /* code 4 with scale 2: twice the spline above */
    const double par[] = {4, 100, 2.0, 1, -1};
    usrsub_coupler c = decode(par, 5, 2);
    const usrsub_jet j = usrsub_coupler_term_eval(&c.term[0], 0.5);
    assert_close(j.value, 1.375, 0, 1e-15);
    assert_close(j.d1, 2.25, 0, 1e-15);
    assert_close(j.d2, -3.0, 0, 1e-15);
    /* linear extension: s(3) = -1.5, times 2 */
    assert_close(usrsub_coupler_term_eval(&c.term[0], 3.0).value, -3.0, 0, 1e-14);
    usrsub_coupler_free(&c);
}

static void sine_term(void **state)
{
    (void)state;
    /* 2 sin(3 M + 0.5) at M = 0.1: 2 sin 0.8, 6 cos 0.8, -18 sin 0.8 */
    const double par[] = {5, 2, 3, 0.5, 1, 1};
    usrsub_coupler c = decode(par, 6, 2);
    const usrsub_jet j = usrsub_coupler_term_eval(&c.term[0], 0.1);
    assert_close(j.value, 2 * sin(0.8), 1e-15, 0);
    assert_close(j.d1, 6 * cos(0.8), 1e-15, 0);
    assert_close(j.d2, -18 * sin(0.8), 1e-15, 0);
    usrsub_coupler_free(&c);
}

static void three_terms_against_finite_differences(void **state)
{
    (void)state;
    /* polynomial, inline spline, sine */
    const double par[] = {2, 3, 0.1, -1, 0.5, 0.2, 3, 4, -1, 2, 0, 0, 1, 1, 3, -2,
                          5, 0.7, 2.0, 0.3};
    usrsub_coupler c = decode(par, 20, 3);
    const double h = 1e-6;
    for (double t = -1.5; t < 3.5; t += 0.173) {
        double m[3] = {0.3 * t, t, -0.5 * t}, g[3], H[9];
        usrsub_coupler_gradient(&c, m, g);
        usrsub_coupler_hessian(&c, m, H);
        for (int i = 0; i < 3; ++i) {
            double mp[3], mm[3], gp[3], gm[3];
            memcpy(mp, m, sizeof m);
            memcpy(mm, m, sizeof m);
            mp[i] += h, mm[i] -= h;
            const double fd = (usrsub_coupler_phi(&c, mp) - usrsub_coupler_phi(&c, mm)) / (2 * h);
            assert_close(g[i], fd, 1e-7, 1e-8);
            usrsub_coupler_gradient(&c, mp, gp);
            usrsub_coupler_gradient(&c, mm, gm);
            for (int j = 0; j < 3; ++j)
                assert_close(H[j + 3 * i], (gp[j] - gm[j]) / (2 * h), 1e-5, 1e-6);
        }
    }
    usrsub_coupler_free(&c);
}

static void term_count_must_equal_ndisp(void **state)
{
    (void)state;
    const double one_term[] = {1, 2.0};
    assert_contains(decode_error(one_term, 2, 2), "has 1 terms", "relates 2 joints");
    const double three_terms[] = {1, 1, 1, 1, 1, 1};
    assert_contains(decode_error(three_terms, 6, 2), "more than 2 terms", "USER parameter 5");
}

static void unknown_code(void **state)
{
    (void)state;
    const double par[] = {1, 1, 7, 1};
    assert_contains(decode_error(par, 4, 2), "USER parameter 3 (par[2]) is 7",
                    "code (1 to 5) of term 2");
    const double fractional[] = {1.5, 1, 1, 1};
    assert_contains(decode_error(fractional, 4, 2), "par[0]) is 1.5", "an integer");
}

static void polynomial_degree_out_of_range(void **state)
{
    (void)state;
    const double par[] = {2, 7, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    assert_contains(decode_error(par, 12, 2), "term 1 (code 2)", "par[1]) is 7",
                    "degree n of a code-2 polynomial", "from 0 to 6");
    const double negative[] = {1, 1, 2, -1, 1};
    assert_contains(decode_error(negative, 5, 2), "par[3]) is -1");
}

static void spline_needs_two_points(void **state)
{
    (void)state;
    const double par[] = {3, 1, 0, 0, 1, 1};
    assert_contains(decode_error(par, 6, 2), "point count n of a code-3 spline", "from 2");
}

static void spline_x_must_increase(void **state)
{
    (void)state;
    const double par[] = {1, 1, 3, 3, 0, 0, 1, 1, 1, 2};
    assert_contains(decode_error(par, 10, 2), "term 2 (code 3)", "USER parameter 5",
                    "point 3", "strictly increasing");
}

static void huge_point_count_is_refused_before_allocating(void **state)
{
    (void)state;
    const double par[] = {3, 1e9, 0, 0, 1, 1};
    assert_contains(decode_error(par, 6, 2), "2000000000 values", "only 4 remain");
}

static void missing_or_malformed_table_file(void **state)
{
    (void)state;
    const double missing[] = {4, 200, 1.0, 1, 1};
    assert_contains(decode_error(missing, 5, 2), "term 1 (code 4)", "cannot open table file",
                    "no-such-table.tbl");
    const double no_string[] = {4, 42, 1.0, 1, 1};
    assert_contains(decode_error(no_string, 5, 2), "no Reference_String 42");
    snprintf(table_path, sizeof table_path, "%s",
             test_write_file("bad.tbl", "# x y\n0 0\n1 1\n2 two\n"));
    const double bad[] = {4, 100, 1.0, 1, 1};
    assert_contains(decode_error(bad, 5, 2), "bad.tbl", "line 4", "'2 two'");
    snprintf(table_path, sizeof table_path, "%s",
             test_write_file("unsorted.tbl", "0 0\n2 1\n1 2\n"));
    assert_contains(decode_error(bad, 5, 2), "unsorted.tbl", "point 3", "strictly increasing");
    snprintf(table_path, sizeof table_path, "%s", test_write_file("empty.tbl", "# nothing\n"));
    assert_contains(decode_error(bad, 5, 2), "empty.tbl", "no 'x y' rows");
    snprintf(table_path, sizeof table_path, "%s", test_write_file("three.tbl", "0 0 0\n1 1\n"));
    assert_contains(decode_error(bad, 5, 2), "three.tbl", "line 1");
}

static void non_finite_parameter(void **state)
{
    (void)state;
    const double par[] = {1, NAN, 1, 2};
    assert_contains(decode_error(par, 4, 2), "USER parameter 2 (par[1]) is nan", "slope s");
    const double inf[] = {1, 1, 5, 1, INFINITY, 0};
    assert_contains(decode_error(inf, 6, 2), "par[4]) is inf", "frequency w");
}

static void ndisp_outside_two_to_three(void **state)
{
    (void)state;
    const double par[] = {1, 1, 1, 1, 1, 1, 1, 1};
    assert_contains(decode_error(par, 8, 4), "ndisp is 4", "2 or 3 joints");
    assert_contains(decode_error(par, 2, 1), "ndisp is 1");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(linear_and_polynomial_terms),
        cmocka_unit_test(inline_spline_term),
        cmocka_unit_test(table_file_term),
        cmocka_unit_test(sine_term),
        cmocka_unit_test(three_terms_against_finite_differences),
        cmocka_unit_test(term_count_must_equal_ndisp),
        cmocka_unit_test(unknown_code),
        cmocka_unit_test(polynomial_degree_out_of_range),
        cmocka_unit_test(spline_needs_two_points),
        cmocka_unit_test(spline_x_must_increase),
        cmocka_unit_test(huge_point_count_is_refused_before_allocating),
        cmocka_unit_test(missing_or_malformed_table_file),
        cmocka_unit_test(non_finite_parameter),
        cmocka_unit_test(ndisp_outside_two_to_three),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
