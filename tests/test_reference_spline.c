/*
 * The model's Reference_Spline and the utilities that answer from it,
 * c_akispl and c_cubspl (docs/interface.md §5.2, §7.11):
 * - Akima's slopes reproduce a quadratic on equally spaced knots, inside and
 *   beyond them, and keep flat data flat (hand-worked values between a step);
 * - the natural cubic spline of four points worked by hand, its two ends
 *   continued and straight;
 * - both pass through every knot exactly; their first and second derivatives
 *   against central differences between the knots; the cubic's second
 *   derivative continuous and zero at the ends, Akima's slope continuous;
 * - the reader: the documented form, and each malformed spline refused with
 *   file, line, id and what is wrong;
 * - the utilities bound to a model: iord 0, 1, 2 in the documented layout and
 *   nothing written beyond; a surface's z; an unknown id, a bad iord, a
 *   non-finite x refused with errflg and noted once per element; the Fortran
 *   forms answer as the C ones.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/cubic_curve.h"
#include "host/call.h"
#include "host/messages.h"
#include "host/utilities.h"
#include "model/model.h"
#include "test_support.h"
#include "usrsub/solver_abi.h"

/* ---- the curves -------------------------------------------------------------------------- */

typedef struct curve {
    int n;
    double x[16], y[16], slope[16];
    int linear;
} curve;

static void fit(curve *c, int akima)
{
    if (akima)
        hx_akima_slopes(c->x, c->y, c->n, c->slope);
    else
        assert_int_equal(hx_natural_cubic_slopes(c->x, c->y, c->n, c->slope), 0);
}

static void at(const curve *c, double u, double out[3])
{
    hx_cubic_curve(c->x, c->y, c->slope, c->n, c->linear, u, out);
}

static void akima_reproduces_an_equally_spaced_quadratic(void **state)
{
    (void)state;
    /* y = x^2 - 3x + 1 on x = -2, -1.5, .. 2: the secants are a straight line
     * in the knot's index, so Akima's weights are equal, each knot's slope
     * is the mean of its secants (exact for a parabola), and the two secants
     * extrapolated at each end stay on that line */
    curve c = {.n = 9};
    for (int k = 0; k < c.n; ++k) {
        c.x[k] = -2.0 + 0.5 * k;
        c.y[k] = c.x[k] * c.x[k] - 3.0 * c.x[k] + 1.0;
    }
    fit(&c, 1);
    for (double u = -3.0; u <= 3.0; u += 0.0625) {
        double f[3];
        at(&c, u, f);
        assert_close(f[0], u * u - 3.0 * u + 1.0, 0, 1e-13);
        assert_close(f[1], 2.0 * u - 3.0, 0, 1e-13);
        assert_close(f[2], 2.0, 0, 1e-12);
    }
    /* a straight line on uneven knots: every secant the same */
    curve line = {.n = 5, .x = {-1, 0.2, 0.3, 2, 7}};
    for (int k = 0; k < line.n; ++k)
        line.y[k] = 4.0 - 2.5 * line.x[k];
    fit(&line, 1);
    double f[3];
    at(&line, 1.1, f);
    assert_close(f[0], 4.0 - 2.5 * 1.1, 0, 1e-14);
    assert_close(f[1], -2.5, 0, 1e-14);
    assert_close(f[2], 0.0, 0, 1e-13);
}

