/*
 * The descriptions of the XML elements the harness reads: for each element
 * its attributes (name, kind, required or not) and the step that builds it
 * into the draft model. One generic reader (xml_reader.c) checks every
 * element against its description, so that a new element is a row of the
 * table in elements.c and a resolve step.
 */
#ifndef HX_MODEL_XML_SCHEMA_H
#define HX_MODEL_XML_SCHEMA_H

#include "model/draft.h"

typedef enum hx_attr_kind {
    HX_ATTR_REAL,    /* a finite number */
    HX_ATTR_INT,     /* an integer */
    HX_ATTR_TEXT,    /* any text, taken as written */
    HX_ATTR_BOOL,    /* TRUE or FALSE */
    HX_ATTR_IGNORED  /* read and without effect on what the harness computes */
} hx_attr_kind;

typedef struct hx_attr_spec {
    const char *name;
    hx_attr_kind kind;
    int required;
} hx_attr_spec;

#define HX_MAX_ATTRS 128 /* a linear Force_Field's 96 (72 matrix entries): test_model_reader
                          * holds every description below it */

/* An element as read: the value of each described attribute. */
typedef struct hx_element_read {
    const char *name; /* as the description spells it */
    int line;
    int id;           /* 0 for elements without one */
    const hx_attr_spec *spec;
    int nspec;
    struct {
        int present;
        double number;    /* REAL, INT, BOOL (1 TRUE, 0 FALSE) */
        const char *text; /* as written */
        int line, column; /* where the text begins, when its reader knows (a dataset's
                           * expression); 0: the element's line, column 1 of the value */
    } value[HX_MAX_ATTRS];
} hx_element_read;

typedef struct hx_element_spec {
    const char *name;
    const hx_attr_spec *attrs; /* ends with a NULL name */
    /* NULL: a container (MotionSolve, Model) */
    void (*build)(hx_draft *d, const hx_element_read *e);
    /* elements with data between their tags (Reference_Array): called at the
     * end tag with the text, once the element was built; NULL: none read */
    void (*text)(hx_draft *d, int line, const char *text);
    /* 1: read only in its user-routine form (usrsub_dll_name or
     * usrsub_param_string present); the other forms go on as unread */
    int user_form_only;
} hx_element_spec;

/* The table (elements.c), and the elements read and skipped: those that do
 * not act on the dynamics (outputs, solver settings) are skipped with a
 * note; any other is named in a warning and marks the model unsimulated. */
extern const hx_element_spec hx_element_specs[];
extern const int hx_element_spec_count;
int hx_element_is_output_only(const char *name);

/* Access to an element's attributes by name (the description's spelling;
 * element_attributes.c): hx_attr_find gives its place in the description, or
 * -1 when the description has no such attribute. */
int hx_attr_find(const hx_element_read *e, const char *name);
int hx_attr_present(const hx_element_read *e, const char *name);
double hx_attr_number(const hx_element_read *e, const char *name, double fallback);
int hx_attr_int(const hx_element_read *e, const char *name, int fallback);
const char *hx_attr_text(const hx_element_read *e, const char *name);

/* The user-subroutine attributes of an element (usrsub_param_string, the
 * library, the function names) into u; 0, or -1 with the draft failed. */
int hx_draft_user_call(hx_draft *d, const hx_element_read *e, hx_user_call *u);

#endif
