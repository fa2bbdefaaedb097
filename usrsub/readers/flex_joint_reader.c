/*
 * Reads a .gfj flexible-joint file: HEADER (FILE_TYPE 'gfj'), UNITS,
 * STIFFNESS and DAMPING (each a (MATRIX) table { x y z ax ay az } of six rows
 * of six numbers; DAMPING may be left out), PRELOAD (a table
 * { fx fy fz tx ty tz } of one row; may be left out). Each block of a matrix
 * is converted to the model's units by its own dimension: K_ij is a force or
 * torque (row i) per length or angle (column j); D_ij the same per velocity.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "usrsub/readers/flex_joint_reader.h"

static const char *const matrix_columns[6] = {"X", "Y", "Z", "AX", "AY", "AZ"};
static const char *const preload_columns[6] = {"FX", "FY", "FZ", "TX", "TY", "TZ"};

/* The columns of a table must be these six, in this order. */
static int check_columns(const usrsub_teim_file *f, const char *block,
                         const usrsub_teim_table *t, const char *const names[6],
                         usrsub_message *msg)
{
    int same = t->ncolumns == 6;
    for (int c = 0; same && c < 6; ++c)
        same = strcmp(t->column[c], names[c]) == 0;
    if (!same)
        return usrsub_fail(msg, "'%s' line %d: [%s] table columns must be { %s %s %s %s %s %s }"
                           " in this order", f->path, t->line, block, names[0], names[1],
                           names[2], names[3], names[4], names[5]);
    return 0;
}

/* One table row of six finite numbers. */
static int read_row(const usrsub_teim_file *f, const char *block, const usrsub_teim_row *r,
                    int index, double out[6], usrsub_message *msg)
{
    if (r->ncells != 6)
        return usrsub_fail(msg, "'%s' line %d: [%s] row %d has %d entr%s, expected 6", f->path,
                           r->line, block, index + 1, r->ncells, r->ncells == 1 ? "y" : "ies");
    for (int c = 0; c < 6; ++c)
        if (usrsub_teim_number(r->cell[c], &out[c]) != 0)
            return usrsub_fail(msg, "'%s' line %d: [%s] row %d, column %d is '%s', not a finite"
                               " number", f->path, r->line, block, index + 1, c + 1, r->cell[c]);
    return 0;
}

/* A 6x6 (MATRIX) into m (column-major), each entry times its unit factor. */
static int read_matrix(const usrsub_teim_file *f, const char *block, const usrsub_unit_factors *u,
                       double time_power, double m[36], int required, usrsub_message *msg)
{
    memset(m, 0, 36 * sizeof(double));
    const usrsub_teim_block *b = usrsub_teim_find_block(f, block);
    if (b == NULL) {
        if (required)
            return usrsub_fail(msg, "'%s': no [%s] block (a (MATRIX) table of 6 rows of 6)",
                               f->path, block);
        return 0;
    }
    const usrsub_teim_table *t = usrsub_teim_find_table(b, "MATRIX");
    if (t == NULL)
        return usrsub_fail(msg, "'%s' line %d: [%s] has no (MATRIX) table { x y z ax ay az } of"
                           " 6 rows of 6", f->path, b->line, block);
    if (check_columns(f, block, t, matrix_columns, msg) != 0)
        return -1;
    if (t->nrows != 6)
        return usrsub_fail(msg, "'%s' line %d: the [%s] matrix has %d row%s, expected 6",
                           f->path, t->nrows > 6 ? t->row[6].line : t->line, block, t->nrows,
                           t->nrows == 1 ? "" : "s");
    for (int i = 0; i < 6; ++i) {
        double row[6];
        if (read_row(f, block, &t->row[i], i, row, msg) != 0)
            return -1;
        for (int j = 0; j < 6; ++j) {
            m[i + 6 * j] = row[j] * usrsub_property_units_force_factor(u, i) *
                           pow(u->time, time_power) /
                           usrsub_property_units_displacement_factor(u, j);
            /* the entries hand -K and -D out as the partials, unchecked: finite here */
            if (!isfinite(m[i + 6 * j]))
                return usrsub_fail(msg, "'%s' line %d: [%s] row %d, column %d (%g) is out of range"
                                   " in the model's units", f->path, t->row[i].line, block, i + 1,
                                   j + 1, row[j]);
        }
    }
    return 0;
}

