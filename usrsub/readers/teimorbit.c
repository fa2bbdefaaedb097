/* TeimOrbit property-file parser (teimorbit.h). */
#include "usrsub/readers/teimorbit.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct parser {
    usrsub_teim_file *file;
    const char *name;
    usrsub_message *msg;
    int line;
    usrsub_teim_block *block;  /* current block */
    char sub[64];              /* current sub-block */
    usrsub_teim_table *table;  /* table rows go to, or NULL */
} parser;

static int fail_at(parser *p, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int fail_at(parser *p, const char *fmt, ...)
{
    char what[USRSUB_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return usrsub_fail(p->msg, "'%s' line %d: %s", p->name, p->line, what);
}

static void *grow(void *array, int count, size_t size)
{
    /* capacities are powers of two: grow when count reaches one */
    if (count == 0 || (count & (count - 1)) == 0) {
        const size_t capacity = count == 0 ? 4 : 2u * (size_t)count;
        return realloc(array, capacity * size);
    }
    return array;
}

static void upper(char *s)
{
    for (; *s; ++s)
        *s = (char)toupper((unsigned char)*s);
}

/* Replaces the first `from` in name by `to`, within size. */
static void replace(char *name, size_t size, const char *from, const char *to)
{
    char *at = strstr(name, from);
    if (at == NULL)
        return;
    const size_t head = (size_t)(at - name), nfrom = strlen(from), nto = strlen(to);
    const size_t tail = strlen(at + nfrom);
    if (head + nto + tail + 1 > size)
        return;
    memmove(at + nto, at + nfrom, tail + 1);
    memcpy(at, to, nto);
}

/* Mends the vendor documentation's misspellings of block names. */
static void mend_name(char *name, size_t size)
{
    replace(name, size, "SIFFNESS", "STIFFNESS");
    if (strncmp(name, "RUBER_", 6) == 0)
        replace(name, size, "RUBER_", "RUBBER_");
    if (strncmp(name, "RUBBER_BUSHING", 14) == 0)
        replace(name, size, "RUBBER_BUSHING", "RUBBER_DAMPING");
}

static char *trim(char *s)
{
    while (isspace((unsigned char)*s))
        ++s;
    size_t n = strlen(s);
    while (n > 0 && isspace((unsigned char)s[n - 1]))
        s[--n] = '\0';
    return s;
}

static void unquote(char *s)
{
    const size_t n = strlen(s);
    if (n >= 2 && (s[0] == '\'' || s[0] == '"') && s[n - 1] == s[0]) {
        memmove(s, s + 1, n - 2);
        s[n - 2] = '\0';
    }
}

/* Cuts a $ or ! comment that is not inside quotes. */
static void strip_comment(char *s)
{
    char quote = 0;
    for (; *s; ++s) {
        if (quote) {
            if (*s == quote)
                quote = 0;
        } else if (*s == '\'' || *s == '"') {
            quote = *s;
        } else if (*s == '$' || *s == '!') {
            *s = '\0';
            return;
        }
    }
}

/* Splits on blanks and commas, keeping quoted cells whole. */
static int split_cells(parser *p, char *s, char ***cells_out, int *count_out)
{
    char **cells = NULL;
    int count = 0;
    while (*s) {
        while (*s && (isspace((unsigned char)*s) || *s == ','))
            ++s;
        if (!*s)
            break;
        char *start = s;
        if (*s == '\'' || *s == '"') {
            const char quote = *s++;
            start = s;
            while (*s && *s != quote)
                ++s;
            if (*s != quote) {
                for (int k = 0; k < count; ++k)
                    free(cells[k]);
                free(cells);
                return fail_at(p, "a quote is not closed: %s", start - 1);
            }
            *s++ = '\0';
        } else {
            while (*s && !isspace((unsigned char)*s) && *s != ',')
                ++s;
            if (*s)
                *s++ = '\0';
        }
        char **grown = grow(cells, count, sizeof *cells);
        char *copy = strdup(start);
        if (grown == NULL || copy == NULL) {
            free(copy);
            free(grown != NULL ? grown : cells);
            return usrsub_fail(p->msg, "'%s': out of memory", p->name);
        }
        cells = grown;
        cells[count++] = copy;
    }
    *cells_out = cells;
    *count_out = count;
    return 0;
}

static int start_block(parser *p, char *name)
{
    usrsub_teim_file *f = p->file;
    usrsub_teim_block *grown = grow(f->block, f->nblocks, sizeof *f->block);
    if (grown == NULL)
        return usrsub_fail(p->msg, "'%s': out of memory", p->name);
    f->block = grown;
    upper(name);
    usrsub_teim_block *b = &f->block[f->nblocks];
    memset(b, 0, sizeof *b);
    snprintf(b->name, sizeof b->name, "%s", trim(name));
    mend_name(b->name, sizeof b->name);
    b->line = p->line;
    for (int k = 0; k < f->nblocks; ++k)
        if (strcmp(f->block[k].name, b->name) == 0) {
            return fail_at(p, "block [%s] appears again (first at line %d)", b->name,
                           f->block[k].line);
        }
    f->nblocks++;
    p->block = b;
    p->sub[0] = '\0';
    p->table = NULL;
    return 0;
}

static int start_table(parser *p, char *columns)
{
    if (p->block == NULL)
        return fail_at(p, "a table {%s} outside any [BLOCK]", columns);
    usrsub_teim_block *b = p->block;
    usrsub_teim_table *grown = grow(b->table, b->ntables, sizeof *b->table);
    if (grown == NULL)
        return usrsub_fail(p->msg, "'%s': out of memory", p->name);
    b->table = grown;
    usrsub_teim_table *t = &b->table[b->ntables];
    memset(t, 0, sizeof *t);
    snprintf(t->sub, sizeof t->sub, "%s", p->sub);
    t->line = p->line;
    upper(columns);
    if (split_cells(p, columns, &t->column, &t->ncolumns) != 0)
        return -1;
    b->ntables++;
    p->table = t;
    return 0;
}

static int add_row(parser *p, char *text)
{
    usrsub_teim_table *t = p->table;
    usrsub_teim_row row = {p->line, 0, NULL};
    if (split_cells(p, text, &row.cell, &row.ncells) != 0)
        return -1;
    usrsub_teim_row *grown = grow(t->row, t->nrows, sizeof *t->row);
    if (grown == NULL) {
        for (int k = 0; k < row.ncells; ++k)
            free(row.cell[k]);
        free(row.cell);
        return usrsub_fail(p->msg, "'%s': out of memory", p->name);
    }
    t->row = grown;
    t->row[t->nrows++] = row;
    return 0;
}

static int add_entry(parser *p, char *key, char *value)
{
    if (p->block == NULL)
        return fail_at(p, "'%s = ...' outside any [BLOCK]", trim(key));
    usrsub_teim_block *b = p->block;
    usrsub_teim_entry *grown = grow(b->entry, b->nentries, sizeof *b->entry);
    if (grown == NULL)
        return usrsub_fail(p->msg, "'%s': out of memory", p->name);
    b->entry = grown;
    usrsub_teim_entry *e = &b->entry[b->nentries];
    memset(e, 0, sizeof *e);
    key = trim(key);
    upper(key);
    if (*key == '\0')
        return fail_at(p, "an entry without a key: '= %s'", trim(value));
    snprintf(e->key, sizeof e->key, "%s", key);
    snprintf(e->sub, sizeof e->sub, "%s", p->sub);
    value = trim(value);
    unquote(value);
    e->value = strdup(value);
    if (e->value == NULL)
        return usrsub_fail(p->msg, "'%s': out of memory", p->name);
    e->line = p->line;
    b->nentries++;
    p->table = NULL; /* an entry ends a table */
    return 0;
}

static int parse_line(parser *p, char *raw)
{
    strip_comment(raw);
    char *s = trim(raw);
    const size_t n = strlen(s);
    if (n == 0)
        return 0;
    if (s[0] == '[') {
        if (s[n - 1] != ']')
            return fail_at(p, "a block name is not closed: %s", s);
        s[n - 1] = '\0';
        return start_block(p, s + 1);
    }
    if (s[0] == '(') {
        if (s[n - 1] != ')')
            return fail_at(p, "a sub-block name is not closed: %s", s);
        if (p->block == NULL)
            return fail_at(p, "a sub-block %s outside any [BLOCK]", s);
        s[n - 1] = '\0';
        char *name = trim(s + 1);
        upper(name);
        snprintf(p->sub, sizeof p->sub, "%s", name);
        p->table = NULL;
        return 0;
    }
    if (s[0] == '{') {
        if (s[n - 1] != '}')
            return fail_at(p, "a table header is not closed: %s", s);
        s[n - 1] = '\0';
        return start_table(p, s + 1);
    }
    char *equals = strchr(s, '=');
    char *quote = strpbrk(s, "'\"");
    if (equals != NULL && (quote == NULL || equals < quote)) {
        *equals = '\0';
        return add_entry(p, s, equals + 1);
    }
    if (p->table != NULL)
        return add_row(p, s);
    return fail_at(p, "cannot read '%s' (not a [BLOCK], (SUB_BLOCK), {table}, KEY = value"
                      " or a table row)", s);
}

int usrsub_teim_parse(const char *text, size_t length, const char *name,
                      usrsub_teim_file **file, usrsub_message *msg)
{
    usrsub_teim_file *f = calloc(1, sizeof *f);
    if (f == NULL || (f->path = strdup(name)) == NULL) {
        free(f);
        return usrsub_fail(msg, "'%s': out of memory", name);
    }
    parser p = {f, name, msg, 0, NULL, "", NULL};
    size_t start = 0;
    int status = 0;
    while (status == 0 && start < length) {
        size_t end = start;
        while (end < length && text[end] != '\n')
            ++end;
        ++p.line;
        const size_t n = end - start;
        char *line = malloc(n + 1);
        if (line == NULL) {
            status = usrsub_fail(msg, "'%s': out of memory", name);
            break;
        }
        memcpy(line, text + start, n);
        line[n] = '\0';
        if (memchr(line, '\0', n) != NULL) {
            status = fail_at(&p, "%s", "a NUL character in the text");
        } else {
            status = parse_line(&p, line);
        }
        free(line);
        start = end + 1;
    }
    if (status != 0) {
        usrsub_teim_free(f);
        return -1;
    }
    *file = f;
    return 0;
}

int usrsub_teim_read(const char *path, usrsub_teim_file **file, usrsub_message *msg)
{
    FILE *in = fopen(path, "rb");
    if (in == NULL)
        return usrsub_fail(msg, "cannot open '%s': %s", path, strerror(errno));
    size_t size = 0, capacity = 65536;
    char *text = malloc(capacity);
    size_t got;
    while (text != NULL && (got = fread(text + size, 1, capacity - size, in)) > 0) {
        size += got;
        if (size == capacity) {
            if (capacity > ((size_t)64 << 20)) {
                free(text);
                fclose(in);
                return usrsub_fail(msg, "'%s' is larger than 64 MiB", path);
            }
            char *grown = realloc(text, capacity *= 2);
            if (grown == NULL)
                free(text);
            text = grown;
        }
    }
    const int read_error = ferror(in);
    fclose(in);
    if (text == NULL)
        return usrsub_fail(msg, "'%s': out of memory", path);
    if (read_error) {
        free(text);
        return usrsub_fail(msg, "'%s': read error", path);
    }
    const int status = usrsub_teim_parse(text, size, path, file, msg);
    free(text);
    return status;
}

void usrsub_teim_free(usrsub_teim_file *f)
{
    if (f == NULL)
        return;
    for (int b = 0; b < f->nblocks; ++b) {
        usrsub_teim_block *block = &f->block[b];
        for (int e = 0; e < block->nentries; ++e)
            free(block->entry[e].value);
        for (int t = 0; t < block->ntables; ++t) {
            usrsub_teim_table *table = &block->table[t];
            for (int c = 0; c < table->ncolumns; ++c)
                free(table->column[c]);
            free(table->column);
            for (int r = 0; r < table->nrows; ++r) {
                for (int c = 0; c < table->row[r].ncells; ++c)
                    free(table->row[r].cell[c]);
                free(table->row[r].cell);
            }
            free(table->row);
        }
        free(block->entry);
        free(block->table);
    }
    free(f->block);
    free(f->path);
    free(f);
}

const usrsub_teim_block *usrsub_teim_find_block(const usrsub_teim_file *f, const char *name)
{
    for (int k = 0; k < f->nblocks; ++k)
        if (strcmp(f->block[k].name, name) == 0)
            return &f->block[k];
    return NULL;
}

const usrsub_teim_entry *usrsub_teim_find_entry(const usrsub_teim_block *b, const char *key)
{
    for (int k = 0; b != NULL && k < b->nentries; ++k)
        if (strcmp(b->entry[k].key, key) == 0)
            return &b->entry[k];
    return NULL;
}

const usrsub_teim_table *usrsub_teim_find_table(const usrsub_teim_block *b, const char *sub)
{
    for (int k = 0; b != NULL && k < b->ntables; ++k)
        if (sub == NULL || strcmp(b->table[k].sub, sub) == 0)
            return &b->table[k];
    return NULL;
}

int usrsub_teim_column(const usrsub_teim_table *t, const char *name)
{
    for (int k = 0; k < t->ncolumns; ++k)
        if (strcmp(t->column[k], name) == 0)
            return k;
    return -1;
}

int usrsub_teim_number(const char *text, double *value)
{
    char *end;
    errno = 0;
    const double v = strtod(text, &end);
    if (end == text || errno == ERANGE || !isfinite(v))
        return -1;
    while (isspace((unsigned char)*end))
        ++end;
    if (*end != '\0')
        return -1;
    *value = v;
    return 0;
}

int usrsub_teim_numbers(const char *text, double *values, int max)
{
    int count = 0;
    const char *s = text;
    for (;;) {
        while (isspace((unsigned char)*s) || *s == ',')
            ++s;
        if (*s == '\0')
            return count;
        char *end;
        errno = 0;
        const double v = strtod(s, &end);
        if (end == s || errno == ERANGE || !isfinite(v) || count == max)
            return -1;
        if (*end != '\0' && !isspace((unsigned char)*end) && *end != ',')
            return -1;
        values[count++] = v;
        s = end;
    }
}
