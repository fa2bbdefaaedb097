/*
 * The MotionSolve XML reader (expat): every element is checked against its
 * description (xml_schema.h) by one generic routine, then built into the
 * draft model, then the references are resolved (resolve.c). Element and
 * attribute names are matched case-insensitively, as MotionSolve does. An
 * attribute the harness does not read is an error: it could move a marker
 * or change a force, and a verifier must never go on with different physics
 * than the model says.
 */
#include <errno.h>
#include <expat.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "model/readers.h"
#include "model/xml_schema.h"

typedef struct xml_reader {
    hx_draft d;
    XML_Parser parser;
    int depth;                     /* of the element open now */
    const hx_element_spec *texted; /* the element whose text is being collected, or NULL */
    int text_depth, text_line;
    char *text;                    /* its text so far */
    size_t text_length, text_capacity;
} xml_reader;

static int parse_number(const char *text, double *out)
{
    char *end;
    errno = 0;
    const double v = strtod(text, &end);
    if (end == text || errno == ERANGE || !isfinite(v))
        return -1;
    while (*end == ' ' || *end == '\t' || *end == '\n' || *end == '\r')
        ++end;
    if (*end != '\0')
        return -1;
    *out = v;
    return 0;
}

/* Reads one attribute into e by its description; 0 or -1 (the draft failed). */
static int read_value(hx_draft *d, hx_element_read *e, int k, const char *text)
{
    const hx_attr_spec *a = &e->spec[k];
    e->value[k].present = 1;
    e->value[k].text = text;
    double v = 0.0;
    switch (a->kind) {
    case HX_ATTR_REAL:
        if (parse_number(text, &v) != 0) {
            hx_draft_fail(d, e->line, "%s: attribute %s = \"%s\" is not a finite number"
                          " (expressions are not read here)", e->name, a->name, text);
            return -1;
        }
        break;
    case HX_ATTR_INT:
        if (parse_number(text, &v) != 0 || v != floor(v) || fabs(v) > INT_MAX) {
            hx_draft_fail(d, e->line, "%s: attribute %s = \"%s\" is not an integer", e->name,
                          a->name, text);
            return -1;
        }
        break;
    case HX_ATTR_BOOL:
        if (strcasecmp(text, "TRUE") == 0)
            v = 1.0;
        else if (strcasecmp(text, "FALSE") != 0) {
            hx_draft_fail(d, e->line, "%s: attribute %s = \"%s\": expected TRUE or FALSE",
                          e->name, a->name, text);
            return -1;
        }
        break;
    case HX_ATTR_TEXT:
    case HX_ATTR_IGNORED:
        break;
    }
    e->value[k].number = v;
    return 0;
}

/* The generic part of every element: its attributes against its description. */
static int read_element(hx_draft *d, const hx_element_spec *spec, const XML_Char **atts,
                        hx_element_read *e)
{
    e->nspec = 0;
    while (spec->attrs[e->nspec].name != NULL && e->nspec < HX_MAX_ATTRS)
        ++e->nspec;
    e->spec = spec->attrs;
    const char *id_text = NULL;
    for (int k = 0; atts[k] != NULL; k += 2)
        if (strcasecmp(atts[k], "id") == 0)
            id_text = atts[k + 1];
    const int id_spec = hx_attr_find(e, "id");
    if (id_spec >= 0 && (e->spec[id_spec].required || id_text != NULL)) {
        double id;
        if (id_text == NULL || parse_number(id_text, &id) != 0 || id != floor(id) || id <= 0 ||
            id > INT_MAX) {
            hx_draft_fail(d, e->line, "%s: id \"%s\" must be a positive integer", e->name,
                          id_text ? id_text : "(missing)");
            return -1;
        }
        e->id = (int)id;
    }
    char label[96];
    snprintf(label, sizeof label, e->id ? "%s %d" : "%s", e->name, e->id);
    for (int k = 0; atts[k] != NULL; k += 2) {
        const int a = hx_attr_find(e, atts[k]);
        if (a < 0) {
            hx_draft_fail(d, e->line, "%s: attribute %s is not one the harness reads (it could"
                          " change the model; docs/interface.md §7 lists what it reads)", label, atts[k]);
            return -1;
        }
        if (read_value(d, e, a, atts[k + 1]) != 0) {
            hx_message_prefix(d->msg, "%s", label);
            return -1;
        }
    }
    for (int k = 0; k < e->nspec; ++k)
        if (e->spec[k].required && !e->value[k].present) {
            hx_draft_fail(d, e->line, "%s: attribute %s is missing", label, e->spec[k].name);
            return -1;
        }
    e->name = spec->name;
    return 0;
}

/* The element names a user routine (a library or a USER list). */
static int has_user_call(const XML_Char **atts)
{
    for (int k = 0; atts[k] != NULL; k += 2)
        if (strcasecmp(atts[k], "usrsub_dll_name") == 0 ||
            strcasecmp(atts[k], "usrsub_param_string") == 0)
            return 1;
    return 0;
}

