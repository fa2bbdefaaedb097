/*
 * The Adams dataset reader (docs/interface.md §9): the title line, then
 * statement by statement (statement.c), each checked against its keyword
 * table (keywords.c, statement_table.c) and kept; then every id a statement
 * names is checked, what the harness simulates is decided (simulated.c),
 * each statement is built into the same draft model the XML reader fills,
 * through the XML reader's element builders (translate.c, build_*.c), the
 * markers are placed in the world (build_parts.c), and the draft goes
 * through the same resolve passes. Nothing downstream knows which file a
 * model came from.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/adm/reader.h"
#include "model/readers.h"
#include "model/user_list.h"

/* ---- the entries and their ids ------------------------------------------------------- */

static unsigned slot_of(int statement, int id, int mask)
{
    return ((unsigned)id * 2654435761u ^ (unsigned)statement * 40503u) & (unsigned)mask;
}

static int spec_index(const hx_adm_spec *spec)
{
    return (int)(spec - hx_adm_statements);
}

static const hx_adm_spec *spec_named(const char *name)
{
    for (int k = 0; k < hx_adm_statement_count; ++k)
        if (hx_adm_statements[k].name[0] == name[0] && strcmp(hx_adm_statements[k].name, name) == 0)
            return &hx_adm_statements[k];
    return NULL;
}

hx_adm_entry *hx_adm_find(const hx_adm_reader *r, const char *name, int id)
{
    const hx_adm_spec *spec = spec_named(name);
    if (spec == NULL || r->nslots == 0)
        return NULL;
    const int statement = spec_index(spec);
    for (unsigned s = slot_of(statement, id, r->nslots - 1);; s = (s + 1) & (unsigned)(r->nslots - 1)) {
        const int k = r->slots[s];
        if (k < 0)
            return NULL;
        if (r->entries[k].spec == spec && r->entries[k].id == id)
            return &r->entries[k];
    }
}

/* Indexes every entry with an id; -1 (failed) on a second one of a statement. */
static int index_entries(hx_adm_reader *r)
{
    r->nslots = 16;
    while (r->nslots < 2 * r->nentries)
        r->nslots *= 2;
    r->slots = malloc(sizeof(int) * (size_t)r->nslots);
    if (r->slots == NULL) {
        hx_draft_fail(r->d, 0, "out of memory");
        return -1;
    }
    for (int s = 0; s < r->nslots; ++s)
        r->slots[s] = -1;
    for (int k = 0; k < r->nentries; ++k) {
        hx_adm_entry *e = &r->entries[k];
        if (e->spec->id_form != HX_ADM_ID_REQUIRED)
            continue;
        const hx_adm_entry *earlier = hx_adm_find(r, e->spec->name, e->id);
        if (earlier != NULL) {
            char label[48];
            return hx_adm_fail(r, e, e->line, "%s is defined twice (first at line %d)",
                               hx_adm_label(e, label, sizeof label), earlier->line);
        }
        unsigned s = slot_of(spec_index(e->spec), e->id, r->nslots - 1);
        while (r->slots[s] >= 0)
            s = (s + 1) & (unsigned)(r->nslots - 1);
        r->slots[s] = k;
    }
    return 0;
}

static const hx_adm_value absent = {0};

const hx_adm_value *hx_adm_get(const hx_adm_entry *e, const char *keyword)
{
    const int k = hx_adm_keyword_index(e->spec, keyword);
    return k >= 0 ? &e->values[k] : &absent;
}

int hx_adm_has(const hx_adm_entry *e, const char *keyword)
{
    return hx_adm_get(e, keyword)->present;
}

double hx_adm_number(const hx_adm_entry *e, const char *keyword, int k, double fallback)
{
    const hx_adm_value *v = hx_adm_get(e, keyword);
    return v->present && v->numbers != NULL && k < v->count ? v->numbers[k] : fallback;
}

int hx_adm_ref(const hx_adm_entry *e, const char *keyword)
{
    return (int)hx_adm_number(e, keyword, 0, 0.0);
}

