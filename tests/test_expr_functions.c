/*
 * Every function of the expression language against values worked by hand
 * from its documented definition (docs/interface.md §8.4): each evaluated
 * with its arguments as variables (the evaluator) and written as numbers
 * (folded by the parser), the two equal. Splines at and between their
 * knots, by hand and against the host's c_akispl and c_cubspl; CURVE on
 * curves built by hand; every domain fault.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expr_support.h"
#include "model/curve.h"
#include "sim_support.h"
#include "usrsub/solver_abi.h"

static expr_fixture fixture;

static int setup(void **state)
{
    (void)state;
    expr_open(&fixture, "functions.xml", expr_function_model);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    expr_close(&fixture);
    return 0;
}

/* FN(args): evaluated with the first nine arguments as VARVAL(1..9), and
 * folded with all written as numbers; the test fails unless both agree. */
static double call(const char *fn, const double *args, int n)
{
    char evaluated[2048], written[2048];
    int e = snprintf(evaluated, sizeof evaluated, "%s(", fn);
    int w = snprintf(written, sizeof written, "%s(", fn);
    for (int k = 0; k < n; ++k) {
        const char *comma = k ? ", " : "";
        if (k < 9) {
            fixture.variables[k] = args[k];
            e += snprintf(evaluated + e, sizeof evaluated - (size_t)e, "%sVARVAL(%d)", comma,
                          k + 1);
        } else {
            e += snprintf(evaluated + e, sizeof evaluated - (size_t)e, "%s%.17g", comma, args[k]);
        }
        w += snprintf(written + w, sizeof written - (size_t)w, "%s(%.17g)", comma, args[k]);
    }
    snprintf(evaluated + e, sizeof evaluated - (size_t)e, ")");
    snprintf(written + w, sizeof written - (size_t)w, ")");
    const double value = expr_value(&fixture, evaluated);
    hx_message msg;
    hx_expr_program *p = hx_expr_parse(written, strlen(written), NULL, &msg);
    double folded = NAN;
    if (p == NULL || !hx_expr_constant(p, &folded))
        fail_msg("\"%s\" did not fold", written);
    hx_expr_free(p);
    if (!(folded == value))
        fail_msg("%s: evaluated %.17g, folded %.17g", written, value, folded);
    return value;
}

#define CALL(fn, ...) call(fn, (const double[]){__VA_ARGS__}, \
                           (int)(sizeof((const double[]){__VA_ARGS__}) / sizeof(double)))

static void arithmetic_functions(void **state)
{
    (void)state;
    assert_close(CALL("ABS", -2.5), 2.5, 0, 0);
    assert_close(CALL("ABS", 0.0), 0.0, 0, 0);
    /* SIGN(a1, a2): |a1| for a2 >= 0, -|a1| for a2 < 0 (the documentation's four cases) */
    assert_close(CALL("SIGN", 9.6, 4.5), 9.6, 0, 0);
    assert_close(CALL("SIGN", -4.7, 1.2), 4.7, 0, 0);
    assert_close(CALL("SIGN", 5.3, -6.5), -5.3, 0, 0);
    assert_close(CALL("SIGN", -2.5, -5.2), -2.5, 0, 0);
    assert_close(CALL("SIGN", -3.0, 0.0), 3.0, 0, 0); /* a2 = 0 counts as positive */
    assert_close(CALL("MIN", -1.0, 2.0), -1.0, 0, 0);
    assert_close(CALL("MIN", 3.0, -2.0), -2.0, 0, 0);
    assert_close(CALL("MAX", -1.0, 2.0), 2.0, 0, 0);
    assert_close(CALL("MAX", 3.0, -2.0), 3.0, 0, 0);
    /* MOD(a1, a2) = a1 - AINT(a1/a2) a2: the documentation's 0 and 13, and the
     * negative cases: -7 - (-2)(3) = -1, 7 - (-2)(-3) = 1, -7 - (2)(-3) = -1 */
    assert_close(CALL("MOD", 45.0, 15.0), 0.0, 0, 0);
    assert_close(CALL("MOD", 45.0, 16.0), 13.0, 0, 0);
    assert_close(CALL("MOD", -7.0, 3.0), -1.0, 0, 0);
    assert_close(CALL("MOD", 7.0, -3.0), 1.0, 0, 0);
    assert_close(CALL("MOD", -7.0, -3.0), -1.0, 0, 0);
    assert_close(CALL("MOD", 5.5, 2.0), 1.5, 0, 0);
    /* DIM(a1, a2) = a1 - a2 where a1 > a2, else 0 */
    assert_close(CALL("DIM", 5.0, 3.0), 2.0, 0, 0);
    assert_close(CALL("DIM", 3.0, 5.0), 0.0, 0, 0);
    assert_close(CALL("DIM", -1.0, -4.0), 3.0, 0, 0);
    /* AINT truncates towards 0 (-6.5 -> -6, -0.5 -> 0); ANINT rounds halves away from 0:
     * int(x + 0.5) above 0, int(x - 0.5) below: -0.5 -> -1, 0.5 -> 1, -2.5 -> -3 */
    assert_close(CALL("AINT", -6.5), -6.0, 0, 0);
    assert_close(CALL("AINT", 4.6), 4.0, 0, 0);
    assert_close(CALL("AINT", -0.5), 0.0, 0, 0);
    assert_close(CALL("AINT", -1.5), -1.0, 0, 0);
    assert_close(CALL("ANINT", -4.6), -5.0, 0, 0);
    assert_close(CALL("ANINT", 4.6), 5.0, 0, 0);
    assert_close(CALL("ANINT", -0.5), -1.0, 0, 0);
    assert_close(CALL("ANINT", 0.5), 1.0, 0, 0);
    assert_close(CALL("ANINT", -2.5), -3.0, 0, 0);
    assert_close(CALL("ANINT", 2.5), 3.0, 0, 0);
    assert_close(CALL("ANINT", 0.33), 0.0, 0, 0);
    assert_close(CALL("ANINT", -0.9), -1.0, 0, 0);
}

