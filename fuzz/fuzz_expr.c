/*
 * Fuzz target: function expressions (harness/model/expr/, harness/expr/) on
 * arbitrary text: parsed, and when it parses linked against a small fixed
 * model, and when it links evaluated, its value and its partials by both
 * methods at a fixed state. A program or an error; an evaluation that
 * returns a value and partials that are finite, or a fault, the same by all
 * three evaluations; never a crash.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expr/evaluate.h"
#include "model/expr/expr.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char *const model_xml =
    "<MotionSolve>\n<Model>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
    "<Reference_Marker id=\"11\" body_id=\"1\" pos_x=\"0.5\" a00=\"0\" a10=\"1\" a01=\"-1\""
    " a11=\"0\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
    " inertia_zz=\"1\" v_ic_x=\"0.1\" v_ic_y=\"0.2\" v_ic_z=\"0.3\" w_ic_z=\"2\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\"/>\n"
    "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"1.5\" pos_y=\"1.7\" pos_z=\"3.2\""
    " psi=\"0.3\" theta=\"0.5\" phi=\"-0.2\"/>\n"
    "<Reference_Variable id=\"1\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Variable id=\"2\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Variable id=\"3\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Array id=\"30\" type=\"IC\" num_element=\"3\">1.5, -2, 7</Reference_Array>\n"
    "<Reference_Array id=\"31\" type=\"U\" num_element=\"2\" variable_id=\"2 3\"/>\n"
    "<Reference_Spline id=\"101\" num_xy_pair=\"5\">0 0  1 1  2 4  3 9  4 16</Reference_Spline>\n"
    "<Control_Diff id=\"7\" type=\"USERSUB\" ic=\"0.25\" ic_dot=\"-1.5\""
    " usrsub_param_string=\"USER(1)\" usrsub_dll_name=\"none.so\"/>\n"
    "</Model>\n</MotionSolve>\n";

static hx_model *model;
static hx_frames frames;
static const double variables[3] = {0.5, -2.0, 3.25};

static void open_model(void)
{
    hx_message msg;
    model = hx_model_parse(model_xml, strlen(model_xml), "/tmp/fuzz_expr.xml", NULL, &msg);
    if (model == NULL || hx_frames_init(&frames, model) != 0) {
        fprintf(stderr, "fuzz_expr: %s\n", model == NULL ? msg.text : "out of memory");
        abort();
    }
    /* a closed cubic curve 1 and an open one 2, by hand (no reader fills curves) */
    static const double square[15] = {1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 1, 0, 0};
    model->curves = calloc(2, sizeof *model->curves);
    model->ncurves = 2;
    for (int k = 0; k < 2; ++k) {
        hx_curve *c = &model->curves[k];
        c->id = k + 1, c->order = 4 - k, c->closed = k == 0, c->npoints = 5 - k;
        c->points = malloc(sizeof square);
        memcpy(c->points, square, sizeof square);
    }
    frames.time = 0.375;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (model == NULL)
        open_model();
    const hx_expr_source where = {"fuzz.xml", 3, 7};
    hx_message msg;
    hx_expr_program *p = hx_expr_parse((const char *)data, size, &where, &msg);
    if (p == NULL)
        return 0;
    if (hx_expr_link(p, model, &msg) != 0) {
        hx_expr_free(p);
        return 0;
    }
    const hx_expr_context c = {&frames, variables, NULL};
    const int n = hx_expr_input_count(p);
    double *scratch = malloc(sizeof(double) * (hx_expr_scratch_size(p) + 1));
    double *adjoint = malloc(sizeof(double) * (size_t)(n + 1));
    double *forward = malloc(sizeof(double) * (size_t)(n + 1));
    double value = 0.0, v_adjoint = 0.0, v_forward = 0.0;
    hx_expr_fault f0, f1, f2;
    const int s0 = hx_expr_eval(p, &c, &value, &f0);
    const int s1 = hx_expr_eval_partials(p, &c, &v_adjoint, adjoint, scratch, &f1);
    const int s2 = hx_expr_eval_partials_forward(p, &c, &v_forward, forward, scratch, &f2);
    if (s0 == 0 && !isfinite(value))
        abort(); /* a value that is not finite was returned */
    if ((s1 == 0 && v_adjoint != value) || (s2 == 0 && v_forward != value))
        abort(); /* the three evaluations disagree on the value */
    /* the methods sum an input's partials in different orders: one may overflow
     * where the other does not, and only then may they disagree */
    const int overflow = (s1 != 0 && f1.kind == HX_EXPR_FAULT_PARTIAL) ||
                         (s2 != 0 && f2.kind == HX_EXPR_FAULT_PARTIAL);
    if (((s1 != s2 || (s1 != 0 && f1.kind != f2.kind)) && !overflow) || (s1 == 0 && s0 != 0) ||
        (s2 == 0 && s0 != 0))
        abort(); /* the partial methods disagree with each other or with the value */
    for (int k = 0; k < n; ++k)
        if ((s1 == 0 && !isfinite(adjoint[k])) || (s2 == 0 && !isfinite(forward[k])))
            abort(); /* a partial that is not finite was returned */
    if (s0 != 0) {
        hx_expr_fail(&msg, p, &f0, "fuzz");
        if (msg.text[0] == '\0')
            abort();
    }
    free(scratch), free(adjoint), free(forward);
    hx_expr_free(p);
    return 0;
}
