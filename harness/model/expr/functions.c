/* The functions of the expression language (functions.h). */
#include "model/expr/functions.h"

#include <string.h>

#define ALL_IDS 0xFu
#define ELEMENT_FORCE(NAME) \
    {NAME, HX_FK_LOAD, 4, 4, ALL_IDS, "(id, jflag, comp, rm)"}
#define CONSTRAINT_FORCE(NAME) \
    {NAME, HX_FK_REACTION, 4, 4, ALL_IDS, "(id, jflag, comp, rm)"}
#define MARKER_FORCE(NAME, MOST, ARGUMENTS) \
    {NAME, HX_FK_MARKER_FORCE, 1, MOST, ALL_IDS, ARGUMENTS}

static const hx_expr_function table[HX_FN_COUNT] = {
    [HX_FN_NEG] = {"-", HX_FK_OPERATOR, 1, 1, 0, ""},
    [HX_FN_ADD] = {"+", HX_FK_OPERATOR, 2, 2, 0, ""},
    [HX_FN_SUB] = {"-", HX_FK_OPERATOR, 2, 2, 0, ""},
    [HX_FN_MUL] = {"*", HX_FK_OPERATOR, 2, 2, 0, ""},
    [HX_FN_DIV] = {"/", HX_FK_OPERATOR, 2, 2, 0, ""},
    [HX_FN_POW] = {"**", HX_FK_OPERATOR, 2, 2, 0, ""},
    [HX_FN_ABS] = {"ABS", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_SIGN] = {"SIGN", HX_FK_PURE, 2, 2, 0, "(a1, a2)"},
    [HX_FN_MIN] = {"MIN", HX_FK_PURE, 2, 2, 0, "(a1, a2)"},
    [HX_FN_MAX] = {"MAX", HX_FK_PURE, 2, 2, 0, "(a1, a2)"},
    [HX_FN_MOD] = {"MOD", HX_FK_PURE, 2, 2, 0, "(a1, a2)"},
    [HX_FN_DIM] = {"DIM", HX_FK_PURE, 2, 2, 0, "(a1, a2)"},
    [HX_FN_SQRT] = {"SQRT", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_EXP] = {"EXP", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_LOG] = {"LOG", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_LOG10] = {"LOG10", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_SIN] = {"SIN", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_COS] = {"COS", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_TAN] = {"TAN", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_ASIN] = {"ASIN", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_ACOS] = {"ACOS", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_ATAN] = {"ATAN", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_ATAN2] = {"ATAN2", HX_FK_PURE, 2, 2, 0, "(y, x)"},
    [HX_FN_SINH] = {"SINH", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_COSH] = {"COSH", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_TANH] = {"TANH", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_AINT] = {"AINT", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_ANINT] = {"ANINT", HX_FK_PURE, 1, 1, 0, "(x)"},
    [HX_FN_STEP] = {"STEP", HX_FK_PURE, 5, 5, 0, "(x, x0, h0, x1, h1)"},
    [HX_FN_STEP5] = {"STEP5", HX_FK_PURE, 5, 5, 0, "(x, x0, h0, x1, h1)"},
    [HX_FN_HAVSIN] = {"HAVSIN", HX_FK_PURE, 5, 5, 0, "(x, x0, h0, x1, h1)"},
    [HX_FN_IMPACT] = {"IMPACT", HX_FK_PURE, 7, 7, 0, "(x, xdot, x1, k, e, cmax, d)"},
    [HX_FN_BISTOP] = {"BISTOP", HX_FK_PURE, 8, 8, 0, "(x, xdot, x1, x2, k, e, cmax, d)"},
    [HX_FN_POLY] = {"POLY", HX_FK_PURE, 3, 33, 0, "(x, x0, a0[, a1, ..., a30])"},
    [HX_FN_CHEBY] = {"CHEBY", HX_FK_PURE, 3, 33, 0, "(x, x0, a0[, a1, ..., a30])"},
    [HX_FN_FORCOS] = {"FORCOS", HX_FK_PURE, 4, 34, 0, "(x, x0, w, a0[, a1, ..., a30])"},
    [HX_FN_FORSIN] = {"FORSIN", HX_FK_PURE, 4, 34, 0, "(x, x0, w, a0[, a1, ..., a30])"},
    [HX_FN_SHF] = {"SHF", HX_FK_PURE, 6, 6, 0, "(x, x0, a, w, phi, b)"},
    [HX_FN_IF] = {"IF", HX_FK_IF, 4, 4, 0, "(e1: e2, e3, e4)"},
    [HX_FN_AKISPL] = {"AKISPL", HX_FK_SPLINE, 3, 4, 0xCu, "(x, z, id[, iord])"},
    [HX_FN_CUBSPL] = {"CUBSPL", HX_FK_SPLINE, 3, 4, 0xCu, "(x, z, id[, iord])"},
    [HX_FN_CURVE] = {"CURVE", HX_FK_CURVE, 4, 4, 0xEu, "(alpha, iord, comp, id)"},
    [HX_FN_DX] = {"DX", HX_FK_MEASURE, 1, 3, ALL_IDS, "(I[, J[, K]])"},
    [HX_FN_DY] = {"DY", HX_FK_MEASURE, 1, 3, ALL_IDS, "(I[, J[, K]])"},
    [HX_FN_DZ] = {"DZ", HX_FK_MEASURE, 1, 3, ALL_IDS, "(I[, J[, K]])"},
    [HX_FN_DM] = {"DM", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_AX] = {"AX", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_AY] = {"AY", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_AZ] = {"AZ", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_PSI] = {"PSI", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_THETA] = {"THETA", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_PHI] = {"PHI", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_YAW] = {"YAW", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_PITCH] = {"PITCH", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_ROLL] = {"ROLL", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_INCANG] = {"INCANG", HX_FK_MEASURE, 3, 3, ALL_IDS, "(I, J, K)"},
    [HX_FN_VX] = {"VX", HX_FK_MEASURE, 1, 4, ALL_IDS, "(I[, J[, K[, L]]])"},
    [HX_FN_VY] = {"VY", HX_FK_MEASURE, 1, 4, ALL_IDS, "(I[, J[, K[, L]]])"},
    [HX_FN_VZ] = {"VZ", HX_FK_MEASURE, 1, 4, ALL_IDS, "(I[, J[, K[, L]]])"},
    [HX_FN_VM] = {"VM", HX_FK_MEASURE, 1, 3, ALL_IDS, "(I[, J[, L]])"},
    [HX_FN_VR] = {"VR", HX_FK_MEASURE, 1, 3, ALL_IDS, "(I[, J[, L]])"},
    [HX_FN_WX] = {"WX", HX_FK_MEASURE, 1, 3, ALL_IDS, "(I[, J[, K]])"},
    [HX_FN_WY] = {"WY", HX_FK_MEASURE, 1, 3, ALL_IDS, "(I[, J[, K]])"},
    [HX_FN_WZ] = {"WZ", HX_FK_MEASURE, 1, 3, ALL_IDS, "(I[, J[, K]])"},
    [HX_FN_WM] = {"WM", HX_FK_MEASURE, 1, 2, ALL_IDS, "(I[, J])"},
    [HX_FN_VARVAL] = {"VARVAL", HX_FK_VARVAL, 1, 1, ALL_IDS, "(id)"},
    [HX_FN_DIF] = {"DIF", HX_FK_DIF, 1, 1, ALL_IDS, "(id)"},
    [HX_FN_DIF1] = {"DIF1", HX_FK_DIF1, 1, 1, ALL_IDS, "(id)"},
    [HX_FN_ARYVAL] = {"ARYVAL", HX_FK_ARYVAL, 2, 2, ALL_IDS, "(id, comp)"},
    [HX_FN_ACCX] = {"ACCX", HX_FK_ACCELERATION, 1, 4, ALL_IDS, "(I[, J[, K[, L]]])"},
    [HX_FN_ACCY] = {"ACCY", HX_FK_ACCELERATION, 1, 4, ALL_IDS, "(I[, J[, K[, L]]])"},
    [HX_FN_ACCZ] = {"ACCZ", HX_FK_ACCELERATION, 1, 4, ALL_IDS, "(I[, J[, K[, L]]])"},
    [HX_FN_ACCM] = {"ACCM", HX_FK_ACCELERATION, 1, 3, ALL_IDS, "(I[, J[, L]])"},
    [HX_FN_WDTX] = {"WDTX", HX_FK_ACCELERATION, 1, 4, ALL_IDS, "(I[, J[, K[, L]]])"},
    [HX_FN_WDTY] = {"WDTY", HX_FK_ACCELERATION, 1, 4, ALL_IDS, "(I[, J[, K[, L]]])"},
    [HX_FN_WDTZ] = {"WDTZ", HX_FK_ACCELERATION, 1, 4, ALL_IDS, "(I[, J[, K[, L]]])"},
    [HX_FN_WDTM] = {"WDTM", HX_FK_ACCELERATION, 1, 3, ALL_IDS, "(I[, J[, L]])"},
    [HX_FN_FX] = MARKER_FORCE("FX", 3, "(I[, J[, K]])"),
    [HX_FN_FY] = MARKER_FORCE("FY", 3, "(I[, J[, K]])"),
    [HX_FN_FZ] = MARKER_FORCE("FZ", 3, "(I[, J[, K]])"),
    [HX_FN_FM] = MARKER_FORCE("FM", 2, "(I[, J])"),
    [HX_FN_TX] = MARKER_FORCE("TX", 3, "(I[, J[, K]])"),
    [HX_FN_TY] = MARKER_FORCE("TY", 3, "(I[, J[, K]])"),
    [HX_FN_TZ] = MARKER_FORCE("TZ", 3, "(I[, J[, K]])"),
    [HX_FN_TM] = MARKER_FORCE("TM", 2, "(I[, J])"),
    [HX_FN_JOINT] = CONSTRAINT_FORCE("JOINT"),
    [HX_FN_SFORCE] = ELEMENT_FORCE("SFORCE"),
    [HX_FN_VFORCE] = ELEMENT_FORCE("VFORCE"),
    [HX_FN_VTORQ] = ELEMENT_FORCE("VTORQ"),
    [HX_FN_GFORCE] = ELEMENT_FORCE("GFORCE"),
    [HX_FN_MOTION] = CONSTRAINT_FORCE("MOTION"),
    [HX_FN_BUSHING] = ELEMENT_FORCE("BUSHING"),
    [HX_FN_FIELD] = ELEMENT_FORCE("FIELD"),
    [HX_FN_COUPLER] = CONSTRAINT_FORCE("COUPLER"),
    [HX_FN_JPRIM] = CONSTRAINT_FORCE("JPRIM"),
    [HX_FN_GCON] = CONSTRAINT_FORCE("GCON"),
    [HX_FN_ORIENT] = {"ORIENT", HX_FK_MEASURE, 3, 4, ALL_IDS, "(system, component, I[, J])"},
    [HX_FN_BEAM] = ELEMENT_FORCE("BEAM"),
    [HX_FN_SPDP] = ELEMENT_FORCE("SPDP"),
};

const hx_expr_function *hx_expr_function_at(int code)
{
    return &table[code];
}

int hx_expr_function_find(const char *name)
{
    for (int k = HX_FN_ABS; k < HX_FN_COUNT; ++k)
        if (strcmp(table[k].name, name) == 0)
            return k;
    return -1;
}
