/*
 * The exact partials of function expressions (docs/interface.md §8.6): every
 * function's, by the adjoint sweep and by forward accumulation, against
 * central differences at points that vary every argument away from kinks;
 * the values at kinks (the mean of the one-sided slopes, or 0 where a
 * function is flat or jumps) against the one-sided differences; only IF's
 * branch contributes; a partial that is not finite faults only where it is
 * used; one program evaluated by four threads at once.
 */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/cubic_curve.h"
#include "expr_support.h"

static expr_fixture fixture;

/* A surface: spline 103, y = x^2 at z = 0 and y = x^3 / 4 + x at z = 2, x = 0 .. 4. */
static void add_surface(hx_model *m)
{
    m->splines = realloc(m->splines, sizeof *m->splines * (size_t)(m->nsplines + 1));
    hx_spline *s = &m->splines[m->nsplines++];
    memset(s, 0, sizeof *s);
    s->id = 103, s->nx = 5, s->nz = 2;
    s->x = malloc(sizeof(double) * 5), s->z = malloc(sizeof(double) * 2);
    s->y = malloc(sizeof(double) * 10);
    s->akima_slope = malloc(sizeof(double) * 10), s->cubic_slope = malloc(sizeof(double) * 10);
    s->z[0] = 0.0, s->z[1] = 2.0;
    for (int k = 0; k < 5; ++k) {
        s->x[k] = k;
        s->y[k] = k * k, s->y[5 + k] = k * k * k / 4.0 + k;
    }
    for (int j = 0; j < 2; ++j) {
        hx_akima_slopes(s->x, s->y + 5 * j, 5, s->akima_slope + 5 * j);
        assert_int_equal(hx_natural_cubic_slopes(s->x, s->y + 5 * j, 5, s->cubic_slope + 5 * j),
                         0);
    }
}

static void add_curve(hx_model *m)
{
    m->curves = realloc(m->curves, sizeof *m->curves);
    m->ncurves = 1;
    hx_curve *c = &m->curves[0];
    static const double points[15] = {0, 0, 0, 1, 2, 0, 3, 2, 1, 4, 0, 0, 5, 1, -1};
    *c = (hx_curve){.id = 2, .order = 4, .npoints = 5, .points = malloc(sizeof points)};
    memcpy(c->points, points, sizeof points);
}

static int setup(void **state)
{
    (void)state;
    expr_open(&fixture, "partials.xml", expr_function_model);
    add_surface(fixture.model);
    add_curve(fixture.model);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    expr_close(&fixture);
    return 0;
}

/* text at the variables given (VARVAL(1) = v[0], ...). */
static void check(const char *text, const double *v, int n)
{
    for (int k = 0; k < n; ++k)
        fixture.variables[k] = v[k];
    expr_check_partials(&fixture, text, 1e-6);
}

#define CHECK(text, ...) check(text, (const double[]){__VA_ARGS__}, \
                               (int)(sizeof((const double[]){__VA_ARGS__}) / sizeof(double)))

