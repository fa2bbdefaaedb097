/*
 * The built-in linear force elements as expression loads (builtin_forces.h).
 * The expression text is generated here and parsed at the element's line,
 * so a fault names the element and its line; the load is tagged so that
 * messages and the force functions (BUSHING, SFORCE) name the element.
 */
#include "model/builtin_forces.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "model/load_elements.h"
#include "model/xml_attrs.h"

const hx_attr_spec hx_springdamper_attrs[] = {
    ID, REQUIRED("i_marker_id", HX_ATTR_INT), REQUIRED("j_marker_id", HX_ATTR_INT),
    REQUIRED("type", HX_ATTR_TEXT), REQUIRED("stiffness", HX_ATTR_REAL), REAL("damping"),
    REAL("length"), REAL("preload"), END};

const hx_attr_spec hx_bushing_attrs[] = {
    ID, REQUIRED("i_marker_id", HX_ATTR_INT), REQUIRED("j_marker_id", HX_ATTR_INT),
    REAL("kx"), REAL("ky"), REAL("kz"), REAL("ktx"), REAL("kty"), REAL("ktz"),
    REAL("cx"), REAL("cy"), REAL("cz"), REAL("ctx"), REAL("cty"), REAL("ctz"),
    REAL("preload_x"), REAL("preload_y"), REAL("preload_z"), REAL("preload_tx"),
    REAL("preload_ty"), REAL("preload_tz"), END};

const hx_attr_spec hx_beam_attrs[] = {
    ID, REQUIRED("i_marker_id", HX_ATTR_INT), REQUIRED("j_marker_id", HX_ATTR_INT),
    REQUIRED("length", HX_ATTR_REAL), REQUIRED("E", HX_ATTR_REAL), REQUIRED("G", HX_ATTR_REAL),
    REQUIRED("area", HX_ATTR_REAL), REQUIRED("ixx", HX_ATTR_REAL), REQUIRED("iyy", HX_ATTR_REAL),
    REQUIRED("izz", HX_ATTR_REAL), REAL("ASY"), REAL("ASZ"), REAL("cratio"), TEXT("cmatrix"),
    REAL("preload_x"), REAL("preload_y"), REAL("preload_z"), REAL("preload_tx"),
    REAL("preload_ty"), REAL("preload_tz"), END};

/* The attributes the load builders read, for the load made of the element. */
static const hx_attr_spec scalar_load[] = {INT("i_marker_id"), INT("j_marker_id"),
                                           TEXT("val_expression"), END};
static const hx_attr_spec vector_load[] = {TEXT("fx_expression"), TEXT("fy_expression"),
                                           TEXT("fz_expression"), TEXT("tx_expression"),
                                           TEXT("ty_expression"), TEXT("tz_expression"), END};

#define TEXT_MAX 1536 /* a beam's row: 13 terms of at most 100 characters */

/* A stiffness or damping below 0 feeds energy in: refused, as the pages do. */
static int refuse_negative(hx_draft *d, const hx_element_read *e, const char *const *names,
                           int n)
{
    for (int k = 0; k < n; ++k)
        if (hx_attr_number(e, names[k], 0.0) < 0.0) {
            hx_draft_fail(d, e->line, "%s %d: %s = %g: it must not be negative", e->name, e->id,
                          names[k], hx_attr_number(e, names[k], 0.0));
            return -1;
        }
    return 0;
}

/* The load read as e (its name, id, line), from the generated texts. */
static hx_element_read as_load(const hx_element_read *e, const hx_attr_spec *spec, int n,
                               char text[][TEXT_MAX])
{
    hx_element_read x = {.name = e->name, .line = e->line, .id = e->id, .spec = spec};
    while (spec[x.nspec].name != NULL)
        ++x.nspec;
    for (int k = 0; k < n; ++k) {
        x.value[x.nspec - n + k].present = 1;
        x.value[x.nspec - n + k].text = text[k];
    }
    return x;
}

/* The load just built (if it was) tagged as the element it stands for. */
static void tag_last(hx_draft *d, int before, enum hx_load_builtin builtin)
{
    if (d->m->nloads > before)
        d->m->loads[d->m->nloads - 1].builtin = builtin;
}