static void transcendental_functions(void **state)
{
    (void)state;
    const double e = exp(1.0);
    assert_close(CALL("SQRT", 6.25), 2.5, 0, 0);
    assert_close(CALL("EXP", 1.0), e, 1e-15, 0);
    assert_close(CALL("LOG", e * e), 2.0, 1e-15, 0);
    assert_close(CALL("LOG10", 1000.0), 3.0, 1e-15, 0);
    assert_close(CALL("SIN", M_PI / 6.0), 0.5, 1e-15, 0);
    assert_close(CALL("COS", M_PI / 3.0), 0.5, 1e-15, 0);
    assert_close(CALL("TAN", M_PI / 4.0), 1.0, 1e-15, 0);
    assert_close(CALL("ASIN", 0.5), M_PI / 6.0, 1e-15, 0);
    assert_close(CALL("ACOS", 0.5), M_PI / 3.0, 1e-15, 0);
    assert_close(CALL("ATAN", 1.0), M_PI / 4.0, 1e-15, 0);
    assert_close(CALL("SINH", 1.0), (e - 1.0 / e) / 2.0, 1e-15, 0);
    assert_close(CALL("COSH", 1.0), (e + 1.0 / e) / 2.0, 1e-15, 0);
    assert_close(CALL("TANH", 1.0), (e * e - 1.0) / (e * e + 1.0), 1e-15, 0);
    /* ATAN2(y, x) in the four quadrants and on the axes */
    assert_close(CALL("ATAN2", 1.0, 1.0), M_PI / 4.0, 1e-15, 0);
    assert_close(CALL("ATAN2", 1.0, -1.0), 3.0 * M_PI / 4.0, 1e-15, 0);
    assert_close(CALL("ATAN2", -1.0, -1.0), -3.0 * M_PI / 4.0, 1e-15, 0);
    assert_close(CALL("ATAN2", -1.0, 1.0), -M_PI / 4.0, 1e-15, 0);
    assert_close(CALL("ATAN2", 2.0, 0.0), M_PI / 2.0, 1e-15, 0);
    assert_close(CALL("ATAN2", 0.0, -3.0), M_PI, 1e-15, 0);
}