static void akima_keeps_flat_data_flat(void **state)
{
    (void)state;
    /* a step 0 0 0 1 1 1: the secants 0 0 1 0 0 (and 0 0 beyond each end);
     * at x = 2 the weight of the left secant is |0 - 1| = 1, of the right
     * |0 - 0| = 0: slope 0, as at x = 3. Between them the cubic with zero end
     * slopes, 3u^2 - 2u^3; the flat parts stay flat */
    curve c = {.n = 6, .x = {0, 1, 2, 3, 4, 5}, .y = {0, 0, 0, 1, 1, 1}};
    fit(&c, 1);
    for (int k = 0; k < c.n; ++k)
        assert_close(c.slope[k], 0.0, 0, 0);
    double f[3];
    at(&c, 2.25, f); /* u = 1/4: 3/16 - 2/64 */
    assert_close(f[0], 0.15625, 0, 1e-15);
    at(&c, 2.5, f);
    assert_close(f[0], 0.5, 0, 1e-15);
    assert_close(f[1], 1.5, 0, 1e-15);
    assert_close(f[2], 0.0, 0, 1e-14);
    at(&c, 1.5, f);
    assert_close(f[0], 0.0, 0, 0);
    assert_close(f[1], 0.0, 0, 0);
    at(&c, 4.75, f);
    assert_close(f[0], 1.0, 0, 0);
}

static void natural_cubic_of_four_points_worked_by_hand(void **state)
{
    (void)state;
    /* (0, 0), (1, 1), (2, 0), (3, 1): with M_k the second derivatives,
     * M_0 = M_3 = 0, M_0 + 4 M_1 + M_2 = 6 (0 - 2 + 0), M_1 + 4 M_2 + M_3 =
     * 6 (1 - 0 + 1): M_1 = -4, M_2 = 4. On [0, 1] S = -2/3 x^3 + 5/3 x; on
     * [1, 2], t = x - 1, S = -2/3 (1 - t)^3 + 2/3 t^3 + 5/3 (1 - t) - 2/3 t;
     * on [2, 3], t = x - 2, S = 2/3 (1 - t)^3 - 2/3 (1 - t) + t */
    curve c = {.n = 4, .x = {0, 1, 2, 3}, .y = {0, 1, 0, 1}};
    fit(&c, 0);
    const double expected[][4] = {
        /* x, S, S', S'' */
        {0.5, 0.75, 7.0 / 6.0, -2.0},
        {1.5, 0.5, -4.0 / 3.0, 0.0},
        {2.5, 0.25, 7.0 / 6.0, 2.0},
        {0.0, 0.0, 5.0 / 3.0, 0.0},
        {3.0, 1.0, 5.0 / 3.0, 0.0},
        /* beyond: the end pieces continued */
        {-1.0, -1.0, -1.0 / 3.0, 4.0},
        {4.0, 2.0, -1.0 / 3.0, -4.0},
    };
    for (size_t k = 0; k < sizeof expected / sizeof expected[0]; ++k) {
        double f[3];
        at(&c, expected[k][0], f);
        for (int i = 0; i < 3; ++i)
            assert_close(f[i], expected[k][1 + i], 0, 1e-14);
    }
    /* straight beyond the ends: the end value and slope */
    c.linear = 1;
    double f[3];
    at(&c, -1.0, f);
    assert_close(f[0], -5.0 / 3.0, 0, 1e-14);
    assert_close(f[1], 5.0 / 3.0, 0, 1e-14);
    assert_close(f[2], 0.0, 0, 0);
    at(&c, 4.0, f);
    assert_close(f[0], 8.0 / 3.0, 0, 1e-14);
    assert_close(f[1], 5.0 / 3.0, 0, 1e-14);
    assert_close(f[2], 0.0, 0, 0);
    at(&c, 0.5, f); /* inside, nothing changes */
    assert_close(f[0], 0.75, 0, 1e-15);
}

/* A curve of n uneven knots with rough values (a fixed sequence). */
static void rough(curve *c, int n)
{
    c->n = n;
    double x = -3.0;
    unsigned seed = 12345u;
    for (int k = 0; k < n; ++k) {
        seed = seed * 1103515245u + 12345u;
        x += 0.2 + (double)(seed >> 16 & 0x7fff) / 32768.0;
        seed = seed * 1103515245u + 12345u;
        c->x[k] = x;
        c->y[k] = 10.0 * ((double)(seed >> 16 & 0x7fff) / 32768.0 - 0.5);
    }
}