void hx_build_springdamper(hx_draft *d, const hx_element_read *e)
{
    const char *type = hx_attr_text(e, "type");
    const int rotational = strcasecmp(type, "ROTATIONAL") == 0;
    if (!rotational && strcasecmp(type, "TRANSLATIONAL") != 0) {
        hx_draft_fail(d, e->line, "%s %d: type \"%s\": expected TRANSLATIONAL or ROTATIONAL",
                      e->name, e->id, type);
        return;
    }
    static const char *const signs[2] = {"stiffness", "damping"};
    if (refuse_negative(d, e, signs, 2) != 0)
        return;
    const int i = hx_attr_int(e, "i_marker_id", 0), j = hx_attr_int(e, "j_marker_id", 0);
    const double k = hx_attr_number(e, "stiffness", 0.0), c = hx_attr_number(e, "damping", 0.0);
    const double free = hx_attr_number(e, "length", 0.0), pre = hx_attr_number(e, "preload", 0.0);
    char text[1][TEXT_MAX];
    if (rotational) /* AZ in (-pi, pi]: its full turns added by the dynamics (§7.17) */
        snprintf(text[0], TEXT_MAX, "-(%.17g)*WZ(%d,%d,%d)-(%.17g)*(AZ(%d,%d)-(%.17g))+(%.17g)",
                 c, i, j, j, k, i, j, free, pre);
    else
        snprintf(text[0], TEXT_MAX, "-(%.17g)*VR(%d,%d)-(%.17g)*(DM(%d,%d)-(%.17g))+(%.17g)", c,
                 i, j, k, i, j, free, pre);
    hx_element_read x = as_load(e, scalar_load, 1, text);
    x.value[0].present = x.value[1].present = 1;
    x.value[0].number = i, x.value[1].number = j;
    const int before = d->m->nloads;
    hx_build_scalar_load(d, &x, rotational, "val_expression");
    tag_last(d, before, HX_LOAD_SPRINGDAMPER);
    if (rotational && d->m->nloads > before) /* AZ's turns counted where it is evaluated */
        d->m->loads[d->m->nloads - 1].turn_stiffness = k;
}

void hx_build_bushing(hx_draft *d, const hx_element_read *e)
{
    static const char *const k_names[6] = {"kx", "ky", "kz", "ktx", "kty", "ktz"};
    static const char *const c_names[6] = {"cx", "cy", "cz", "ctx", "cty", "ctz"};
    static const char *const preloads[6] = {"preload_x", "preload_y", "preload_z",
                                            "preload_tx", "preload_ty", "preload_tz"};
    if (refuse_negative(d, e, k_names, 6) != 0 || refuse_negative(d, e, c_names, 6) != 0)
        return;
    const int i = hx_attr_int(e, "i_marker_id", 0), j = hx_attr_int(e, "j_marker_id", 0);
    char text[6][TEXT_MAX];
    for (int n = 0; n < 6; ++n) {
        const double k = hx_attr_number(e, k_names[n], 0.0), c = hx_attr_number(e, c_names[n], 0.0);
        const double pre = hx_attr_number(e, preloads[n], 0.0);
        const char axis = (char)('X' + n % 3);
        if (n < 3) /* I's displacement and velocity from J, seen by J, in J's axes */
            snprintf(text[n], TEXT_MAX, "-(%.17g)*D%c(%d,%d,%d)-(%.17g)*V%c(%d,%d,%d,%d)+(%.17g)",
                     k, axis, i, j, j, c, axis, i, j, j, j, pre);
        else /* the projected angles (§8.3) and I's angular velocity from J in J's axes */
            snprintf(text[n], TEXT_MAX, "-(%.17g)*A%c(%d,%d)-(%.17g)*W%c(%d,%d,%d)+(%.17g)", k,
                     axis, i, j, c, axis, i, j, j, pre);
    }
    hx_element_read x = as_load(e, vector_load, 6, text);
    const int before = d->m->nloads;
    hx_build_vector_load(d, &x, i, j, j);
    tag_last(d, before, HX_LOAD_BUSHING);
}

/* Timoshenko's stiffness of a straight beam along J's x axis (§7.17):
 * Py, Pz the shear's share of the bending in y and in z. */
