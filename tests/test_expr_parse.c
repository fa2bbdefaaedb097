/*
 * The function-expression language read (docs/interface.md §8.1, §8.2):
 * numbers and degrees, names in any case, precedence and associativity (each
 * case folded as a constant and evaluated with the numbers as variables, so
 * that the parser's folding and the evaluator agree), blanks and line breaks
 * anywhere, IF's branches, the constants folded, and every error with its
 * line and column: parse, link and evaluation.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expr_support.h"
#include "model/expr/expr.h"

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

/* text with every digit d written VARVAL(d) (variable d holds d): the same
 * arithmetic, evaluated instead of folded. */
static const char *as_variables(const char *text, char *out, size_t size)
{
    size_t n = 0;
    for (const char *c = text; *c != '\0' && n + 12 < size; ++c)
        n += (size_t)(*c >= '1' && *c <= '9' ? snprintf(out + n, size - n, "VARVAL(%c)", *c)
                                             : snprintf(out + n, size - n, "%c", *c));
    return out;
}

static double folded(const char *text)
{
    hx_message msg;
    hx_expr_program *p = hx_expr_parse(text, strlen(text), NULL, &msg);
    if (p == NULL)
        fail_msg("\"%s\": %s", text, msg.text);
    double value = NAN;
    if (!hx_expr_constant(p, &value))
        fail_msg("\"%s\" did not fold to one constant (%d ops)", text, hx_expr_op_count(p));
    hx_expr_free(p);
    return value;
}

/* Fortran's precedence (** over * / over + -, ** right to left, the others
 * left to right), a sign taking the power after it, a sign after an
 * operator. Each worked by hand. */
static void precedence_and_associativity(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        double value;
    } cases[] = {
        {"-2**2", -4.0},      /* -(2**2): the sign below the power */
        {"2**3**2", 512.0},   /* 2**(3**2) = 2**9, not (2**3)**2 = 64 */
        {"2*-3", -6.0},       /* a sign after an operator */
        {"2**-1", 0.5},       /* a signed exponent */
        {"-(2)**2", -4.0},    /* -((2)**2) */
        {"1-2-3", -4.0},      /* (1-2)-3, not 1-(2-3) = 2 */
        {"8/4/2", 1.0},       /* (8/4)/2, not 8/(4/2) = 4 */
        {"2+3*4", 14.0},
        {"(2+3)*4", 20.0},
        {"2**2*3", 12.0},     /* (2**2)*3 */
        {"2*3**2", 18.0},     /* 2*(3**2) */
        {"-2**-2", -0.25},    /* -(2**(-2)) */
        {"2-3**2", -7.0},
        {"6/2*3", 9.0},       /* (6/2)*3 */
        {"- -2", 2.0},
        {"+2*+3", 6.0},
        {"9-+2", 7.0},
        {"-2*3+4", -2.0},     /* ((-2)*3)+4 */
        {"2**(1+1)**3", 256.0}, /* 2**((1+1)**3) = 2**8 */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char text[512];
        assert_close(folded(cases[k].text), cases[k].value, 0, 0);
        assert_close(expr_value(&fixture, as_variables(cases[k].text, text, sizeof text)),
                     cases[k].value, 0, 0);
    }
}

static void numbers_and_degrees(void **state)
{
    (void)state;
    assert_close(folded("1"), 1.0, 0, 0);
    assert_close(folded("1.5"), 1.5, 0, 0);
    assert_close(folded(".5"), 0.5, 0, 0);
    assert_close(folded("1."), 1.0, 0, 0);
    assert_close(folded("1E-3"), 1e-3, 0, 0);
    assert_close(folded("1.5e+2"), 150.0, 0, 0);
    assert_close(folded("2.5E2"), 250.0, 0, 0);
    assert_close(folded("0202"), 202.0, 0, 0);  /* leading zeros, as in marker ids */
    /* a D after a number: degrees; 30D = pi/6, 1.5E1D = 15 degrees, 360D = 2 pi */
    assert_close(folded("30D"), M_PI / 6.0, 1e-15, 0);
    assert_close(folded("30d"), M_PI / 6.0, 1e-15, 0);
    assert_close(folded("1.5E1D"), M_PI / 12.0, 1e-15, 0);
    assert_close(folded("360D"), 2.0 * M_PI, 1e-15, 0);
    assert_close(folded("-90D*RTOD"), -90.0, 1e-13, 0);
    assert_close(folded("PI"), M_PI, 0, 0);
    assert_close(folded("180*DTOR"), M_PI, 1e-15, 0);
    assert_close(folded("RTOD"), 180.0 / M_PI, 0, 0);
}

