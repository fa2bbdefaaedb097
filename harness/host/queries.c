/* State queries and their answers (queries.h). */
#include "host/queries.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/vecmath.h"
#include "frames/acceleration_measures.h"
#include "frames/measure_functions.h"
#include "frames/measures.h"
#include "model/expr/functions.h"

/* Function codes: the arrays, then the scalar measures (F_MEASURE plus the
 * measure, frames/measure_functions.h), then DIF and DIF1, then the
 * accelerations: the arrays ACC TACC RACC and the scalars (F_ACCX plus
 * frames/acceleration_measures.h's measure), then the forces (F_FORCE plus
 * the place in force_functions). */
enum {
    F_DISP, F_TDISP, F_RDISP, F_VEL, F_TVEL, F_RVEL, F_ARRAY,
    F_MEASURE,
    F_DIF = F_MEASURE + HX_MEASURE_COUNT, /* DIF, DIF1: a Control_Diff's state and its rate */
    F_DIF1,
    F_VARVAL, /* a Reference_Variable's value, as the variables stage computed it */
    F_ACC, F_TACC, F_RACC,
    F_ACCX,
    F_FORCE = F_ACCX + HX_WDT_M + 1
};
/* The forces' expression functions (model/expr/functions.h), F_FORCE's order. */
static const int force_functions[] = {
    HX_FN_JOINT,  HX_FN_JPRIM, HX_FN_MOTION, HX_FN_COUPLER, HX_FN_GCON,    HX_FN_SFORCE,
    HX_FN_VFORCE, HX_FN_VTORQ, HX_FN_GFORCE, HX_FN_FIELD,   HX_FN_BUSHING, HX_FN_BEAM,
    HX_FN_SPDP,   HX_FN_FX,    HX_FN_FY,     HX_FN_FZ,      HX_FN_FM,      HX_FN_TX,
    HX_FN_TY,     HX_FN_TZ,    HX_FN_TM};
/* the most ids each array function and DIF, DIF1 take */
static const int array_nsize[F_MEASURE] = {3, 3, 2, 4, 4, 3, 1};

/* The name packed into an integer, one byte per character, as the library's
 * pointer may be to any text: a switch on it replaces string comparisons on
 * the host's hot path. */
#define PACK2(a, b) ((unsigned long long)(a) | (unsigned long long)(b) << 8)
#define PACK3(a, b, c) (PACK2(a, b) | (unsigned long long)(c) << 16)
#define PACK4(a, b, c, d) (PACK3(a, b, c) | (unsigned long long)(d) << 24)
#define PACK5(a, b, c, d, e) (PACK4(a, b, c, d) | (unsigned long long)(e) << 32)
#define PACK6(a, b, c, d, e, f) (PACK5(a, b, c, d, e) | (unsigned long long)(f) << 40)
#define PACK7(a, b, c, d, e, f, g) (PACK6(a, b, c, d, e, f) | (unsigned long long)(g) << 48)

