/* Prescribed rig histories (rig_path.h). */
#include "tools/rig/rig_path.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

int hx_direction_index(const char *name)
{
    static const char *const a[6] = {"x", "y", "z", "ax", "ay", "az"};
    static const char *const b[6] = {"fx", "fy", "fz", "tx", "ty", "tz"};
    for (int k = 0; k < 6; ++k)
        if (strcasecmp(name, a[k]) == 0 || strcasecmp(name, b[k]) == 0)
            return k;
    return -1;
}

/* Splits "a,b,c" into up to max fields. */
static int fields(const char *text, char out[][32], int max)
{
    int n = 0;
    const char *s = text;
    while (n < max) {
        const char *comma = strchr(s, ',');
        const size_t len = comma ? (size_t)(comma - s) : strlen(s);
        snprintf(out[n], 32, "%.*s", (int)(len < 31 ? len : 31), s);
        ++n;
        if (comma == NULL)
            break;
        s = comma + 1;
    }
    return n;
}

static int number(const char *text, double *v)
{
    char *end;
    *v = strtod(text, &end);
    return end != text && *end == '\0' && isfinite(*v) ? 0 : -1;
}

int hx_rig_path_add(hx_rig_path *p, const char *kind, const char *text, hx_message *msg)
{
    if (p->nterms == HX_RIG_MAX_TERMS)
        return hx_fail(msg, "at most %d path terms", HX_RIG_MAX_TERMS);
    hx_rig_term *t = &p->term[p->nterms];
    memset(t, 0, sizeof *t);
    char f[5][32];
    const int n = fields(text, f, 5);
    if (strcmp(kind, "circle") == 0) {
        t->kind = HX_RIG_CIRCLE;
        t->a = 0, t->b = 1;
        if (n == 3) {
            static const struct { const char *name; int a, b; } planes[] = {
                {"xy", 0, 1}, {"yz", 1, 2}, {"zx", 2, 0}, {"axay", 3, 4}, {"ayaz", 4, 5}, {"azax", 5, 3}};
            int found = 0;
            for (size_t k = 0; k < sizeof planes / sizeof planes[0]; ++k)
                if (strcasecmp(f[2], planes[k].name) == 0)
                    t->a = planes[k].a, t->b = planes[k].b, found = 1;
            if (!found)
                return hx_fail(msg, "circle plane '%s': expected xy, yz, zx, axay, ayaz or azax", f[2]);
        }
        if ((n != 2 && n != 3) || number(f[0], &t->p1) || number(f[1], &t->p2))
            return hx_fail(msg, "circle '%s': expected R,W[,PLANE]", text);
    } else if (strcmp(kind, "line") == 0) {
        t->kind = HX_RIG_LINE;
        if (n != 3 || (t->a = hx_direction_index(f[0])) < 0 || number(f[1], &t->p1) ||
            number(f[2], &t->p2))
            return hx_fail(msg, "line '%s': expected K,FROM,TO with K one of x y z ax ay az", text);
    } else if (strcmp(kind, "sine") == 0) {
        t->kind = HX_RIG_SINE;
        if ((n != 3 && n != 4) || (t->a = hx_direction_index(f[0])) < 0 || number(f[1], &t->p1) ||
            number(f[2], &t->p2) || (n == 4 && number(f[3], &t->p3)))
            return hx_fail(msg, "sine '%s': expected K,AMP,FREQ[,PHASE]", text);
    } else {
        return hx_fail(msg, "unknown path kind '%s'", kind);
    }
    p->directions |= 1u << t->a;
    if (t->kind == HX_RIG_CIRCLE)
        p->directions |= 1u << t->b;
    p->nterms++;
    return 0;
}

int hx_rig_path_history(hx_rig_path *p, const char *csv, hx_message *msg)
{
    FILE *f = fopen(csv, "r");
    if (f == NULL)
        return hx_fail(msg, "cannot open history '%s'", csv);
    char line[1024];
    int capacity = 0, line_no = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        ++line_no;
        double v[7];
        char *s = line;
        int count = 0;
        for (; count < 7; ++count) {
            char *end;
            v[count] = strtod(s, &end);
            if (end == s)
                break;
            s = end;
            while (*s == ',' || *s == ' ' || *s == '\t')
                ++s;
        }
        if (count == 0 && (line_no == 1 || line[0] == '#' || line[0] == '\n'))
            continue; /* a header or a blank line */
        if (count != 7 || (p->nrows > 0 && !(v[0] > p->rows[7 * (p->nrows - 1)]))) {
            fclose(f);
            return hx_fail(msg, "history '%s' line %d: expected t,x,y,z,ax,ay,az with t"
                               " increasing", csv, line_no);
        }
        if (p->nrows == capacity) {
            capacity = capacity ? 2 * capacity : 256;
            double *grown = realloc(p->rows, sizeof(double) * 7u * (size_t)capacity);
            if (grown == NULL) {
                fclose(f);
                return hx_fail(msg, "out of memory");
            }
            p->rows = grown;
        }
        memcpy(p->rows + 7 * p->nrows++, v, sizeof v);
    }
    fclose(f);
    if (p->nrows < 2)
        return hx_fail(msg, "history '%s' has fewer than 2 rows", csv);
    p->directions = 0x3f;
    return 0;
}

void hx_rig_path_free(hx_rig_path *p)
{
    free(p->rows);
    memset(p, 0, sizeof *p);
}

void hx_rig_path_at(const hx_rig_path *p, double t, double t_end, double value[6], double rate[6])
{
    for (int k = 0; k < 6; ++k)
        value[k] = rate[k] = 0.0;
    if (p->nrows > 0) {
        int i = 0;
        while (i < p->nrows - 2 && p->rows[7 * (i + 1)] <= t)
            ++i;
        const double *a = p->rows + 7 * i, *b = a + 7;
        const double span = b[0] - a[0];
        double s = (t - a[0]) / span;
        s = s < 0.0 ? 0.0 : s > 1.0 ? 1.0 : s;
        for (int k = 0; k < 6; ++k) {
            value[k] += a[1 + k] + s * (b[1 + k] - a[1 + k]);
            rate[k] += (b[1 + k] - a[1 + k]) / span;
        }
    }
    for (int n = 0; n < p->nterms; ++n) {
        const hx_rig_term *term = &p->term[n];
        switch (term->kind) {
        case HX_RIG_CIRCLE: {
            const double c = cos(term->p2 * t), s = sin(term->p2 * t);
            value[term->a] += term->p1 * c;
            value[term->b] += term->p1 * s;
            rate[term->a] -= term->p1 * term->p2 * s;
            rate[term->b] += term->p1 * term->p2 * c;
            break;
        }
        case HX_RIG_LINE: {
            const double s = t_end > 0.0 ? t / t_end : 1.0;
            value[term->a] += term->p1 + s * (term->p2 - term->p1);
            rate[term->a] += t_end > 0.0 ? (term->p2 - term->p1) / t_end : 0.0;
            break;
        }
        case HX_RIG_SINE: {
            const double w = 2.0 * M_PI * term->p2;
            value[term->a] += term->p1 * sin(w * t + term->p3);
            rate[term->a] += term->p1 * w * cos(w * t + term->p3);
            break;
        }
        }
    }
}