/* STEP, STEP5, HAVSIN from (1, 2) to (3, 6): h = 2 + 4 s(u), u = (x - 1) / 2. */
static void transitions(void **state)
{
    (void)state;
    static const char *const names[3] = {"STEP", "STEP5", "HAVSIN"};
    /* at x = 1.5, u = 1/4: the cubic u^2 (3 - 2u) = 0.15625; the quintic
     * u^3 (10 - 15u + 6u^2) = 0.015625 * 6.625 = 0.103515625; the haversine
     * (1 - cos(pi/4)) / 2, so h = 4 - 2 cos(pi/4) = 4 - sqrt 2. At x = 2 (u =
     * 1/2) all three are halfway, 4. */
    const double quarter[3] = {2.625, 2.4140625, 4.0 - sqrt(2.0)};
    for (int k = 0; k < 3; ++k) {
        assert_close(CALL(names[k], 0.0, 1.0, 2.0, 3.0, 6.0), 2.0, 0, 0);  /* before x0 */
        assert_close(CALL(names[k], 1.0, 1.0, 2.0, 3.0, 6.0), 2.0, 0, 0);  /* at x0 */
        assert_close(CALL(names[k], 1.5, 1.0, 2.0, 3.0, 6.0), quarter[k], 1e-15, 0);
        assert_close(CALL(names[k], 2.0, 1.0, 2.0, 3.0, 6.0), 4.0, 1e-15, 0);
        assert_close(CALL(names[k], 3.0, 1.0, 2.0, 3.0, 6.0), 6.0, 0, 0);  /* at x1 */
        assert_close(CALL(names[k], 4.0, 1.0, 2.0, 3.0, 6.0), 6.0, 0, 0);  /* beyond */
    }
    /* the documentation's check values: STEP(x, 3, 0, 4, 1) at 2, 3, 3.5, 4, 5 */
    const double x[5] = {2.0, 3.0, 3.5, 4.0, 5.0}, h[5] = {0.0, 0.0, 0.5, 1.0, 1.0};
    for (int k = 0; k < 5; ++k)
        assert_close(CALL("STEP", x[k], 3.0, 0.0, 4.0, 1.0), h[k], 1e-15, 0);
    /* x1 = x0: a jump, h0 at x0 itself (STEP, STEP5) */
    assert_close(CALL("STEP", 1.0, 1.0, 2.0, 1.0, 6.0), 2.0, 0, 0);
    assert_close(CALL("STEP5", 1.0 + 1e-12, 1.0, 2.0, 1.0, 6.0), 6.0, 0, 0);
}

/* IMPACT(x, xdot, x1 = 1, k = 100, e = 2, cmax = 10, d = 0.1) and BISTOP(x,
 * xdot, -1, 1, 100, 1.5, 10, 0.1): k p^e less the damping STEP(x, x1 - d,
 * cmax, x1, 0) xdot, never pulling. */
static void impact_and_bistop(void **state)
{
    (void)state;
    /* clear of the stop */
    assert_close(CALL("IMPACT", 1.2, -2.0, 1.0, 100.0, 2.0, 10.0, 0.1), 0.0, 0, 0);
    assert_close(CALL("IMPACT", 1.0, -2.0, 1.0, 100.0, 2.0, 10.0, 0.1), 0.0, 0, 0);
    /* inside the damping ramp: p = 0.05, halfway, damping 5: 100 (0.05)^2 + 5 * 2 */
    assert_close(CALL("IMPACT", 0.95, -2.0, 1.0, 100.0, 2.0, 10.0, 0.1), 10.25, 1e-14, 0);
    /* p = 0.025, a quarter: damping 10 * 0.15625; 0.0625 + 1.5625 */
    assert_close(CALL("IMPACT", 0.975, -1.0, 1.0, 100.0, 2.0, 10.0, 0.1), 1.625, 1e-14, 0);
    /* beyond the ramp, full damping 10: 100 * 0.04 - 10 * 0.1 = 3 */
    assert_close(CALL("IMPACT", 0.8, 0.1, 1.0, 100.0, 2.0, 10.0, 0.1), 3.0, 1e-14, 0);
    /* separating fast: 4 - 10 = -6 would pull: 0 */
    assert_close(CALL("IMPACT", 0.8, 1.0, 1.0, 100.0, 2.0, 10.0, 0.1), 0.0, 0, 0);
    /* BISTOP between its bounds */
    assert_close(CALL("BISTOP", 0.0, 5.0, -1.0, 1.0, 100.0, 1.5, 10.0, 0.1), 0.0, 0, 0);
    /* below x1 by 0.05 moving down: 100 (0.05)^1.5 + 5 * 2 */
    const double k_p = 100.0 * pow(0.05, 1.5);
    assert_close(CALL("BISTOP", -1.05, -2.0, -1.0, 1.0, 100.0, 1.5, 10.0, 0.1), k_p + 10.0,
                 1e-14, 0);
    /* above x2 by 0.05 moving up: pushes down */
    assert_close(CALL("BISTOP", 1.05, 2.0, -1.0, 1.0, 100.0, 1.5, 10.0, 0.1), -(k_p + 10.0),
                 1e-14, 0);
    /* above x2 by 0.2, full damping: -100 (0.2)^1.5 - 10 * 0.5; moving back fast: 0 */
    assert_close(CALL("BISTOP", 1.2, 0.5, -1.0, 1.0, 100.0, 1.5, 10.0, 0.1),
                 -100.0 * pow(0.2, 1.5) - 5.0, 1e-14, 0);
    assert_close(CALL("BISTOP", 1.2, -3.0, -1.0, 1.0, 100.0, 1.5, 10.0, 0.1), 0.0, 0, 0);
}

