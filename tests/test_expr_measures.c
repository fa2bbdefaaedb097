/*
 * The measures of function expressions (docs/interface.md §8.5) on a model
 * with turned, moving markers at a general state: every measure in every
 * form of its optional markers against the host's answer (hx_answer, what a
 * library's c_sysfnc gets) and against the formula computed here from the
 * frames; INCANG, VM, VR, WM and the sign of PITCH by hand; the partials of
 * an expression of measures in its inputs.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "expr_support.h"
#include "frames/measure_functions.h"
#include "frames/measures.h"
#include "host/queries.h"
#include "model/expr/functions.h"

/* Ground markers 10 (origin) and 11 (at x = 0.5, turned 90 deg about z);
 * body 2 with markers 20 (its centre) and 21 (elsewhere, turned by Euler
 * angles); body 3 with 30 and 31 likewise. */
static const char *const model_xml =
    "<MotionSolve>\n<Model>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
    "<Reference_Marker id=\"11\" body_id=\"1\" pos_x=\"0.5\" a00=\"0\" a10=\"1\" a01=\"-1\""
    " a11=\"0\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
    " inertia_zz=\"1\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\"/>\n"
    "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"1.5\" pos_y=\"1.7\" pos_z=\"3.2\""
    " psi=\"0.3\" theta=\"0.5\" phi=\"-0.2\"/>\n"
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
    " inertia_zz=\"1\"/>\n"
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"-1\" pos_y=\"0.5\" pos_z=\"2\"/>\n"
    "<Reference_Marker id=\"31\" body_id=\"3\" pos_x=\"-0.7\" pos_y=\"0.9\" pos_z=\"2.4\""
    " psi=\"-0.6\" theta=\"1.1\" phi=\"0.4\"/>\n"
    "</Model>\n</MotionSolve>\n";

static expr_fixture fixture;

/* Body id at position p, turned by angle about axis, moving at v, spinning at w. */
static void place(int id, const double p[3], const double axis[3], double angle,
                  const double v[3], const double w[3])
{
    hx_frame *b = &fixture.frames.bodies[hx_model_body(fixture.model, id)];
    double unit[3];
    v3_scale(unit, axis, 1.0 / v3_norm(axis));
    m3_axis_angle(b->R, unit, angle);
    v3_copy(b->p, p), v3_copy(b->v, v), v3_copy(b->w, w);
}

static int setup(void **state)
{
    (void)state;
    expr_open(&fixture, "measures.xml", model_xml);
    place(2, (const double[]){1.1, 2.2, 2.9}, (const double[]){1, 2, 3}, 0.7,
          (const double[]){0.3, -0.2, 0.5}, (const double[]){0.4, -1.1, 0.7});
    place(3, (const double[]){-0.9, 0.6, 2.2}, (const double[]){-1, 0.5, 2}, 1.3,
          (const double[]){-0.1, 0.4, 0.2}, (const double[]){1.2, 0.3, -0.5});
    hx_frames_update(&fixture.frames);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    expr_close(&fixture);
    return 0;
}

/* The world frame of marker id (0: the world). */
static const hx_frame *frame(int id, hx_frame *scratch)
{
    return hx_frames_marker(&fixture.frames, id ? hx_model_marker(fixture.model, id) : -1,
                            scratch);
}

/* The measure named by its definition, from the frames, written out here:
 * ids in the function's order (I, J, K or L), 0 for those left out. */
