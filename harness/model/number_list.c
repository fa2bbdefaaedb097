/* The numbers written between an element's tags (number_list.h). */
#include "model/number_list.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>

int hx_read_numbers(const char *text, double **out)
{
    int count = 0, capacity = 0;
    double *values = NULL;
    const char *p = text;
    for (;;) {
        while (isspace((unsigned char)*p) || *p == ',')
            ++p;
        if (*p == '\0')
            break;
        char *end;
        errno = 0;
        const double v = strtod(p, &end);
        if (end == p || errno == ERANGE || !isfinite(v) ||
            !(isspace((unsigned char)*end) || *end == ',' || *end == '\0')) {
            free(values);
            return -2 - count;
        }
        if (count == capacity) {
            capacity = capacity ? 2 * capacity : 16;
            double *grown = realloc(values, sizeof(double) * (size_t)capacity);
            if (grown == NULL) {
                free(values);
                return -1;
            }
            values = grown;
        }
        values[count++] = v;
        p = end;
    }
    *out = values;
    return count;
}
