/*
 * The utilities the harness answers beyond the state queries
 * (docs/interface.md §5.2), called as a library calls them:
 * - STEP, STEP5, HAVSIN, IMPACT, BISTOP, POLY, CHEBY, FORCOS, FORSIN, SHF at
 *   values worked by hand, and every first and second derivative against
 *   central differences at points that vary every argument;
 * - arguments they refuse set the error flag;
 * - RCNVRT: hand-worked matrices, round trips between every pair of the
 *   systems at random rotations, a conversion in place, and EULER as the
 *   angles DISP answers;
 * - the Fortran forms (by address, blank-padded names) give the C forms'
 *   answers.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "host/utilities.h"
#include "frames/measures.h"
#include "test_support.h"
#include "usrsub/solver_abi.h"

/* One of the function utilities with its arguments gathered: the value or a
 * derivative of order iord in the first argument (x), or in dxdt (slot 1 of
 * a stop's vector). */
typedef struct case_ {
    const char *name;
    int kind; /* 0 transition, 1 stop, 2 coefficients, 3 Fourier, 4 SHF */
    void (*transition)(double, double, double, double, double, int, double *, int *);
    double a[8];
    double par[4];
    int npar;
} case_;

static double value_of(const case_ *c, double x, double dxdt, int iord, int slot)
{
    double out[3] = {0, 0, 0};
    int err = -1;
    const double *a = c->a;
    switch (c->kind) {
    case 0: c->transition(x, a[0], a[1], a[2], a[3], iord, out, &err); break;
    case 1:
        if (strcmp(c->name, "IMPACT") == 0)
            c_impact(x, dxdt, a[0], a[1], a[2], a[3], a[4], iord, out, &err);
        else
            c_bistop(x, dxdt, a[0], a[1], a[2], a[3], a[4], a[5], iord, out, &err);
        break;
    case 2:
        (strcmp(c->name, "POLY") == 0 ? c_poly : c_cheby)(x, a[0], c->par, c->npar, iord, out,
                                                           &err);
        break;
    case 3:
        (strcmp(c->name, "FORCOS") == 0 ? c_forcos : c_forsin)(x, a[0], a[1], c->par, c->npar,
                                                               iord, out, &err);
        break;
    default: c_shf(x, a[0], a[1], a[2], a[3], a[4], iord, out, &err); break;
    }
    assert_int_equal(err, 0);
    return out[slot];
}