static void names_in_any_case(void **state)
{
    (void)state;
    assert_close(folded("sin(pi/2)"), 1.0, 0, 0);
    assert_close(folded("Sin(Pi/2)*dtor*RTOD"), 1.0, 1e-15, 0);
    assert_close(folded("step(1.5, 1, 0, 2, 10)"), 5.0, 1e-15, 0);
    fixture.frames.time = 0.75;
    assert_close(expr_value(&fixture, "time + Time + TIME"), 2.25, 0, 0);
    assert_close(expr_value(&fixture, "varval(2) + VarVal(3)"), 5.0, 0, 0);
    fixture.frames.time = 0.0;
}

static void blanks_and_line_breaks(void **state)
{
    (void)state;
    assert_close(folded(" \n 1 \n +\t2\r\n"), 3.0, 0, 0);
    assert_close(folded("STEP ( 1.5 ,\n 1 , 0 ,\n\t2 , 10 )"), 5.0, 1e-15, 0);
    assert_close(expr_value(&fixture, "VARVAL\n(\n4\n)\n**\n2"), 16.0, 0, 0);
    assert_close(expr_value(&fixture, "IF(VARVAL(1)-1\n:\n10,\n20,\n30)"), 20.0, 0, 0);
}

/* IF(e1: e2, e3, e4): e2 where e1 < 0, e3 where e1 = 0, e4 where e1 > 0; the
 * branch not taken is not evaluated (a division by zero there is no fault). */
static void if_takes_one_branch(void **state)
{
    (void)state;
    for (int k = 1; k <= 3; ++k) {
        fixture.variables[0] = k;
        assert_close(expr_value(&fixture, "IF(VARVAL(1) - 2: 10, 20, 30)"), 10.0 * k, 0, 0);
        assert_close(expr_value(&fixture, "IF(VARVAL(1) - 2, 10, 20, 30)"), 10.0 * k, 0, 0);
    }
    fixture.variables[0] = 3.0;
    assert_close(expr_value(&fixture, "IF(VARVAL(1): 1/0, LOG(-1), 7)"), 7.0, 0, 0);
    fixture.variables[0] = -3.0;
    assert_close(expr_value(&fixture, "IF(VARVAL(1): 8, LOG(-1), 1/0)"), 8.0, 0, 0);
    fixture.variables[0] = 0.0;
    assert_close(expr_value(&fixture, "IF(VARVAL(1): 1/0, 9, 1/0)"), 9.0, 0, 0);
    /* nested, and a known condition chooses its branch when parsed */
    fixture.variables[0] = 1.0;
    assert_close(expr_value(&fixture, "IF(VARVAL(1): 1, IF(VARVAL(1)-1: 2, 3, 4), 5) +"
                                      " IF(0: 1/0, 100, 1/0)"), 105.0, 0, 0);
    assert_close(folded("IF(-1: 2, 3, 4)"), 2.0, 0, 0);
    fixture.variables[0] = 1.0;
}

/* The documentation's examples, as they are written. */
static void documented_examples(void **state)
{
    (void)state;
    fixture.frames.time = 1.5;
    /* STEP(1.5, 1, 0, 2, 10) = 10 (0.5^2 (3 - 1)) = 5 */
    assert_close(expr_value(&fixture, "IF(TIME-1: 0, 0, STEP(TIME,1,0,2,10))"), 5.0, 1e-14, 0);
    fixture.frames.time = 0.5;
    assert_close(expr_value(&fixture, "IF(TIME-1: 0, 0, STEP(TIME,1,0,2,10))"), 0.0, 0, 0);
    fixture.frames.time = 0.0;
    assert_close(expr_value(&fixture, "-1.0*RTOD*(VARVAL(2)-0.0*DTOR)-5E-2*RTOD*VARVAL(1)"),
                 -(2.0 + 0.05) * 180.0 / M_PI, 1e-14, 0);
    /* VARVAL(3)*SQRT(ABS(-4)) = 3 * 2 */
    assert_close(expr_value(&fixture, "VARVAL(3)*SQRT(ABS(-4))"), 6.0, 0, 0);
}