static int function_code(unsigned long long name)
{
    switch (name) {
    case PACK4('D', 'I', 'S', 'P'): return F_DISP;
    case PACK5('T', 'D', 'I', 'S', 'P'): return F_TDISP;
    case PACK5('R', 'D', 'I', 'S', 'P'): return F_RDISP;
    case PACK3('V', 'E', 'L'): return F_VEL;
    case PACK4('T', 'V', 'E', 'L'): return F_TVEL;
    case PACK4('R', 'V', 'E', 'L'): return F_RVEL;
    case PACK5('A', 'R', 'R', 'A', 'Y'): return F_ARRAY;
    case PACK2('D', 'X'): return F_MEASURE + HX_MEASURE_DX;
    case PACK2('D', 'Y'): return F_MEASURE + HX_MEASURE_DY;
    case PACK2('D', 'Z'): return F_MEASURE + HX_MEASURE_DZ;
    case PACK2('D', 'M'): return F_MEASURE + HX_MEASURE_DM;
    case PACK2('A', 'X'): return F_MEASURE + HX_MEASURE_AX;
    case PACK2('A', 'Y'): return F_MEASURE + HX_MEASURE_AY;
    case PACK2('A', 'Z'): return F_MEASURE + HX_MEASURE_AZ;
    case PACK3('P', 'S', 'I'): return F_MEASURE + HX_MEASURE_PSI;
    case PACK5('T', 'H', 'E', 'T', 'A'): return F_MEASURE + HX_MEASURE_THETA;
    case PACK3('P', 'H', 'I'): return F_MEASURE + HX_MEASURE_PHI;
    case PACK3('Y', 'A', 'W'): return F_MEASURE + HX_MEASURE_YAW;
    case PACK5('P', 'I', 'T', 'C', 'H'): return F_MEASURE + HX_MEASURE_PITCH;
    case PACK4('R', 'O', 'L', 'L'): return F_MEASURE + HX_MEASURE_ROLL;
    case PACK6('I', 'N', 'C', 'A', 'N', 'G'): return F_MEASURE + HX_MEASURE_INCANG;
    case PACK2('V', 'X'): return F_MEASURE + HX_MEASURE_VX;
    case PACK2('V', 'Y'): return F_MEASURE + HX_MEASURE_VY;
    case PACK2('V', 'Z'): return F_MEASURE + HX_MEASURE_VZ;
    case PACK2('V', 'M'): return F_MEASURE + HX_MEASURE_VM;
    case PACK2('V', 'R'): return F_MEASURE + HX_MEASURE_VR;
    case PACK2('W', 'X'): return F_MEASURE + HX_MEASURE_WX;
    case PACK2('W', 'Y'): return F_MEASURE + HX_MEASURE_WY;
    case PACK2('W', 'Z'): return F_MEASURE + HX_MEASURE_WZ;
    case PACK2('W', 'M'): return F_MEASURE + HX_MEASURE_WM;
    case PACK3('D', 'I', 'F'): return F_DIF;
    case PACK4('D', 'I', 'F', '1'): return F_DIF1;
    case PACK6('V', 'A', 'R', 'V', 'A', 'L'): return F_VARVAL;
    case PACK3('A', 'C', 'C'): return F_ACC;
    case PACK4('T', 'A', 'C', 'C'): return F_TACC;
    case PACK4('R', 'A', 'C', 'C'): return F_RACC;
    case PACK4('A', 'C', 'C', 'X'): return F_ACCX + HX_ACC_X;
    case PACK4('A', 'C', 'C', 'Y'): return F_ACCX + HX_ACC_Y;
    case PACK4('A', 'C', 'C', 'Z'): return F_ACCX + HX_ACC_Z;
    case PACK4('A', 'C', 'C', 'M'): return F_ACCX + HX_ACC_M;
    case PACK4('W', 'D', 'T', 'X'): return F_ACCX + HX_WDT_X;
    case PACK4('W', 'D', 'T', 'Y'): return F_ACCX + HX_WDT_Y;
    case PACK4('W', 'D', 'T', 'Z'): return F_ACCX + HX_WDT_Z;
    case PACK4('W', 'D', 'T', 'M'): return F_ACCX + HX_WDT_M;
    case PACK5('J', 'O', 'I', 'N', 'T'): return F_FORCE;
    case PACK5('J', 'P', 'R', 'I', 'M'): return F_FORCE + 1;
    case PACK6('M', 'O', 'T', 'I', 'O', 'N'): return F_FORCE + 2;
    case PACK7('C', 'O', 'U', 'P', 'L', 'E', 'R'): return F_FORCE + 3;
    case PACK4('G', 'C', 'O', 'N'): return F_FORCE + 4;
    case PACK6('S', 'F', 'O', 'R', 'C', 'E'): return F_FORCE + 5;
    case PACK6('V', 'F', 'O', 'R', 'C', 'E'): return F_FORCE + 6;
    case PACK5('V', 'T', 'O', 'R', 'Q'): return F_FORCE + 7;
    case PACK6('G', 'F', 'O', 'R', 'C', 'E'): return F_FORCE + 8;
    case PACK5('F', 'I', 'E', 'L', 'D'): return F_FORCE + 9;
    case PACK7('B', 'U', 'S', 'H', 'I', 'N', 'G'): return F_FORCE + 10;
    case PACK4('B', 'E', 'A', 'M'): return F_FORCE + 11;
    case PACK4('S', 'P', 'D', 'P'): return F_FORCE + 12;
    case PACK2('F', 'X'): return F_FORCE + 13;
    case PACK2('F', 'Y'): return F_FORCE + 14;
    case PACK2('F', 'Z'): return F_FORCE + 15;
    case PACK2('F', 'M'): return F_FORCE + 16;
    case PACK2('T', 'X'): return F_FORCE + 17;
    case PACK2('T', 'Y'): return F_FORCE + 18;
    case PACK2('T', 'Z'): return F_FORCE + 19;
    case PACK2('T', 'M'): return F_FORCE + 20;
    default: return -1;
    }
}

