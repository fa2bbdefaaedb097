/*
 * The envelope Cholesky (harness/base/envelope.c) that solves the
 * multipliers' matrix of long chains: a factor worked by hand, a solve
 * against the dense product, and a matrix that is not positive definite.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "base/envelope.h"

/* A = [[4, 2, 0], [2, 5, 3], [0, 3, 10]] (envelope: row 0 from 0, row 1 from
 * 0, row 2 from 1). By hand: L00 = 2, L10 = 2/2 = 1, L11 = sqrt(5 - 1) = 2,
 * L21 = 3/2 = 1.5, L22 = sqrt(10 - 2.25) = sqrt(7.75). */
static void a_factor_worked_by_hand(void **state)
{
    (void)state;
    const int first[3] = {0, 0, 1};
    size_t start[4];
    hx_envelope_layout(3, first, start);
    assert_int_equal(start[3], 5); /* 1 + 2 + 2 values */
    double v[5] = {4, 2, 5, 3, 10};
    assert_int_equal(hx_envelope_factor(3, first, start, v), 0);
    const double want[5] = {2, 1, 2, 1.5, sqrt(7.75)};
    for (int k = 0; k < 5; ++k)
        assert_true(fabs(v[k] - want[k]) < 1e-15);
    /* A x = b with x = (1, -2, 3): b = (0, 1, 24) */
    double b[3] = {0, 1, 24};
    hx_envelope_solve(3, first, start, v, b);
    assert_true(fabs(b[0] - 1) < 1e-14 && fabs(b[1] + 2) < 1e-14 && fabs(b[2] - 3) < 1e-14);
}

/* A banded matrix with an irregular envelope (rows reaching back 0..3
 * columns), diagonally dominant: the solve's x times the dense A gives b back. */
static void a_solve_returns_the_right_hand_side(void **state)
{
    (void)state;
    enum { N = 40 };
    int first[N];
    size_t start[N + 1];
    double A[N][N] = {{0}};
    for (int i = 0; i < N; ++i) {
        first[i] = i - (i * 7) % 4 < 0 ? 0 : i - (i * 7) % 4;
        for (int j = first[i]; j < i; ++j)
            A[i][j] = A[j][i] = sin(1.0 + i * 0.37 + j * 1.1);
    }
    for (int i = 0; i < N; ++i) /* rows above i may reach it: sum the whole row */
        for (int j = 0; j < N; ++j)
            A[i][i] += j != i ? fabs(A[i][j]) : 0.5;
    hx_envelope_layout(N, first, start);
    double *v = malloc(sizeof(double) * start[N]);
    assert_non_null(v);
    for (int i = 0; i < N; ++i)
        for (int j = first[i]; j <= i; ++j)
            *hx_envelope_at(first, start, v, i, j) = A[i][j];
    double x[N], b[N];
    for (int i = 0; i < N; ++i)
        b[i] = x[i] = cos(0.3 * i) - 0.2 * i;
    assert_int_equal(hx_envelope_factor(N, first, start, v), 0);
    hx_envelope_solve(N, first, start, v, x);
    for (int i = 0; i < N; ++i) {
        double s = 0.0;
        for (int j = 0; j < N; ++j)
            s += A[i][j] * x[j];
        assert_true(fabs(s - b[i]) < 1e-12 * (1.0 + fabs(b[i])));
    }
    free(v);
}

/* [[1, 2], [2, 1]] has eigenvalues 3 and -1: refused, not a NaN factor. */
static void an_indefinite_matrix_is_refused(void **state)
{
    (void)state;
    const int first[2] = {0, 0};
    size_t start[3];
    hx_envelope_layout(2, first, start);
    double v[3] = {1, 2, 1};
    assert_int_equal(hx_envelope_factor(2, first, start, v), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_factor_worked_by_hand),
        cmocka_unit_test(a_solve_returns_the_right_hand_side),
        cmocka_unit_test(an_indefinite_matrix_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