const char *hx_adm_text(const hx_adm_entry *e, const char *keyword)
{
    const hx_adm_value *v = hx_adm_get(e, keyword);
    return v->present && v->texts != NULL ? v->texts[0] : NULL;
}

const char *hx_adm_label(const hx_adm_entry *e, char *out, size_t size)
{
    if (e->spec->id_form == HX_ADM_ID_REQUIRED)
        snprintf(out, size, "%s/%d", e->spec->name, e->id);
    else
        snprintf(out, size, "%s", e->spec->name);
    return out;
}

int hx_adm_fail(hx_adm_reader *r, const hx_adm_entry *e, int line, const char *fmt, ...)
{
    char what[HX_MESSAGE_MAX], label[48];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    hx_draft_fail(r->d, line > 0 ? line : e->line, "%s: %s", hx_adm_label(e, label, sizeof label),
                  what);
    return -1;
}

void hx_adm_note(hx_adm_reader *r, int line, const char *fmt, ...)
{
    if (r->d->warnings == NULL)
        return;
    va_list ap;
    va_start(ap, fmt);
    fprintf(r->d->warnings, "%s:%d: note: ", r->path, line);
    vfprintf(r->d->warnings, fmt, ap);
    fputc('\n', r->d->warnings);
    va_end(ap);
}

/* The expressions of an unsimulated entry, kept for the expression engine. */
static void keep_expressions(hx_adm_reader *r, const hx_adm_entry *e)
{
    hx_model *m = r->d->m;
    const int nk = hx_adm_keyword_count(e->spec);
    for (int k = 0; k < nk; ++k) {
        const hx_adm_value *v = &e->values[k];
        if (e->spec->keywords[k].kind != HX_ADM_EXPR || !v->present || hx_adm_is_user(v->texts[0]))
            continue;
        hx_model_expression *x = hx_draft_push(r->d, (void **)&m->expressions, &m->nexpressions,
                                               &r->d->cap_expressions, sizeof *x, NULL, 0);
        if (x == NULL)
            return;
        snprintf(x->statement, sizeof x->statement, "%s", e->spec->name);
        snprintf(x->keyword, sizeof x->keyword, "%s", e->spec->keywords[k].name);
        x->id = e->id;
        x->line = v->value_lines[0];
        x->column = v->value_columns[0];
        if ((x->text = strdup(v->texts[0])) == NULL)
            hx_draft_fail(r->d, e->line, "out of memory");
    }
}

void hx_adm_unsimulated(hx_adm_reader *r, hx_adm_entry *e, const char *fmt, ...)
{
    char why[512], label[48];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, sizeof why, fmt, ap);
    va_end(ap);
    e->unsimulated = 1;
    hx_adm_label(e, label, sizeof label);
    hx_draft_warn(r->d, e->line, "%s: %s: check verifies the user elements, run and bench refuse"
                  " the model", label, why);
    hx_model *m = r->d->m;
    if (m->nunsimulated++ == 0)
        snprintf(m->unsimulated, sizeof m->unsimulated, "%s (line %d)", label, e->line);
    if (e->values != NULL)
        keep_expressions(r, e);
}

/* ---- reading ------------------------------------------------------------------------ */

static hx_adm_entry *push_entry(hx_adm_reader *r)
{
    if (r->nentries == r->capacity) {
        const int capacity = r->capacity ? 2 * r->capacity : 64;
        hx_adm_entry *grown = realloc(r->entries, sizeof *grown * (size_t)capacity);
        if (grown == NULL) {
            hx_draft_fail(r->d, 0, "out of memory");
            return NULL;
        }
        r->entries = grown;
        r->capacity = capacity;
    }
    hx_adm_entry *e = &r->entries[r->nentries++];
    memset(e, 0, sizeof *e);
    e->index = -1;
    return e;
}