static void values_worked_by_hand(void **state)
{
    (void)state;
    double v[3];
    int err;
    /* STEP(0.5; 0, 1, 1, 3): 1 + 2 (0.25 (3 - 1)) = 2; slope 2 * 6 * 0.25 = 3 */
    c_step(0.5, 0, 1, 1, 3, 0, v, &err);
    assert_close(v[0], 2.0, 1e-15, 0);
    c_step(0.5, 0, 1, 1, 3, 1, v, &err);
    assert_close(v[0], 3.0, 1e-15, 0);
    c_step(-1, 0, 1, 1, 3, 0, v, &err);
    assert_close(v[0], 1.0, 0, 0);
    c_step(7, 0, 1, 1, 3, 0, v, &err);
    assert_close(v[0], 3.0, 0, 0);
    /* STEP5 at a quarter: 0.25^3 (10 - 3.75 + 0.375) */
    c_step5(0.25, 0, 0, 1, 1, 0, v, &err);
    assert_close(v[0], 0.103515625, 1e-15, 0);
    /* HAVSIN half way: the mean */
    c_havsin(0.5, 0, 0, 1, 2, 0, v, &err);
    assert_close(v[0], 1.0, 1e-15, 0);
    /* IMPACT: 0.5 into a stop of 100 (e 2) closing at 2: 25 + 10 * 2 = 45;
     * in the damping's ramp (0.05 of 0.1: half of cmax) 0.25 + 5 * 1; never
     * pulling */
    c_impact(0.5, -2.0, 1.0, 100, 2, 10, 0.1, 0, v, &err);
    assert_close(v[0], 45.0, 1e-15, 0);
    c_impact(0.5, -2.0, 1.0, 100, 2, 10, 0.1, 1, v, &err);
    assert_close(v[0], -100.0, 1e-15, 0);
    assert_close(v[1], -10.0, 1e-15, 0);
    c_impact(0.95, -1.0, 1.0, 100, 2, 10, 0.1, 0, v, &err);
    assert_close(v[0], 5.25, 1e-14, 0);
    c_impact(0.95, 10.0, 1.0, 100, 2, 10, 0.1, 0, v, &err);
    assert_close(v[0], 0.0, 0, 0);
    c_impact(1.5, -1.0, 1.0, 100, 2, 10, 0.1, 0, v, &err);
    assert_close(v[0], 0.0, 0, 0);
    /* BISTOP: free between the stops, pushed back beyond the upper one */
    c_bistop(1.5, 3.0, 1.0, 2.0, 100, 1, 10, 0.1, 0, v, &err);
    assert_close(v[0], 0.0, 0, 0);
    c_bistop(2.5, 0.0, 1.0, 2.0, 100, 1, 10, 0.1, 0, v, &err);
    assert_close(v[0], -50.0, 1e-15, 0);
    c_bistop(0.5, 0.0, 1.0, 2.0, 100, 1, 10, 0.1, 0, v, &err);
    assert_close(v[0], 50.0, 1e-15, 0);
    /* POLY 1 + 2u + 3u^2 at u = 1: 6, 8, 6 */
    const double p3[3] = {1, 2, 3}, poly_expected[3] = {6, 8, 6};
    for (int k = 0; k < 3; ++k) {
        c_poly(2.0, 1.0, p3, 3, k, v, &err);
        assert_close(v[0], poly_expected[k], 1e-15, 0);
    }
    /* CHEBY T0 + T1 + T2 at 0.5: 1 + 0.5 - 0.5; slopes 1 + 2; T2'' = 4 */
    const double ones[3] = {1, 1, 1}, cheby_expected[3] = {1, 3, 4};
    for (int k = 0; k < 3; ++k) {
        c_cheby(0.5, 0.0, ones, 3, k, v, &err);
        assert_close(v[0], cheby_expected[k], 1e-15, 0);
    }
    /* FORCOS / FORSIN 1 + 2 f(pi/2); SHF 2 sin(pi - pi/2) + 1 */
    const double fc[2] = {1, 2};
    c_forcos(1.0, 0.0, M_PI / 2, fc, 2, 0, v, &err);
    assert_close(v[0], 1.0, 0, 1e-15);
    c_forsin(1.0, 0.0, M_PI / 2, fc, 2, 0, v, &err);
    assert_close(v[0], 3.0, 1e-15, 0);
    /* the harmonics' index: 1 + 2 f(pi/4) + 3 f(2 pi/4) */
    const double f3[3] = {1, 2, 3};
    c_forcos(1.0, 0.0, M_PI / 4, f3, 3, 0, v, &err);
    assert_close(v[0], 1.0 + sqrt(2.0), 1e-15, 0);
    c_forsin(1.0, 0.0, M_PI / 4, f3, 3, 0, v, &err);
    assert_close(v[0], 4.0 + sqrt(2.0), 1e-15, 0);
    c_forcos(1.0, 0.0, M_PI / 4, f3, 3, 1, v, &err); /* -2 w sin(w) - 3 (2w) sin(2w) */
    assert_close(v[0], -2 * M_PI / 4 * sin(M_PI / 4) - 3 * M_PI / 2, 1e-14, 0);
    c_shf(1.0, 0.0, 2.0, M_PI, M_PI / 2, 1.0, 0, v, &err);
    assert_close(v[0], 3.0, 1e-15, 0);
}

