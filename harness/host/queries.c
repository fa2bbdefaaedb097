/* State queries and their answers (queries.h). */
#include "host/queries.h"

#include <stdio.h>
#include <string.h>

#include "base/vecmath.h"
#include "state/measures.h"

/* Function codes: the arrays, then the scalars (axis added to the base). */
enum {
    F_DISP, F_TDISP, F_RDISP, F_VEL, F_TVEL, F_RVEL, F_DM,
    F_DX, F_AX = F_DX + 3, F_VX = F_AX + 3, F_WX = F_VX + 3, F_COUNT = F_WX + 3
};
static const int max_nsize[F_COUNT] = {3, 3, 2, 4, 4, 3, 2, 3, 3, 3, 2, 2, 2, 4, 4, 4, 3, 3, 3};

static int is(const char *f, const char *name)
{
    while (*name != '\0' && *f == *name)
        ++f, ++name;
    return *name == '\0' && *f == '\0';
}

static int function_code(const char *f)
{
    if (f == NULL || f[0] == '\0')
        return -1;
    const int axis = f[1] >= 'X' && f[1] <= 'Z' && f[2] == '\0' ? f[1] - 'X' : -1;
    switch (f[0]) {
    case 'D':
        return is(f, "DISP") ? F_DISP : is(f, "DM") ? F_DM : axis >= 0 ? F_DX + axis : -1;
    case 'T':
        return is(f, "TDISP") ? F_TDISP : is(f, "TVEL") ? F_TVEL : -1;
    case 'R':
        return is(f, "RDISP") ? F_RDISP : is(f, "RVEL") ? F_RVEL : -1;
    case 'V':
        return is(f, "VEL") ? F_VEL : axis >= 0 ? F_VX + axis : -1;
    case 'A':
        return axis >= 0 ? F_AX + axis : -1;
    case 'W':
        return axis >= 0 ? F_WX + axis : -1;
    default:
        return -1;
    }
}

void hx_query_make(hx_query *q, const char *fnc, const int *ipar, int nsize, int is_array)
{
    q->function = function_code(fnc);
    q->nsize = nsize;
    q->is_array = is_array;
    for (int k = 0; k < 4; ++k)
        q->ipar[k] = k < nsize && ipar != NULL ? ipar[k] : 0;
    /* a plain copy: snprintf would cost more than the answer on the host's hot path */
    int n = 0;
    for (; fnc != NULL && n < (int)sizeof q->fnc - 1 && fnc[n] != '\0'; ++n)
        q->fnc[n] = fnc[n];
    q->fnc[n] = '\0';
}

int hx_query_same(const hx_query *a, const hx_query *b)
{
    if (a->function != b->function || a->nsize != b->nsize || strcmp(a->fnc, b->fnc) != 0)
        return 0;
    for (int k = 0; k < a->nsize && k < 4; ++k)
        if (a->ipar[k] != b->ipar[k])
            return 0;
    return 1;
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
static const hx_frame *marker_world(const hx_state *s, int id, hx_frame *scratch)
{
    if (id == 0)
        return &hx_world_frame;
    const int index = hx_model_marker(s->model, id);
    return index < 0 ? NULL : hx_state_marker(s, index, scratch);
}

int hx_answer(const hx_state *s, const hx_query *q, const int *ipar, double *values)
{
    const int code = q->function, nsize = q->nsize;
    const int array_function = code >= F_DISP && code <= F_RVEL;
    if (s == NULL || code < 0 || array_function != q->is_array || nsize < 1 ||
        nsize > max_nsize[code] || ipar == NULL || ipar[0] == 0)
        return -1;
    hx_frame scratch[4];
    const hx_frame *f[4];
    for (int k = 0; k < 4; ++k) {
        const int id = k < nsize ? ipar[k] : 0;
        /* repeated ids (J, J, J) share one frame */
        f[k] = k > 0 && id == (k - 1 < nsize ? ipar[k - 1] : 0) ? f[k - 1]
                                                                 : marker_world(s, id, &scratch[k]);
        if (f[k] == NULL)
            return -1;
    }
    const hx_frame *I = f[0], *J = f[1], *K = f[2], *L = f[3];
    double R[9], v[3];
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
    case F_DM:
        v3_sub(v, I->p, J->p);
        values[0] = v3_norm(v);
        return 1;
    default:
        break;
    }
    if (code < F_AX) {
        hx_displacement(I, J, K, v);
        values[0] = v[code - F_DX];
    } else if (code < F_VX) {
        hx_relative_rotation(I, J, R);
        hx_projection_angles(R, v);
        values[0] = v[code - F_AX];
    } else if (code < F_WX) {
        hx_relative_velocity(I, J, K, L, v);
        values[0] = v[code - F_VX];
    } else {
        hx_relative_angular_velocity(I, J, K, v);
        values[0] = v[code - F_WX];
    }
    return 1;
}

int hx_answer_query(const hx_state *s, const char *fnc, const int *ipar, int nsize,
                    int is_array, double *values)
{
    hx_query q;
    hx_query_make(&q, fnc, ipar, nsize, is_array);
    return hx_answer(s, &q, ipar, values);
}