/* One statement checked into an entry (or set aside); 1 at END, 0, or -1. */
static int take_statement(hx_adm_reader *r, hx_adm_statement *st)
{
    hx_message why;
    const hx_adm_spec *spec = hx_adm_find_spec(hx_adm_statements, hx_adm_statement_count,
                                               st->name.text, &why);
    if (spec == NULL) {
        hx_draft_fail(r->d, st->line, "%s%s (statements the harness reads, notes, warns of and"
                      " refuses: docs/interface.md §9)", why.text,
                      strstr(why.text, "ambiguous") ? "" : " (an Adams statement it does not know,"
                      " or a misspelling)");
        return -1;
    }
    char label[64];
    if (st->has_id)
        snprintf(label, sizeof label, "%s/%d", spec->name, st->id);
    else
        snprintf(label, sizeof label, "%s", spec->name);
    if (spec->role == HX_ADM_REFUSED) {
        hx_draft_fail(r->d, st->line, "%s: %s", label, spec->why);
        return -1;
    }
    if (spec->role == HX_ADM_OUTPUT)
        return 0;
    if (spec->role == HX_ADM_SETTING) {
        if (!r->noted[spec_index(spec)])
            hx_adm_note(r, st->line, "%s is read and has no effect: %s", spec->name, spec->why);
        r->noted[spec_index(spec)] = 1;
        return 0;
    }
    if (spec->id_form == HX_ADM_ID_REQUIRED && (!st->has_id || st->id <= 0)) {
        hx_draft_fail(r->d, st->line, "%s: needs a positive id (%s/id, ...)", spec->name,
                      spec->name);
        return -1;
    }
    if (spec->id_form == HX_ADM_ID_NONE && st->has_id) {
        hx_draft_fail(r->d, st->line, "%s: takes no id (%s/KEYWORD=..., ...)", label, spec->name);
        return -1;
    }
    hx_adm_value *values = NULL;
    if (spec->keywords != NULL) {
        int line;
        if (hx_adm_check(spec, st, &values, &line, &why) != 0) {
            hx_adm_values_free(spec, values);
            hx_draft_fail(r->d, line, "%s: %s", label, why.text);
            return -1;
        }
    }
    if (spec->role == HX_ADM_END) {
        hx_adm_values_free(spec, values);
        return 1;
    }
    hx_adm_entry *e = push_entry(r);
    if (e == NULL) {
        hx_adm_values_free(spec, values);
        return -1;
    }
    e->spec = spec;
    e->line = st->line;
    e->id = st->has_id ? st->id : 0;
    e->values = values;
    e->buffer = hx_adm_statement_take_buffer(st);
    return 0;
}

static int read_statements(hx_adm_reader *r, const char *text, size_t length)
{
    hx_adm_source src;
    hx_adm_source_init(&src, r->path, text, length);
    const char *title;
    size_t n;
    int line;
    (void)hx_adm_source_line(&src, &title, &n, &line); /* the first line is the title */
    hx_adm_statement st;
    memset(&st, 0, sizeof st);
    int status = 0, ended = 0;
    while (status == 0 && !ended) {
        const int got = hx_adm_statement_next(&src, &st, r->d->msg);
        if (got < 0) {
            r->d->failed = 1;
            status = -1;
        } else if (got == 0) {
            hx_draft_fail(r->d, src.line - 1, "the dataset has no END statement (a dataset ends"
                          " with END; a file cut short would lose statements)");
            status = -1;
        } else {
            const int taken = take_statement(r, &st);
            if (taken < 0)
                status = -1;
            ended = taken == 1;
        }
    }
    hx_adm_statement_free(&st);
    return status;
}

/* Every id a statement names is a statement of the kind, and every USER
 * list parses. */