static void series_functions(void **state)
{
    (void)state;
    /* POLY(3, 1, 1, -2, 0.5, 2): u = 2: 1 - 4 + 2 + 16 */
    assert_close(CALL("POLY", 3.0, 1.0, 1.0, -2.0, 0.5, 2.0), 15.0, 1e-15, 0);
    /* CHEBY(1.5, 1, 1, 2, 3, 4): u = 1/2: T = 1, 1/2, -1/2, -1: 1 + 1 - 1.5 - 4 */
    assert_close(CALL("CHEBY", 1.5, 1.0, 1.0, 2.0, 3.0, 4.0), -3.5, 1e-15, 0);
    /* the documentation's FORCOS(TIME, 0, 360D, 1, 2, 3, 4) at TIME = 1/4:
     * 1 + 2 cos(pi/2) + 3 cos(pi) + 4 cos(3 pi/2) = -2; FORSIN: 1 + 2 - 4 = -1 */
    assert_close(CALL("FORCOS", 0.25, 0.0, 2.0 * M_PI, 1.0, 2.0, 3.0, 4.0), -2.0, 0, 1e-14);
    assert_close(CALL("FORSIN", 0.25, 0.0, 2.0 * M_PI, 1.0, 2.0, 3.0, 4.0), -1.0, 0, 1e-14);
    fixture.frames.time = 0.25;
    assert_close(expr_value(&fixture, "FORCOS(TIME, 0, 360D, 1, 2, 3, 4)"), -2.0, 0, 1e-14);
    fixture.frames.time = 0.0;
    /* SHF(1.25, 0.5, 2, pi, pi/2, 3) = 2 sin(0.75 pi - 0.5 pi) + 3 = 3 + sqrt 2 */
    assert_close(CALL("SHF", 1.25, 0.5, 2.0, M_PI, M_PI / 2.0, 3.0), 3.0 + sqrt(2.0), 1e-15, 0);
    assert_close(CALL("SHF", 1.0, 0.5, 2.0, M_PI, M_PI / 2.0, 3.0), 3.0, 1e-15, 0);
    /* 31 coefficients, the most: POLY(2, 1, 1, ..., 1) = 31 at u = 1 */
    double many[33] = {2.0, 1.0};
    for (int k = 2; k < 33; ++k)
        many[k] = 1.0;
    assert_close(call("POLY", many, 33), 31.0, 0, 0);
}

/* AKISPL and CUBSPL: spline 101 is the line y = -1000 x, reproduced by both;
 * spline 102 is y = x^2 at 0 .. 4: Akima's method reproduces a parabola on
 * equally spaced knots (2.5 -> 6.25, slope 5, curvature 2); the natural
 * cubic spline passes through the knots with zero curvature at the ends:
 * M1 = M3 = 18/7, M2 = 12/7 from M(i-1) + 4 M(i) + M(i+1) = 12, so at 2.5,
 * S = 6.5 - (M2 + M3) / 16 = 6.5 - 15/56 = 349/56. */
