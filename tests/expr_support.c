/* Helpers of the function-expression tests (expr_support.h). */
#include "expr_support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const expr_function_model =
    "<MotionSolve>\n<Model>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
    "<Reference_Variable id=\"1\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Variable id=\"2\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Variable id=\"3\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Variable id=\"4\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Variable id=\"5\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Variable id=\"6\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Variable id=\"7\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Variable id=\"8\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Variable id=\"9\" type=\"EXPRESSION\" expr=\"0\"/>\n"
    "<Reference_Array id=\"30\" type=\"IC\" num_element=\"3\">1.5, -2, 7</Reference_Array>\n"
    "<Reference_Array id=\"31\" type=\"U\" num_element=\"2\" variable_id=\"2 3\"/>\n"
    "<Reference_Array id=\"32\" type=\"X\" num_element=\"2\"/>\n"
    "<Reference_Spline id=\"101\" num_xy_pair=\"6\">\n"
    "  -1.0 1000.0\n -0.6 600.0\n -0.25 250.0\n 0.1 -100.0\n 0.5 -500.0\n 1.0 -1000.0\n"
    "</Reference_Spline>\n"
    "<Reference_Spline id=\"102\" num_xy_pair=\"5\">0 0  1 1  2 4  3 9  4 16</Reference_Spline>\n"
    "<Control_Diff id=\"7\" type=\"USERSUB\" ic=\"0.25\" ic_dot=\"-1.5\""
    " usrsub_param_string=\"USER(1)\" usrsub_dll_name=\"none.so\"/>\n"
    "</Model>\n</MotionSolve>\n";

void expr_open(expr_fixture *f, const char *name, const char *xml)
{
    memset(f, 0, sizeof *f);
    hx_message msg;
    f->model = hx_model_parse(xml, strlen(xml), name, NULL, &msg);
    if (f->model == NULL)
        fail_msg("%s", msg.text);
    if (hx_frames_init(&f->frames, f->model) != 0)
        fail_msg("out of memory");
    for (int k = 0; k < 16; ++k)
        f->variables[k] = k + 1;
}

void expr_close(expr_fixture *f)
{
    hx_frames_free(&f->frames);
    hx_model_free(f->model);
    f->model = NULL;
}

hx_expr_context expr_context(expr_fixture *f)
{
    hx_expr_context c = {&f->frames, f->variables, NULL};
    return c;
}

hx_expr_program *expr_compile(expr_fixture *f, const char *text)
{
    const hx_expr_source where = {"test.xml", 1, 1};
    hx_message msg;
    hx_expr_program *p = hx_expr_parse(text, strlen(text), &where, &msg);
    if (p == NULL)
        fail_msg("\"%s\": %s", text, msg.text);
    if (hx_expr_link(p, f->model, &msg) != 0)
        fail_msg("\"%s\": %s", text, msg.text);
    return p;
}

double expr_value(expr_fixture *f, const char *text)
{
    hx_expr_program *p = expr_compile(f, text);
    const hx_expr_context c = expr_context(f);
    double value, adjoint, forward, partials[64];
    hx_expr_fault fault;
    hx_message msg;
    double *scratch = malloc(sizeof(double) * (hx_expr_scratch_size(p) + 1));
    if (hx_expr_eval(p, &c, &value, &fault) != 0 ||
        hx_expr_eval_partials(p, &c, &adjoint, partials, scratch, &fault) != 0 ||
        hx_expr_eval_partials_forward(p, &c, &forward, partials, scratch, &fault) != 0) {
        hx_expr_fail(&msg, p, &fault, NULL);
        fail_msg("\"%s\": %s", text, msg.text);
    }
    if (!(adjoint == value && forward == value))
        fail_msg("\"%s\": value %.17g, with the partials %.17g and %.17g", text, value, adjoint,
                 forward);
    free(scratch);
    hx_expr_free(p);
    return value;
}

