/*
 * The requests the harness answers itself (request_elements.h,
 * docs/interface.md §7.13): built by both readers through one builder,
 * their expressions parsed where they are written and linked once the model
 * is resolved.
 */
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "model/marker_elements.h"
#include "model/request_elements.h"

hx_request *hx_draft_request(hx_draft *d, int id, enum hx_request_kind kind,
                             const int marker_ids[3], int line, const char *label)
{
    hx_model *m = d->m;
    for (int k = 0; k < m->nrequests; ++k)
        if (m->requests[k].id == id) {
            hx_draft_fail(d, line, "%s is defined twice (line %d)", label, m->requests[k].line);
            return NULL;
        }
    hx_request *q = hx_draft_push(d, (void **)&m->requests, &m->nrequests, &d->cap_requests,
                                  sizeof *q, NULL, 0);
    if (q == NULL)
        return NULL;
    q->id = id;
    q->kind = kind;
    q->line = line;
    for (int k = 0; k < 3; ++k) {
        q->marker_ids[k] = marker_ids != NULL ? marker_ids[k] : 0;
        q->markers[k] = -1;
    }
    snprintf(q->label, sizeof q->label, "%s", label);
    return q;
}

static void component_name(const hx_request *q, int k, char *out, size_t size)
{
    snprintf(out, size, q->adams ? "F%d" : "expr%d", k + 1);
}

/* The engine's "file:line:column: what" with "LABEL COMPONENT: " put after
 * the place, as the draft's first failure. */
static void fail_at_place(hx_draft *d, const hx_request *q, int k, const hx_message *engine)
{
    if (d->failed)
        return;
    char name[16];
    component_name(q, k, name, sizeof name);
    const char *text = engine->text;
    const size_t n = strlen(d->path);
    const char *what = text;
    if (strncmp(text, d->path, n) == 0) { /* past "path:line:column: " */
        const char *p = text + n;
        for (int colons = 0; *p != '\0' && colons < 3; ++p)
            if (*p == ':')
                ++colons;
        what = *p == ' ' ? p + 1 : text;
    }
    if (what == text)
        hx_fail(d->msg, "%s:%d: %s %s: %s", d->path, q->line, q->label, name, text);
    else
        hx_fail(d->msg, "%.*s%s %s: %s", (int)(what - text), text, q->label, name, what);
    d->failed = 1;
}

static int blank_or_null(const char *text)
{
    while (isspace((unsigned char)*text))
        ++text;
    if (strncasecmp(text, "NULL", 4) == 0)
        text += 4;
    while (isspace((unsigned char)*text))
        ++text;
    return *text == '\0';
}

int hx_draft_request_expression(hx_draft *d, hx_request *q, int k, const char *text,
                                const hx_expr_source *where, const char *label)
{
    (void)label;
    if (text == NULL || blank_or_null(text))
        return 0;
    hx_message why;
    q->f[k] = hx_expr_parse(text, strlen(text), where, &why);
    if (q->f[k] == NULL) {
        fail_at_place(d, q, k, &why);
        return -1;
    }
    return 0;
}