static double by_definition(const char *name, const int ids[4])
{
    hx_frame s[4];
    const hx_frame *I = frame(ids[0], &s[0]), *J = frame(ids[1], &s[1]);
    const hx_frame *K = frame(ids[2], &s[2]), *L = frame(ids[3], &s[3]);
    double r[3], R[9], a[3];
    for (int k = 0; k < 3; ++k)
        r[k] = I->p[k] - J->p[k];
    const char family = name[0], axis = name[1];
    const int component = axis == 'X' ? 0 : axis == 'Y' ? 1 : 2;
    if (strcmp(name, "DM") == 0)
        return sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (family == 'D') /* R_K^T r: K's axis dotted with r */
        return K->R[component] * r[0] + K->R[3 + component] * r[1] + K->R[6 + component] * r[2];
    if (strcmp(name, "INCANG") == 0) { /* the angle at J between J->I and J->K */
        double b[3];
        for (int k = 0; k < 3; ++k)
            b[k] = K->p[k] - J->p[k];
        return acos(v3_dot(r, b) / (v3_norm(r) * v3_norm(b)));
    }
    if (family == 'A' || strcmp(name, "PSI") == 0 || strcmp(name, "THETA") == 0 ||
        strcmp(name, "PHI") == 0) {
        hx_relative_rotation(I, J, R);
        if (family == 'A')
            return hx_projection_angle(R, component);
        hx_euler313(R, a);
        return a[name[1] == 'S' ? 0 : name[1] == 'H' && name[2] == 'E' ? 1 : 2];
    }
    if (family == 'V' || family == 'W') {
        double dv[3], wr[3];
        if (family == 'W') {
            for (int k = 0; k < 3; ++k)
                dv[k] = I->w[k] - J->w[k];
            if (axis == 'M')
                return v3_norm(dv);
            return K->R[component] * dv[0] + K->R[3 + component] * dv[1] +
                   K->R[6 + component] * dv[2];
        }
        /* VR: along the line of sight, whatever the frame of the derivative */
        if (axis == 'R') {
            for (int k = 0; k < 3; ++k)
                dv[k] = I->v[k] - J->v[k];
            return v3_dot(dv, r) / v3_norm(r);
        }
        /* VM(I, J, L): L is the third argument */
        const hx_frame *D = axis == 'M' ? K : L;
        v3_cross(wr, D->w, r);
        for (int k = 0; k < 3; ++k)
            dv[k] = I->v[k] - J->v[k] - wr[k];
        if (axis == 'M')
            return v3_norm(dv);
        return K->R[component] * dv[0] + K->R[3 + component] * dv[1] +
               K->R[6 + component] * dv[2];
    }
    fail_msg("no definition written for %s", name);
    return 0.0;
}

/* Every measure with every count of markers it takes, ids drawn from the
 * model's (0 in the later places too): its expression against hx_answer and
 * the definition. */
static void every_measure_in_every_form(void **state)
{
    (void)state;
    const int choices[4][4] = {{21, 31, 20, 30}, {31, 10, 11, 21}, {20, 0, 31, 11},
                               {30, 21, 0, 0}};
    int checked = 0;
    for (int m = 0; m < HX_MEASURE_COUNT; ++m) {
        const char *name = hx_measure_name((hx_measure)m);
        int least, most;
        hx_measure_markers((hx_measure)m, &least, &most);
        /* the expression table takes the same arguments */
        const hx_expr_function *f = hx_expr_function_at(HX_FN_DX + m);
        assert_string_equal(f->name, name);
        assert_int_equal(f->least, least);
        assert_int_equal(f->most, most);
        for (int n = least; n <= most; ++n)
            for (int c = 0; c < 4; ++c) {
                int ids[4] = {0, 0, 0, 0};
                char text[96];
                int length = snprintf(text, sizeof text, "%s(", name);
                for (int k = 0; k < n; ++k) {
                    ids[k] = choices[c][k];
                    length += snprintf(text + length, sizeof text - (size_t)length, "%s%d",
                                       k ? ", " : "", ids[k]);
                }
                snprintf(text + length, sizeof text - (size_t)length, ")");
                if (strcmp(name, "INCANG") == 0 && (ids[1] == ids[0] || ids[1] == ids[2]))
                    continue;
                const double value = expr_value(&fixture, text);
                double answer = NAN;
                assert_int_equal(hx_answer_query(&fixture.frames, name, ids, n, 0, &answer), 1);
                if (!(value == answer))
                    fail_msg("%s = %.17g, c_sysfnc's answer %.17g", text, value, answer);
                if (strcmp(name, "YAW") != 0 && strcmp(name, "PITCH") != 0 &&
                    strcmp(name, "ROLL") != 0) {
                    const double defined = by_definition(name, ids);
                    if (!(fabs(value - defined) <= 1e-12 * (1.0 + fabs(defined))))
                        fail_msg("%s = %.17g, by its definition %.17g", text, value, defined);
                }
                ++checked;
            }
    }
    assert_true(checked > 150);
}