/* Constants fold as the text is parsed: one op; a call that would fault is
 * left for the evaluation to report in its place. */
static void constants_fold(void **state)
{
    (void)state;
    assert_close(folded("2*PI*RTOD"), 360.0, 1e-13, 0);
    assert_close(folded("MAX(1, 2) + STEP(0.5, 0, 0, 1, 1)"), 2.5, 1e-15, 0);
    hx_message msg;
    const char *product = "VARVAL(1) * (2 + 3) * 4";
    hx_expr_program *p = hx_expr_parse(product, strlen(product), NULL, &msg);
    assert_non_null(p);
    assert_int_equal(hx_expr_op_count(p), 5); /* VARVAL, 5, *, 4, * */
    hx_expr_free(p);
    p = hx_expr_parse("1/0", 3, NULL, &msg);
    assert_non_null(p);
    assert_int_equal(hx_expr_op_count(p), 3);
    hx_expr_free(p);
    /* x, x0 and 30 coefficients on the stack at once */
    const char *poly = "POLY(VARVAL(1), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,"
                       " 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30)";
    p = hx_expr_parse(poly, strlen(poly), NULL, &msg);
    assert_non_null(p);
    assert_int_equal(hx_expr_depth(p), 32);
    hx_expr_free(p);
}

static void parse_errors_name_line_and_column(void **state)
{
    (void)state;
    hx_message msg;
    assert_string_equal(expr_parse_error("FOO(1)", &msg), "m.xml:10:5: unknown function FOO");
    assert_string_equal(expr_parse_error("1 +\n  foo(2)", &msg),
                        "m.xml:11:3: unknown function FOO");
    assert_string_equal(expr_parse_error("DX(1,2,3,4)", &msg),
                        "m.xml:10:5: DX takes 1 to 3 arguments DX(I[, J[, K]]), not 4");
    assert_string_equal(expr_parse_error("2*SIN()", &msg),
                        "m.xml:10:7: SIN takes 1 argument SIN(x), not 0");
    assert_string_equal(expr_parse_error("STEP(TIME, 0, 1)", &msg),
                        "m.xml:10:5: STEP takes 5 arguments STEP(x, x0, h0, x1, h1), not 3");
    assert_string_equal(expr_parse_error("(1+2", &msg),
                        "m.xml:10:9: missing ')' to close the '(' at 10:5, found the end of"
                        " the expression");
    assert_string_equal(expr_parse_error("SIN(1+\n(2)", &msg),
                        "m.xml:11:4: expected ',' or ')' in the arguments of a call after ')',"
                        " found the end of the expression");
    assert_string_equal(expr_parse_error("1+2)", &msg), "m.xml:10:8: ')' without a '(' to close");
    assert_string_equal(expr_parse_error("1+", &msg),
                        "m.xml:10:7: expected a number, a name or '(' after '+', found the end"
                        " of the expression");
    assert_string_equal(expr_parse_error("2*\n  *3", &msg),
                        "m.xml:11:3: expected a number, a name or '(' after '*', found '*'");
    assert_string_equal(expr_parse_error("", &msg), "m.xml:10:5: empty expression");
    assert_string_equal(expr_parse_error("  \n\t ", &msg), "m.xml:11:3: empty expression");
    assert_string_equal(expr_parse_error("1 2", &msg),
                        "m.xml:10:7: the number 2 where an operator or the end was expected");
    assert_string_equal(expr_parse_error("1 @ 2", &msg),
                        "m.xml:10:7: a character the language does not have");
    assert_string_equal(expr_parse_error("1E+", &msg),
                        "m.xml:10:5: a number whose exponent has no digits");
    assert_string_equal(expr_parse_error("2DX(1)", &msg),
                        "m.xml:10:5: a number run into a name (an operator is missing)");
    assert_string_equal(expr_parse_error("1e999", &msg),
                        "m.xml:10:5: a number too large for a double");
    assert_string_equal(expr_parse_error("DM", &msg), "m.xml:10:5: DM is a function: write"
                        " DM(I[, J])");
    assert_string_equal(expr_parse_error("MODE - 4", &msg), "m.xml:10:5: unknown name MODE"
                        " (the constants are PI, DTOR, RTOD and TIME)");
    assert_string_equal(expr_parse_error("PI(2)", &msg),
                        "m.xml:10:5: PI is a constant, not a function");
    assert_string_equal(expr_parse_error("DX(1.5)", &msg),
                        "m.xml:10:8: DX(I[, J[, K]]): argument 1 must be written as a whole"
                        " number (an id or an option), not an expression");
    assert_string_equal(expr_parse_error("DX(21, 10+1)", &msg),
                        "m.xml:10:14: DX(I[, J[, K]]): argument 2 must be written as a whole"
                        " number (an id or an option), not an expression");
    assert_string_equal(expr_parse_error("DX(0, 10)", &msg),
                        "m.xml:10:8: DX: its I marker is 0: I names a marker (0 stands for the"
                        " ground's origin only in the later places)");
    assert_string_equal(expr_parse_error("IF(1: 2, 3)", &msg),
                        "m.xml:10:5: IF takes 4 expressions, IF(e1: e2, e3, e4): the value of"
                        " e2 where e1 < 0, e3 where e1 = 0, e4 where e1 > 0");
    assert_string_equal(expr_parse_error("1: 2", &msg),
                        "m.xml:10:6: ':' belongs in IF(e1: e2, e3, e4) only");
    assert_string_equal(expr_parse_error("AKISPL(TIME, 0, 101, 3)", &msg),
                        "m.xml:10:26: AKISPL: iord (argument 4) is 3: the value (0) or its first"
                        " (1) or second (2) derivative in x");
    assert_string_equal(expr_parse_error("CURVE(0, 0, 4, 1)", &msg),
                        "m.xml:10:17: CURVE: comp (argument 3) is 4: 1, 2 or 3 (x, y or z)");
    assert_string_equal(expr_parse_error("ARYVAL(30, 0)", &msg),
                        "m.xml:10:16: ARYVAL: its component (argument 2) counts from 1, not 0");
    assert_contains(expr_parse_error("2 * USER(1, 2)", &msg), "m.xml:10:9: USER(...) is not an"
                    " expression");
    /* a text nested past the parser's depth is refused, not a crash */
    char deep[1024];
    memset(deep, '(', 300);
    strcpy(deep + 300, "1");
    memset(deep + 301, ')', 300);
    deep[601] = '\0';
    assert_contains(expr_parse_error(deep, &msg), "nests deeper than");
    /* a chain of operations that do not fold, longer than the parser builds: refused;
     * a long one within the bound evaluates */
    char *chain = malloc(5 * 4100 + 1);
    size_t n = 0;
    for (int k = 0; k < 4100; ++k)
        n += (size_t)sprintf(chain + n, k ? "+TIME" : "TIME");
    assert_contains(expr_parse_error(chain, &msg), "the expression is longer than the harness"
                    " reads");
    chain[5 * 3000 - 1] = '\0';
    fixture.frames.time = 0.5;
    assert_close(expr_value(&fixture, chain), 1500.0, 0, 0);
    fixture.frames.time = 0.0;
    free(chain);
    /* a length that stops before the NUL reads only the length */
    hx_expr_program *p = hx_expr_parse("1+2junk", 3, NULL, &msg);
    assert_non_null(p);
    double value;
    assert_true(hx_expr_constant(p, &value) && value == 3.0);
    hx_expr_free(p);
}