static void every_derivative_against_differences(void **state)
{
    (void)state;
    const case_ cases[] = {
        {"STEP", 0, c_step, {0.3, -1.2, 2.1, 4.5}, {0}, 0},
        {"STEP5", 0, c_step5, {0.3, -1.2, 2.1, 4.5}, {0}, 0},
        {"HAVSIN", 0, c_havsin, {0.3, -1.2, 2.1, 4.5}, {0}, 0},
        {"IMPACT", 1, NULL, {2.0, 300.0, 2.2, 15.0, 0.4}, {0}, 0},
        {"BISTOP", 1, NULL, {1.0, 1.6, 300.0, 1.5, 15.0, 0.4}, {0}, 0},
        {"POLY", 2, NULL, {0.7}, {1.5, -2.0, 0.75, 0.3}, 4},
        {"CHEBY", 2, NULL, {0.2}, {1.5, -2.0, 0.75, 0.3}, 4},
        {"FORCOS", 3, NULL, {0.2, 1.7}, {0.5, -1.0, 0.3, 0.8}, 4},
        {"FORSIN", 3, NULL, {0.2, 1.7}, {0.5, -1.0, 0.3, 0.8}, 4},
        {"SHF", 4, NULL, {0.2, 1.3, 2.9, 0.4, -0.6}, {0}, 0},
    };
    /* points across each function's pieces: a stop's free side, its damping
     * ramp and beyond it; both stops of BISTOP */
    const double xs[] = {0.55, 1.05, 1.67, 1.85, 2.3, 3.7};
    const double rates[] = {-2.3, 0.7};
    double worst = 0.0;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c)
        for (size_t i = 0; i < sizeof xs / sizeof xs[0]; ++i)
            for (size_t r = 0; r < 2; ++r) {
                const double x = xs[i], dxdt = rates[r], h = 1e-6;
                const case_ *k = &cases[c];
                /* d/dx of the value and of the slope in x */
                for (int order = 1; order <= 2; ++order) {
                    const double fd = (value_of(k, x + h, dxdt, order - 1, 0) -
                                       value_of(k, x - h, dxdt, order - 1, 0)) / (2 * h);
                    const double exact = value_of(k, x, dxdt, order, 0);
                    const double e = fabs(exact - fd) / fmax(1.0, fabs(fd));
                    worst = fmax(worst, e);
                    if (e > 1e-5)
                        fail_msg("%s at x = %g, dxdt = %g: derivative %d is %.10g, differences"
                                 " %.10g", k->name, x, dxdt, order, exact, fd);
                }
                if (k->kind != 1)
                    continue;
                /* a stop's slope in dxdt, and the mixed and dxdt second derivatives */
                const double fd1 = (value_of(k, x, dxdt + h, 0, 0) -
                                    value_of(k, x, dxdt - h, 0, 0)) / (2 * h);
                const double fd2 = (value_of(k, x, dxdt + h, 1, 0) -
                                    value_of(k, x, dxdt - h, 1, 0)) / (2 * h);
                const double fd3 = (value_of(k, x, dxdt + h, 1, 1) -
                                    value_of(k, x, dxdt - h, 1, 1)) / (2 * h);
                const double got[3] = {value_of(k, x, dxdt, 1, 1), value_of(k, x, dxdt, 2, 1),
                                       value_of(k, x, dxdt, 2, 2)};
                const double want[3] = {fd1, fd2, fd3};
                for (int j = 0; j < 3; ++j) {
                    const double e = fabs(got[j] - want[j]) / fmax(1.0, fabs(want[j]));
                    worst = fmax(worst, e);
                    if (e > 1e-5)
                        fail_msg("%s at x = %g, dxdt = %g: dxdt derivative %d is %.10g,"
                                 " differences %.10g", k->name, x, dxdt, j, got[j], want[j]);
                }
            }
    printf("  10 functions at 12 points: every derivative within %.2g of differences\n", worst);
}

static void refused_arguments_set_the_flag(void **state)
{
    (void)state;
    double v[3] = {0, 0, 0};
    const double par[2] = {1, 2};
    int err = 0;
    c_step(0.5, 1.0, 0, 1.0, 1, 0, v, &err); /* x1 = x0 */
    assert_int_equal(err, 1);
    c_step5(0.5, 0.0, 0, 1.0, 1, 3, v, &err); /* iord 3 */
    assert_int_equal(err, 1);
    c_impact(0.5, 0, 1, -1, 2, 1, 0.1, 0, v, &err); /* k < 0 */
    assert_int_equal(err, 1);
    c_bistop(0.5, 0, 2, 1, 1, 2, 1, 0.1, 0, v, &err); /* x2 < x1 */
    assert_int_equal(err, 1);
    c_step(NAN, 0.0, 0, 1.0, 1, 0, v, &err); /* a non-finite argument */
    assert_int_equal(err, 1);
    c_impact(0.5, INFINITY, 1, 1, 2, 1, 0.1, 0, v, &err);
    assert_int_equal(err, 1);
    c_poly(0.5, 0, par, 0, 0, v, &err); /* no coefficient */
    assert_int_equal(err, 1);
    c_cheby(0.5, 0, par, 40, 0, v, &err); /* more than 31 */
    assert_int_equal(err, 1);
    int istat = 0;
    c_rcnvrt("EULER", par, "QUATERNION", v, &istat);
    assert_int_equal(istat, 1);
    const double zero[4] = {0, 0, 0, 0};
    c_rcnvrt("EULPAR", zero, "COSINES", v, &istat);
    assert_int_equal(istat, 1);
    double gone = 0.0;
    c_gtaray(5, &gone, (int[]){1}, &istat); /* outside any call: no model */
    assert_int_equal(istat, 1);
}

