/*
 * The general constraints (docs/interface.md §7.16): a Constraint_General
 * element, or an Adams GCON statement translated into one, an expression
 * the motion holds at zero. Its expression is parsed where it is written and
 * linked once the model is whole; what it reads is checked there (the
 * markers' displacements and rotations and TIME). Private to the model layer.
 */
#ifndef HX_MODEL_GCON_ELEMENTS_H
#define HX_MODEL_GCON_ELEMENTS_H

#include "model/xml_schema.h"

extern const hx_attr_spec hx_gcon_attrs[];
/* A Constraint_General: id, expr, the optional i_marker_id. */
void hx_build_gcon(hx_draft *d, const hx_element_read *e);

#endif