static void link_errors_name_the_id(void **state)
{
    (void)state;
    hx_message msg;
    assert_string_equal(expr_link_error(&fixture, "1 + DX(10, 99)", &msg),
                        "m.xml:10:9: DX(10,99): no Reference_Marker 99 in the model");
    assert_string_equal(expr_link_error(&fixture, "2*\nVARVAL(42)", &msg),
                        "m.xml:11:1: VARVAL(42): no Reference_Variable 42 in the model");
    assert_string_equal(expr_link_error(&fixture, "DIF(3)", &msg),
                        "m.xml:10:5: DIF(3): no Control_Diff 3 in the model");
    assert_string_equal(expr_link_error(&fixture, "ARYVAL(30, 4)", &msg),
                        "m.xml:10:5: ARYVAL(30,4): Reference_Array 30 has 3 components");
    assert_string_equal(expr_link_error(&fixture, "ARYVAL(33, 1)", &msg),
                        "m.xml:10:5: ARYVAL(33,1): no Reference_Array 33 in the model");
    assert_contains(expr_link_error(&fixture, "ARYVAL(32, 1)", &msg),
                    "m.xml:10:5: ARYVAL(32,1): Reference_Array 32 is of type X");
    assert_string_equal(expr_link_error(&fixture, "AKISPL(TIME, 0, 999)", &msg),
                        "m.xml:10:5: AKISPL: no Reference_Spline 999 in the model");
    assert_string_equal(expr_link_error(&fixture, "CURVE(0, 0, 1, 5)", &msg),
                        "m.xml:10:5: CURVE: no curve 5 in the model");
    assert_contains(expr_link_error(&fixture, "1 + COUPLER(1, 0, 2, 0)", &msg),
                    "m.xml:10:9: COUPLER(1,0,2,0): a constraint element's force is known only"
                    " once the accelerations are");
    assert_contains(expr_link_error(&fixture, "1 + VFORCE(1, 0, 2, 0)", &msg),
                    "m.xml:10:9: VFORCE(1,0,2,0): another element's force: here it would"
                    " close an algebraic loop");
    assert_contains(expr_link_error(&fixture, "1 + SFORCE(1, 0, 2, 0)", &msg),
                    "m.xml:10:9: SFORCE(1,0,2,0): another element's force: here it would"
                    " close an algebraic loop");
    assert_contains(expr_link_error(&fixture, "ACCX(10)", &msg),
                    "m.xml:10:5: ACCX(10): an acceleration is known only once the forces are",
                    "algebraic loop");
    assert_contains(expr_link_error(&fixture, "FM(10)", &msg),
                    "m.xml:10:5: FM(10): the forces at a marker are known only once the"
                    " accelerations are", "algebraic loop");
}