/* ---- rotational coordinates ---------------------------------------------------------- */

static void matrix_of(const char *sys, const double *coord, double A[9])
{
    int istat = -1;
    c_rcnvrt(sys, coord, "COSINES", A, &istat);
    assert_int_equal(istat, 0);
}

static void rotations_convert_between_every_system(void **state)
{
    (void)state;
    /* a quarter turn about z: the x axis goes to y (a21 = 1), y to -x */
    double A[9];
    matrix_of("EULER", (double[]){M_PI / 2, 0, 0}, A);
    const double quarter[9] = {0, 1, 0, -1, 0, 0, 0, 0, 1};
    for (int k = 0; k < 9; ++k)
        assert_close(A[k], quarter[k], 0, 1e-15);
    matrix_of("EULPAR", (double[]){cos(M_PI / 4), 0, 0, sin(M_PI / 4)}, A);
    for (int k = 0; k < 9; ++k)
        assert_close(A[k], quarter[k], 0, 1e-15);
    matrix_of("RODPAR", (double[]){0, 0, 1}, A); /* tan(pi/4) about z */
    for (int k = 0; k < 9; ++k)
        assert_close(A[k], quarter[k], 0, 1e-15);
    /* YPR and AXAYAZ are one matrix, written in reverse */
    double B[9];
    matrix_of("YPR", (double[]){0.3, -0.2, 0.5}, A);
    matrix_of("AXAYAZ", (double[]){0.5, -0.2, 0.3}, B);
    for (int k = 0; k < 9; ++k)
        assert_close(A[k], B[k], 0, 1e-15);
    /* BRYANT = B123: Rx Ry Rz; a21 of Rx(a) Ry(b) = sin a sin b */
    matrix_of("BRYANT", (double[]){0.4, 0.7, 0.0}, A);
    assert_close(A[1], sin(0.4) * sin(0.7), 1e-15, 0);

    /* round trips between every pair, at random rotations */
    static const char *const systems[] = {"EULER", "EULPAR", "RODPAR", "AXAYAZ", "YPR",
                                          "COSINES", "BRYANT", "B313", "B321", "B312",
                                          "B323", "B123", "B121", "B131", "B212", "B213",
                                          "B231", "B232", "B132"};
    const int ns = sizeof systems / sizeof systems[0];
    unsigned seed = 7;
    double worst = 0.0;
    for (int t = 0; t < 40; ++t) {
        double q[4], n = 0.0;
        for (int k = 0; k < 4; ++k) {
            seed = seed * 1664525u + 1013904223u;
            q[k] = (seed >> 8) / 8388608.0 - 1.0;
            n += q[k] * q[k];
        }
        for (int k = 0; k < 4; ++k)
            q[k] /= sqrt(n);
        double R0[9];
        matrix_of("EULPAR", q, R0);
        for (int a = 0; a < ns; ++a)
            for (int b = 0; b < ns; ++b) {
                double ca[9], cb[9], R[9];
                int istat = -1;
                c_rcnvrt("COSINES", R0, systems[a], ca, &istat);
                assert_int_equal(istat, 0);
                c_rcnvrt(systems[a], ca, systems[b], cb, &istat);
                assert_int_equal(istat, 0);
                matrix_of(systems[b], cb, R);
                for (int k = 0; k < 9; ++k)
                    worst = fmax(worst, fabs(R[k] - R0[k]));
            }
    }
    printf("  %d systems, 40 random rotations: every round trip within %.2g\n", ns, worst);
    assert_true(worst < 1e-13);

    /* the sequences where their first and last axes line up (middle angle 0
     * or pi of a proper Euler sequence, +-pi/2 of a Tait-Bryan one), and just
     * off it: the angles differ, the rotation comes back */
    double lock = 0.0;
    for (int a = 7; a < ns; ++a) {
        const int proper = systems[a][1] == systems[a][3];
        const double middles[3] = {proper ? 0.0 : M_PI / 2, proper ? M_PI : -M_PI / 2,
                                   (proper ? M_PI : M_PI / 2) - 1.5e-12};
        for (int k = 0; k < 3; ++k) {
            const double angles[3] = {0.3, middles[k], -0.4};
            double R[9], back[3], R2[9];
            int istat = -1;
            matrix_of(systems[a], angles, R);
            c_rcnvrt("COSINES", R, systems[a], back, &istat);
            assert_int_equal(istat, 0);
            matrix_of(systems[a], back, R2);
            for (int i = 0; i < 9; ++i)
                lock = fmax(lock, fabs(R2[i] - R[i]));
        }
    }
    printf("  12 sequences with their axes lined up: every round trip within %.2g\n", lock);
    assert_true(lock < 1e-11);

    /* in place, blank-padded as from Fortran */
    double c[9] = {0.3, 1.1, -0.4};
    double expected[9];
    int istat = -1;
    c_rcnvrt("EULER", c, "COSINES", expected, &istat);
    c_rcnvrt("EULER   ", c, "COSINES ", c, &istat);
    assert_int_equal(istat, 0);
    for (int k = 0; k < 9; ++k)
        assert_true(c[k] == expected[k]);

    /* EULER is what DISP answers: the harness's own 3-1-3 angles of a matrix */
    double e[3] = {0.3, 1.1, -0.4}, R[9], back[3];
    matrix_of("EULER", e, A);
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            R[3 * r + k] = A[r + 3 * k];
    hx_euler313(R, back);
    for (int k = 0; k < 3; ++k)
        assert_close(back[k], e[k], 0, 1e-14);
}