/* The fewest and the most ids a function takes. */
static void nsize_range(int code, int *least, int *most)
{
    *least = 1;
    if (code >= F_FORCE) { /* as the function language takes them (id, jflag, comp, rm) */
        const hx_expr_function *f = hx_expr_function_at(force_functions[code - F_FORCE]);
        *least = f->least, *most = f->most;
    } else if (code >= F_MEASURE && code < F_DIF)
        hx_measure_markers((hx_measure)(code - F_MEASURE), least, most);
    else if (code >= F_ACC) /* (I[, J[, K[, L]]]); the magnitudes (I[, J[, L]]) */
        *most = code == F_ACCX + HX_ACC_M || code == F_ACCX + HX_WDT_M ? 3 : 4;
    else
        *most = code < F_MEASURE ? array_nsize[code] : 1;
}

void hx_query_make(hx_query *q, const char *fnc, const int *ipar, int nsize, int is_array)
{
    /* a plain copy: snprintf would cost more than the answer on the host's hot path */
    unsigned long long name = 0;
    int n = 0;
    for (; fnc != NULL && n < (int)sizeof q->fnc - 1 && fnc[n] != '\0'; ++n) {
        q->fnc[n] = fnc[n];
        name |= (unsigned long long)(unsigned char)fnc[n] << 8 * n;
    }
    q->fnc[n] = '\0';
    /* a longer name is none of ours, whatever its first seven characters */
    q->function = fnc != NULL && fnc[n] == '\0' ? function_code(name) : -1;
    q->nsize = nsize;
    q->is_array = is_array;
    for (int k = 0; k < 4; ++k)
        q->ipar[k] = k < nsize && ipar != NULL ? ipar[k] : 0;
}

int hx_query_reads(const hx_query *q)
{
    if (q->function < 0)
        return -1;
    if (q->function == F_DIF || q->function == F_DIF1)
        return HX_READS_DIFF;
    if (q->function == F_VARVAL)
        return HX_READS_VARIABLE;
    if (q->function >= F_FORCE)
        return HX_READS_FORCES;
    if (q->function >= F_ACC)
        return HX_READS_ACCELERATIONS;
    return q->function == F_ARRAY ? HX_READS_ARRAY : HX_READS_MARKERS;
}

int hx_query_same(const hx_query *a, const hx_query *b)
{
    /* a known function code stands for its name; unknown ones compare by text */
    if (a->function != b->function || a->nsize != b->nsize || a->is_array != b->is_array ||
        a->ipar[0] != b->ipar[0] || a->ipar[1] != b->ipar[1] || a->ipar[2] != b->ipar[2] ||
        a->ipar[3] != b->ipar[3])
        return 0;
    return a->function >= 0 || strcmp(a->fnc, b->fnc) == 0;
}

const char *hx_query_text(const hx_query *q, char *text, size_t size)
{
    int n = snprintf(text, size, "%s(", q->fnc);
    for (int k = 0; k < q->nsize && k < 4 && n > 0 && (size_t)n < size; ++k)
        n += snprintf(text + n, size - (size_t)n, k ? ",%d" : "%d", q->ipar[k]);
    if (n > 0 && (size_t)n < size)
        snprintf(text + n, size - (size_t)n, ")");
    return text;
}

/* The world frame of a marker id (0: the world). */
static const hx_frame *marker_world(const hx_frames *fr, int id, hx_frame *scratch)
{
    if (id == 0)
        return &hx_world_frame;
    const int index = hx_model_marker(fr->model, id);
    return index < 0 ? NULL : hx_frames_marker(fr, index, scratch);
}

/* The numbers of the Reference_Array of type IC with id: its count, or -1. */
static int array_numbers(const hx_model *m, int id, double *values)
{
    const int k = hx_model_array(m, id);
    if (k < 0 || m->arrays[k].type != HX_ARRAY_IC)
        return -1;
    memcpy(values, m->arrays[k].numbers, sizeof(double) * (size_t)m->arrays[k].count);
    return m->arrays[k].count;
}

int hx_query_capacity(const hx_model *m)
{
    int most = 6;
    for (int k = 0; k < m->narrays; ++k)
        if (m->arrays[k].type == HX_ARRAY_IC && m->arrays[k].count > most)
            most = m->arrays[k].count;
    return most;
}