/* Evaluation faults name the op, its place and the time; the value at
 * fault where there is one. */
static void evaluation_faults_name_line_and_column(void **state)
{
    (void)state;
    hx_message msg;
    fixture.frames.time = 0.25;
    fixture.variables[1] = 2.0;
    hx_expr_fault f = expr_fault(&fixture, "VARVAL(1) /\n (VARVAL(2) - 2)", &msg);
    assert_int_equal(f.kind, HX_EXPR_FAULT_DIVISION_BY_ZERO);
    assert_string_equal(msg.text, "test.xml:1:11: SFORCE/1: '/': division by zero at t = 0.25");
    f = expr_fault(&fixture, "1 +\n  LOG(VARVAL(1) - 2)", &msg);
    assert_int_equal(f.kind, HX_EXPR_FAULT_DOMAIN);
    assert_string_equal(msg.text, "test.xml:2:3: SFORCE/1: LOG: its argument is not above 0"
                        " (-1) at t = 0.25");
    f = expr_fault(&fixture, "2 * 1/0", &msg); /* left unfolded, faults in its place */
    assert_string_equal(msg.text, "test.xml:1:6: SFORCE/1: '/': division by zero at t = 0.25");
    fixture.variables[0] = NAN;
    f = expr_fault(&fixture, "1 + SQRT(\n VARVAL(1))", &msg);
    assert_int_equal(f.kind, HX_EXPR_FAULT_INPUT);
    assert_string_equal(msg.text, "test.xml:2:2: SFORCE/1: VARVAL: its value is not finite"
                        " (nan) at t = 0.25");
    fixture.variables[0] = 1000.0;
    f = expr_fault(&fixture, "EXP(VARVAL(1))", &msg);
    assert_int_equal(f.kind, HX_EXPR_FAULT_NOT_FINITE);
    assert_string_equal(msg.text, "test.xml:1:1: SFORCE/1: EXP: its result is not finite at"
                        " t = 0.25");
    f = expr_fault(&fixture, "VARVAL(1) * 1e308", &msg); /* overflow of '*' */
    assert_string_equal(msg.text, "test.xml:1:11: SFORCE/1: '*': its result is not finite at"
                        " t = 0.25");
    fixture.variables[0] = 1.0, fixture.variables[1] = 2.0;
    fixture.frames.time = 0.0;
}