/* YAW, PITCH, ROLL of I relative to J turned Rz(yaw) Ry(b) Rx(roll): yaw,
 * -b (PITCH is the second angle negated, as the vendors define it), roll;
 * PSI, THETA, PHI of a turn Rz(psi) Rx(theta) Rz(phi) give those angles. */
static void angle_sequences_by_hand(void **state)
{
    (void)state;
    const double yaw = 0.3, b = 0.2, roll = -0.4;
    double Rz[9], Ry[9], Rx[9], T[9], R[9];
    m3_axis_angle(Rz, (const double[]){0, 0, 1}, yaw);
    m3_axis_angle(Ry, (const double[]){0, 1, 0}, b);
    m3_axis_angle(Rx, (const double[]){1, 0, 0}, roll);
    m3_mul(T, Rz, Ry);
    m3_mul(R, T, Rx);
    hx_frame *body = &fixture.frames.bodies[hx_model_body(fixture.model, 3)];
    const hx_frame saved = *body;
    memcpy(body->R, R, sizeof R);
    hx_frames_update(&fixture.frames);
    /* marker 30 has the body's axes; 10 is the world's */
    assert_close(expr_value(&fixture, "YAW(30)"), yaw, 1e-14, 0);
    assert_close(expr_value(&fixture, "PITCH(30, 10)"), -b, 1e-14, 0);
    assert_close(expr_value(&fixture, "ROLL(30)"), roll, 1e-14, 0);
    const double psi = 0.5, theta = 0.9, phi = -0.7;
    m3_axis_angle(Rz, (const double[]){0, 0, 1}, psi);
    m3_axis_angle(Rx, (const double[]){1, 0, 0}, theta);
    m3_axis_angle(Ry, (const double[]){0, 0, 1}, phi);
    m3_mul(T, Rz, Rx);
    m3_mul(body->R, T, Ry);
    hx_frames_update(&fixture.frames);
    assert_close(expr_value(&fixture, "PSI(30)"), psi, 1e-14, 0);
    assert_close(expr_value(&fixture, "THETA(30, 0)"), theta, 1e-14, 0);
    assert_close(expr_value(&fixture, "PHI(30)"), phi, 1e-14, 0);
    *body = saved;
    hx_frames_update(&fixture.frames);
}

/* INCANG, VM, VR and WM where they are plain: ground markers 10 (origin) and
 * 11 (x = 0.5), and body 2's centre moved to (0.5, 0.5, 0) moving at (1, 2,
 * 0) and spinning at (0, 0, 3). */
