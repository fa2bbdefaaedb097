/*
 * The functions of the expression language (docs/interface.md §8.3): every
 * name the parser knows, with its argument counts, which of its arguments
 * are ids written as whole numbers, and what the harness does with it:
 * operators and pure functions it computes, IF, the model's splines and
 * curves, the measures and values it reads, and the functions it parses but
 * does not answer yet.
 */
#ifndef HX_MODEL_EXPR_FUNCTIONS_H
#define HX_MODEL_EXPR_FUNCTIONS_H

typedef enum hx_expr_function_code {
    /* operators */
    HX_FN_NEG, HX_FN_ADD, HX_FN_SUB, HX_FN_MUL, HX_FN_DIV, HX_FN_POW,
    /* pure functions of their arguments */
    HX_FN_ABS, HX_FN_SIGN, HX_FN_MIN, HX_FN_MAX, HX_FN_MOD, HX_FN_DIM, HX_FN_SQRT,
    HX_FN_EXP, HX_FN_LOG, HX_FN_LOG10, HX_FN_SIN, HX_FN_COS, HX_FN_TAN, HX_FN_ASIN,
    HX_FN_ACOS, HX_FN_ATAN, HX_FN_ATAN2, HX_FN_SINH, HX_FN_COSH, HX_FN_TANH, HX_FN_AINT,
    HX_FN_ANINT, HX_FN_STEP, HX_FN_STEP5, HX_FN_HAVSIN, HX_FN_IMPACT, HX_FN_BISTOP,
    HX_FN_POLY, HX_FN_CHEBY, HX_FN_FORCOS, HX_FN_FORSIN, HX_FN_SHF,
    HX_FN_IF,
    /* the model's splines and curves */
    HX_FN_AKISPL, HX_FN_CUBSPL, HX_FN_CURVE,
    /* the measures, in the order of frames/measure_functions.h's hx_measure */
    HX_FN_DX, HX_FN_DY, HX_FN_DZ, HX_FN_DM, HX_FN_AX, HX_FN_AY, HX_FN_AZ, HX_FN_PSI,
    HX_FN_THETA, HX_FN_PHI, HX_FN_YAW, HX_FN_PITCH, HX_FN_ROLL, HX_FN_INCANG, HX_FN_VX,
    HX_FN_VY, HX_FN_VZ, HX_FN_VM, HX_FN_VR, HX_FN_WX, HX_FN_WY, HX_FN_WZ, HX_FN_WM,
    /* values the caller keeps or the model holds */
    HX_FN_VARVAL, HX_FN_DIF, HX_FN_DIF1, HX_FN_ARYVAL,
    /* accelerations (HX_FK_ACCELERATION), the forces at a marker (FX .. TM:
     * HX_FK_MARKER_FORCE), the constraint elements' forces (JOINT, JPRIM, MOTION,
     * COUPLER, GCON: HX_FK_REACTION) and the force elements' forces (HX_FK_LOAD),
     * answered in output expressions (and some in the algebraic loop); but ORIENT, a
     * measure (HX_FK_MEASURE) of its own arguments (system, component, I[, J]) */
    HX_FN_ACCX, HX_FN_ACCY, HX_FN_ACCZ, HX_FN_ACCM, HX_FN_WDTX, HX_FN_WDTY, HX_FN_WDTZ,
    HX_FN_WDTM, HX_FN_FX, HX_FN_FY, HX_FN_FZ, HX_FN_FM, HX_FN_TX, HX_FN_TY, HX_FN_TZ,
    HX_FN_TM, HX_FN_JOINT, HX_FN_SFORCE, HX_FN_VFORCE, HX_FN_VTORQ, HX_FN_GFORCE,
    HX_FN_MOTION, HX_FN_BUSHING, HX_FN_FIELD, HX_FN_COUPLER, HX_FN_JPRIM, HX_FN_GCON,
    HX_FN_ORIENT, HX_FN_BEAM, HX_FN_SPDP,
    HX_FN_COUNT
} hx_expr_function_code;

typedef enum hx_expr_function_kind {
    HX_FK_OPERATOR,   /* + - * / ** and unary minus */
    HX_FK_PURE,       /* a function of its arguments alone */
    HX_FK_IF,         /* IF(e1: e2, e3, e4) */
    HX_FK_SPLINE,     /* AKISPL, CUBSPL of a Reference_Spline */
    HX_FK_CURVE,      /* CURVE of a curve */
    HX_FK_MEASURE,    /* a measure of markers (frames) */
    HX_FK_VARVAL,     /* a Reference_Variable's value */
    HX_FK_DIF,        /* a Control_Diff's state */
    HX_FK_DIF1,       /* a Control_Diff's rate */
    HX_FK_ARYVAL,     /* a component of a Reference_Array */
    HX_FK_REACTION,   /* a constraint element's force (JOINT, JPRIM, MOTION, COUPLER, GCON:
                       * id, jflag, comp, rm) */
    HX_FK_ACCELERATION, /* a marker's acceleration (ACCX .. WDTM): output expressions only */
    HX_FK_LOAD,       /* an element's force (SFORCE, VFORCE, VTORQ, GFORCE, BUSHING, FIELD:
                       * id, jflag, comp, rm): output expressions only */
    HX_FK_MARKER_FORCE  /* the net force or torque at a marker (FX .. TM: I[, J[, K]]): output
                       * expressions only */
} hx_expr_function_kind;

typedef struct hx_expr_function {
    const char *name;          /* as written, in capitals: "STEP", "+" */
    hx_expr_function_kind kind;
    int least, most;           /* how many arguments it takes */
    unsigned ids;              /* bit k: argument k is an id or a whole-number option,
                                * written as a whole number, not an expression */
    const char *arguments;     /* its arguments for messages: "(x, x0, h0, x1, h1)" */
} hx_expr_function;

/* The function with this code. */
const hx_expr_function *hx_expr_function_at(int code);
/* The code of the function named (capitals), or -1. Operators are not
 * found by name. */
int hx_expr_function_find(const char *name);

#endif