static void splines(void **state)
{
    (void)state;
    assert_close(expr_value(&fixture, "AKISPL(0.3, 0, 101)"), -300.0, 1e-12, 0);
    assert_close(expr_value(&fixture, "AKISPL(-0.6, 0, 101)"), 600.0, 1e-12, 0);
    assert_close(expr_value(&fixture, "CUBSPL(-0.25, 7, 101, 1)"), -1000.0, 1e-12, 0);
    assert_close(expr_value(&fixture, "CUBSPL(0.7, 0, 101, 2)"), 0.0, 0, 1e-9);
    assert_close(expr_value(&fixture, "AKISPL(2, 0, 102)"), 4.0, 1e-15, 0);  /* a knot */
    assert_close(expr_value(&fixture, "AKISPL(2.5, 0, 102)"), 6.25, 1e-14, 0);
    assert_close(expr_value(&fixture, "AKISPL(2.5, 0, 102, 1)"), 5.0, 1e-14, 0);
    assert_close(expr_value(&fixture, "AKISPL(2.5, 0, 102, 2)"), 2.0, 1e-13, 0);
    assert_close(expr_value(&fixture, "CUBSPL(3, 0, 102)"), 9.0, 1e-14, 0);  /* a knot */
    assert_close(expr_value(&fixture, "CUBSPL(2.5, 0, 102)"), 349.0 / 56.0, 1e-14, 0);
    /* S'' at knot 2 is M2 = 12/7 */
    assert_close(expr_value(&fixture, "CUBSPL(2, 0, 102, 2)"), 12.0 / 7.0, 1e-13, 0);
    /* the same as the host's c_akispl and c_cubspl, at and between knots and beyond */
    host_model h;
    host_model_attach(&h, "splines.xml", expr_function_model);
    const double xs[5] = {-0.5, 0.0, 1.7, 3.0, 4.6};
    for (int k = 0; k < 5; ++k)
        for (int iord = 0; iord <= 2; ++iord) {
            double array[3];
            int errflg;
            char text[128];
            c_akispl(xs[k], 0.0, 102, iord, array, &errflg);
            assert_int_equal(errflg, 0);
            snprintf(text, sizeof text, "AKISPL(%.17g, 0, 102, %d)", xs[k], iord);
            assert_close(expr_value(&fixture, text), array[0], 0, 0);
            c_cubspl(xs[k], 0.0, 102, iord, array, &errflg);
            assert_int_equal(errflg, 0);
            snprintf(text, sizeof text, "CUBSPL(%.17g, 0, 102, %d)", xs[k], iord);
            assert_close(expr_value(&fixture, text), array[0], 0, 0);
        }
    host_model_detach(&h);
}

/* Adds curve id to the fixture's model (by hand: no reader fills curves). */
static void add_curve(int id, int order, int closed, const double *points, int n)
{
    hx_model *m = fixture.model;
    m->curves = realloc(m->curves, sizeof *m->curves * (size_t)(m->ncurves + 1));
    assert_non_null(m->curves);
    hx_curve *c = &m->curves[m->ncurves++];
    memset(c, 0, sizeof *c);
    c->id = id, c->order = order, c->closed = closed, c->npoints = n;
    c->points = malloc(sizeof(double) * 3 * (size_t)n);
    memcpy(c->points, points, sizeof(double) * 3 * (size_t)n);
}

static double curve(double alpha, int iord, int comp, int id)
{
    char text[128];
    snprintf(text, sizeof text, "CURVE(%.17g, %d, %d, %d)", alpha, iord, comp, id);
    return expr_value(&fixture, text);
}

