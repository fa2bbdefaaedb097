/*
 * A parsed statement checked against its keyword table (keywords.h): the
 * keywords by their unique prefixes, each value's kind and count, the
 * required keywords. Messages say what and why; the caller puts the file,
 * the line and the statement before them.
 */
#include "model/adm/keywords.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define DEGREE 0.017453292519943295 /* pi / 180 */

int hx_adm_keyword_count(const hx_adm_spec *spec)
{
    int n = 0;
    if (spec->keywords != NULL)
        while (spec->keywords[n].name != NULL)
            ++n;
    return n;
}

int hx_adm_keyword_index(const hx_adm_spec *spec, const char *name)
{
    for (int k = 0; spec->keywords != NULL && spec->keywords[k].name != NULL; ++k)
        if (spec->keywords[k].name[0] == name[0] && strcmp(spec->keywords[k].name, name) == 0)
            return k;
    return -1;
}

/* "A, B and C" of the names matched, into out. */
static void list_names(char *out, size_t size, const char *const *names, int n)
{
    size_t used = 0;
    out[0] = '\0';
    for (int k = 0; k < n && used < size; ++k)
        used += (size_t)snprintf(out + used, size - used, "%s%s", k == 0 ? "" : k == n - 1 ? " and " : ", ",
                                 names[k]);
}

/* The entry of names (stride bytes apart, n of them) that text names: an
 * exact match, the one it is a prefix of, or the one whose documented
 * abbreviation it reaches; -1 unknown, -2 ambiguous (candidates listed in
 * msg's text by the caller). */
static int match(const char *text, const char *const *names, const unsigned char *abbrev, int n,
                 const char **candidates, int *ncandidates)
{
    const size_t len = strlen(text);
    int found = -1, count = 0, by_abbrev = -1, nby_abbrev = 0;
    const int first = toupper((unsigned char)text[0]);
    for (int k = 0; k < n; ++k) {
        if (toupper((unsigned char)names[k][0]) != first)
            continue;
        if (strcasecmp(names[k], text) == 0)
            return k;
        if (len > 0 && strncasecmp(names[k], text, len) == 0) {
            if (count < 16)
                candidates[count] = names[k];
            ++count;
            found = k;
            if (abbrev != NULL && abbrev[k] != 0 && len >= abbrev[k])
                by_abbrev = k, ++nby_abbrev;
        }
    }
    *ncandidates = count < 16 ? count : 16;
    if (count == 1)
        return found;
    if (nby_abbrev == 1)
        return by_abbrev;
    return count == 0 ? -1 : -2;
}

const hx_adm_spec *hx_adm_find_spec(const hx_adm_spec *table, int count, const char *name,
                                    hx_message *msg)
{
    const char *names[256];
    const int n = count < 256 ? count : 256;
    for (int k = 0; k < n; ++k)
        names[k] = table[k].name;
    const char *candidates[16];
    int nc = 0;
    const int k = match(name, names, NULL, n, candidates, &nc);
    if (k >= 0)
        return &table[k];
    if (k == -2) {
        char list[512];
        list_names(list, sizeof list, candidates, nc);
        hx_fail(msg, "%s is ambiguous: it abbreviates %s", name, list);
    } else {
        hx_fail(msg, "%s is not a statement the harness knows", name);
    }
    return NULL;
}

/* A number as Adams writes one: [sign] digits [. digits] [E [sign] digits],
 * with a trailing D (degrees) when angle is set. 0, or -1 (not a number),
 * -2 (a D where no angle is read). */
static int parse_number(const char *text, int angle, double *out)
{
    const char *p = text;
    if (*p == '+' || *p == '-')
        ++p;
    int digits = 0;
    while (isdigit((unsigned char)*p))
        ++p, ++digits;
    if (*p == '.') {
        ++p;
        while (isdigit((unsigned char)*p))
            ++p, ++digits;
    }
    if (digits == 0)
        return -1;
    if (*p == 'e' || *p == 'E') {
        ++p;
        if (*p == '+' || *p == '-')
            ++p;
        if (!isdigit((unsigned char)*p))
            return -1;
        while (isdigit((unsigned char)*p))
            ++p;
    }
    const char *end = p;
    int degrees = 0;
    if (*p == 'd' || *p == 'D') {
        degrees = 1;
        ++p;
    }
    while (*p == ' ' || *p == '\t')
        ++p;
    if (*p != '\0')
        return -1;
    if (degrees && !angle)
        return -2;
    char copy[128];
    const size_t n = (size_t)(end - text);
    if (n >= sizeof copy)
        return -1;
    memcpy(copy, text, n);
    copy[n] = '\0';
    errno = 0;
    double v = strtod(copy, NULL);
    if (errno == ERANGE || !isfinite(v))
        return -1;
    if (degrees)
        v *= DEGREE;
    *out = v;
    return 0;
}

