/* Two-column "x y" table files (table_file.h). */
#include "usrsub/readers/table_file.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TABLE_LINE_MAX 1024

static int is_separator(char c)
{
    return c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '\n';
}

/* Parses exactly two finite numbers; returns 0 on success. */
static int parse_row(char *line, double *x, double *y)
{
    double v[2];
    char *p = line;
    for (int k = 0; k < 2; ++k) {
        while (is_separator(*p))
            ++p;
        char *end;
        errno = 0;
        v[k] = strtod(p, &end);
        if (end == p || errno == ERANGE || !isfinite(v[k]))
            return -1;
        if (*end != '\0' && !is_separator(*end))
            return -1;
        p = end;
    }
    while (is_separator(*p))
        ++p;
    if (*p != '\0')
        return -1;
    *x = v[0];
    *y = v[1];
    return 0;
}

int usrsub_table_file_read(const char *path, double **x_out, double **y_out, int *n_out,
                           usrsub_message *msg)
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return usrsub_fail(msg, "cannot open table file '%s': %s", path, strerror(errno));
    int n = 0, capacity = 0, line_no = 0;
    double *x = NULL, *y = NULL;
    char line[TABLE_LINE_MAX];
    int status = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        ++line_no;
        const size_t len = strlen(line);
        if (len == sizeof line - 1 && line[len - 1] != '\n' && !feof(f)) {
            status = usrsub_fail(msg, "table file '%s' line %d: longer than %d characters",
                                 path, line_no, TABLE_LINE_MAX - 2);
            break;
        }
        const char *first = line;
        while (*first == ' ' || *first == '\t')
            ++first;
        if (*first == '\0' || *first == '\n' || *first == '\r' || *first == '#' ||
            *first == '$')
            continue;
        double xv, yv;
        if (parse_row(line, &xv, &yv) != 0) {
            line[strcspn(line, "\r\n")] = '\0';
            status = usrsub_fail(msg, "table file '%s' line %d: expected two finite numbers"
                                 " 'x y', got '%.60s'", path, line_no, first);
            break;
        }
        if (n == capacity) {
            capacity = capacity ? 2 * capacity : 64;
            double *nx = realloc(x, sizeof(double) * (size_t)capacity);
            if (nx != NULL)
                x = nx;
            double *ny = realloc(y, sizeof(double) * (size_t)capacity);
            if (ny != NULL)
                y = ny;
            if (nx == NULL || ny == NULL) {
                status = usrsub_fail(msg, "table file '%s': out of memory at line %d", path,
                                     line_no);
                break;
            }
        }
        x[n] = xv;
        y[n] = yv;
        ++n;
    }
    if (status == 0 && ferror(f))
        status = usrsub_fail(msg, "table file '%s': read error after line %d", path, line_no);
    fclose(f);
    if (status == 0 && n == 0)
        status = usrsub_fail(msg, "table file '%s' has no 'x y' rows", path);
    if (status != 0) {
        free(x);
        free(y);
        return -1;
    }
    *x_out = x;
    *y_out = y;
    *n_out = n;
    return 0;
}