static void knots_exactly_and_derivatives_against_differences(void **state)
{
    (void)state;
    double worst = 0.0;
    for (int akima = 0; akima <= 1; ++akima)
        for (int linear = 0; linear <= 1; ++linear) {
            curve c;
            rough(&c, 11);
            c.linear = linear;
            fit(&c, akima);
            double f[3], g[3];
            for (int k = 0; k < c.n; ++k) {
                at(&c, c.x[k], f);
                if (f[0] != c.y[k])
                    fail_msg("%s: at knot %d %.17g, not %.17g", akima ? "Akima" : "cubic", k,
                             f[0], c.y[k]);
            }
            /* every piece's inside, and a stretch beyond each end */
            const double from = c.x[0] - 1.0, to = c.x[c.n - 1] + 1.0;
            for (int i = 1; i < 400; ++i) {
                const double u = from + (to - from) * (i + 0.37) / 400.0, h = 1e-6;
                double plus[3], minus[3];
                at(&c, u, f);
                at(&c, u + h, plus);
                at(&c, u - h, minus);
                int near_knot = fabs(u - c.x[0]) < 2 * h || fabs(u - c.x[c.n - 1]) < 2 * h;
                for (int k = 0; k < c.n; ++k)
                    near_knot |= fabs(u - c.x[k]) < 2 * h;
                if (near_knot)
                    continue;
                const double d1 = (plus[0] - minus[0]) / (2 * h);
                const double d2 = (plus[1] - minus[1]) / (2 * h);
                const double scale = 1.0 + fabs(f[1]) + fabs(f[2]);
                worst = fmax(worst, fmax(fabs(d1 - f[1]), fabs(d2 - f[2])) / scale);
                if (fabs(d1 - f[1]) > 1e-6 * scale || fabs(d2 - f[2]) > 1e-5 * scale)
                    fail_msg("%s%s at %g: slope %.10g (differences %.10g), second %.10g"
                             " (%.10g)", akima ? "Akima" : "cubic", linear ? " linear" : "", u,
                             f[1], d1, f[2], d2);
            }
            /* at the inner knots: the slope continuous for both, the second
             * derivative for the cubic; zero at the cubic's ends */
            for (int k = 1; k < c.n - 1; ++k) {
                at(&c, c.x[k] - 1e-9, f);
                at(&c, c.x[k] + 1e-9, g);
                assert_close(f[1], g[1], 0, 1e-6 * (1.0 + fabs(f[2])));
                if (!akima)
                    assert_close(f[2], g[2], 0, 1e-6 * (1.0 + fabs(f[2])));
            }
            if (!akima) {
                at(&c, c.x[0], f);
                assert_close(f[2], 0.0, 0, 1e-12);
                at(&c, c.x[c.n - 1], f);
                assert_close(f[2], 0.0, 0, 1e-12);
            }
            /* straight beyond the ends when linear, from the end knot's value and slope */
            if (linear) {
                at(&c, c.x[0], g);
                at(&c, c.x[0] - 2.0, f);
                assert_close(f[0], g[0] - 2.0 * g[1], 0, 1e-12);
                assert_close(f[2], 0.0, 0, 0);
            }
        }
    printf("  Akima and natural cubic, 11 uneven knots: derivatives within %.2g of differences\n",
           worst);
}

/* ---- the element ---------------------------------------------------------------------------- */

#define HEAD "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
#define TAIL "</Model></MotionSolve>\n"

static hx_model *read_text(const char *name, const char *xml, hx_message *msg)
{
    return hx_model_read(test_write_file(name, xml), NULL, msg);
}