/* ---- the Fortran forms ----------------------------------------------------------------- */

void step_(const double *, const double *, const double *, const double *, const double *,
           const int *, double *, int *);
void impact_(const double *, const double *, const double *, const double *, const double *,
             const double *, const double *, const int *, double *, int *);
void rcnvrt_(const char *, const double *, const char *, double *, int *, size_t, size_t);
void gtunts_(int *, double *, char *, size_t);

static void fortran_forms_answer_as_the_c_ones(void **state)
{
    (void)state;
    const double x = 0.5, x0 = 0, h0 = 1, x1 = 1, h1 = 3;
    const int one = 1;
    double v = 0, w = 0;
    int err = -1, cerr = -1;
    step_(&x, &x0, &h0, &x1, &h1, &one, &v, &err);
    c_step(x, x0, h0, x1, h1, 1, &w, &cerr);
    assert_int_equal(err, 0);
    assert_true(v == w);
    const double xi = 0.5, xd = -2, stop = 1, k = 100, e = 2, cmax = 10, d = 0.1;
    const int zero = 0;
    double f[3] = {0, 0, 0};
    impact_(&xi, &xd, &stop, &k, &e, &cmax, &d, &zero, f, &err);
    assert_close(f[0], 45.0, 1e-15, 0);
    /* names blank-padded to their declared length, and not terminated */
    const char sys1[8] = {'E', 'U', 'L', 'E', 'R', ' ', ' ', ' '};
    const char sys2[8] = {'E', 'U', 'L', 'P', 'A', 'R', ' ', ' '};
    const double angles[3] = {M_PI / 2, 0, 0};
    double q[4];
    int istat = -1;
    rcnvrt_(sys1, angles, sys2, q, &istat, sizeof sys1, sizeof sys2);
    assert_int_equal(istat, 0);
    assert_close(q[0], cos(M_PI / 4), 1e-15, 0);
    assert_close(q[3], sin(M_PI / 4), 1e-15, 0);
    /* outside any call the model has no units: exists false, the text left blank */
    int exists = 1;
    double scales[4] = {0, 0, 0, 0};
    char units[20];
    memset(units, 'x', sizeof units);
    gtunts_(&exists, scales, units, sizeof units);
    assert_int_equal(exists, 0);
    for (size_t i = 0; i < sizeof units; ++i)
        assert_int_equal(units[i], ' ');
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(values_worked_by_hand),
        cmocka_unit_test(every_derivative_against_differences),
        cmocka_unit_test(refused_arguments_set_the_flag),
        cmocka_unit_test(rotations_convert_between_every_system),
        cmocka_unit_test(fortran_forms_answer_as_the_c_ones),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