static void curves(void **state)
{
    (void)state;
    /* order 2 over (0,0,0) (1,2,0) (3,2,1): the polyline, P1 at alpha = 0 (u =
     * 1/2), halfway along the second leg at alpha = 1/2: (2, 2, 0.5), its
     * slope in alpha (P2 - P1) / 0.5 * 0.5 = (2, 0, 1) */
    const double polyline[9] = {0, 0, 0, 1, 2, 0, 3, 2, 1};
    add_curve(1, 2, 0, polyline, 3);
    assert_close(curve(0.0, 0, 2, 1), 2.0, 1e-15, 0);
    assert_close(curve(0.5, 0, 1, 1), 2.0, 1e-15, 0);
    assert_close(curve(0.5, 0, 3, 1), 0.5, 1e-15, 0);
    assert_close(curve(0.5, 1, 1, 1), 2.0, 1e-15, 0);
    assert_close(curve(0.5, 1, 3, 1), 1.0, 1e-15, 0);
    /* order 4 over four points: the Bezier cubic. At u = 1/2: (P0 + 3 P1 + 3 P2
     * + P3) / 8 = (2, 1.5, 0.375); B' = 3 (P1 - P0)/4 + 3 (P2 - P1)/2 + 3 (P3 -
     * P2)/4 = (4.5, 0, 0.75), halved in alpha; B'' = 3 (P2 - 2 P1 + P0) + 3 (P3
     * - 2 P2 + P1) = (0, -12, -3), quartered */
    const double bezier[12] = {0, 0, 0, 1, 2, 0, 3, 2, 1, 4, 0, 0};
    add_curve(2, 4, 0, bezier, 4);
    const double value[3] = {2.0, 1.5, 0.375}, slope[3] = {2.25, 0.0, 0.375};
    const double bend[3] = {0.0, -3.0, -0.75};
    for (int comp = 1; comp <= 3; ++comp) {
        assert_close(curve(0.0, 0, comp, 2), value[comp - 1], 1e-15, 1e-15);
        assert_close(curve(0.0, 1, comp, 2), slope[comp - 1], 1e-15, 1e-15);
        assert_close(curve(0.0, 2, comp, 2), bend[comp - 1], 1e-15, 1e-15);
        assert_close(curve(-1.0, 0, comp, 2), bezier[comp - 1], 0, 1e-15);      /* P0 */
        assert_close(curve(1.0, 0, comp, 2), bezier[9 + comp - 1], 0, 1e-15);   /* P3 */
    }
    /* closed, cubic, over the square (1,0) (0,1) (-1,0) (0,-1): at alpha = -1 the
     * uniform cubic's (P0 + 4 P1 + P2) / 6 = (0, 2/3), a quarter on (P1 + 4 P2 +
     * P3) / 6 = (-2/3, 0); it repeats with period 2 */
    const double square[15] = {1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 1, 0, 0};
    add_curve(3, 4, 1, square, 5);
    assert_close(curve(-1.0, 0, 1, 3), 0.0, 0, 1e-15);
    assert_close(curve(-1.0, 0, 2, 3), 2.0 / 3.0, 1e-15, 0);
    assert_close(curve(-0.5, 0, 1, 3), -2.0 / 3.0, 1e-15, 0);
    assert_close(curve(1.0, 0, 2, 3), 2.0 / 3.0, 1e-15, 0);
    assert_close(curve(2.3, 1, 1, 3), curve(0.3, 1, 1, 3), 1e-12, 0);
    /* fitted through points: it passes through each at its parameter (open:
     * the Greville sites 0, 1/6, 1/2, 5/6, 1 of the clamped cubic's knots) */
    const double points[15] = {0, 0, 0, 1, 3, 0, 2, 1, 1, 3, 4, 0, 5, 5, 5};
    hx_curve through = {.id = 4, .order = 4};
    hx_message msg;
    assert_int_equal(hx_curve_through(&through, points, 5, &msg), 0);
    add_curve(4, 4, 0, through.points, through.npoints);
    free(through.points);
    const double sites[5] = {0.0, 1.0 / 6.0, 0.5, 5.0 / 6.0, 1.0};
    for (int j = 0; j < 5; ++j)
        for (int comp = 1; comp <= 3; ++comp)
            assert_close(curve(2.0 * sites[j] - 1.0, 0, comp, 4), points[3 * j + comp - 1], 0,
                         1e-12);
    /* closed, through four points and back: point j at alpha = -1 + 2 j / 4 */
    const double loop[15] = {2, 0, 1, 0, 3, 1, -2, 0, 0, 0, -1, 2, 2, 0, 1};
    for (int order = 3; order <= 4; ++order) {
        hx_curve closed = {.id = 5, .order = order, .closed = 1};
        assert_int_equal(hx_curve_through(&closed, loop, 5, &msg), 0);
        add_curve(5 + order, order, 1, closed.points, closed.npoints);
        free(closed.points);
        for (int j = 0; j < 5; ++j)
            for (int comp = 1; comp <= 3; ++comp)
                assert_close(curve(-1.0 + 0.5 * j, 0, comp, 5 + order), loop[3 * j + comp - 1],
                             0, 1e-12);
    }
    /* refused: too few points, a closed curve that does not close */
    hx_curve bad = {.id = 9, .order = 4, .closed = 1};
    assert_int_equal(hx_curve_through(&bad, points, 5, &msg), -1);
    assert_string_equal(msg.text, "curve 9: it is closed, but its last point is not its first");
    bad.closed = 0;
    assert_int_equal(hx_curve_through(&bad, points, 3, &msg), -1);
    assert_contains(msg.text, "curve 9: 3 points are too few");
    /* an open curve's alpha outside [-1, 1] */
    fixture.variables[0] = 1.25;
    hx_expr_fault f = expr_fault(&fixture, "CURVE(VARVAL(1), 0, 1, 2)", &msg);
    assert_int_equal(f.kind, HX_EXPR_FAULT_DOMAIN);
    assert_contains(msg.text, "CURVE: its alpha is outside [-1, 1] (1.25)");
}