static void operators_and_elementary_functions(void **state)
{
    (void)state;
    CHECK("VARVAL(1) + VARVAL(2)", 1.3, -0.7);
    CHECK("VARVAL(1) - VARVAL(2)", 1.3, -0.7);
    CHECK("VARVAL(1) * VARVAL(2)", 1.3, -0.7);
    CHECK("VARVAL(1) / VARVAL(2)", 1.3, -0.7);
    CHECK("VARVAL(1) ** VARVAL(2)", 1.3, -0.7);
    CHECK("VARVAL(1) ** 3", -1.3);
    CHECK("-VARVAL(1) * 2", 1.3);
    CHECK("ABS(VARVAL(1))", -1.3);
    CHECK("SIGN(VARVAL(1), VARVAL(2))", -1.2, 0.7);
    CHECK("SIGN(VARVAL(1), VARVAL(2))", 1.2, -0.7);
    CHECK("MIN(VARVAL(1), VARVAL(2))", 1.1, 2.3);
    CHECK("MIN(VARVAL(1), VARVAL(2))", 2.4, 2.3);
    CHECK("MAX(VARVAL(1), VARVAL(2))", 1.1, 2.3);
    CHECK("MAX(VARVAL(1), VARVAL(2))", 2.4, 2.3);
    CHECK("MOD(VARVAL(1), VARVAL(2))", 7.3, 2.1);  /* d/da2 = -AINT(7.3/2.1) = -3 */
    CHECK("MOD(VARVAL(1), VARVAL(2))", -7.3, 2.1);
    CHECK("DIM(VARVAL(1), VARVAL(2))", 5.1, 3.2);
    CHECK("DIM(VARVAL(1), VARVAL(2))", 3.1, 3.2);
    CHECK("SQRT(VARVAL(1))", 2.3);
    CHECK("EXP(VARVAL(1))", 0.7);
    CHECK("LOG(VARVAL(1))", 2.3);
    CHECK("LOG10(VARVAL(1))", 2.3);
    CHECK("SIN(VARVAL(1)) + COS(2*VARVAL(1)) + TAN(VARVAL(1)/2)", 0.7);
    CHECK("ASIN(VARVAL(1)) * ACOS(VARVAL(2))", 0.3, -0.4);
    CHECK("ATAN(VARVAL(1))", 1.7);
    for (int q = 0; q < 4; ++q) /* the four quadrants */
        CHECK("ATAN2(VARVAL(1), VARVAL(2))", q < 2 ? 0.6 : -0.6, q % 2 ? 1.1 : -1.1);
    CHECK("SINH(VARVAL(1)) + COSH(VARVAL(1)) * TANH(VARVAL(1))", 0.6);
    CHECK("AINT(VARVAL(1)) + ANINT(VARVAL(1)) * VARVAL(1)", 2.7);
}

static void transitions_and_stops(void **state)
{
    (void)state;
    static const char *const names[3] = {"STEP", "STEP5", "HAVSIN"};
    for (int k = 0; k < 3; ++k) {
        char text[128];
        snprintf(text, sizeof text, "%s(VARVAL(1), VARVAL(2), VARVAL(3), VARVAL(4), VARVAL(5))",
                 names[k]);
        CHECK(text, 1.3, 0.9, -1.2, 2.1, 3.4);  /* inside */
        CHECK(text, 0.3, 0.9, -1.2, 2.1, 3.4);  /* before */
        CHECK(text, 2.3, 0.9, -1.2, 2.1, 3.4);  /* beyond */
    }
    const char *impact = "IMPACT(VARVAL(1), VARVAL(2), VARVAL(3), VARVAL(4), VARVAL(5),"
                         " VARVAL(6), VARVAL(7))";
    CHECK(impact, 0.95, -2.0, 1.0, 100.0, 2.3, 10.0, 0.1);  /* inside the ramp */
    CHECK(impact, 0.8, 0.1, 1.0, 100.0, 1.7, 10.0, 0.1);    /* beyond it */
    CHECK(impact, 1.2, -2.0, 1.0, 100.0, 2.3, 10.0, 0.1);   /* clear */
    const char *bistop = "BISTOP(VARVAL(1), VARVAL(2), VARVAL(3), VARVAL(4), VARVAL(5),"
                         " VARVAL(6), VARVAL(7), VARVAL(8))";
    CHECK(bistop, -1.05, -2.0, -1.0, 1.0, 100.0, 1.5, 10.0, 0.1);
    CHECK(bistop, -1.3, -2.0, -1.0, 1.0, 100.0, 2.5, 10.0, 0.1);
    CHECK(bistop, 1.05, 2.0, -1.0, 1.0, 100.0, 1.5, 10.0, 0.1);
    CHECK(bistop, 1.2, 0.5, -1.0, 1.0, 100.0, 1.5, 10.0, 0.1);
    CHECK(bistop, 0.2, 0.5, -1.0, 1.0, 100.0, 1.5, 10.0, 0.1);
}

static void series(void **state)
{
    (void)state;
    CHECK("POLY(VARVAL(1), VARVAL(2), VARVAL(3), VARVAL(4), VARVAL(5), VARVAL(6), VARVAL(7))",
          1.7, 0.4, 1.0, -2.0, 0.5, 2.0, -0.3);
    CHECK("CHEBY(VARVAL(1), VARVAL(2), VARVAL(3), VARVAL(4), VARVAL(5), VARVAL(6), VARVAL(7))",
          1.2, 0.4, 1.0, -2.0, 0.5, 2.0, -0.3);
    CHECK("FORCOS(VARVAL(1), VARVAL(2), VARVAL(3), VARVAL(4), VARVAL(5), VARVAL(6), VARVAL(7))",
          0.3, 0.1, 5.0, 1.0, -2.0, 0.5, 2.0);
    CHECK("FORSIN(VARVAL(1), VARVAL(2), VARVAL(3), VARVAL(4), VARVAL(5), VARVAL(6), VARVAL(7))",
          0.3, 0.1, 5.0, 1.0, -2.0, 0.5, 2.0);
    CHECK("SHF(VARVAL(1), VARVAL(2), VARVAL(3), VARVAL(4), VARVAL(5), VARVAL(6))",
          0.8, 0.1, 2.0, 3.0, 0.4, -1.0);
}