/* A program not linked, or evaluated with another model's frames, faults. */
static void unlinked_programs_fault(void **state)
{
    (void)state;
    hx_message msg;
    hx_expr_program *p = hx_expr_parse("TIME", 4, NULL, &msg);
    assert_non_null(p);
    const hx_expr_context c = expr_context(&fixture);
    double value;
    hx_expr_fault fault;
    assert_int_equal(hx_expr_eval(p, &c, &value, &fault), -1);
    assert_int_equal(fault.kind, HX_EXPR_FAULT_NOT_LINKED);
    hx_expr_fail(&msg, p, &fault, NULL);
    assert_string_equal(msg.text, "(text):1:1: the expression is not linked against a model"
                        " (hx_expr_link) at t = 0");
    expr_fixture other;
    expr_open(&other, "other.xml", expr_function_model);
    assert_int_equal(hx_expr_link(p, other.model, &msg), 0);
    assert_int_equal(hx_expr_eval(p, &c, &value, &fault), -1);
    assert_int_equal(fault.kind, HX_EXPR_FAULT_NOT_LINKED);
    const hx_expr_context o = expr_context(&other);
    other.frames.time = 2.5;
    assert_int_equal(hx_expr_eval(p, &o, &value, &fault), 0);
    assert_close(value, 2.5, 0, 0);
    expr_close(&other);
    hx_expr_free(p);
}

/* What a program reads, each distinct input once, as linked. */
static void inputs_are_listed_once(void **state)
{
    (void)state;
    hx_expr_program *p = expr_compile(&fixture, "DX(10, 10) + DX(10, 10, 0) * TIME + VARVAL(1)"
                                                " + DIF(7) - DIF1(7) + ARYVAL(31, 2) + TIME"
                                                " + IF(1: DM(10), 0, 2)");
    assert_int_equal(hx_expr_input_count(p), 6);
    const hx_expr_input *in = hx_expr_inputs(p);
    char text[64];
    static const char *const names[6] = {"DX(10,10)", "TIME", "VARVAL(1)", "DIF(7)", "DIF1(7)",
                                         "ARYVAL(31,2)"};
    for (int k = 0; k < 6; ++k)
        assert_string_equal(hx_expr_input_text(&in[k], text, sizeof text), names[k]);
    assert_int_equal(in[0].kind, HX_EXPR_INPUT_MEASURE);
    assert_int_equal(in[0].index[0], hx_model_marker(fixture.model, 10));
    assert_int_equal(in[0].index[1], hx_model_marker(fixture.model, 10));
    assert_int_equal(in[0].index[2], -1); /* left out: the world's axes */
    assert_int_equal(in[2].variable, 0);
    assert_int_equal(in[5].variable, hx_model_variable(fixture.model, 3)); /* array 31's 2nd */
    /* the values read: DIF and DIF1 start at ic and ic_dot */
    const hx_expr_context c = expr_context(&fixture);
    hx_expr_fault fault;
    double v;
    assert_int_equal(hx_expr_input_value(p, &c, 3, &v, &fault), 0);
    assert_close(v, 0.25, 0, 0);
    assert_int_equal(hx_expr_input_value(p, &c, 4, &v, &fault), 0);
    assert_close(v, -1.5, 0, 0);
    assert_int_equal(hx_expr_input_value(p, &c, 5, &v, &fault), 0);
    assert_close(v, 3.0, 0, 0);
    hx_expr_free(p);
    assert_close(expr_value(&fixture, "ARYVAL(30, 2) * ARYVAL(30, 3) + ARYVAL(31, 1)"), -12.0,
                 0, 0); /* -2 * 7 + variable 2 (holding 2) */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(precedence_and_associativity),
        cmocka_unit_test(numbers_and_degrees),
        cmocka_unit_test(names_in_any_case),
        cmocka_unit_test(blanks_and_line_breaks),
        cmocka_unit_test(if_takes_one_branch),
        cmocka_unit_test(documented_examples),
        cmocka_unit_test(constants_fold),
        cmocka_unit_test(parse_errors_name_line_and_column),
        cmocka_unit_test(link_errors_name_the_id),
        cmocka_unit_test(evaluation_faults_name_line_and_column),
        cmocka_unit_test(unlinked_programs_fault),
        cmocka_unit_test(inputs_are_listed_once),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