static void beam_stiffness(const hx_element_read *e, double K[6][6])
{
    const double L = hx_attr_number(e, "length", 0.0), E = hx_attr_number(e, "E", 0.0);
    const double G = hx_attr_number(e, "G", 0.0), A = hx_attr_number(e, "area", 0.0);
    const double iyy = hx_attr_number(e, "iyy", 0.0), izz = hx_attr_number(e, "izz", 0.0);
    const double py = 12.0 * E * izz * hx_attr_number(e, "ASY", 0.0) / (G * A * L * L);
    const double pz = 12.0 * E * iyy * hx_attr_number(e, "ASZ", 0.0) / (G * A * L * L);
    memset(K, 0, 36 * sizeof K[0][0]);
    K[0][0] = E * A / L;
    K[1][1] = 12.0 * E * izz / (L * L * L * (1.0 + py));
    K[1][5] = K[5][1] = -6.0 * E * izz / (L * L * (1.0 + py));
    K[2][2] = 12.0 * E * iyy / (L * L * L * (1.0 + pz));
    K[2][4] = K[4][2] = 6.0 * E * iyy / (L * L * (1.0 + pz));
    K[3][3] = G * hx_attr_number(e, "ixx", 0.0) / L;
    K[4][4] = (4.0 + pz) * E * iyy / (L * (1.0 + pz));
    K[5][5] = (4.0 + py) * E * izz / (L * (1.0 + py));
}

/* The damping: cratio times K, or cmatrix's 21 numbers (Adams' CMATRIX: the
 * lower half by columns, c11 c21 .. c61 c22 .. c66); 0, or -1 (failed). */
static int beam_damping(hx_draft *d, const hx_element_read *e, double K[6][6], double C[6][6])
{
    const char *text = hx_attr_text(e, "cmatrix");
    const double ratio = hx_attr_number(e, "cratio", 0.0);
    if (text == NULL) {
        for (int r = 0; r < 6; ++r)
            for (int c = 0; c < 6; ++c)
                C[r][c] = ratio * K[r][c];
        return 0;
    }
    if (hx_attr_present(e, "cratio")) {
        hx_draft_fail(d, e->line, "%s %d: give cmatrix or cratio, not both", e->name, e->id);
        return -1;
    }
    double r[22];
    int n = 0;
    for (const char *s = text; *s != '\0';) {
        if (*s == ',' || isspace((unsigned char)*s)) {
            ++s;
            continue;
        }
        char *end;
        const double x = strtod(s, &end);
        if (end == s || !isfinite(x) || (*end != '\0' && *end != ',' &&
                                         !isspace((unsigned char)*end))) {
            hx_draft_fail(d, e->line, "%s %d: cmatrix: \"%.20s\" is not a number", e->name,
                          e->id, s);
            return -1;
        }
        if (n < 22)
            r[n] = x;
        ++n, s = end;
    }
    if (n != 21) {
        hx_draft_fail(d, e->line, "%s %d: cmatrix holds %d numbers: it takes 21 (the lower"
                      " half by columns)", e->name, e->id, n);
        return -1;
    }
    n = 0;
    for (int c = 0; c < 6; ++c)
        for (int row = c; row < 6; ++row, ++n)
            C[row][c] = C[c][row] = r[n];
    for (int k = 0; k < 6; ++k)
        if (C[k][k] < 0.0) { /* a negative damping feeds energy in, as a bushing's would */
            hx_draft_fail(d, e->line, "%s %d: cmatrix: c%d%d = %g: a damping on the diagonal"
                          " must not be negative", e->name, e->id, k + 1, k + 1, C[k][k]);
            return -1;
        }
    return 0;
}

/* A stiffness or damping the numbers overflow (a tiny length, a huge modulus)
 * is refused rather than written into the generated text. */
static int refuse_infinite(hx_draft *d, const hx_element_read *e, double K[6][6], double C[6][6])
{
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c)
            if (!isfinite(K[r][c]) || !isfinite(C[r][c])) {
                hx_draft_fail(d, e->line, "%s %d: its %s %c%d%d is not a finite number",
                              e->name, e->id, isfinite(K[r][c]) ? "damping" : "stiffness",
                              isfinite(K[r][c]) ? 'C' : 'K', r + 1, c + 1);
                return -1;
            }
    return 0;
}

/* Appends one term of a generated text; -1 when it does not fit. */
static int append(char *out, size_t *used, const char *format, ...)
    __attribute__((format(printf, 3, 4)));
