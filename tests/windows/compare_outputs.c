/*
 * compare_outputs EXPECTED ACTUAL [RTOL ATOL]
 *
 * Compares two outputs of entry_host line by line and token by token: up to
 * "=" (the call, its queries and messages) the words must be equal; after it
 * the values a and b must satisfy |a - b| <= max(RTOL max(|a|, |b|), ATOL):
 * relative, with an absolute floor for values near zero; by default
 * RTOL = 1e-12 and ATOL = 1e-15 (docs/windows.md). A NaN never matches.
 * Prints the largest relative difference seen and the first differences;
 * exits 1 on any.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tokens.h"

enum { LINE_MAX_CHARS = 1 << 20, SHOWN = 10 };


static int number(const char *t, double *v)
{
    char *end;
    *v = strtod(t, &end);
    return end != t && *end == '\0';
}

int main(int argc, char **argv)
{
    if (argc != 3 && argc != 5) {
        fputs("usage: compare_outputs EXPECTED ACTUAL [RTOL ATOL]\n", stderr);
        return 2;
    }
    const double rtol = argc == 5 ? atof(argv[3]) : 1e-12;
    const double atol = argc == 5 ? atof(argv[4]) : 1e-15;
    FILE *fa = fopen(argv[1], "r"), *fb = fopen(argv[2], "r");
    if (fa == NULL || fb == NULL) {
        fprintf(stderr, "compare_outputs: cannot read %s\n", fa == NULL ? argv[1] : argv[2]);
        return 2;
    }
    static char la[LINE_MAX_CHARS], lb[LINE_MAX_CHARS];
    long line = 0, values = 0, differences = 0, equal = 0;
    double worst = 0.0;
    char worst_at[128] = "";
    for (;;) {
        char *ra = fgets(la, sizeof la, fa), *rb = fgets(lb, sizeof lb, fb);
        ++line;
        if (ra == NULL || rb == NULL) {
            if (ra != rb) {
                printf("compare_outputs: line %ld: %s ends first\n", line, ra == NULL ? argv[1] : argv[2]);
                ++differences;
            }
            break;
        }
        la[strcspn(la, "\r\n")] = '\0';
        lb[strcspn(lb, "\r\n")] = '\0';
        char *sa = la, *sb = lb;
        int after_values = 0; /* words up to "=", then numbers */
        for (int k = 1;; ++k) {
            char *ta = token(&sa), *tb = token(&sb);
            if (ta == NULL || tb == NULL) {
                if (ta != tb && differences++ < SHOWN)
                    printf("compare_outputs: line %ld: one has more tokens from token %d on\n", line, k);
                break;
            }
            if (!after_values && strcmp(ta, "=") == 0 && strcmp(tb, "=") == 0)
                after_values = 1;
            double a, b;
            if (!after_values || !number(ta, &a) || !number(tb, &b)) {
                if (strcmp(ta, tb) != 0 && differences++ < SHOWN)
                    printf("compare_outputs: line %ld token %d: '%s' against '%s'\n", line, k, ta, tb);
                continue;
            }
            ++values;
            if (a == b) {
                ++equal;
                continue;
            }
            /* relative to the larger size, or to the size below which ATOL rules */
            const double scale = fmax(fmax(fabs(a), fabs(b)), atol / rtol);
            const double relative = isnan(a) || isnan(b) ? INFINITY : fabs(a - b) / scale;
            if (!(relative <= worst)) {
                worst = relative;
                /* numbers as printed: 17 digits and an exponent fit in 32 */
                snprintf(worst_at, sizeof worst_at, "line %ld token %d: %.32s against %.32s", line, k,
                         ta, tb);
            }
            if (!(relative <= rtol) && differences++ < SHOWN)
                printf("compare_outputs: line %ld token %d: %s against %s (relative %.3g)\n", line, k,
                       ta, tb, relative);
        }
    }
    printf("compare_outputs: %ld values on %ld lines, %ld bit-identical; largest relative"
           " difference %.3g%s%s (tolerance %g relative, %g absolute)\n", values, line - 1, equal,
           worst, worst > 0 ? " at " : "", worst_at, rtol, atol);
    if (differences > 0) {
        printf("compare_outputs: %ld differences beyond the tolerance\n", differences);
        return 1;
    }
    return 0;
}
