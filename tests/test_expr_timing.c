/*
 * What one evaluation of a function expression costs (docs/performance.md,
 * "Function expressions"): printed, never asserted (a loaded machine would
 * fail a bound), each the least of five rounds. The SFORCE law -k (DM - L) - c VR and an expression of some
 * 60 ops: the value alone, with partials by the adjoint sweep and by
 * forward accumulation, against one hx_answer of DM (what a library's
 * c_sysfnc costs the host), and the stack program against the same ops in
 * register form (each op naming its operands' slots), the alternative
 * compact form. Asserted: the methods agree, and DM read by the expression
 * is hx_answer's.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/clock.h"
#include "base/vecmath.h"
#include "expr_support.h"
#include "host/queries.h"
#include "model/expr/apply.h"
#include "model/expr/functions.h"
#include "model/expr/program.h"

static const char *const model_xml =
    "<MotionSolve>\n<Model>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"11\" body_id=\"1\" pos_x=\"0.5\" a00=\"0\" a10=\"1\" a01=\"-1\""
    " a11=\"0\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
    " inertia_zz=\"1\" v_ic_x=\"0.1\" v_ic_y=\"0.2\" v_ic_z=\"0.3\" w_ic_z=\"2\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\"/>\n"
    "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"0.7\" pos_y=\"0.2\" pos_z=\"0.01\""
    " psi=\"0.3\" theta=\"0.5\" phi=\"-0.2\"/>\n"
    "</Model>\n</MotionSolve>\n";

static const char *const sforce = "-1e4*(DM(21,11) - 0.25) - 50*VR(21,11)";
static const char *const sixty =
    "-2e4*(DX(21,11,11) - 0.01) - 80*VX(21,11,11)"
    " + 1e3*STEP(TIME, 0, 0, 0.5, 1)*SIN(AZ(21,11))"
    " - 30*WZ(21,11,11)*ABS(WZ(21,11,11))"
    " + IF(DZ(21,11,11): 0, 0, 5e3*DZ(21,11,11)**1.5)"
    " + IMPACT(DY(21,11,11), VY(21,11,11,11), 0.02, 1e5, 1.5, 100, 0.001)"
    " + POLY(AX(21,11), 0, 1, 2, 3, 4)*COS(TIME)";

/* The same ops in register form: each value in a slot of its own, each op
 * naming its operands' slots (made from the stack program by following the
 * stack; straight-line programs only). */
typedef struct reg_op {
    int code, function, nargs, a;
    int args[HX_EXPR_MAX_ARGUMENTS];
} reg_op;

static int to_registers(const hx_expr_program *p, reg_op *out)
{
    int stack[HX_EXPR_MAX_DEPTH], sp = 0;
    for (int k = 0; k < p->nops; ++k) {
        const hx_expr_op *op = &p->ops[k];
        if (op->code == HX_OP_IF || op->code == HX_OP_JUMP)
            return -1;
        out[k].code = op->code, out[k].function = op->function, out[k].nargs = op->nargs;
        out[k].a = op->a;
        sp -= op->nargs;
        for (int i = 0; i < op->nargs; ++i)
            out[k].args[i] = stack[sp + i];
        stack[sp++] = k;
    }
    return 0;
}

static double run_registers(const hx_expr_program *p, const reg_op *ops, const hx_expr_context *c,
                            double *slots)
{
    hx_expr_fault fault;
    double inputs[HX_EXPR_MAX_INPUTS];
    for (int k = 0; k < p->ninputs; ++k)
        hx_expr_input_value(p, c, k, &inputs[k], &fault);
    for (int k = 0; k < p->nops; ++k) {
        const reg_op *op = &ops[k];
        if (op->code == HX_OP_CONST) {
            slots[k] = p->constants[op->a];
        } else if (op->code == HX_OP_INPUT) {
            slots[k] = inputs[op->a];
        } else {
            double args[HX_EXPR_MAX_ARGUMENTS];
            for (int i = 0; i < op->nargs; ++i)
                args[i] = slots[op->args[i]];
            switch (op->function) {
            case HX_FN_ADD: slots[k] = args[0] + args[1]; break;
            case HX_FN_SUB: slots[k] = args[0] - args[1]; break;
            case HX_FN_MUL: slots[k] = args[0] * args[1]; break;
            default: hx_expr_apply(op->function, args, op->nargs, &slots[k], NULL, &fault);
            }
        }
    }
    return slots[p->nops - 1];
}

/* Nanoseconds per call of what: the least of five rounds of about 0.1 s
 * each (the machine is shared; the least is the cost without the others). */