static int is_word(const char *text)
{
    if (*text == '\0')
        return 0;
    for (const char *p = text; *p != '\0'; ++p)
        if (!isalnum((unsigned char)*p) && *p != '_' && *p != ':' && *p != '.')
            return 0;
    return 1;
}

/* The values of one argument into v by the keyword's kind. */
#define HEAD (sizeof(double) > sizeof(char *) ? sizeof(double) : sizeof(char *))

/* The bytes an argument's values take in the statement's block. */
static size_t value_bytes(const hx_adm_argument *a)
{
    return (HEAD + 2 * sizeof(int)) * (size_t)(a->count > 0 ? a->count : 1);
}

static int read_values(const hx_adm_keyword *kw, const hx_adm_statement *st,
                       const hx_adm_argument *a, hx_adm_value *v, char *block, int *line,
                       hx_message *msg)
{
    const int n = a->count, slots = n > 0 ? n : 1;
    v->count = n;
    /* its part of the statement's block: the numbers (or texts), then each
     * value's line and column */
    v->numbers = (double *)block;
    v->texts = (char **)block;
    v->value_lines = (int *)(block + HEAD * (size_t)slots);
    v->value_columns = v->value_lines + slots;
    for (int i = 0; i < n; ++i) {
        v->value_lines[i] = st->values[a->first + i].line;
        v->value_columns[i] = st->values[a->first + i].column;
    }
    if (kw->kind == HX_ADM_EXPR || kw->kind == HX_ADM_TEXT) {
        /* one text: the pieces of an expression continued over lines
         * (FUNCTION = -K*(DM(1,2) - L) / , - C*VR(1,2)) joined by blanks */
        size_t total = 1;
        for (int i = 0; i < n; ++i)
            total += strlen(st->values[a->first + i].text) + 2;
        v->numbers = NULL;
        char *joined = malloc(total);
        if (joined == NULL)
            return hx_fail(msg, "out of memory");
        joined[0] = '\0';
        for (int i = 0; i < n; ++i) {
            if (i > 0)
                strcat(joined, kw->kind == HX_ADM_TEXT ? ", " : " ");
            strcat(joined, st->values[a->first + i].text);
        }
        const size_t len = strlen(joined);
        if (kw->kind == HX_ADM_TEXT && len >= 2 && joined[0] == '"' && joined[len - 1] == '"') {
            memmove(joined, joined + 1, len - 2);
            joined[len - 2] = '\0';
        }
        v->texts[0] = joined;
        v->count = 1;
        return 0;
    }
    if (n < kw->min || n > kw->max || (kw->only && n != kw->min && n != kw->max)) {
        *line = a->keyword.line;
        if (kw->only)
            return hx_fail(msg, "%s takes %d or %d values, not %d", kw->name, kw->min, kw->max, n);
        if (kw->min == kw->max)
            return hx_fail(msg, "%s takes %d value%s, not %d", kw->name, kw->min,
                           kw->min == 1 ? "" : "s", n);
        return hx_fail(msg, "%s takes %d to %d values, not %d", kw->name, kw->min, kw->max, n);
    }
    if (kw->kind == HX_ADM_WORD || kw->kind == HX_ADM_ROUTINE) {
        v->numbers = NULL;
        for (int i = 0; i < n; ++i) {
            const hx_adm_token *t = &st->values[a->first + i];
            v->texts[i] = t->text;
            if (kw->kind == HX_ADM_WORD && !is_word(t->text)) {
                *line = t->line;
                return hx_fail(msg, "%s = %s (column %d) is not a name", kw->name, t->text,
                               t->column);
            }
        }
        return 0;
    }
    v->texts = NULL;
    for (int i = 0; i < n; ++i) {
        const hx_adm_token *t = &st->values[a->first + i];
        const int angle = kw->kind == HX_ADM_ANGLE || (kw->kind == HX_ADM_POSE && i >= 3);
        const int status = parse_number(t->text, angle, &v->numbers[i]);
        *line = t->line;
        char which[32] = "";
        if (n > 1)
            snprintf(which, sizeof which, ", value %d,", i + 1);
        if (status == -2)
            return hx_fail(msg, "%s%s %s (column %d): a degree mark (D) on a value that is not"
                           " an angle", kw->name, which, t->text, t->column);
        if (status != 0)
            return hx_fail(msg, "%s%s %s (column %d) is not a number", kw->name, which, t->text,
                           t->column);
        const double x = v->numbers[i];
        if ((kw->kind == HX_ADM_ID || kw->kind == HX_ADM_INT) &&
            (x != floor(x) || fabs(x) > INT_MAX || strpbrk(t->text, ".eE") != NULL))
            return hx_fail(msg, "%s%s %s (column %d) is not an integer", kw->name, which, t->text,
                           t->column);
        if (kw->kind == HX_ADM_ID && !(x >= 1.0))
            return hx_fail(msg, "%s%s %s (column %d) is not an id (a positive integer)", kw->name,
                           which, t->text, t->column);
    }
    return 0;
}

