/*
 * c_rcnvrt (docs/interface.md §5.2): rotational coordinates from one system
 * to another through the direction-cosine matrix A, whose columns are the
 * rotated axes in the reference frame (v_reference = A v_body):
 *   COSINES  9: A column by column (a11 a21 a31 a12 ...);
 *   EULPAR   4: e0 e1 e2 e3, e0 the scalar part;
 *   RODPAR   3: e1/e0 e2/e0 e3/e0;
 *   Bijk     3: body-fixed i-j-k angles, A = R_i(a1) R_j(a2) R_k(a3), for
 *               the twelve sequences (B313 ... B123);
 *   EULER    = B313 (psi theta phi, the angles DISP returns); BRYANT = B123;
 *   YPR      = B321 (yaw pitch roll);
 *   AXAYAZ   3: space-fixed X, then Y, then Z: A = Rz(az) Ry(ay) Rx(ax).
 * Angles come back as the harness's own measures take them (frames/measures.h,
 * hx_euler_sequence): in (-pi, pi], the middle one of a proper Euler sequence
 * in [0, pi], of a Tait-Bryan one in [-pi/2, pi/2]. coord2 may be coord1.
 */
#include <math.h>
#include <string.h>
#include <strings.h>

#include "base/vecmath.h"
#include "frames/measures.h"
#include "host/utilities.h"
#include "usrsub/solver_abi.h"

/* A system's name with Fortran's blank padding taken off. */
typedef struct system_spec {
    int size;     /* values */
    int kind;     /* 0 cosines, 1 Euler parameters, 2 Rodrigues, 3 a sequence */
    int axis[3];  /* a sequence's axes, 0..2 */
    int reversed; /* the angles are written in the reverse order (AXAYAZ) */
} system_spec;

static int parse_system(const char *name, system_spec *s)
{
    char text[16];
    size_t n = 0;
    while (name != NULL && name[n] != '\0' && n < sizeof text - 1 && name[n] != ' ')
        text[n] = name[n], ++n;
    text[n] = '\0';
    memset(s, 0, sizeof *s);
    s->size = 3, s->kind = 3;
    static const struct {
        const char *name;
        int kind, size, axis[3], reversed;
    } named[] = {{"COSINES", 0, 9, {0, 0, 0}, 0}, {"EULPAR", 1, 4, {0, 0, 0}, 0},
                 {"RODPAR", 2, 3, {0, 0, 0}, 0},  {"EULER", 3, 3, {2, 0, 2}, 0},
                 {"BRYANT", 3, 3, {0, 1, 2}, 0},  {"YPR", 3, 3, {2, 1, 0}, 0},
                 {"AXAYAZ", 3, 3, {2, 1, 0}, 1}};
    for (size_t k = 0; k < sizeof named / sizeof named[0]; ++k)
        if (strcasecmp(text, named[k].name) == 0) {
            s->kind = named[k].kind, s->size = named[k].size, s->reversed = named[k].reversed;
            memcpy(s->axis, named[k].axis, sizeof s->axis);
            return 0;
        }
    if (n == 4 && (text[0] == 'B' || text[0] == 'b')) {
        for (int k = 0; k < 3; ++k) {
            if (text[k + 1] < '1' || text[k + 1] > '3')
                return -1;
            s->axis[k] = text[k + 1] - '1';
        }
        if (s->axis[0] != s->axis[1] && s->axis[1] != s->axis[2])
            return 0;
    }
    return -1;
}

/* R_axis(angle), row-major */
static void elementary(int axis, double angle, double *R)
{
    const double c = cos(angle), s = sin(angle);
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    m3_identity(R);
    R[3 * i + i] = c, R[3 * i + j] = -s;
    R[3 * j + i] = s, R[3 * j + j] = c;
}

static void sequence_to_matrix(const int axis[3], const double a[3], double *A)
{
    double R1[9], R2[9], R3[9], T[9];
    elementary(axis[0], a[0], R1);
    elementary(axis[1], a[1], R2);
    elementary(axis[2], a[2], R3);
    m3_mul(T, R1, R2);
    m3_mul(A, T, R3);
}

static int to_matrix(const system_spec *s, const double *c, double *A)
{
    double q[4];
    switch (s->kind) {
    case 0:
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k)
                A[3 * r + k] = c[r + 3 * k]; /* column by column */
        return 0;
    case 1:
    case 2: {
        q[0] = s->kind == 1 ? c[0] : 1.0;
        for (int k = 0; k < 3; ++k)
            q[k + 1] = c[k + (s->kind == 1)];
        const double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(norm > 0.0) || !isfinite(norm))
            return -1;
        for (int k = 0; k < 4; ++k)
            q[k] /= norm;
        quat_to_matrix(A, q);
        return 0;
    }
    default: {
        double a[3] = {c[0], c[1], c[2]};
        if (s->reversed)
            a[0] = c[2], a[2] = c[0];
        sequence_to_matrix(s->axis, a, A);
        return 0;
    }
    }
}

static int from_matrix(const system_spec *s, const double *A, double *c)
{
    double q[4];
    switch (s->kind) {
    case 0:
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k)
                c[r + 3 * k] = A[3 * r + k];
        return 0;
    case 1:
    case 2:
        hx_euler_parameters(A, q);
        if (s->kind == 1) {
            memcpy(c, q, sizeof q);
            return 0;
        }
        if (!(q[0] > 0.0))
            return -1; /* a half turn has no Rodrigues parameters */
        for (int k = 0; k < 3; ++k)
            c[k] = q[k + 1] / q[0];
        return 0;
    default: {
        double a[3];
        hx_euler_sequence(s->axis, A, a);
        c[0] = s->reversed ? a[2] : a[0], c[1] = a[1], c[2] = s->reversed ? a[0] : a[2];
        return 0;
    }
    }
}

void c_rcnvrt(const char *sys1, const double *coord1, const char *sys2, double *coord2,
              int *istat)
{
    system_spec from, to;
    *istat = 0;
    if (coord1 == NULL || coord2 == NULL) {
        hx_utility_refused(HX_UTILITY_RCNVRT, "no coordinates (a null coord1 or coord2)");
        *istat = 1;
        return;
    }
    if (parse_system(sys1, &from) != 0 || parse_system(sys2, &to) != 0) {
        hx_utility_refused(HX_UTILITY_RCNVRT, "systems '%s' to '%s' (COSINES EULPAR RODPAR"
                           " EULER BRYANT YPR AXAYAZ Bijk)", sys1 != NULL ? sys1 : "(null)",
                           sys2 != NULL ? sys2 : "(null)");
        *istat = 1;
        return;
    }
    double in[9], A[9];
    memcpy(in, coord1, sizeof(double) * (size_t)from.size); /* coord2 may be coord1 */
    for (int k = 0; k < from.size; ++k)
        if (!isfinite(in[k])) {
            if (hx_utility_non_finite(HX_UTILITY_RCNVRT, "a non-finite coordinate (%g) in '%s'",
                                      in[k], sys1))
                for (int i = 0; i < to.size; ++i)
                    coord2[i] = NAN;
            else
                *istat = 1;
            return;
        }
    if (to_matrix(&from, in, A) != 0 || from_matrix(&to, A, coord2) != 0) {
        hx_utility_refused(HX_UTILITY_RCNVRT, "'%s' coordinates that '%s' cannot express (zero"
                           " Euler parameters, or a half turn as Rodrigues parameters)", sys1,
                           sys2);
        *istat = 1;
    }
}