void hx_build_builtin_request(hx_draft *d, const hx_element_read *e)
{
    char label[32];
    snprintf(label, sizeof label, "%s %d", e->name, e->id);
    const char *type = hx_attr_text(e, "type");
    if (type == NULL) {
        hx_draft_fail(d, e->line, "%s: attribute type is missing (MARKER_DISPLACEMENT,"
                      " MARKER_VELOCITY, MARKER_ACCELERATION, EXPRESSION, or USERSUB with a user"
                      " routine)", label);
        return;
    }
    static const char *const refused[][2] = {
        {"ELEMENTAL_FORCE", "the forces of an element by its type are not answered by the harness"
         " (a force element's loads are the CSV's forceID columns)"},
    };
    for (size_t k = 0; k < sizeof refused / sizeof refused[0]; ++k)
        if (strcasecmp(type, refused[k][0]) == 0) {
            hx_draft_fail(d, e->line, "%s: type \"%s\": %s", label, type, refused[k][1]);
            return;
        }
    const int expressions = strcasecmp(type, "EXPRESSION") == 0;
    const int displacement = strcasecmp(type, "MARKER_DISPLACEMENT") == 0;
    const int acceleration = strcasecmp(type, "MARKER_ACCELERATION") == 0;
    const int force = strcasecmp(type, "MARKER_FORCE") == 0;
    if (!expressions && !displacement && !acceleration && !force &&
        strcasecmp(type, "MARKER_VELOCITY") != 0) {
        hx_draft_fail(d, e->line, "%s: type \"%s\": expected MARKER_DISPLACEMENT, MARKER_VELOCITY,"
                      " MARKER_ACCELERATION, MARKER_FORCE, EXPRESSION, or USERSUB with a user"
                      " routine", label, type);
        return;
    }
    static const char *const markers[3] = {"i_marker_id", "j_marker_id", "ref_marker_id"};
    static const char *const exprs[8] = {"expr1", "expr2", "expr3", "expr4",
                                         "expr5", "expr6", "expr7", "expr8"};
    for (int k = 0; k < (expressions ? 3 : 8); ++k) {
        const char *attr = expressions ? markers[k] : exprs[k];
        if (hx_attr_present(e, attr) && !(!expressions && blank_or_null(hx_attr_text(e, attr)))) {
            hx_draft_fail(d, e->line, "%s: type \"%s\" takes no %s", label, type, attr);
            return;
        }
    }
    int ids[3] = {0, 0, 0};
    if (!expressions) {
        if (!hx_attr_present(e, "i_marker_id")) {
            hx_draft_fail(d, e->line, "%s: attribute i_marker_id is missing", label);
            return;
        }
        for (int k = 0; k < 3; ++k)
            ids[k] = hx_attr_int(e, markers[k], 0);
    }
    hx_request *q = hx_draft_request(d, e->id, expressions ? HX_REQUEST_EXPRESSIONS
                                     : displacement ? HX_REQUEST_DISPLACEMENT
                                     : acceleration ? HX_REQUEST_ACCELERATION
                                     : force        ? HX_REQUEST_FORCE
                                                    : HX_REQUEST_VELOCITY, ids, e->line, label);
    if (q == NULL || !expressions)
        return;
    /* an attribute's place is its element's line; the column counts in its value */
    const hx_expr_source where = {d->path, e->line, 1};
    for (int k = 0; k < 8; ++k)
        if (hx_draft_request_expression(d, q, k, hx_attr_text(e, exprs[k]), &where, label) != 0)
            return;
}

int hx_draft_resolve_requests(hx_draft *d)
{
    hx_model *m = d->m;
    static const char *const xml_names[3] = {"i_marker_id", "j_marker_id", "ref_marker_id"};
    static const char *const adams_names[3] = {"I", "J", "RM"};
    for (int k = 0; k < m->nrequests; ++k) {
        hx_request *q = &m->requests[k];
        const int routine = hx_model_routine(m, HX_ROUTINE_REQUEST, q->id);
        if (routine >= 0) { /* the two would write the same columns */
            hx_draft_fail(d, q->line, "%s: a request with a user routine has the same id (line"
                          " %d)", q->label, m->routines[routine].line);
            return -1;
        }
        for (int j = 0; j < 3 && q->kind != HX_REQUEST_EXPRESSIONS; ++j) {
            const int id = q->marker_ids[j];
            if (id == 0 && j > 0)
                continue; /* J and RM left out: the ground's origin, the world's axes */
            if (id <= 0 || (q->markers[j] = hx_model_marker(m, id)) < 0) {
                hx_draft_fail(d, q->line, "%s: %s=%d: no %s %d in the model", q->label,
                              q->adams ? adams_names[j] : xml_names[j], id,
                              q->adams ? "MARKER" : "Reference_Marker", id);
                return -1;
            }
        }
        char what[128];
        if (q->kind == HX_REQUEST_FORCE && q->markers[1] >= 0 &&
            hx_marker_unsummed(m, q->markers[0], q->markers[1], what, sizeof what)) {
            hx_draft_fail(d, q->line, "%s: FORCE: %s acts between I=%d and J=%d, and the harness"
                          " does not sum its force at a marker yet", q->label, what,
                          q->marker_ids[0], q->marker_ids[1]);
            return -1;
        }
        for (int j = 0; j < 8; ++j) {
            hx_message why;
            if (q->f[j] != NULL && hx_expr_link_output(q->f[j], m, &why) != 0) {
                fail_at_place(d, q, j, &why);
                return -1;
            }
        }
    }
    return 0;
}