static int read_preload(const usrsub_teim_file *f, const usrsub_unit_factors *u, double p[6],
                        usrsub_message *msg)
{
    memset(p, 0, 6 * sizeof(double));
    const usrsub_teim_block *b = usrsub_teim_find_block(f, "PRELOAD");
    if (b == NULL)
        return 0;
    const usrsub_teim_table *t = usrsub_teim_find_table(b, NULL);
    if (t == NULL || t->nrows != 1)
        return usrsub_fail(msg, "'%s' line %d: [PRELOAD] must hold a table { fx fy fz tx ty tz }"
                           " of one row", f->path, t != NULL ? t->line : b->line);
    if (check_columns(f, "PRELOAD", t, preload_columns, msg) != 0 ||
        read_row(f, "PRELOAD", &t->row[0], 0, p, msg) != 0)
        return -1;
    for (int i = 0; i < 6; ++i)
        p[i] *= usrsub_property_units_force_factor(u, i);
    return 0;
}

/* The one-time warnings: asymmetric or indefinite stiffness, indefinite damping. */
static void check_matrices(const char *path, const usrsub_flex_joint *j,
                           usrsub_read_report *report)
{
    char text[384];
    double worst = 0.0, largest = 0.0;
    int wi = 0, wj = 0;
    for (int i = 0; i < 6; ++i)
        for (int c = 0; c < 6; ++c) {
            const double a = j->k[i + 6 * c], b = j->k[c + 6 * i];
            /* compare with the diagonal scales, so that mixed units do not matter */
            const double scale = sqrt(fabs(j->k[i + 6 * i] * j->k[c + 6 * c]));
            largest = fmax(largest, fabs(a));
            const double asym = fabs(a - b) / (scale > 0.0 ? scale : 1.0);
            if (asym > worst)
                worst = asym, wi = i, wj = c;
        }
    if (worst > 1e-9 && largest > 0.0) {
        snprintf(text, sizeof text, "'%s': the stiffness matrix is not symmetric (K[%d][%d] ="
                 " %g, K[%d][%d] = %g): the joint is not conservative", path, wi + 1, wj + 1,
                 j->k[wi + 6 * wj], wj + 1, wi + 1, j->k[wj + 6 * wi]);
        usrsub_property_file_notice(report, "%s", text);
    }
    if (usrsub_scaled_smallest_eigenvalue(j->k, 6) < -1e-9) {
        snprintf(text, sizeof text, "'%s': the stiffness matrix is not positive semi-definite"
                 " (some deformation gives energy back): the joint can drive motion", path);
        usrsub_property_file_notice(report, "%s", text);
    }
    if (usrsub_scaled_smallest_eigenvalue(j->d, 6) < -1e-9) {
        snprintf(text, sizeof text, "'%s': the damping matrix is not positive semi-definite"
                 " (some motion is pushed, not damped): the joint can add energy", path);
        usrsub_property_file_notice(report, "%s", text);
    }
}

static int read_joint(const usrsub_teim_file *f, const usrsub_unit_factors *u, void *ctx,
                      usrsub_read_report *report, usrsub_message *msg)
{
    usrsub_flex_joint *j = ctx;
    static const char *const known[] = {"HEADER", "UNITS", "GLOBAL", "STIFFNESS", "DAMPING",
                                        "PRELOAD"};
    for (int b = 0; b < f->nblocks; ++b) {
        int found = 0;
        for (size_t k = 0; k < sizeof known / sizeof known[0]; ++k)
            found |= strcmp(f->block[b].name, known[k]) == 0;
        if (!found) /* a misspelled block would otherwise be lost */
            return usrsub_fail(msg, "'%s' line %d: [%s] is not a flexible-joint block (expected"
                               " HEADER, UNITS, GLOBAL, STIFFNESS, DAMPING or PRELOAD)", f->path,
                               f->block[b].line, f->block[b].name);
    }
    if (usrsub_property_file_rotation_measure(f, &j->rotation_measure, msg) != 0 ||
        read_matrix(f, "STIFFNESS", u, 0.0, j->k, 1, msg) != 0 ||
        read_matrix(f, "DAMPING", u, 1.0, j->d, 0, msg) != 0 || read_preload(f, u, j->preload, msg) != 0)
        return -1;
    usrsub_flex_joint_prepare(j);
    check_matrices(f->path, j, report);
    return 0;
}

int usrsub_flex_joint_read(const char *path, const double *model_scales,
                           usrsub_flex_joint **out, usrsub_read_report *report,
                           usrsub_message *msg)
{
    usrsub_flex_joint *j = calloc(1, sizeof *j);
    if (j == NULL)
        return usrsub_fail(msg, "out of memory");
    if (usrsub_property_file_read(path, "gfj", "a flexible-joint file", model_scales, read_joint,
                                  j, report, msg) != 0) {
        usrsub_flex_joint_free(j);
        return -1;
    }
    *out = j;
    return 0;
}
