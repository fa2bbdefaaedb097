/* Model look-ups, USER list parsing and release (model.h). */
#include "model.h"

#include "usrsub/step.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

int hx_model_marker(const hx_model *m, int id)
{
    if (m->marker_slot_count == 0)
        return -1;
    const unsigned mask = (unsigned)m->marker_slot_count - 1u; /* a power of two */
    for (unsigned s = ((unsigned)id * 2654435761u) & mask;; s = (s + 1) & mask) {
        const int k = m->marker_slots[s];
        if (k < 0)
            return -1;
        if (m->markers[k].id == id)
            return k;
    }
}

int hx_model_body(const hx_model *m, int id)
{
    for (int k = 0; k < m->nbodies; ++k)
        if (m->bodies[k].id == id)
            return k;
    return -1;
}

int hx_model_joint(const hx_model *m, int id)
{
    for (int k = 0; k < m->njoints; ++k)
        if (m->joints[k].id == id)
            return k;
    return -1;
}

const char *hx_model_string(const hx_model *m, int id)
{
    for (int k = 0; k < m->nstrings; ++k)
        if (m->strings[k].id == id)
            return m->strings[k].text;
    return NULL;
}

int hx_model_find_force(const hx_model *m, const char *text, int *index, usrsub_message *msg)
{
    int want = -1; /* -1 any, else the interface */
    const char *number = text;
    if (strncasecmp(text, "vector:", 7) == 0)
        want = HX_FORCE_GFOSUB, number = text + 7;
    else if (strncasecmp(text, "field:", 6) == 0)
        want = HX_FORCE_FIESUB, number = text + 6;
    const int id = atoi(number);
    int found = 0;
    for (int k = 0; k < m->nforces; ++k)
        if (m->forces[k].id == id && (want < 0 || (int)m->forces[k].interface == want)) {
            *index = k;
            ++found;
        }
    if (found == 1)
        return 0;
    return usrsub_fail(msg, found ? "element %d is both a Force_Vector_TwoBody and a Force_Field:"
                                    " write vector:%d or field:%d"
                                  : "no Force_Vector_TwoBody or Force_Field %d%.0d%.0d",
                       id, id, id);
}

int hx_model_string_copy(void *model, int id, char *text, int capacity)
{
    const char *s = hx_model_string(model, id);
    if (s == NULL)
        return -1;
    snprintf(text, (size_t)capacity, "%s", s);
    return 0;
}

int hx_parse_user_list(const char *text, double **par_out, int *npar_out, usrsub_message *msg)
{
    const char *p = text;
    while (isspace((unsigned char)*p))
        ++p;
    if (strncasecmp(p, "USER", 4) != 0)
        return usrsub_fail(msg, "'%s' does not start with USER(", text);
    p += 4;
    while (isspace((unsigned char)*p))
        ++p;
    if (*p != '(')
        return usrsub_fail(msg, "'%s': expected '(' after USER", text);
    ++p;
    int n = 0, capacity = 8;
    double *par = malloc(sizeof(double) * (size_t)capacity);
    if (par == NULL)
        return usrsub_fail(msg, "out of memory");
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
                return usrsub_fail(msg, "'%s': value %d is not a number", text, n + 1);
            }
            if (n == capacity) {
                capacity *= 2;
                double *grown = realloc(par, sizeof(double) * (size_t)capacity);
                if (grown == NULL) {
                    free(par);
                    return usrsub_fail(msg, "out of memory");
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
            return usrsub_fail(msg, "'%s': expected ',' or ')' after value %d", text, n);
        }
    }
    while (isspace((unsigned char)*p))
        ++p;
    if (*p != '\0') {
        free(par);
        return usrsub_fail(msg, "'%s': unexpected text after ')'", text);
    }
    *par_out = par;
    *npar_out = n;
    return 0;
}

static void free_user_call(hx_user_call *u)
{
    free(u->dll_name);
    free(u->fnc_name);
    free(u->der1_name);
    free(u->der2_name);
    free(u->param_string);
    free(u->par);
}

void hx_model_free(hx_model *m)
{
    if (m == NULL)
        return;
    for (int k = 0; k < m->nbodies; ++k)
        free(m->bodies[k].label);
    for (int k = 0; k < m->ncouplers; ++k)
        free_user_call(&m->couplers[k].user);
    for (int k = 0; k < m->nforces; ++k)
        free_user_call(&m->forces[k].user);
    for (int k = 0; k < m->nstrings; ++k)
        free(m->strings[k].text);
    free(m->bodies);
    free(m->markers);
    free(m->joints);
    free(m->couplers);
    free(m->forces);
    free(m->loads);
    free(m->strings);
    free(m->marker_slots);
    free(m->path);
    free(m->dir);
    free(m);
}

double hx_time_function_at(const hx_time_function *f, double t)
{
    switch (f->kind) {
    case 1: return usrsub_step(t, f->a[0], f->a[1], f->a[2], f->a[3]).value;
    case 2: return usrsub_step5(t, f->a[0], f->a[1], f->a[2], f->a[3]).value;
    default: return f->a[0];
    }
}

int hx_parse_time_function(const char *text, hx_time_function *f)
{
    memset(f, 0, sizeof *f);
    const char *p = text;
    while (isspace((unsigned char)*p))
        ++p;
    int kind = 0;
    if (strncasecmp(p, "STEP5", 5) == 0)
        kind = 2, p += 5;
    else if (strncasecmp(p, "STEP", 4) == 0)
        kind = 1, p += 4;
    if (kind == 0) {
        char *end;
        errno = 0;
        f->a[0] = strtod(p, &end);
        while (isspace((unsigned char)*end))
            ++end;
        return end != p && *end == '\0' && errno != ERANGE && isfinite(f->a[0]) ? 0 : -1;
    }
    while (isspace((unsigned char)*p))
        ++p;
    if (*p++ != '(')
        return -1;
    while (isspace((unsigned char)*p))
        ++p;
    if (strncasecmp(p, "TIME", 4) != 0)
        return -1;
    p += 4;
    for (int k = 0; k < 4; ++k) {
        while (isspace((unsigned char)*p))
            ++p;
        if (*p++ != ',')
            return -1;
        char *end;
        f->a[k] = strtod(p, &end);
        if (end == p || !isfinite(f->a[k]))
            return -1;
        p = end;
    }
    while (isspace((unsigned char)*p))
        ++p;
    if (*p++ != ')')
        return -1;
    while (isspace((unsigned char)*p))
        ++p;
    if (*p != '\0' || !(f->a[2] >= f->a[0]))
        return -1;
    f->kind = kind;
    return 0;
}