int hx_query_accelerations(const hx_query *q, int measures[6])
{
    static const int acc[6] = {HX_ACC_X, HX_ACC_Y, HX_ACC_Z, HX_WDT_X, HX_WDT_Y, HX_WDT_Z};
    switch (q->function) {
    case F_ACC:
    case F_TACC:
        memcpy(measures, acc, sizeof acc);
        return q->function == F_ACC ? 6 : 3;
    case F_RACC:
        memcpy(measures, acc + 3, 3 * sizeof *acc);
        return 3;
    default:
        if (q->function < F_ACCX || q->function >= F_FORCE)
            return 0;
        measures[0] = q->function - F_ACCX;
        return 1;
    }
}

int hx_query_force(const hx_query *q)
{
    return q->function >= F_FORCE ? force_functions[q->function - F_FORCE] : -1;
}

int hx_answer(const hx_frames *fr, const hx_query *q, const int *ipar, double *values)
{
    const int code = q->function, nsize = q->nsize;
    const int array_function = (code >= F_DISP && code <= F_ARRAY) ||
                               (code >= F_ACC && code <= F_RACC);
    int least = 1, most = 0;
    if (code >= 0)
        nsize_range(code, &least, &most);
    if (fr == NULL || code < 0 || array_function != q->is_array || nsize < least ||
        nsize > most || ipar == NULL || ipar[0] == 0)
        return -1;
    if (code >= F_FORCE) { /* the element is linked where it is declared; the loop's value */
        values[0] = 0.0;
        return 1;
    }
    if (code == F_ARRAY)
        return array_numbers(fr->model, ipar[0], values);
    if (code == F_DIF || code == F_DIF1) {
        const int k = hx_model_routine(fr->model, HX_ROUTINE_DIFF, ipar[0]);
        if (k < 0)
            return -1;
        values[0] = fr->diffs[2 * fr->model->routines[k].slot + (code == F_DIF1)];
        return 1;
    }
    if (code == F_VARVAL) {
        const int k = hx_model_variable(fr->model, ipar[0]);
        if (k < 0)
            return -1;
        values[0] = fr->variables != NULL ? fr->variables[k] : 0.0;
        return 1;
    }
    hx_frame scratch[4];
    const hx_frame *f[4];
    for (int k = 0; k < 4; ++k) {
        const int id = k < nsize ? ipar[k] : 0;
        /* repeated ids (J, J, J) share one frame */
        f[k] = k > 0 && id == (k - 1 < nsize ? ipar[k - 1] : 0) ? f[k - 1]
                                                                 : marker_world(fr, id, &scratch[k]);
        if (f[k] == NULL)
            return -1;
    }
    int measures[6];
    const int accelerations = hx_query_accelerations(q, measures);
    if (accelerations > 0) { /* the ids are good; the values are the loop's (queries.h) */
        memset(values, 0, sizeof *values * (size_t)accelerations);
        return accelerations;
    }
    const hx_frame *I = f[0], *J = f[1], *K = f[2], *L = f[3];
    switch (code) {
    case F_DISP:
    case F_TDISP:
        hx_displacement(I, J, K, values);
        if (code == F_TDISP)
            return 3;
        hx_relative_euler313(I, J, values + 3);
        return 6;
    case F_RDISP:
        hx_relative_euler313(I, J, values);
        return 3;
    case F_VEL:
    case F_TVEL:
        hx_relative_velocity(I, J, K, L, values);
        if (code == F_TVEL)
            return 3;
        hx_relative_angular_velocity(I, J, K, values + 3);
        return 6;
    case F_RVEL:
        hx_relative_angular_velocity(I, J, K, values);
        return 3;
    default:
        values[0] = hx_measure_value((hx_measure)(code - F_MEASURE), f);
        return 1;
    }
}

int hx_answer_family(const hx_frames *fr, char family, const int ipar[4], double v[3])
{
    hx_frame scratch[4];
    const hx_frame *f[4];
    for (int k = 0; k < 4; ++k)
        if ((f[k] = marker_world(fr, ipar[k], &scratch[k])) == NULL)
            return -1;
    double R[9];
    switch (family) {
    case 'D': hx_displacement(f[0], f[1], f[2], v); return 0;
    case 'V': hx_relative_velocity(f[0], f[1], f[2], f[3], v); return 0;
    case 'W': hx_relative_angular_velocity(f[0], f[1], f[2], v); return 0;
    case 'A':
        hx_relative_rotation(f[0], f[1], R);
        hx_projection_angles(R, v);
        return 0;
    default: return -1;
    }
}

int hx_answer_query(const hx_frames *fr, const char *fnc, const int *ipar, int nsize,
                    int is_array, double *values)
{
    hx_query q;
    hx_query_make(&q, fnc, ipar, nsize, is_array);
    return hx_answer(fr, &q, ipar, values);
}
