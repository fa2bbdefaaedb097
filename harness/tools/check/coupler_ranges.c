/* Sampling ranges of a coupler's joints (coupler_ranges.h). */
#include "tools/check/coupler_ranges.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The x range of a two-column table file (blank, '#' and '$' lines skipped);
 * 0, or -1 when it cannot be read as one. */
static int table_range(const char *path, double *lo, double *hi)
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return -1;
    char line[1024];
    int rows = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        const char *p = line;
        while (*p == ' ' || *p == '\t')
            ++p;
        if (*p == '\0' || *p == '\n' || *p == '\r' || *p == '#' || *p == '$')
            continue;
        double x, y;
        if (sscanf(p, "%lf%*[ \t,]%lf", &x, &y) != 2)
            break;
        *lo = rows ? fmin(*lo, x) : x;
        *hi = rows ? fmax(*hi, x) : x;
        ++rows;
    }
    fclose(f);
    return rows >= 2 && *hi > *lo ? 0 : -1;
}

static int whole(double v, double lo, double hi)
{
    return v == floor(v) && v >= lo && v <= hi;
}

int hx_coupler_ranges(const hx_model *m, const double *par, int npar, int n, const double *q0,
                      double lo[3], double hi[3])
{
    double data_lo[3], data_hi[3];
    int has_data[3] = {0, 0, 0}, next = 0, layout = 1;
    for (int k = 0; k < n && layout; ++k) {
        if (next >= npar || !whole(par[next], 1, 5)) {
            layout = 0;
            break;
        }
        const int code = (int)par[next++];
        int count = 0; /* the numbers that follow the code */
        if (code == 1)
            count = 1;
        else if (code == 2)
            count = next < npar && whole(par[next], 0, 6) ? 2 + (int)par[next] : -1;
        else if (code == 3)
            count = next < npar && whole(par[next], 2, 1e6) ? 1 + 2 * (int)par[next] : -1;
        else
            count = code == 4 ? 2 : 3;
        if (count < 0 || next + count > npar) {
            layout = 0;
            break;
        }
        if (code == 3) {
            const int points = (int)par[next];
            data_lo[k] = par[next + 1];
            data_hi[k] = par[next + 2 * points - 1];
            has_data[k] = data_hi[k] > data_lo[k];
        } else if (code == 4) {
            const char *path = whole(par[next], 1, 2147483647.0) ? hx_model_string(m, (int)par[next])
                                                                 : NULL;
            has_data[k] = path != NULL && table_range(path, &data_lo[k], &data_hi[k]) == 0;
        }
        next += count;
    }
    layout = layout && next == npar;
    for (int i = 0; i < n; ++i) {
        if (layout && has_data[i]) {
            const double margin = 0.1 * (data_hi[i] - data_lo[i]);
            lo[i] = data_lo[i] - margin;
            hi[i] = data_hi[i] + margin;
        } else {
            lo[i] = q0[i] - 1.0;
            hi[i] = q0[i] + 1.0;
        }
    }
    return layout;
}