/* AKISPL and CUBSPL in x and z on a surface (between its curves) and a
 * curve, every order; CURVE in alpha, every order. */
static void splines_and_curves(void **state)
{
    (void)state;
    for (int order = 0; order <= 2; ++order) {
        char text[128];
        snprintf(text, sizeof text, "AKISPL(VARVAL(1), VARVAL(2), 103, %d)", order);
        CHECK(text, 2.3, 0.7);
        snprintf(text, sizeof text, "CUBSPL(VARVAL(1), VARVAL(2), 103, %d)", order);
        CHECK(text, 1.4, 1.3);
        snprintf(text, sizeof text, "CUBSPL(VARVAL(1), VARVAL(2), 102, %d)", order);
        CHECK(text, 4.6, 1.3); /* beyond the knots: the end piece continued */
        snprintf(text, sizeof text, "AKISPL(VARVAL(1)**2, 0, 101, %d)", order);
        CHECK(text, 0.6);
        for (int comp = 1; comp <= 3; ++comp) {
            snprintf(text, sizeof text, "CURVE(VARVAL(1), %d, %d, 2)", order, comp);
            CHECK(text, 0.2);
            CHECK(text, -0.65);
        }
    }
}

/* IF: the branch taken alone; TIME an input like the others. */
static void branches_and_time(void **state)
{
    (void)state;
    const char *text = "IF(VARVAL(1) - 2: VARVAL(2)**2, VARVAL(3), 3*VARVAL(2)*VARVAL(1))";
    CHECK(text, 1.0, 1.7, -0.4); /* e1 < 0: d/dVARVAL(1) = 0, d/dVARVAL(2) = 3.4 */
    CHECK(text, 3.0, 1.7, -0.4); /* e1 > 0 */
    /* each branch with a condition the differences do not move (IC array 30 holds 1.5,
     * -2, 7): the middle one at e1 = 0 exactly too */
    static const char *const conditions[3] = {"ARYVAL(30, 2)", "ARYVAL(30, 1) - 1.5",
                                              "ARYVAL(30, 3)"};
    for (int k = 0; k < 3; ++k) {
        char branches[256];
        snprintf(branches, sizeof branches, "IF(%s: VARVAL(2)**2*VARVAL(1), VARVAL(3)*VARVAL(1),"
                 " 3*VARVAL(2)*VARVAL(1))", conditions[k]);
        CHECK(branches, 0.6, 1.7, -0.4);
    }
    fixture.frames.time = 0.4;
    CHECK("STEP(TIME, 0, 0, 1, 5) * SIN(TIME * VARVAL(1))", 2.0);
    fixture.frames.time = 0.0;
    /* the SFORCE law -k (DM - L) - c VR with the measures as variables */
    CHECK("-1e4*(VARVAL(1) - 0.25) - 50*VARVAL(2)", 0.27, -0.3);
}

/* The one-sided differences at x and the partial there. */
static void one_sided(const char *text, double x, double *left, double *right, double *partial)
{
    fixture.variables[0] = x;
    hx_expr_program *p = expr_compile(&fixture, text);
    const hx_expr_context c = expr_context(&fixture);
    double value, forward, scratch[512];
    hx_expr_fault fault;
    assert_true(hx_expr_scratch_size(p) <= 512);
    assert_int_equal(hx_expr_eval_partials(p, &c, &value, partial, scratch, &fault), 0);
    assert_int_equal(hx_expr_eval_partials_forward(p, &c, &value, &forward, scratch, &fault), 0);
    assert_close(forward, *partial, 0, 0);
    const double h = 1e-7;
    double up, down;
    fixture.variables[0] = x + h;
    assert_int_equal(hx_expr_eval(p, &c, &up, &fault), 0);
    fixture.variables[0] = x - h;
    assert_int_equal(hx_expr_eval(p, &c, &down, &fault), 0);
    *right = (up - value) / h, *left = (value - down) / h;
    hx_expr_free(p);
}

