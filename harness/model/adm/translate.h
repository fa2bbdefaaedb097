/*
 * A statement translated into the MotionSolve XML element it stands for, as
 * MotionSolve's own pre-processor translates a dataset into XML, and built
 * by the XML reader's builder of that element (elements.c and the files of
 * its table): one builder per concept, whichever file the model came from.
 */
#ifndef HX_MODEL_ADM_TRANSLATE_H
#define HX_MODEL_ADM_TRANSLATE_H

#include "model/adm/reader.h"

#define HX_ADM_MAX_ATTRS 128 /* as the XML reader's (a linear FIELD: 72 matrix entries) */

typedef struct hx_adm_element {
    const char *name;          /* the XML element, e.g. "Body_Rigid" */
    int n;
    const char *attr[HX_ADM_MAX_ATTRS];
    const char *text[HX_ADM_MAX_ATTRS];
    double number[HX_ADM_MAX_ATTRS];
    int line[HX_ADM_MAX_ATTRS], column[HX_ADM_MAX_ATTRS]; /* an expression's place, else 0 */
    char storage[HX_ADM_MAX_ATTRS][32];
} hx_adm_element;

void hx_adm_element_init(hx_adm_element *el, const char *name);
void hx_adm_element_text(hx_adm_element *el, const char *attr, const char *text);
/* An expression: the entry's keyword's text, with where it begins (for the
 * engine's file:line:column); nothing when the keyword is absent. */
void hx_adm_element_expression(hx_adm_element *el, const char *attr, const hx_adm_entry *e,
                               const char *keyword);
void hx_adm_element_number(hx_adm_element *el, const char *attr, double x);
/* usrsub_param_string from the entry's FUNCTION=USER(...), usrsub_dll_name and
 * usrsub_fnc_name from its ROUTINE=[library::]name, and the further
 * routines' names into der_attrs[0..] (NULL-terminated); 0 or -1 (failed). */
int hx_adm_element_user(hx_adm_reader *r, const hx_adm_entry *e, hx_adm_element *el,
                        const char *const *der_attrs);
/* An entry not calling a user routine (no FUNCTION=USER(...)) must not name
 * one: a ROUTINE= is an error at its line; 0, or -1 (failed). */
int hx_adm_no_routine(hx_adm_reader *r, const hx_adm_entry *e);
/* Builds the element into the draft for the entry (its line and id); 0, or
 * -1 with the draft failed. With data, the element's text between its tags
 * too (Reference_Array's numbers, Reference_Spline's points). */
int hx_adm_element_build(hx_adm_reader *r, const hx_adm_entry *e, hx_adm_element *el,
                         const char *data);

#endif