/* The model is refused with a message holding every needle. */
#define expect_error(name, xml, ...)                                                      \
    do {                                                                                  \
        hx_message msg_;                                                                  \
        hx_model *m_ = read_text((name), (xml), &msg_);                                   \
        if (m_ != NULL) {                                                                 \
            hx_model_free(m_);                                                            \
            fail_msg("%s was read; expected an error", (name));                           \
        }                                                                                 \
        assert_contains(msg_.text, __VA_ARGS__);                                          \
    } while (0)

/* The form of the solver's pages: num_xy_pair, linear_extrap, x y pairs. */
static const char documented[] =
    HEAD
    "<Reference_Spline id=\"301002\" label=\"spring\" num_xy_pair=\"5\" linear_extrap=\"FALSE\">\n"
    "    0.0000000E+00  -2.2000000E+02\n"
    "    2.0000000E+02  -2.2000000E+02\n"
    "    2.3000000E+02  -2.2000000E+02\n"
    "    3.7322400E+02  -1.1000000E+02\n"
    "    5.0000000E+02  -1.1000000E+02\n"
    "</Reference_Spline>\n"
    "<Reference_Spline id=\"7\" num_xy_pair=\"4\" linear_extrap=\"TRUE\">0, 0, 1, 1, 2, 0, 3, 1"
    "</Reference_Spline>\n" TAIL;