/* At a kink the partial is the mean of the one-sided slopes (ABS, MIN, MAX,
 * DIM); where a function jumps, 0 (SIGN in a2, AINT, ANINT); STEP at x0 and
 * x1 is smooth (0 on both sides); IMPACT where contact begins is smooth for
 * e > 1. */
static void kinks(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        double x, left, right, partial;
    } cases[] = {
        {"ABS(VARVAL(1))", 0.0, -1.0, 1.0, 0.0},
        {"MIN(VARVAL(1), 2)", 2.0, 1.0, 0.0, 0.5},
        {"MAX(VARVAL(1), 2)", 2.0, 0.0, 1.0, 0.5},
        {"DIM(VARVAL(1), 2)", 2.0, 0.0, 1.0, 0.5},
        {"DIM(3, VARVAL(1))", 3.0, -1.0, 0.0, -0.5},
        {"SIGN(VARVAL(1), 1)", 0.0, -1.0, 1.0, 0.0},
        {"STEP(VARVAL(1), 1, 2, 3, 6)", 1.0, 0.0, 0.0, 0.0},
        {"STEP5(VARVAL(1), 1, 2, 3, 6)", 3.0, 0.0, 0.0, 0.0},
        {"HAVSIN(VARVAL(1), 1, 2, 3, 6)", 1.0, 0.0, 0.0, 0.0},
        {"IMPACT(VARVAL(1), 0, 1, 100, 2, 10, 0.1)", 1.0, 0.0, 0.0, 0.0},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        double left, right, partial;
        one_sided(cases[k].text, cases[k].x, &left, &right, &partial);
        if (fabs(left - cases[k].left) > 1e-5 || fabs(right - cases[k].right) > 1e-5 ||
            partial != cases[k].partial)
            fail_msg("%s at %g: one-sided %.9g and %.9g, partial %.9g", cases[k].text,
                     cases[k].x, left, right, partial);
    }
    /* jumps: SIGN in a2, AINT, ANINT: 0 on either side and at the jump */
    double left, right, partial;
    one_sided("SIGN(2, VARVAL(1)) + AINT(VARVAL(1) + 3) + ANINT(VARVAL(1) - 0.5)", 0.25, &left,
              &right, &partial);
    assert_close(partial, 0.0, 0, 0);
    assert_close(left, 0.0, 0, 0);
}

/* A partial that is not finite faults where its argument depends on an
 * input, and nowhere else; the value's evaluation does not care. */
static void partials_that_are_not_finite(void **state)
{
    (void)state;
    fixture.variables[0] = 1.0;
    hx_expr_program *p = expr_compile(&fixture, "2 + SQRT(VARVAL(1) - 1)");
    const hx_expr_context c = expr_context(&fixture);
    double value, partials[4], scratch[64];
    hx_expr_fault fault;
    assert_int_equal(hx_expr_eval(p, &c, &value, &fault), 0);
    assert_close(value, 2.0, 0, 0);
    assert_int_equal(hx_expr_eval_partials(p, &c, &value, partials, scratch, &fault), -1);
    assert_int_equal(fault.kind, HX_EXPR_FAULT_PARTIAL);
    assert_string_equal(fault.function, "SQRT");
    assert_int_equal(fault.column, 5);
    assert_int_equal(hx_expr_eval_partials_forward(p, &c, &value, partials, scratch, &fault), -1);
    assert_int_equal(fault.kind, HX_EXPR_FAULT_PARTIAL);
    hx_expr_free(p);
    /* 0 ** VARVAL(1): the infinite partial in the base is not used (the base is a constant) */
    fixture.variables[0] = 0.5;
    p = expr_compile(&fixture, "0 ** VARVAL(1) + VARVAL(1)");
    assert_int_equal(hx_expr_eval_partials(p, &c, &value, partials, scratch, &fault), 0);
    assert_close(partials[0], 1.0, 0, 0);
    assert_int_equal(hx_expr_eval_partials_forward(p, &c, &value, partials, scratch, &fault), 0);
    assert_close(partials[0], 1.0, 0, 0);
    hx_expr_free(p);
    /* each term finite, their sum in one input not: a fault at the input (the fuzzer's
     * find, fuzz/corpus/expr/partial_sum_overflow) */
    fixture.variables[0] = 0.001, fixture.variables[1] = 1.0;
    p = expr_compile(&fixture, "1e308*VARVAL(1) + 1e308*VARVAL(2)*VARVAL(1)");
    assert_int_equal(hx_expr_eval(p, &c, &value, &fault), 0);
    assert_close(value, 2e305, 1e-15, 0);
    assert_int_equal(hx_expr_eval_partials(p, &c, &value, partials, scratch, &fault), -1);
    assert_int_equal(fault.kind, HX_EXPR_FAULT_PARTIAL);
    assert_string_equal(fault.function, "VARVAL");
    assert_int_equal(fault.column, 7);
    assert_int_equal(hx_expr_eval_partials_forward(p, &c, &value, partials, scratch, &fault), -1);
    assert_int_equal(fault.kind, HX_EXPR_FAULT_PARTIAL);
    hx_expr_free(p);
    /* a constant program has no inputs and no partials */
    p = expr_compile(&fixture, "2 * PI");
    assert_int_equal(hx_expr_input_count(p), 0);
    assert_int_equal(hx_expr_eval_partials(p, &c, &value, partials, scratch, &fault), 0);
    assert_close(value, 2.0 * M_PI, 0, 0);
    hx_expr_free(p);
    for (int k = 0; k < 16; ++k)
        fixture.variables[k] = k + 1;
}