static int check_references(hx_adm_reader *r)
{
    for (int k = 0; k < r->nentries; ++k) {
        hx_adm_entry *e = &r->entries[k];
        const hx_adm_keyword *kw = e->spec->keywords;
        for (int i = 0; kw != NULL && kw[i].name != NULL; ++i) {
            const hx_adm_value *v = &e->values[i];
            if (!v->present)
                continue;
            if (kw[i].kind == HX_ADM_ID && kw[i].refers != NULL)
                for (int j = 0; j < v->count; ++j)
                    if (hx_adm_find(r, kw[i].refers, (int)v->numbers[j]) == NULL)
                        return hx_adm_fail(r, e, v->value_lines[j], "%s=%d (column %d) names no"
                                           " %s statement", kw[i].name, (int)v->numbers[j],
                                           v->value_columns[j], kw[i].refers);
            if (kw[i].kind == HX_ADM_EXPR && hx_adm_is_user(v->texts[0])) {
                double *par = NULL;
                int npar = 0;
                hx_message why;
                if (hx_parse_user_list(v->texts[0], &par, &npar, &why) != 0)
                    return hx_adm_fail(r, e, v->value_lines[0], "%s (column %d): %s", kw[i].name,
                                       v->value_columns[0], why.text);
                free(par);
            }
        }
    }
    return 0;
}

static int build_entries(hx_adm_reader *r)
{
    for (int k = 0; k < r->nentries; ++k) {
        hx_adm_entry *e = &r->entries[k];
        if (!e->unsimulated && e->spec->build != NULL && e->spec->build(r, e) != 0)
            return -1;
    }
    return 0;
}

/* A message of the XML builders or the resolve passes names the element it
 * became: the statement it came from goes in front ("file:line: JOINT/1:
 * Constraint_Joint 1: ..."). */
static void name_statement(hx_adm_reader *r, hx_message *msg)
{
    char head[HX_MESSAGE_MAX];
    const size_t n = strlen(r->path);
    if (strncmp(msg->text, r->path, n) != 0 || msg->text[n] != ':')
        return;
    char *end;
    const long line = strtol(msg->text + n + 1, &end, 10);
    /* an expression's "file:line:column: ": the statement it is in may have begun
     * lines before (the last to begin at or before it) */
    const int column = end[0] == ':' && end[1] >= '0' && end[1] <= '9';
    if (column)
        strtol(end + 1, &end, 10);
    if (end == msg->text + n + 1 || strncmp(end, ": ", 2) != 0)
        return;
    int within = -1;
    for (int k = 0; column && k < r->nentries; ++k)
        if (r->entries[k].line <= line)
            within = k;
    for (int k = 0; k < r->nentries; ++k) {
        const hx_adm_entry *e = &r->entries[k];
        char label[48];
        hx_adm_label(e, label, sizeof label);
        if ((column ? k != within : e->line != line) ||
            strncmp(end + 2, label, strlen(label)) == 0)
            continue;
        snprintf(head, sizeof head, "%.*s: %s: %s", (int)(end - msg->text), msg->text, label,
                 end + 2);
        memcpy(msg->text, head, sizeof head);
        return;
    }
}

hx_model *hx_dataset_read(const char *path, const char *text, size_t length, int from_file,
                          FILE *warnings, hx_message *msg)
{
    hx_draft d;
    if (hx_draft_open(&d, path, !from_file, warnings, msg) != 0)
        return hx_draft_finish(&d, -1);
    hx_adm_reader r;
    memset(&r, 0, sizeof r);
    r.d = &d;
    r.path = path;
    r.noted = calloc((size_t)hx_adm_statement_count, 1);
    int status = r.noted != NULL ? 0 : hx_fail(msg, "out of memory");
    if (status == 0)
        status = read_statements(&r, text, length);
    if (status == 0)
        status = index_entries(&r);
    if (status == 0)
        status = check_references(&r);
    if (status == 0)
        status = hx_adm_decide_simulated(&r);
    if (status == 0)
        status = build_entries(&r);
    if (status == 0)
        status = hx_adm_place_markers(&r);
    hx_model *m = hx_draft_finish(&d, status);
    if (m == NULL)
        name_statement(&r, msg);
    for (int k = 0; k < r.nentries; ++k) {
        hx_adm_values_free(r.entries[k].spec, r.entries[k].values);
        free(r.entries[k].buffer);
    }
    free(r.entries);
    free(r.slots);
    free(r.noted);
    return m;
}