static int append(char *out, size_t *used, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    const int n = vsnprintf(out + *used, TEXT_MAX - *used, format, args);
    va_end(args);
    if (n < 0 || (size_t)n >= TEXT_MAX - *used)
        return -1;
    *used += (size_t)n;
    return 0;
}

/* The six components -K (d - length) - C v + preload on I in J's axes (d
 * I's place from J in J's axes and its angles AX AY AZ, v its velocity and
 * angular velocity from J in J's axes), J's body taking the reaction: a
 * vector load tagged as the element it stands for (§7.17). */
static void build_six(hx_draft *d, const hx_element_read *e, double K[6][6], double C[6][6],
                      const double length[6], const double preload[6],
                      enum hx_load_builtin builtin)
{
    const int i = hx_attr_int(e, "i_marker_id", 0), j = hx_attr_int(e, "j_marker_id", 0);
    char text[6][TEXT_MAX];
    for (int r = 0; r < 6; ++r) {
        size_t used = 0;
        int bad = append(text[r], &used, "(%.17g)", preload[r]);
        for (int c = 0; c < 6 && bad == 0; ++c) {
            const char axis = (char)('X' + c % 3);
            char measure[48]; /* DX(I,J,J) in J's axes; AX(I,J) */
            if (c < 3)
                snprintf(measure, sizeof measure, "D%c(%d,%d,%d)", axis, i, j, j);
            else
                snprintf(measure, sizeof measure, "A%c(%d,%d)", axis, i, j);
            if (K[r][c] != 0.0 && length[c] != 0.0) /* from the free length or angle */
                bad = append(text[r], &used, "-(%.17g)*(%s-(%.17g))", K[r][c], measure,
                             length[c]);
            else if (K[r][c] != 0.0)
                bad = append(text[r], &used, "-(%.17g)*%s", K[r][c], measure);
            if (bad == 0 && C[r][c] != 0.0 && c < 3)
                bad = append(text[r], &used, "-(%.17g)*V%c(%d,%d,%d,%d)", C[r][c], axis, i, j,
                             j, j);
            else if (bad == 0 && C[r][c] != 0.0)
                bad = append(text[r], &used, "-(%.17g)*W%c(%d,%d,%d)", C[r][c], axis, i, j, j);
        }
        if (bad != 0) { /* not at TEXT_MAX */
            hx_draft_fail(d, e->line, "%s %d: its generated text is too long", e->name, e->id);
            return;
        }
    }
    hx_element_read x = as_load(e, vector_load, 6, text);
    const int before = d->m->nloads;
    hx_build_vector_load(d, &x, i, j, j);
    tag_last(d, before, builtin);
}

static const char *const preload_names[6] = {"preload_x",  "preload_y",  "preload_z",
                                             "preload_tx", "preload_ty", "preload_tz"};

void hx_build_beam(hx_draft *d, const hx_element_read *e)
{
    static const char *const positive[4] = {"length", "E", "G", "area"};
    static const char *const signs[6] = {"ixx", "iyy", "izz", "ASY", "ASZ", "cratio"};
    for (int k = 0; k < 4; ++k)
        if (!(hx_attr_number(e, positive[k], 0.0) > 0.0)) {
            hx_draft_fail(d, e->line, "%s %d: %s = %g: it must be positive", e->name, e->id,
                          positive[k], hx_attr_number(e, positive[k], 0.0));
            return;
        }
    double K[6][6], C[6][6];
    if (refuse_negative(d, e, signs, 6) != 0)
        return;
    beam_stiffness(e, K);
    if (beam_damping(d, e, K, C) != 0 || refuse_infinite(d, e, K, C) != 0)
        return;
    double length[6] = {hx_attr_number(e, "length", 0.0), 0, 0, 0, 0, 0}, preload[6];
    for (int k = 0; k < 6; ++k)
        preload[k] = hx_attr_number(e, preload_names[k], 0.0);
    build_six(d, e, K, C, length, preload, HX_LOAD_BEAM);
}

