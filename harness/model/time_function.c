/* Numbers and STEP/STEP5 of TIME (time_function.h); the steps are base/transition.h's. */
#include "model/time_function.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/transition.h"

double hx_step(double x, double x0, double h0, double x1, double h1)
{
    return hx_transition(HX_TRANSITION_STEP, x, x0, h0, x1, h1, 0);
}

double hx_step5(double x, double x0, double h0, double x1, double h1)
{
    return hx_transition(HX_TRANSITION_STEP5, x, x0, h0, x1, h1, 0);
}

double hx_time_function_at(const hx_time_function *f, double t)
{
    switch (f->kind) {
    case 1: return hx_step(t, f->a[0], f->a[1], f->a[2], f->a[3]);
    case 2: return hx_step5(t, f->a[0], f->a[1], f->a[2], f->a[3]);
    default: return f->a[0];
    }
}

static const char *skip_blanks(const char *p)
{
    while (isspace((unsigned char)*p))
        ++p;
    return p;
}

int hx_parse_time_function(const char *text, hx_time_function *f)
{
    memset(f, 0, sizeof *f);
    const char *p = skip_blanks(text);
    int kind = 0;
    if (strncasecmp(p, "STEP5", 5) == 0)
        kind = 2, p += 5;
    else if (strncasecmp(p, "STEP", 4) == 0)
        kind = 1, p += 4;
    if (kind == 0) {
        char *end;
        errno = 0;
        f->a[0] = strtod(p, &end);
        return end != p && *skip_blanks(end) == '\0' && errno != ERANGE && isfinite(f->a[0]) ? 0
                                                                                            : -1;
    }
    p = skip_blanks(p);
    if (*p++ != '(')
        return -1;
    p = skip_blanks(p);
    if (strncasecmp(p, "TIME", 4) != 0)
        return -1;
    p += 4;
    for (int k = 0; k < 4; ++k) {
        p = skip_blanks(p);
        if (*p++ != ',')
            return -1;
        char *end;
        f->a[k] = strtod(p, &end);
        if (end == p || !isfinite(f->a[k]))
            return -1;
        p = end;
    }
    p = skip_blanks(p);
    if (*p++ != ')' || *skip_blanks(p) != '\0' || !(f->a[2] >= f->a[0]))
        return -1;
    f->kind = kind;
    return 0;
}
