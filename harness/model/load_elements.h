/*
 * The loads the harness computes itself (docs/interface.md §7.1): a
 * Force_Vector_OneBody, a Force_Vector_TwoBody given by expressions and a
 * Force_Scalar_TwoBody given by a value, each component a function
 * expression (§8) parsed once when the element is read and linked against
 * the model once it is whole.
 */
#ifndef HX_MODEL_LOAD_ELEMENTS_H
#define HX_MODEL_LOAD_ELEMENTS_H

#include "model/xml_schema.h"

/* A vector load on the marker i_id by e's fx_expression .. tz_expression, in
 * ref_id's axes (0: the world's); j_id, when not 0, the marker whose body
 * takes the reaction (a Force_Vector_TwoBody). */
void hx_build_vector_load(hx_draft *d, const hx_element_read *e, int i_id, int j_id, int ref_id);

/* A Force_Scalar_TwoBody by its value_attr (val or val_expression). */
void hx_build_scalar_load(hx_draft *d, const hx_element_read *e, int torque,
                          const char *value_attr);

/* Attribute `name` of e parsed by the expression engine into *out (NULL when
 * absent), from the attribute's place in the file; 0, or -1 with the draft
 * failed naming the element, the attribute and file:line:column. */
struct hx_expr_program;
int hx_draft_parse_expression(hx_draft *d, const hx_element_read *e, const char *name,
                              struct hx_expr_program **out);
/* The engine's "file:line:column: what" as "file:line:column: element id:
 * attribute: what" (the draft's first error wins). */
void hx_draft_fail_expression(hx_draft *d, const char *element, int id, const char *attr,
                              const char *text);

/* Links every load's expressions against the model (its markers resolved),
 * marks the markers they measure tracked, and refuses what a force
 * expression cannot read yet; 0, or -1 with the draft failed. */
int hx_draft_link_loads(hx_draft *d);

#endif