/* A linear field's attributes (MotionSolve's names): Krc, Crc row r, column c. */
#define MATRIX_ROW(m, r)                                                                       \
    REAL(m #r "1"), REAL(m #r "2"), REAL(m #r "3"), REAL(m #r "4"), REAL(m #r "5"),            \
        REAL(m #r "6")
#define MATRIX(m)                                                                              \
    MATRIX_ROW(m, 1), MATRIX_ROW(m, 2), MATRIX_ROW(m, 3), MATRIX_ROW(m, 4), MATRIX_ROW(m, 5),  \
        MATRIX_ROW(m, 6)
const hx_attr_spec hx_field_attrs[] = {
    ID, REQUIRED("i_marker_id", HX_ATTR_INT), REQUIRED("j_marker_id", HX_ATTR_INT),
    IGNORED("body1_id"), IGNORED("body2_id"), USER_CALL, REAL("length_x"), REAL("length_y"),
    REAL("length_z"), REAL("length_tx"), REAL("length_ty"), REAL("length_tz"),
    REAL("preload_x"), REAL("preload_y"), REAL("preload_z"), REAL("preload_tx"),
    REAL("preload_ty"), REAL("preload_tz"), MATRIX("K"), REAL("CRATIO"), MATRIX("C"), END};

/* The first linear attribute e has (its spec's name), or NULL. */
const char *hx_field_linear_attribute(const hx_element_read *e)
{
    for (int k = 0; k < e->nspec; ++k)
        if (e->value[k].present && (strncmp(e->spec[k].name, "length_", 7) == 0 ||
                                    strncmp(e->spec[k].name, "preload_", 8) == 0 ||
                                    strcmp(e->spec[k].name, "CRATIO") == 0 ||
                                    ((e->spec[k].name[0] == 'K' || e->spec[k].name[0] == 'C') &&
                                     strlen(e->spec[k].name) == 3)))
            return e->spec[k].name;
    return NULL;
}

void hx_build_field(hx_draft *d, const hx_element_read *e)
{
    static const char *const lengths[6] = {"length_x",  "length_y",  "length_z",
                                           "length_tx", "length_ty", "length_tz"};
    double K[6][6], C[6][6], length[6], preload[6];
    int damped = 0, stiff = 0;
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) {
            char name[4] = {'K', (char)('1' + r), (char)('1' + c), '\0'};
            K[r][c] = hx_attr_number(e, name, 0.0);
            stiff |= hx_attr_present(e, name);
            name[0] = 'C';
            C[r][c] = hx_attr_number(e, name, 0.0);
            damped |= hx_attr_present(e, name);
        }
    const double ratio = hx_attr_number(e, "CRATIO", 0.0);
    if (!stiff && hx_attr_present(e, "CRATIO")) { /* as Adams' CRATIO without KMATRIX */
        hx_draft_fail(d, e->line, "%s %d: CRATIO without a stiffness entry (K11 .. K66):"
                      " CRATIO scales the stiffness matrix", e->name, e->id);
        return;
    }
    if (damped && hx_attr_present(e, "CRATIO")) {
        hx_draft_fail(d, e->line, "%s %d: give CRATIO or the damping matrix (C11 .. C66), not"
                      " both", e->name, e->id);
        return;
    }
    static const char *const ratio_name[1] = {"CRATIO"};
    if (refuse_negative(d, e, ratio_name, 1) != 0)
        return;
    for (int r = 0; r < 6 && !damped; ++r)
        for (int c = 0; c < 6; ++c)
            C[r][c] = ratio * K[r][c];
    for (int k = 0; k < 6; ++k)
        if (K[k][k] < 0.0 || C[k][k] < 0.0) { /* feeds energy in, as a bushing's would */
            hx_draft_fail(d, e->line, "%s %d: %c%d%d = %g: a %s on the diagonal must not be"
                          " negative", e->name, e->id, K[k][k] < 0.0 ? 'K' : 'C', k + 1, k + 1,
                          K[k][k] < 0.0 ? K[k][k] : C[k][k],
                          K[k][k] < 0.0 ? "stiffness" : "damping");
            return;
        }
    if (refuse_infinite(d, e, K, C) != 0)
        return;
    for (int k = 0; k < 6; ++k) {
        length[k] = hx_attr_number(e, lengths[k], 0.0);
        preload[k] = hx_attr_number(e, preload_names[k], 0.0);
    }
    build_six(d, e, K, C, length, preload, HX_LOAD_FIELD);
}
