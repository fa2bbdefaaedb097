/*
 * The joints' elements of the XML reader (joint_elements.c): their attribute
 * lists and builders for the table of elements (elements.c).
 */
#ifndef HX_MODEL_JOINT_ELEMENTS_H
#define HX_MODEL_JOINT_ELEMENTS_H

#include "model/xml_schema.h"

/* Constraint_Joint's and Constraint_Jprim's attributes (one list). */
extern const hx_attr_spec hx_joint_attrs[];

void hx_build_joint(hx_draft *d, const hx_element_read *e);
void hx_build_jprim(hx_draft *d, const hx_element_read *e);

#endif