#define TIME_IT(label, what)                                                             \
    do {                                                                                 \
        double sink = 0.0, best = INFINITY;                                              \
        for (int round_ = 0; round_ < 5; ++round_) {                                     \
            long calls = 0;                                                              \
            const double start = hx_seconds();                                           \
            double now = start;                                                          \
            while (now - start < 0.1) {                                                  \
                for (int r_ = 0; r_ < 1000; ++r_) {                                      \
                    fixture.frames.time = 1e-4 * r_;                                     \
                    what;                                                                \
                }                                                                        \
                calls += 1000;                                                           \
                now = hx_seconds();                                                      \
            }                                                                            \
            if (1e9 * (now - start) / (double)calls < best)                              \
                best = 1e9 * (now - start) / (double)calls;                              \
        }                                                                                \
        printf("  %-46s %8.1f ns%s\n", label, best, sink == 12345.678 ? " " : "");      \
    } while (0)

static expr_fixture fixture;

static void time_one(const char *name, const char *text, int with_registers)
{
    hx_expr_program *p = expr_compile(&fixture, text);
    const hx_expr_context c = expr_context(&fixture);
    double *scratch = malloc(sizeof(double) * hx_expr_scratch_size(p));
    double value, adjoint[HX_EXPR_MAX_INPUTS], forward[HX_EXPR_MAX_INPUTS];
    hx_expr_fault fault;
    assert_int_equal(hx_expr_eval(p, &c, &value, &fault), 0);
    double v1, v2;
    assert_int_equal(hx_expr_eval_partials(p, &c, &v1, adjoint, scratch, &fault), 0);
    assert_int_equal(hx_expr_eval_partials_forward(p, &c, &v2, forward, scratch, &fault), 0);
    assert_true(v1 == value && v2 == value);
    for (int k = 0; k < hx_expr_input_count(p); ++k)
        assert_close(adjoint[k], forward[k], 1e-14, 1e-14);
    printf("%s: %d ops, %d inputs, stack %d, scratch %zu doubles\n", name, hx_expr_op_count(p),
           hx_expr_input_count(p), hx_expr_depth(p), hx_expr_scratch_size(p));
    TIME_IT("value", (hx_expr_eval(p, &c, &value, &fault), sink += value));
    TIME_IT("value and partials, adjoint sweep",
            (hx_expr_eval_partials(p, &c, &value, adjoint, scratch, &fault), sink += adjoint[0]));
    TIME_IT("value and partials, forward accumulation",
            (hx_expr_eval_partials_forward(p, &c, &value, forward, scratch, &fault),
             sink += forward[0]));
    /* the same ops with the inputs taken first: the ops' own cost, stack against registers */
    reg_op *ops = malloc(sizeof *ops * (size_t)p->nops);
    double *slots = malloc(sizeof(double) * (size_t)p->nops);
    if (with_registers && to_registers(p, ops) == 0) {
        const double registers = run_registers(p, ops, &c, slots);
        assert_close(registers, value, 1e-15, 1e-15);
        TIME_IT("register form (inputs, then the ops)",
                (sink += run_registers(p, ops, &c, slots)));
    }
    double inputs[HX_EXPR_MAX_INPUTS];
    TIME_IT("its inputs alone (measures from the frames)",
            for (int k_ = 0; k_ < hx_expr_input_count(p); ++k_)
                (hx_expr_input_value(p, &c, k_, &inputs[k_], &fault), sink += inputs[k_]));
    free(ops);
    free(slots);
    free(scratch);
    hx_expr_free(p);
}

static void timings(void **state)
{
    (void)state;
    expr_open(&fixture, "timing.xml", model_xml);
    time_one("SFORCE law -k (DM - L) - c VR", sforce, 1);
    time_one("an expression of 60 ops (a bushing-like law)", sixty, 0);
    /* DM as a library asks it: the query made from its name, answered */
    const int ipar[2] = {21, 11};
    double dm = 0.0;
    assert_int_equal(hx_answer_query(&fixture.frames, "DM", ipar, 2, 0, &dm), 1);
    hx_expr_program *p = expr_compile(&fixture, "DM(21, 11)");
    const hx_expr_context c = expr_context(&fixture);
    double value;
    hx_expr_fault fault;
    assert_int_equal(hx_expr_eval(p, &c, &value, &fault), 0);
    assert_close(value, dm, 0, 0);
    printf("one answer of DM:\n");
    TIME_IT("hx_answer_query(\"DM\", 21, 11)",
            (hx_answer_query(&fixture.frames, "DM", ipar, 2, 0, &dm), sink += dm));
    TIME_IT("the expression DM(21, 11)", (hx_expr_eval(p, &c, &value, &fault), sink += value));
    hx_expr_free(p);
    expr_close(&fixture);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(timings),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
