/*
 * The descriptions and builders of the state-equation elements
 * (docs/interface.md §7.10): Force_StateEqn, the Reference_Array elements it
 * names (its states X, its inputs U, its initial states IC; Y arrays are read
 * and unused) and the Reference_Variable elements of its U array. Rows of
 * the element table (elements.c); their references are resolved by
 * hx_draft_resolve_stateeqns once the whole file is read.
 */
#ifndef HX_MODEL_STATEEQN_ELEMENTS_H
#define HX_MODEL_STATEEQN_ELEMENTS_H

#include "model/xml_schema.h"

extern const hx_attr_spec hx_stateeqn_attrs[];
void hx_build_stateeqn(hx_draft *d, const hx_element_read *e);

extern const hx_attr_spec hx_array_attrs[];
void hx_build_array(hx_draft *d, const hx_element_read *e);
/* The numbers (IC) or variable ids (U) written between the array's tags. */
void hx_array_text(hx_draft *d, int line, const char *text);

extern const hx_attr_spec hx_variable_attrs[];
void hx_build_variable(hx_draft *d, const hx_element_read *e);

#endif