static void new_measures_by_hand(void **state)
{
    (void)state;
    hx_frame *body = &fixture.frames.bodies[hx_model_body(fixture.model, 2)];
    const hx_frame saved = *body;
    m3_identity(body->R);
    v3_set(body->p, 0.5, 0.5, 0.0), v3_set(body->v, 1.0, 2.0, 0.0), v3_set(body->w, 0, 0, 3);
    hx_frames_update(&fixture.frames);
    /* the angle at 11 between 11->20 (0, 0.5, 0) and 11->10 (-0.5, 0, 0): 90 deg;
     * at 10 between 10->20 (0.5, 0.5) and 10->11 (0.5, 0): 45 deg */
    assert_close(expr_value(&fixture, "INCANG(20, 11, 10)"), M_PI / 2.0, 1e-15, 0);
    assert_close(expr_value(&fixture, "INCANG(20, 10, 11)"), M_PI / 4.0, 1e-15, 0);
    assert_close(expr_value(&fixture, "INCANG(11, 0, 20)"), M_PI / 4.0, 1e-15, 0);
    /* |v| = sqrt 5 in ground; seen from 20's own turning frame (L = 20) the
     * origin's rate is v - w x r = (1, 2) - 3 (-0.5, 0.5) = (2.5, 0.5) */
    assert_close(expr_value(&fixture, "VM(20)"), sqrt(5.0), 1e-15, 0);
    assert_close(expr_value(&fixture, "VM(20, 10, 20)"), sqrt(2.5 * 2.5 + 0.25), 1e-15, 0);
    /* VR(20, 10) = v . r / |r| = (0.5 + 1) / sqrt(0.5) = 1.5 sqrt 2; as seen from 11:
     * r = (0, 0.5): 2; the same in any frame L */
    assert_close(expr_value(&fixture, "VR(20)"), 1.5 * sqrt(2.0), 1e-15, 0);
    assert_close(expr_value(&fixture, "VR(20, 11)"), 2.0, 1e-15, 0);
    assert_close(expr_value(&fixture, "VR(20, 11, 20)"), 2.0, 1e-15, 0);
    assert_close(expr_value(&fixture, "WM(20)"), 3.0, 0, 0);
    assert_close(expr_value(&fixture, "WM(20, 30)"), v3_norm((const double[]){-1.2, -0.3, 3.5}),
                 1e-15, 0);
    /* where the direction is not defined: 0 */
    assert_close(expr_value(&fixture, "VR(10, 10)"), 0.0, 0, 0);
    assert_close(expr_value(&fixture, "INCANG(20, 10, 10)"), 0.0, 0, 0);
    *body = saved;
    hx_frames_update(&fixture.frames);
}

/* An expression of measures: its partials in its inputs are its
 * coefficients; the inputs' values are the measures'. */
static void partials_in_measures(void **state)
{
    (void)state;
    hx_expr_program *p = expr_compile(&fixture, "3*DM(21, 11) - 2*VR(21, 11)*DM(21,11)"
                                                " + 0.5*WZ(31, 10, 20)**2");
    const hx_expr_context c = expr_context(&fixture);
    assert_int_equal(hx_expr_input_count(p), 3);
    double in[3], value, adjoint[3], forward[3];
    hx_expr_fault fault;
    for (int k = 0; k < 3; ++k)
        assert_int_equal(hx_expr_input_value(p, &c, k, &in[k], &fault), 0);
    assert_close(in[0], by_definition("DM", (const int[]){21, 11, 0, 0}), 1e-15, 0);
    assert_close(in[1], by_definition("VR", (const int[]){21, 11, 0, 0}), 1e-14, 0);
    assert_close(in[2], by_definition("WZ", (const int[]){31, 10, 20, 0}), 1e-14, 0);
    double scratch[256];
    assert_true(hx_expr_scratch_size(p) <= 256);
    assert_int_equal(hx_expr_eval_partials(p, &c, &value, adjoint, scratch, &fault), 0);
    assert_int_equal(hx_expr_eval_partials_forward(p, &c, &value, forward, scratch, &fault), 0);
    assert_close(value, 3.0 * in[0] - 2.0 * in[1] * in[0] + 0.5 * in[2] * in[2], 1e-15, 0);
    const double expected[3] = {3.0 - 2.0 * in[1], -2.0 * in[0], in[2]};
    for (int k = 0; k < 3; ++k) {
        assert_close(adjoint[k], expected[k], 1e-15, 1e-15);
        assert_close(forward[k], expected[k], 1e-15, 1e-15);
    }
    hx_expr_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_measure_in_every_form),
        cmocka_unit_test(angle_sequences_by_hand),
        cmocka_unit_test(new_measures_by_hand),
        cmocka_unit_test(partials_in_measures),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