int hx_adm_check(const hx_adm_spec *spec, const hx_adm_statement *st, hx_adm_value **values_out,
                 int *line, hx_message *msg)
{
    *line = st->line;
    *values_out = NULL;
    const int nk = hx_adm_keyword_count(spec);
    hx_adm_value *values = calloc((size_t)nk + 1, sizeof *values);
    if (values == NULL)
        return hx_fail(msg, "out of memory");
    *values_out = values;
    const char *names[96];
    unsigned char abbrev[96];
    for (int k = 0; k < nk && k < 96; ++k) {
        names[k] = spec->keywords[k].name;
        abbrev[k] = spec->keywords[k].abbrev;
    }
    /* one block for every value of the statement, kept in the spare last slot */
    size_t bytes = 0;
    for (int i = 0; i < st->nargs; ++i)
        bytes += value_bytes(&st->args[i]);
    char *block = malloc(bytes > 0 ? bytes : 1);
    if (block == NULL)
        return hx_fail(msg, "out of memory");
    values[nk].block = block;
    for (int i = 0; i < st->nargs; ++i) {
        const hx_adm_argument *a = &st->args[i];
        *line = a->keyword.line;
        const char *candidates[16];
        int nc = 0;
        const int k = match(a->keyword.text, names, abbrev, nk < 96 ? nk : 96, candidates, &nc);
        if (k == -2) {
            char list[512];
            list_names(list, sizeof list, candidates, nc);
            return hx_fail(msg, "keyword %s (column %d) is ambiguous: it abbreviates %s",
                           a->keyword.text, a->keyword.column, list);
        }
        if (k < 0) {
            char list[1024];
            list_names(list, sizeof list, names, nk < 96 ? nk : 96);
            return hx_fail(msg, "%s (column %d) is not a keyword of %s (it takes %s)",
                           a->keyword.text, a->keyword.column, spec->name, list);
        }
        const hx_adm_keyword *kw = &spec->keywords[k];
        hx_adm_value *v = &values[k];
        if (v->present)
            return hx_fail(msg, "%s is given twice (first at line %d)", kw->name, v->line);
        v->present = 1;
        v->line = a->keyword.line;
        v->column = a->keyword.column;
        if (kw->kind == HX_ADM_FLAG) {
            if (a->has_equals || a->count > 0)
                return hx_fail(msg, "%s is a flag: it takes no value", kw->name);
            continue;
        }
        if (!a->has_equals)
            return hx_fail(msg, "%s needs a value (%s=...)", kw->name, kw->name);
        if (read_values(kw, st, a, v, block, line, msg) != 0)
            return -1;
        block += value_bytes(a);
    }
    *line = st->line;
    for (int k = 0; k < nk; ++k)
        if (spec->keywords[k].required && !values[k].present)
            return hx_fail(msg, "%s is missing (the statement needs it)", spec->keywords[k].name);
    return 0;
}

void hx_adm_values_free(const hx_adm_spec *spec, hx_adm_value *values)
{
    if (values == NULL)
        return;
    const int nk = hx_adm_keyword_count(spec);
    for (int k = 0; k < nk; ++k) {
        const hx_adm_kind kind = spec->keywords[k].kind;
        if ((kind == HX_ADM_EXPR || kind == HX_ADM_TEXT) && values[k].texts != NULL &&
            values[k].count > 0)
            free(values[k].texts[0]);
    }
    free(values[nk].block);
    free(values);
}
