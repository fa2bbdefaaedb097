/*
 * Lines into statements, and each statement's generic parse (statement.h).
 * The rules, from the Adams Solver documentation and the datasets Adams/View
 * writes (docs/interface.md §9.1, docs/sources.md): a statement begins on a
 * line whose first non-blank character is not a comma and goes on over the
 * lines that begin with one; '!' outside a quoted string starts a comment
 * to the end of the line; blank lines and comment lines may stand anywhere.
 * Arguments are separated by commas outside parentheses, and by '\' (the
 * separator of F1=..\F2=.. and FX=..\FY=..). A continuation line's comma
 * is a comma (between arguments, or between a function's arguments inside
 * parentheses), except where no comma can stand, after '(', '=', an
 * operator or another comma: there it only marks the continuation and reads
 * as a blank.
 */
#include "model/adm/statement.h"

#include <ctype.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void hx_adm_source_init(hx_adm_source *src, const char *path, const char *text, size_t length)
{
    src->path = path;
    src->text = text;
    src->length = length;
    src->pos = 0;
    src->line = 1;
}

int hx_adm_source_line(hx_adm_source *src, const char **start, size_t *n, int *line)
{
    if (src->pos >= src->length)
        return -1;
    const char *p = src->text + src->pos;
    const size_t left = src->length - src->pos;
    const char *end = memchr(p, '\n', left);
    size_t len = end != NULL ? (size_t)(end - p) : left;
    src->pos += len + (end != NULL);
    if (len > 0 && p[len - 1] == '\r')
        --len;
    *start = p;
    *n = len;
    *line = src->line++;
    return 0;
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

static int is_name_char(char c)
{
    return isalnum((unsigned char)c) || c == '_';
}

/* The length of the line's content: up to a '!' outside a quoted string,
 * less trailing blanks. */
static size_t content_length(const char *p, size_t n)
{
    int quoted = 0;
    size_t k = 0;
    for (; k < n; ++k) {
        if (p[k] == '"')
            quoted = !quoted;
        else if (p[k] == '!' && !quoted)
            break;
    }
    while (k > 0 && is_blank(p[k - 1]))
        --k;
    return k;
}

static int reserve(hx_adm_statement *st, size_t more, hx_message *msg)
{
    if (st->length + more + 1 <= st->capacity)
        return 0;
    size_t capacity = st->capacity ? 2 * st->capacity : 256;
    while (capacity < st->length + more + 1)
        capacity *= 2;
    char *grown = realloc(st->buffer, capacity);
    if (grown == NULL)
        return hx_fail(msg, "out of memory");
    st->buffer = grown;
    st->capacity = capacity;
    return 0;
}

/* Appends a piece of a line (from its first non-blank character, which is
 * at column); a continuation's leading comma is kept as a separator or
 * turned into a blank (the header comment). */
static int append(hx_adm_statement *st, const char *p, size_t n, int line, int column,
                  hx_message *msg)
{
    if (reserve(st, n + 1, msg) != 0)
        return -1;
    if (st->nsegments == st->cap_segments) {
        const int cap = st->cap_segments ? 2 * st->cap_segments : 8;
        hx_adm_segment *grown = realloc(st->segments, sizeof *grown * (size_t)cap);
        if (grown == NULL)
            return hx_fail(msg, "out of memory");
        st->segments = grown;
        st->cap_segments = cap;
    }
    size_t start = st->length;
    if (start > 0) {
        /* a blank between lines, so that no two words run together */
        st->buffer[st->length++] = ' ';
        start = st->length;
        size_t k = start - 1;
        while (k > 0 && is_blank(st->buffer[k - 1]))
            --k;
        const char last = k > 0 ? st->buffer[k - 1] : '/';
        memcpy(st->buffer + start, p, n);
        if (p[0] == ',' && strchr("=+-*/^(,:\\", last) != NULL)
            st->buffer[start] = ' ';
    } else {
        memcpy(st->buffer, p, n);
    }
    st->length += n;
    st->buffer[st->length] = '\0';
    st->segments[st->nsegments++] = (hx_adm_segment){start, line, column};
    return 0;
}

void hx_adm_statement_position(const hx_adm_statement *st, size_t offset, int *line, int *column)
{
    int lo = 0, hi = st->nsegments - 1;
    while (lo < hi) { /* the last segment that begins at or before offset */
        const int mid = (lo + hi + 1) / 2;
        if (st->segments[mid].offset <= offset)
            lo = mid;
        else
            hi = mid - 1;
    }
    const hx_adm_segment *s = &st->segments[lo];
    *line = s->line;
    *column = s->column + (int)(offset - s->offset);
}

static hx_adm_token text_at(hx_adm_statement *st, size_t offset)
{
    hx_adm_token t = {st->buffer + offset, 0, 0};
    hx_adm_statement_position(st, offset, &t.line, &t.column);
    return t;
}

static int fail_at(hx_adm_source *src, hx_adm_statement *st, size_t offset, hx_message *msg,
                   const char *what)
{
    int line, column;
    hx_adm_statement_position(st, offset, &line, &column);
    return hx_fail(msg, "%s:%d: column %d: %s", src->path, line, column, what);
}

static int push_value(hx_adm_statement *st, hx_adm_token t, hx_message *msg)
{
    if (st->nvalues == st->cap_values) {
        const int cap = st->cap_values ? 2 * st->cap_values : 32;
        hx_adm_token *grown = realloc(st->values, sizeof *grown * (size_t)cap);
        if (grown == NULL)
            return hx_fail(msg, "out of memory");
        st->values = grown;
        st->cap_values = cap;
    }
    st->values[st->nvalues++] = t;
    return 0;
}

static int push_argument(hx_adm_statement *st, hx_adm_token keyword, int has_equals,
                         hx_message *msg)
{
    if (st->nargs == st->cap_args) {
        const int cap = st->cap_args ? 2 * st->cap_args : 16;
        hx_adm_argument *grown = realloc(st->args, sizeof *grown * (size_t)cap);
        if (grown == NULL)
            return hx_fail(msg, "out of memory");
        st->args = grown;
        st->cap_args = cap;
    }
    st->args[st->nargs++] = (hx_adm_argument){keyword, has_equals, st->nvalues, 0};
    return 0;
}

/* One argument item [s, e) of the buffer, trimmed and not empty. */
static int parse_item(hx_adm_source *src, hx_adm_statement *st, size_t s, size_t e, int first,
                      hx_message *msg)
{
    char *b = st->buffer;
    if (first) { /* NAME/id */
        size_t k = s;
        while (k < e && isdigit((unsigned char)b[k]))
            ++k;
        if (k == e) {
            long long id = 0;
            for (k = s; k < e && id <= INT_MAX; ++k)
                id = 10 * id + (b[k] - '0');
            if (id > INT_MAX)
                return fail_at(src, st, s, msg, "the statement's id is too large");
            st->has_id = 1;
            st->id = (int)id;
            st->id_text = text_at(st, s);
            b[e] = '\0';
            return 0;
        }
        if (k > s && is_blank(b[k]))
            return fail_at(src, st, k, msg, "expected ',' after the statement's id");
    }
    size_t k = s;
    if (isalpha((unsigned char)b[k]) || b[k] == '_') {
        while (k < e && is_name_char(b[k]))
            ++k;
        size_t name_end = k;
        while (k < e && is_blank(b[k]))
            ++k;
        if (name_end == e) { /* a bare word: a flag */
            b[e] = '\0';
            return push_argument(st, text_at(st, s), 0, msg);
        }
        if (b[k] == '=') {
            size_t v = k + 1;
            while (v < e && is_blank(b[v]))
                ++v;
            b[name_end] = '\0';
            if (push_argument(st, text_at(st, s), 1, msg) != 0)
                return -1;
            if (v == e)
                return fail_at(src, st, s, msg, "a keyword with '=' and no value after it");
            b[e] = '\0';
            if (push_value(st, text_at(st, v), msg) != 0)
                return -1;
            st->args[st->nargs - 1].count = 1;
            return 0;
        }
    }
    /* a further value of the argument before it (QP=1, 2, 3) */
    if (st->nargs == 0)
        return fail_at(src, st, s, msg, "a value with no keyword before it");
    b[e] = '\0';
    if (push_value(st, text_at(st, s), msg) != 0)
        return -1;
    st->args[st->nargs - 1].count++;
    return 0;
}

static int parse(hx_adm_source *src, hx_adm_statement *st, hx_message *msg)
{
    char *b = st->buffer;
    const size_t n = st->length;
    size_t k = 0;
    while (k < n && is_name_char(b[k]))
        ++k;
    if (k == 0)
        return fail_at(src, st, 0, msg, "expected a statement name (NAME/id, ...)");
    const size_t name_end = k;
    while (k < n && is_blank(b[k]))
        ++k;
    if (k < n && b[k] != '/') {
        char what[96];
        snprintf(what, sizeof what, "expected '/' after the statement name, found '%c'", b[k]);
        return fail_at(src, st, k, msg, what);
    }
    st->name = text_at(st, 0);
    int first = 1, depth = 0, quoted = 0;
    size_t s = k + 1;
    for (size_t i = k + 1; i <= n && k < n; ++i) {
        const char c = i < n ? b[i] : ',';
        if (c == '"')
            quoted = !quoted;
        if (quoted && i < n)
            continue;
        if (c == '(')
            depth++;
        else if (c == ')' && depth > 0)
            depth--;
        if (i < n && (depth > 0 || (c != ',' && c != '\\')))
            continue;
        size_t e = i;
        while (s < e && is_blank(b[s]))
            ++s;
        while (e > s && is_blank(b[e - 1]))
            --e;
        if (e > s) {
            if (parse_item(src, st, s, e, first, msg) != 0)
                return -1;
            first = 0;
        }
        s = i + 1;
    }
    b[name_end] = '\0';
    return 0;
}

/* The next line that holds more than blanks and a comment: 1 with its text
 * from its first non-blank (*p, *len) and its column (*column); 0 at the end
 * of the source; -1 (msg) on a NUL byte. */
static int next_content_line(hx_adm_source *src, const char **p, size_t *len, int *line,
                             int *column, hx_message *msg)
{
    for (;;) {
        const char *text;
        size_t n;
        if (hx_adm_source_line(src, &text, &n, line) != 0)
            return 0;
        if (memchr(text, '\0', n) != NULL)
            return hx_fail(msg, "%s:%d: the line holds a NUL byte (a dataset is text)", src->path,
                           *line);
        const size_t cut = content_length(text, n);
        size_t b = 0;
        while (b < cut && is_blank(text[b]))
            ++b;
        if (b < cut) {
            *p = text + b, *len = cut - b, *column = (int)b + 1;
            return 1;
        }
    }
}

int hx_adm_statement_next(hx_adm_source *src, hx_adm_statement *st, hx_message *msg)
{
    st->nargs = st->nvalues = st->nsegments = 0;
    st->length = 0;
    st->has_id = 0;
    st->id = 0;
    const char *p;
    size_t n;
    int line, column;
    const int first = next_content_line(src, &p, &n, &line, &column, msg);
    if (first <= 0)
        return first;
    if (p[0] == ',')
        return hx_fail(msg, "%s:%d: a continuation line (it begins with ',') with no statement"
                       " before it", src->path, line);
    st->line = line;
    if (append(st, p, n, line, column, msg) != 0)
        return -1;
    for (;;) { /* continuation lines, up to the next line that is not one */
        const size_t pos = src->pos;
        const int next = src->line;
        const int more = next_content_line(src, &p, &n, &line, &column, msg);
        if (more < 0)
            return -1;
        if (more == 0)
            break;
        if (p[0] != ',') {
            src->pos = pos;
            src->line = next;
            break;
        }
        if (append(st, p, n, line, column, msg) != 0)
            return -1;
    }
    return parse(src, st, msg) == 0 ? 1 : -1;
}

char *hx_adm_statement_take_buffer(hx_adm_statement *st)
{
    char *b = st->buffer;
    st->buffer = NULL;
    st->capacity = st->length = 0;
    return b;
}

void hx_adm_statement_free(hx_adm_statement *st)
{
    free(st->buffer);
    free(st->args);
    free(st->values);
    free(st->segments);
    memset(st, 0, sizeof *st);
}