static void XMLCALL on_start(void *data, const XML_Char *name, const XML_Char **atts)
{
    xml_reader *r = data;
    hx_draft *d = &r->d;
    r->depth++;
    if (d->failed)
        return;
    const int line = (int)XML_GetCurrentLineNumber(r->parser);
    for (int k = 0; k < hx_element_spec_count; ++k) {
        const hx_element_spec *spec = &hx_element_specs[k];
        if (strcasecmp(spec->name, name) != 0 || (spec->user_form_only && !has_user_call(atts)))
            continue;
        if (spec->build == NULL)
            return; /* a container */
        hx_element_read e;
        memset(&e, 0, sizeof e);
        e.name = spec->name;
        e.line = line;
        if (read_element(d, spec, atts, &e) == 0)
            spec->build(d, &e);
        if (spec->text != NULL && !d->failed) { /* its data, up to its end tag */
            r->texted = spec;
            r->text_depth = r->depth;
            r->text_line = line;
            r->text_length = 0;
        }
        return;
    }
    if (hx_element_is_output_only(name))
        return;
    /* an element the harness does not model: check can still verify the user
     * elements; a run would be different physics */
    const char *id = NULL;
    for (int k = 0; atts[k] != NULL; k += 2)
        if (strcasecmp(atts[k], "id") == 0)
            id = atts[k + 1];
    hx_draft_warn(d, line, "element <%s%s%s> is not modelled by the harness: check verifies the"
                  " user elements, run and bench refuse the model", name, id ? " id=" : "",
                  id ? id : "");
    if (d->m->nunsimulated++ == 0)
        snprintf(d->m->unsimulated, sizeof d->m->unsimulated, "%s%s%s (line %d)", name,
                 id ? " " : "", id ? id : "", line);
}

/* The text of an element whose data is read (Reference_Array). */
static void XMLCALL on_text(void *data, const XML_Char *text, int length)
{
    xml_reader *r = data;
    if (r->texted == NULL || r->d.failed || length <= 0)
        return;
    if (r->text_length + (size_t)length + 1 > r->text_capacity) {
        const size_t capacity = 2 * (r->text_length + (size_t)length + 1);
        char *grown = realloc(r->text, capacity);
        if (grown == NULL) {
            hx_draft_fail(&r->d, r->text_line, "out of memory");
            return;
        }
        r->text = grown;
        r->text_capacity = capacity;
    }
    memcpy(r->text + r->text_length, text, (size_t)length);
    r->text_length += (size_t)length;
}

static void XMLCALL on_end(void *data, const XML_Char *name)
{
    (void)name;
    xml_reader *r = data;
    if (r->texted != NULL && r->depth == r->text_depth) {
        const hx_element_spec *spec = r->texted;
        r->texted = NULL;
        if (r->text != NULL)
            r->text[r->text_length] = '\0'; /* the buffer always has room for it */
        if (!r->d.failed)
            spec->text(&r->d, r->text_line, r->text != NULL ? r->text : "");
    }
    r->depth--;
}

/* Feeds the XML to expat: from the file at d->path, or from text when not NULL. */
static int parse_source(xml_reader *r, const char *text, size_t length)
{
    hx_draft *d = &r->d;
    FILE *f = NULL;
    if (text == NULL) {
        struct stat st;
        if (stat(d->path, &st) == 0 && S_ISDIR(st.st_mode))
            return hx_fail(d->msg, "%s is a folder, not a model file (give the path of a"
                           " MotionSolve XML file)", d->path);
        if ((f = fopen(d->path, "rb")) == NULL)
            return hx_fail(d->msg, "%s: cannot open the model: %s", d->path, strerror(errno));
    }
    r->parser = XML_ParserCreate(NULL);
    if (r->parser == NULL) {
        if (f != NULL)
            fclose(f);
        return hx_fail(d->msg, "%s: out of memory", d->path);
    }
    XML_SetUserData(r->parser, r);
    XML_SetStartElementHandler(r->parser, on_start);
    XML_SetEndElementHandler(r->parser, on_end);
    XML_SetCharacterDataHandler(r->parser, on_text);
    char buffer[16384];
    size_t offset = 0;
    int done = 0;
    while (!done && !d->failed) {
        size_t n;
        if (f != NULL) {
            n = fread(buffer, 1, sizeof buffer, f);
            if (ferror(f)) {
                hx_draft_fail(d, 0, "cannot read the model: %s", strerror(errno));
                break;
            }
            done = n < sizeof buffer;
        } else {
            n = length - offset < sizeof buffer ? length - offset : sizeof buffer;
            memcpy(buffer, text + offset, n);
            offset += n;
            done = offset == length;
        }
        if (XML_Parse(r->parser, buffer, (int)n, done) == XML_STATUS_ERROR && !d->failed)
            hx_draft_fail(d, (int)XML_GetCurrentLineNumber(r->parser), "malformed XML: %s",
                          XML_ErrorString(XML_GetErrorCode(r->parser)));
    }
    XML_ParserFree(r->parser);
    r->parser = NULL;
    if (f != NULL)
        fclose(f);
    return d->failed ? -1 : 0;
}

static hx_model *read_model(const char *path, const char *text, size_t length, FILE *warnings,
                            hx_message *msg)
{
    xml_reader r;
    memset(&r, 0, sizeof r);
    int status = hx_draft_open(&r.d, path, text != NULL, warnings, msg);
    if (status == 0)
        status = parse_source(&r, text, length);
    free(r.text);
    return hx_draft_finish(&r.d, status);
}

hx_model *hx_xml_read(const char *path, const char *text, size_t length, FILE *warnings,
                      hx_message *msg)
{
    return read_model(path, text, length, warnings, msg);
}
