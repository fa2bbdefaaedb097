/* USER(...) lists (user_list.h). */
#include "model/user_list.h"

#include <ctype.h>
#include <errno.h>
#include <stdlib.h>
#include <strings.h>

int hx_parse_user_list(const char *text, double **par_out, int *npar_out, hx_message *msg)
{
    const char *p = text;
    while (isspace((unsigned char)*p))
        ++p;
    if (strncasecmp(p, "USER", 4) != 0)
        return hx_fail(msg, "'%s' does not start with USER(", text);
    p += 4;
    while (isspace((unsigned char)*p))
        ++p;
    if (*p != '(')
        return hx_fail(msg, "'%s': expected '(' after USER", text);
    ++p;
    int n = 0, capacity = 8;
    double *par = malloc(sizeof(double) * (size_t)capacity);
    if (par == NULL)
        return hx_fail(msg, "out of memory");
    while (isspace((unsigned char)*p))
        ++p;
    if (*p == ')') {
        ++p;
    } else {
        for (;;) {
            char *end;
            errno = 0;
            const double v = strtod(p, &end);
            if (end == p || errno == ERANGE) {
                free(par);
                return hx_fail(msg, "'%s': value %d is not a number", text, n + 1);
            }
            if (n == capacity) {
                capacity *= 2;
                double *grown = realloc(par, sizeof(double) * (size_t)capacity);
                if (grown == NULL) {
                    free(par);
                    return hx_fail(msg, "out of memory");
                }
                par = grown;
            }
            par[n++] = v;
            p = end;
            while (isspace((unsigned char)*p))
                ++p;
            if (*p == ',') {
                ++p;
                continue;
            }
            if (*p == ')') {
                ++p;
                break;
            }
            free(par);
            return hx_fail(msg, "'%s': expected ',' or ')' after value %d", text, n);
        }
    }
    while (isspace((unsigned char)*p))
        ++p;
    if (*p != '\0') {
        free(par);
        return hx_fail(msg, "'%s': unexpected text after ')'", text);
    }
    *par_out = par;
    *npar_out = n;
    return 0;
}