static void the_documented_form_is_read(void **state)
{
    (void)state;
    hx_message msg;
    hx_model *m = read_text("documented.xml", documented, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    assert_int_equal(m->nsplines, 2);
    const hx_spline *s = &m->splines[hx_model_spline(m, 301002)];
    assert_int_equal(s->nx, 5);
    assert_int_equal(s->nz, 1);
    assert_int_equal(s->linear_extrapolate, 0);
    assert_close(s->x[3], 373.224, 0, 0);
    assert_close(s->y[3], -110.0, 0, 0);
    assert_int_equal(s->line, 3);
    const hx_spline *t = &m->splines[hx_model_spline(m, 7)];
    assert_int_equal(t->linear_extrapolate, 1);
    assert_close(t->y[2], 0.0, 0, 0);
    assert_int_equal(hx_model_spline(m, 8), -1);
    assert_int_equal(m->nunsimulated, 0);
    hx_model_free(m);
}

static void malformed_splines_are_refused(void **state)
{
    (void)state;
    expect_error("few.xml",
                 HEAD "<Reference_Spline id=\"3\" num_xy_pair=\"3\">0 0 1 1 2 2</Reference_Spline>\n"
                 TAIL, "few.xml:3: Reference_Spline 3: num_xy_pair is 3", "at least 4 points");
    expect_error("order.xml",
                 HEAD "\n<Reference_Spline id=\"4\" num_xy_pair=\"4\">0 0 1 1 1 2 3 3"
                 "</Reference_Spline>\n" TAIL,
                 "order.xml:4: Reference_Spline 4: its x values must increase",
                 "point 3 (x = 1)", "point 2 (x = 1)");
    expect_error("count.xml",
                 HEAD "<Reference_Spline id=\"5\" num_xy_pair=\"4\">0 0 1 1 2 2 3"
                 "</Reference_Spline>\n" TAIL,
                 "count.xml:3: Reference_Spline 5: num_xy_pair is 4 but its data holds 7 numbers",
                 "(4 x y pairs are 8)");
    expect_error("nan.xml",
                 HEAD "<Reference_Spline id=\"6\" num_xy_pair=\"4\">0 0 1 1 2 two 3 3"
                 "</Reference_Spline>\n" TAIL,
                 "nan.xml:3: Reference_Spline 6: entry 6 (from 1) of its data is not a finite"
                 " number");
    expect_error("empty.xml", HEAD "<Reference_Spline id=\"9\" num_xy_pair=\"4\"/>\n" TAIL,
                 "empty.xml:3: Reference_Spline 9: num_xy_pair is 4 but its data holds 0");
    expect_error("missing.xml",
                 HEAD "<Reference_Spline id=\"10\">0 0 1 1 2 2 3 3</Reference_Spline>\n" TAIL,
                 "missing.xml:3: Reference_Spline 10: attribute num_xy_pair is missing");
    expect_error("python.xml",
                 HEAD "<Reference_Spline id=\"11\" num_xy_pair=\"4\" linear_extrapolate=\"TRUE\">"
                 "0 0 1 1 2 2 3 3</Reference_Spline>\n" TAIL,
                 "python.xml:3: Reference_Spline 11: attribute linear_extrapolate",
                 "names it linear_extrap");
    expect_error("read.xml",
                 HEAD "<Reference_Spline id=\"12\" usrsub_dll_name=\"x.so\" file_name=\"a.dat\""
                 " block_name=\"b\"></Reference_Spline>\n" TAIL,
                 "read.xml:3: Reference_Spline 12", "SPLINE_READ", "not supported");
    expect_error("twice.xml",
                 HEAD "<Reference_Spline id=\"13\" num_xy_pair=\"4\">0 0 1 1 2 2 3 3"
                 "</Reference_Spline>\n<Reference_Spline id=\"13\" num_xy_pair=\"4\">0 0 1 1 2 2"
                 " 3 3</Reference_Spline>\n" TAIL,
                 "twice.xml:4: Reference_Spline 13 is defined twice (line 3)");
    expect_error("surface.xml",
                 HEAD "<Reference_Spline id=\"14\" num_xy_pair=\"4\" num_z=\"2\">0 0 1 1 2 2 3 3"
                 "</Reference_Spline>\n" TAIL,
                 "surface.xml:3: Reference_Spline 14: attribute num_z is not one the harness"
                 " reads");
    expect_error("overflow.xml",
                 HEAD "<Reference_Spline id=\"16\" num_xy_pair=\"4\">0 1e308 1 -1e308 2 1e308"
                 " 3 -1e308</Reference_Spline>\n" TAIL,
                 "overflow.xml:3: Reference_Spline 16: its numbers are too large");
    expect_error("bool.xml",
                 HEAD "<Reference_Spline id=\"15\" num_xy_pair=\"4\" linear_extrap=\"YES\">0 0 1 1"
                 " 2 2 3 3</Reference_Spline>\n" TAIL,
                 "bool.xml:3:", "linear_extrap", "expected TRUE or FALSE");
}

/* ---- the utilities ------------------------------------------------------------------------ */

typedef struct bound {
    hx_model *model;
    hx_messages messages;
    hx_call call;
    unsigned long long reported_unoffered, reported_misused;
    char text[4096];
    FILE *stream;
} bound;

static void bind(bound *b, const char *name, const char *xml)
{
    memset(b, 0, sizeof *b);
    hx_message msg;
    b->model = read_text(name, xml, &msg);
    if (b->model == NULL)
        fail_msg("%s", msg.text);
    b->stream = fmemopen(b->text, sizeof b->text - 1, "w");
    assert_non_null(b->stream);
    hx_messages_init(&b->messages, b->stream);
    hx_call_init(&b->call, "Force_Scalar_TwoBody", 4, "SFOSUB", b->model, NULL, &b->messages, 0,
                 NULL);
    b->call.reported_unoffered = &b->reported_unoffered;
    b->call.reported_misused = &b->reported_misused;
    hx_host_bind(&b->call);
}

static void unbind(bound *b)
{
    hx_host_unbind();
    fclose(b->stream);
    hx_messages_destroy(&b->messages);
    hx_model_free(b->model);
}

static void the_utilities_answer_in_the_documented_layout(void **state)
{
    (void)state;
    bound b;
    bind(&b, "layout.xml", documented);
    /* spline 7 is the hand-worked cubic of four points, straight beyond */
    const hx_spline *s = &b.model->splines[hx_model_spline(b.model, 7)];
    curve c = {.n = 4, .linear = 1};
    memcpy(c.x, s->x, sizeof(double) * 4);
    memcpy(c.y, s->y, sizeof(double) * 4);
    const double points[] = {-1.0, 0.0, 0.5, 1.5, 3.0, 4.0};
    for (int akima = 0; akima <= 1; ++akima) {
        fit(&c, akima);
        for (size_t k = 0; k < sizeof points / sizeof points[0]; ++k) {
            double want[3];
            at(&c, points[k], want);
            for (int iord = 0; iord <= 2; ++iord) {
                double array[4] = {-7, -7, -7, -7};
                int err = -1;
                (akima ? c_akispl : c_cubspl)(points[k], 0.3, 7, iord, array, &err);
                assert_int_equal(err, 0);
                /* 0: y; 1: dy/dx, dy/dz; 2: d2y/dx2, d2y/dxdz, d2y/dz2 */
                assert_close(array[0], want[iord], 0, 1e-14);
                if (iord >= 1)
                    assert_close(array[1], 0.0, 0, 0); /* one curve: no z */
                if (iord == 2)
                    assert_close(array[2], 0.0, 0, 0);
                for (int i = iord + 1; i < 4; ++i)
                    assert_close(array[i], -7.0, 0, 0); /* nothing beyond */
            }
        }
    }
    /* the hand-worked values through the utility */
    double v[3];
    int err = -1;
    c_cubspl(0.5, 0.0, 7, 0, v, &err);
    assert_close(v[0], 0.75, 0, 1e-15);
    c_cubspl(-1.0, 0.0, 7, 0, v, &err);
    assert_close(v[0], -5.0 / 3.0, 0, 1e-14); /* linear_extrap="TRUE" */
    /* the documented spring: flat, then a step down to -110 */
    c_akispl(100.0, 0.0, 301002, 0, v, &err);
    assert_close(v[0], -220.0, 0, 1e-12);
    c_akispl(600.0, 0.0, 301002, 1, v, &err);
    assert_int_equal(err, 0);
    fflush(b.stream);
    assert_null(strstr(b.text, "host:"));
    unbind(&b);
}

/* A surface of two curves: y = x at z = 0 and y = 2 x + 1 at z = 2 (made
 * here: the reader reads curves only, docs/interface.md §7.11). */
static void a_surface_is_linear_across_z(void **state)
{
    (void)state;
    bound b;
    bind(&b, "surface_model.xml", documented);
    hx_spline *s = &b.model->splines[hx_model_spline(b.model, 7)];
    free(s->z), free(s->y), free(s->akima_slope), free(s->cubic_slope);
    s->nz = 2;
    s->z = malloc(2 * sizeof(double));
    s->y = malloc(8 * sizeof(double));
    s->akima_slope = malloc(8 * sizeof(double));
    s->cubic_slope = malloc(8 * sizeof(double));
    s->z[0] = 0.0, s->z[1] = 2.0;
    for (int k = 0; k < 4; ++k)
        s->y[k] = s->x[k], s->y[4 + k] = 2.0 * s->x[k] + 1.0;
    for (int j = 0; j < 2; ++j) {
        hx_akima_slopes(s->x, s->y + 4 * j, 4, s->akima_slope + 4 * j);
        assert_int_equal(hx_natural_cubic_slopes(s->x, s->y + 4 * j, 4, s->cubic_slope + 4 * j), 0);
    }
    /* y = x + z (x + 1) / 2: y_x = 1 + z / 2, y_z = (x + 1) / 2, y_xz = 1/2 */
    const double xz[][2] = {{1.5, 0.5}, {0.25, 2.0}, {2.0, -1.0}, {5.0, 3.0}};
    for (size_t k = 0; k < 4; ++k) {
        const double x = xz[k][0], z = xz[k][1];
        double v[3];
        int err = -1;
        c_cubspl(x, z, 7, 0, v, &err);
        assert_int_equal(err, 0);
        assert_close(v[0], x + z * (x + 1.0) / 2.0, 0, 1e-14);
        c_akispl(x, z, 7, 1, v, &err);
        assert_close(v[0], 1.0 + z / 2.0, 0, 1e-14);
        assert_close(v[1], (x + 1.0) / 2.0, 0, 1e-14);
        c_akispl(x, z, 7, 2, v, &err);
        assert_close(v[0], 0.0, 0, 1e-13);
        assert_close(v[1], 0.5, 0, 1e-14);
        assert_close(v[2], 0.0, 0, 0);
    }
    unbind(&b);
}

static void refused_arguments_set_the_flag_and_are_noted_once(void **state)
{
    (void)state;
    bound b;
    bind(&b, "refused.xml", documented);
    double v[3] = {0, 0, 0};
    int err = 0;
    c_akispl(1.0, 0.0, 99, 0, v, &err);
    assert_int_equal(err, 1);
    c_akispl(2.0, 0.0, 99, 0, v, &err); /* again: noted once */
    assert_int_equal(err, 1);
    c_cubspl(1.0, 0.0, 7, 3, v, &err);
    assert_int_equal(err, 1);
    c_cubspl(NAN, 0.0, 7, 0, v, &err);
    assert_int_equal(err, 1);
    c_cubspl(1.0, 0.0, 7, 0, NULL, &err);
    assert_int_equal(err, 1);
    assert_true(b.call.misused & (1ull << HX_UTILITY_AKISPL));
    assert_true(b.call.misused & (1ull << HX_UTILITY_CUBSPL));
    assert_int_equal(b.call.unoffered, 0);
    fflush(b.stream);
    assert_contains(b.text, "Force_Scalar_TwoBody 4 (SFOSUB) called c_akispl with id 99, which"
                    " names no Reference_Spline of the model; it answered errflg = 1",
                    "called c_cubspl with iord = 3");
    const char *first = strstr(b.text, "id 99");
    assert_null(strstr(first + 1, "id 99"));
    unbind(&b);
    /* outside any call: no model, no spline */
    c_akispl(1.0, 0.0, 7, 0, v, &err);
    assert_int_equal(err, 1);
}

void akispl_(const double *xval, const double *zval, const int *id, const int *iord,
             double *array, int *errflg);
void cubspl_(const double *xval, const double *zval, const int *id, const int *iord,
             double *array, int *errflg);

static void fortran_forms_answer_as_the_c_ones(void **state)
{
    (void)state;
    bound b;
    bind(&b, "fortran.xml", documented);
    const double x = 250.0, z = 0.0;
    const int id = 301002;
    for (int iord = 0; iord <= 2; ++iord) {
        double f[3] = {0, 0, 0}, c[3] = {0, 0, 0};
        int ferr = -1, cerr = -1;
        akispl_(&x, &z, &id, &iord, f, &ferr);
        c_akispl(x, z, id, iord, c, &cerr);
        assert_int_equal(ferr, 0);
        assert_memory_equal(f, c, sizeof f);
        cubspl_(&x, &z, &id, &iord, f, &ferr);
        c_cubspl(x, z, id, iord, c, &cerr);
        assert_int_equal(ferr, 0);
        assert_memory_equal(f, c, sizeof f);
    }
    unbind(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(akima_reproduces_an_equally_spaced_quadratic),
        cmocka_unit_test(akima_keeps_flat_data_flat),
        cmocka_unit_test(natural_cubic_of_four_points_worked_by_hand),
        cmocka_unit_test(knots_exactly_and_derivatives_against_differences),
        cmocka_unit_test(the_documented_form_is_read),
        cmocka_unit_test(malformed_splines_are_refused),
        cmocka_unit_test(the_utilities_answer_in_the_documented_layout),
        cmocka_unit_test(a_surface_is_linear_across_z),
        cmocka_unit_test(refused_arguments_set_the_flag_and_are_noted_once),
        cmocka_unit_test(fortran_forms_answer_as_the_c_ones),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
