/* Statements into the XML reader's element builders (translate.h). */
#include "model/adm/translate.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/xml_schema.h"

void hx_adm_element_init(hx_adm_element *el, const char *name)
{
    el->name = name;
    el->n = 0;
}

void hx_adm_element_text(hx_adm_element *el, const char *attr, const char *text)
{
    if (el->n == HX_ADM_MAX_ATTRS || text == NULL)
        return;
    el->attr[el->n] = attr;
    el->text[el->n] = text;
    el->number[el->n] = 0.0;
    el->line[el->n] = el->column[el->n] = 0;
    el->n++;
}

void hx_adm_element_expression(hx_adm_element *el, const char *attr, const hx_adm_entry *e,
                               const char *keyword)
{
    const hx_adm_value *v = hx_adm_get(e, keyword);
    if (!v->present || el->n == HX_ADM_MAX_ATTRS)
        return;
    hx_adm_element_text(el, attr, v->texts[0]);
    el->line[el->n - 1] = v->value_lines[0];
    el->column[el->n - 1] = v->value_columns[0];
}

void hx_adm_element_number(hx_adm_element *el, const char *attr, double x)
{
    if (el->n == HX_ADM_MAX_ATTRS)
        return;
    el->attr[el->n] = attr;
    el->text[el->n] = NULL; /* formatted when the attribute is read as text */
    el->number[el->n] = x;
    el->line[el->n] = el->column[el->n] = 0;
    el->n++;
}

/* ROUTINE=[library::]name: 0, or -1 (failed) when it names no library
 * before "::" or nothing at all. */
static int split_routine(hx_adm_reader *r, const hx_adm_entry *e, const char *text,
                         char *library, char *name, size_t size)
{
    const char *sep = strstr(text, "::");
    library[0] = name[0] = '\0';
    if (sep == NULL) {
        snprintf(name, size, "%s", text);
    } else {
        snprintf(library, size, "%.*s", (int)(sep - text), text);
        snprintf(name, size, "%s", sep + 2);
        if (library[0] == '\0')
            return hx_adm_fail(r, e, hx_adm_get(e, "ROUTINE")->line, "ROUTINE=%s names no"
                               " library before '::' (ROUTINE=library::name, library:: for the"
                               " routine's own name, or name alone for the default library)",
                               text);
    }
    if (library[0] == '\0' && name[0] == '\0')
        return hx_adm_fail(r, e, hx_adm_get(e, "ROUTINE")->line, "ROUTINE names no routine");
    return 0;
}

int hx_adm_element_user(hx_adm_reader *r, const hx_adm_entry *e, hx_adm_element *el,
                        const char *const *der_attrs)
{
    const char *function = hx_adm_text(e, "FUNCTION");
    if (function != NULL)
        hx_adm_element_text(el, "usrsub_param_string", function);
    const hx_adm_value *routine = hx_adm_get(e, "ROUTINE");
    if (!routine->present)
        return 0;
    int nder = 0;
    while (der_attrs != NULL && der_attrs[nder] != NULL)
        ++nder;
    if (routine->count > 1 + nder)
        return hx_adm_fail(r, e, routine->line, "ROUTINE names %d routines; this statement takes"
                           " %d", routine->count, 1 + nder);
    /* the names live in the element's storage while it is built */
    static const size_t size = sizeof el->storage[0];
    char library[256], first_library[256];
    for (int k = 0; k < routine->count; ++k) {
        char name[256];
        if (split_routine(r, e, routine->texts[k], library, name, sizeof name) != 0)
            return -1;
        if (k == 0)
            memcpy(first_library, library, sizeof library);
        else if (library[0] != '\0' && strcmp(library, first_library) != 0)
            return hx_adm_fail(r, e, routine->line, "ROUTINE names two libraries (%s, %s): an"
                               " element's routines come from one", first_library, library);
        if (strlen(library) >= size || strlen(name) >= size)
            return hx_adm_fail(r, e, routine->line, "ROUTINE=%s: a name longer than %zu"
                               " characters", routine->texts[k], size - 1);
        if (el->n + 2 > HX_ADM_MAX_ATTRS)
            return hx_adm_fail(r, e, routine->line, "too many attributes");
        if (k == 0 && library[0] != '\0') {
            snprintf(el->storage[el->n], size, "%s", library);
            hx_adm_element_text(el, "usrsub_dll_name", el->storage[el->n]);
        }
        if (name[0] != '\0') {
            snprintf(el->storage[el->n], size, "%s", name);
            hx_adm_element_text(el, k == 0 ? "usrsub_fnc_name" : der_attrs[k - 1],
                                el->storage[el->n]);
        }
    }
    return 0;
}

int hx_adm_element_build(hx_adm_reader *r, const hx_adm_entry *e, hx_adm_element *el,
                         const char *data)
{
    const hx_element_spec *spec = NULL;
    for (int k = 0; k < hx_element_spec_count && spec == NULL; ++k)
        if (strcmp(hx_element_specs[k].name, el->name) == 0)
            spec = &hx_element_specs[k];
    hx_element_read x;
    memset(&x, 0, sizeof x);
    x.name = el->name;
    x.line = e->line;
    x.id = e->id;
    x.spec = spec != NULL ? spec->attrs : NULL;
    while (x.spec != NULL && x.spec[x.nspec].name != NULL && x.nspec < HX_MAX_ATTRS)
        ++x.nspec;
    for (int i = 0; i < el->n && spec != NULL; ++i) {
        const int k = hx_attr_find(&x, el->attr[i]);
        if (k < 0) {
            spec = NULL;
            break;
        }
        x.value[k].present = 1;
        if (el->text[i] == NULL) { /* a number: the builders read numeric attributes as numbers */
            if (x.spec[k].kind == HX_ATTR_TEXT || x.spec[k].kind == HX_ATTR_IGNORED)
                snprintf(el->storage[i], sizeof el->storage[0], "%.17g", el->number[i]);
            else
                el->storage[i][0] = '\0';
            el->text[i] = el->storage[i];
        }
        x.value[k].text = el->text[i];
        x.value[k].number = el->number[i];
        x.value[k].line = el->line[i];
        x.value[k].column = el->column[i];
        if (x.spec[k].kind == HX_ATTR_BOOL)
            x.value[k].number = strcmp(el->text[i], "TRUE") == 0;
    }
    if (spec == NULL || spec->build == NULL)
        return hx_adm_fail(r, e, e->line, "the harness's translation to %s is wrong (a bug)",
                           el->name);
    spec->build(r->d, &x);
    if (!r->d->failed && data != NULL && spec->text != NULL)
        spec->text(r->d, e->line, data);
    return r->d->failed ? -1 : 0;
}

int hx_adm_no_routine(hx_adm_reader *r, const hx_adm_entry *e)
{
    if (!hx_adm_has(e, "ROUTINE"))
        return 0;
    return hx_adm_fail(r, e, hx_adm_get(e, "ROUTINE")->line, "ROUTINE without"
                       " FUNCTION=USER(...)");
}
