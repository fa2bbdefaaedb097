/* Reference_Variable expressions (variable_expression.h). */
#include "model/variable_expression.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The measures and how many marker ids each takes (I, J, K, L: the later
 * ones may be left out), as c_sysfnc takes them (docs/interface.md §5). */
static const struct {
    const char *name;
    int max_markers;
} measures[] = {{"DX", 3}, {"DY", 3}, {"DZ", 3}, {"DM", 2}, {"AX", 2}, {"AY", 2}, {"AZ", 2},
                {"VX", 4}, {"VY", 4}, {"VZ", 4}, {"WX", 3}, {"WY", 3}, {"WZ", 3}};

static const char *skip_blanks(const char *p)
{
    while (isspace((unsigned char)*p))
        ++p;
    return p;
}

static int refuse(hx_message *msg, const char *text, const char *why)
{
    return hx_fail(msg, "\"%s\" %s; the harness evaluates one measure, DX DY DZ (I[,J[,K]]),"
                   " DM AX AY AZ (I[,J]), VX VY VZ (I[,J[,K[,L]]]) or WX WY WZ (I[,J[,K]]),"
                   " optionally negated, or a number", text, why);
}

static int parse_number(const char *text, const char *p, hx_variable *v, hx_message *msg)
{
    char *end;
    errno = 0;
    const double value = strtod(p, &end);
    if (end == p || errno == ERANGE || !isfinite(value) || *skip_blanks(end) != '\0')
        return refuse(msg, text, "is not an expression the harness evaluates");
    v->function[0] = '\0';
    v->nmarkers = 0;
    v->number = v->sign * value;
    v->sign = 1.0;
    return 0;
}

int hx_parse_variable_expression(const char *text, hx_variable *v, hx_message *msg)
{
    const char *p = skip_blanks(text);
    v->sign = 1.0;
    if (*p == '-' || *p == '+') {
        v->sign = *p == '-' ? -1.0 : 1.0;
        p = skip_blanks(p + 1);
    }
    if (!isalpha((unsigned char)*p))
        return parse_number(text, p, v, msg);
    char name[8] = "";
    int n = 0;
    while (isalnum((unsigned char)p[n]) || p[n] == '_') {
        if (n < 7)
            name[n] = (char)toupper((unsigned char)p[n]);
        ++n;
    }
    name[n < 7 ? n : 7] = '\0';
    int max_markers = 0;
    for (size_t k = 0; k < sizeof measures / sizeof measures[0]; ++k)
        if (n == 2 && strcmp(name, measures[k].name) == 0)
            max_markers = measures[k].max_markers;
    if (max_markers == 0)
        return refuse(msg, text, "calls a function the harness does not evaluate");
    p = skip_blanks(p + n);
    if (*p != '(')
        return refuse(msg, text, "has no argument list");
    v->nmarkers = 0;
    memset(v->marker_ids, 0, sizeof v->marker_ids);
    for (;;) {
        p = skip_blanks(p + 1);
        char *end;
        errno = 0;
        const long id = strtol(p, &end, 10);
        if (end == p || errno == ERANGE || id < 0 || id > 2147483647L)
            return refuse(msg, text, "has an argument that is not a marker id");
        if (v->nmarkers == max_markers)
            return refuse(msg, text, "has more marker ids than the measure takes");
        v->marker_ids[v->nmarkers++] = (int)id;
        p = skip_blanks(end);
        if (*p == ')')
            break;
        if (*p != ',')
            return refuse(msg, text, "is not one measure call");
    }
    if (*skip_blanks(p + 1) != '\0')
        return refuse(msg, text, "is more than one measure call");
    if (v->marker_ids[0] == 0)
        return refuse(msg, text, "names no I marker (its first id is 0)");
    memcpy(v->function, name, 3);
    v->number = 0.0;
    return 0;
}