/* Every argument outside a function's domain is a fault naming the function
 * and the value. */
static void domain_faults(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        hx_expr_fault_kind kind;
        const char *needle;
    } cases[] = {
        {"SQRT(VARVAL(1) - 2)", HX_EXPR_FAULT_DOMAIN, "SQRT: its argument is negative (-1)"},
        {"LOG(VARVAL(1) - 1)", HX_EXPR_FAULT_DOMAIN, "LOG: its argument is not above 0 (0)"},
        {"LOG10(-VARVAL(1))", HX_EXPR_FAULT_DOMAIN, "LOG10: its argument is not above 0 (-1)"},
        {"ASIN(VARVAL(2))", HX_EXPR_FAULT_DOMAIN, "ASIN: its argument is outside [-1, 1] (2)"},
        {"ACOS(-VARVAL(2))", HX_EXPR_FAULT_DOMAIN, "ACOS: its argument is outside [-1, 1] (-2)"},
        {"ATAN2(VARVAL(1) - 1, 0)", HX_EXPR_FAULT_DOMAIN, "ATAN2: both its arguments are 0"},
        {"(-VARVAL(8))**(1/3)", HX_EXPR_FAULT_DOMAIN, "'**': a negative number raised to a power"
                                                       " that is not whole (-8)"},
        {"(VARVAL(1) - 1)**-1", HX_EXPR_FAULT_DIVISION_BY_ZERO, "'**': division by zero"},
        {"MOD(VARVAL(1), VARVAL(1) - 1)", HX_EXPR_FAULT_DIVISION_BY_ZERO, "MOD: division by"},
        {"STEP(TIME, VARVAL(2), 0, 1, 1)", HX_EXPR_FAULT_DOMAIN, "STEP: its x1 is below its x0"},
        {"HAVSIN(TIME, 1, 0, VARVAL(1), 1)", HX_EXPR_FAULT_DOMAIN, "HAVSIN: its x1 equals its x0"},
        {"IMPACT(0, 0, 1, -VARVAL(1), 2, 1, 0.1)", HX_EXPR_FAULT_DOMAIN,
         "IMPACT: its stiffness k is negative (-1)"},
        {"IMPACT(0, 0, 1, 1, VARVAL(1) - 1, 1, 0.1)", HX_EXPR_FAULT_DOMAIN,
         "IMPACT: its exponent e is not positive (0)"},
        {"IMPACT(0, 0, 1, 1, 2, -VARVAL(1), 0.1)", HX_EXPR_FAULT_DOMAIN,
         "IMPACT: its damping cmax is negative (-1)"},
        {"BISTOP(0, 0, 1, 1, 1, 2, 1, VARVAL(1) - 1)", HX_EXPR_FAULT_DOMAIN,
         "BISTOP: its penetration d is not positive (0)"},
        {"BISTOP(0, 0, 1, VARVAL(1) - 1, 1, 2, 1, 0.1)", HX_EXPR_FAULT_DOMAIN,
         "BISTOP: its x2 is below its x1 (0)"},
        {"SINH(VARVAL(1) * 1000)", HX_EXPR_FAULT_NOT_FINITE, "SINH: its result is not finite"},
    };
    fixture.variables[0] = 1.0, fixture.variables[1] = 2.0, fixture.variables[7] = 8.0;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        hx_message msg;
        const hx_expr_fault f = expr_fault(&fixture, cases[k].text, &msg);
        if (f.kind != cases[k].kind || strstr(msg.text, cases[k].needle) == NULL)
            fail_msg("\"%s\": %s (kind %d)", cases[k].text, msg.text, (int)f.kind);
    }
    fixture.variables[0] = 2.0; /* 2**5000 overflows as well */
    hx_message msg;
    assert_int_equal(expr_fault(&fixture, "VARVAL(1)**5000", &msg).kind,
                     HX_EXPR_FAULT_NOT_FINITE);
    for (int k = 0; k < 16; ++k)
        fixture.variables[k] = k + 1;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(arithmetic_functions),
        cmocka_unit_test(transcendental_functions),
        cmocka_unit_test(transitions),
        cmocka_unit_test(impact_and_bistop),
        cmocka_unit_test(series_functions),
        cmocka_unit_test(splines),
        cmocka_unit_test(curves),
        cmocka_unit_test(domain_faults),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