/* One program evaluated by four threads at once, each with variables of its
 * own: the same values and partials as one thread gets, bit for bit (the
 * program is read only; under ThreadSanitizer a write would be a race). */
typedef struct worker {
    const hx_expr_program *p;
    const hx_frames *frames;
    double variables[16];
    double value, partials[8];
    int failures;
} worker;

static void *work(void *arg)
{
    worker *w = arg;
    const hx_expr_context c = {w->frames, w->variables, NULL};
    double scratch[512], value, partials[8];
    hx_expr_fault fault;
    for (int k = 0; k < 2000; ++k) {
        if (hx_expr_eval_partials(w->p, &c, &value, partials, scratch, &fault) != 0 ||
            value != w->value || memcmp(partials, w->partials, sizeof partials) != 0)
            ++w->failures;
    }
    return NULL;
}

static void threads_share_a_program(void **state)
{
    (void)state;
    hx_expr_program *p = expr_compile(&fixture, "IMPACT(VARVAL(1), VARVAL(2), 1, 100, 2.3, 10,"
                                                " 0.1) * AKISPL(VARVAL(3), VARVAL(4), 103, 1)"
                                                " + CURVE(VARVAL(5), 1, 2, 2)");
    assert_true(hx_expr_scratch_size(p) <= 512 && hx_expr_input_count(p) <= 8);
    worker w[4];
    pthread_t thread[4];
    for (int t = 0; t < 4; ++t) {
        memset(&w[t], 0, sizeof w[t]);
        w[t].p = p, w[t].frames = &fixture.frames;
        const double v[5] = {0.95 - 0.01 * t, -2.0 + t, 2.3 + 0.1 * t, 0.7, -0.5 + 0.2 * t};
        memcpy(w[t].variables, v, sizeof v);
        const hx_expr_context c = {&fixture.frames, w[t].variables, NULL};
        double scratch[512];
        hx_expr_fault fault;
        assert_int_equal(hx_expr_eval_partials(p, &c, &w[t].value, w[t].partials, scratch,
                                               &fault), 0);
    }
    for (int t = 0; t < 4; ++t)
        assert_int_equal(pthread_create(&thread[t], NULL, work, &w[t]), 0);
    for (int t = 0; t < 4; ++t) {
        pthread_join(thread[t], NULL);
        assert_int_equal(w[t].failures, 0);
    }
    hx_expr_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(operators_and_elementary_functions),
        cmocka_unit_test(transitions_and_stops),
        cmocka_unit_test(series),
        cmocka_unit_test(splines_and_curves),
        cmocka_unit_test(branches_and_time),
        cmocka_unit_test(kinks),
        cmocka_unit_test(partials_that_are_not_finite),
        cmocka_unit_test(threads_share_a_program),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