hx_expr_fault expr_fault(expr_fixture *f, const char *text, hx_message *msg)
{
    hx_expr_program *p = expr_compile(f, text);
    const hx_expr_context c = expr_context(f);
    double value, partials[64];
    hx_expr_fault fault, other;
    if (hx_expr_eval(p, &c, &value, &fault) == 0)
        fail_msg("\"%s\" evaluated to %.17g; a fault was expected", text, value);
    double *scratch = malloc(sizeof(double) * (hx_expr_scratch_size(p) + 1));
    /* the partials' evaluation faults alike */
    if (hx_expr_eval_partials(p, &c, &value, partials, scratch, &other) == 0 ||
        other.kind != fault.kind || other.line != fault.line || other.column != fault.column)
        fail_msg("\"%s\": the adjoint evaluation does not fault as the value's does", text);
    if (hx_expr_eval_partials_forward(p, &c, &value, partials, scratch, &other) == 0 ||
        other.kind != fault.kind || other.line != fault.line || other.column != fault.column)
        fail_msg("\"%s\": the forward evaluation does not fault as the value's does", text);
    free(scratch);
    hx_expr_fail(msg, p, &fault, "SFORCE/1");
    hx_expr_free(p);
    return fault;
}

const char *expr_parse_error(const char *text, hx_message *msg)
{
    const hx_expr_source where = {"m.xml", 10, 5};
    hx_expr_program *p = hx_expr_parse(text, strlen(text), &where, msg);
    if (p != NULL) {
        hx_expr_free(p);
        fail_msg("\"%s\" parsed; an error was expected", text);
    }
    return msg->text;
}

const char *expr_link_error(expr_fixture *f, const char *text, hx_message *msg)
{
    const hx_expr_source where = {"m.xml", 10, 5};
    hx_expr_program *p = hx_expr_parse(text, strlen(text), &where, msg);
    if (p == NULL)
        fail_msg("\"%s\": %s", text, msg->text);
    if (hx_expr_link(p, f->model, msg) == 0)
        fail_msg("\"%s\" linked; an error was expected", text);
    hx_expr_free(p);
    return msg->text;
}

/* The value at f, the test failing on a fault. */
static double value_at(const hx_expr_program *p, expr_fixture *f, const char *text)
{
    const hx_expr_context c = expr_context(f);
    double value;
    hx_expr_fault fault;
    if (hx_expr_eval(p, &c, &value, &fault) != 0) {
        hx_message msg;
        hx_expr_fail(&msg, p, &fault, NULL);
        fail_msg("\"%s\": %s", text, msg.text);
    }
    return value;
}

/* Where input in is held at f (a variable, or the time), or NULL. */
static double *held(expr_fixture *f, const hx_expr_input *in)
{
    if (in->kind == HX_EXPR_INPUT_TIME)
        return &f->frames.time;
    if (in->kind == HX_EXPR_INPUT_VARVAL)
        return &f->variables[in->variable];
    return NULL;
}

double expr_check_partials(expr_fixture *f, const char *text, double tolerance)
{
    hx_expr_program *p = expr_compile(f, text);
    const hx_expr_context c = expr_context(f);
    const int n = hx_expr_input_count(p);
    const hx_expr_input *in = hx_expr_inputs(p);
    double value, adjoint[64], forward[64];
    hx_expr_fault fault;
    double *scratch = malloc(sizeof(double) * (hx_expr_scratch_size(p) + 1));
    if (hx_expr_eval_partials(p, &c, &value, adjoint, scratch, &fault) != 0 ||
        hx_expr_eval_partials_forward(p, &c, &value, forward, scratch, &fault) != 0) {
        hx_message msg;
        hx_expr_fail(&msg, p, &fault, NULL);
        fail_msg("\"%s\": %s", text, msg.text);
    }
    free(scratch);
    double worst = 0.0;
    for (int k = 0; k < n; ++k) {
        double *x = held(f, &in[k]);
        if (x == NULL)
            continue;
        const double x0 = *x, h = 1e-6 * (fabs(x0) > 1.0 ? fabs(x0) : 1.0);
        *x = x0 + h;
        const double up = value_at(p, f, text);
        *x = x0 - h;
        const double down = value_at(p, f, text);
        *x = x0;
        const double difference = (up - down) / (2.0 * h);
        const double scale = fabs(difference) > 1.0 ? fabs(difference) : 1.0;
        const double error = fmax(fabs(adjoint[k] - difference), fabs(forward[k] - difference))
                             / scale;
        if (error > worst)
            worst = error;
        if (!(error <= tolerance) || fabs(adjoint[k] - forward[k]) > 1e-12 * scale) {
            char name[64];
            fail_msg("\"%s\": d/d%s: adjoint %.17g, forward %.17g, differences %.17g", text,
                     hx_expr_input_text(&in[k], name, sizeof name), adjoint[k], forward[k],
                     difference);
        }
    }
    hx_expr_free(p);
    return worst;
}
