/*
 * The user routines that are not forces (docs/interface.md §7.12): the
 * descriptions and builders of Post_Request (REQSUB), Control_Diff (DIFSUB)
 * and Motion_Joint (MOTSUB) in their user form, the USERSUB form of
 * Reference_Variable (VARSUB, read through hx_build_variable), and their
 * resolve pass.
 */
#ifndef HX_MODEL_ROUTINE_ELEMENTS_H
#define HX_MODEL_ROUTINE_ELEMENTS_H

#include "model/xml_schema.h"

extern const hx_attr_spec hx_request_attrs[];
void hx_build_request(hx_draft *d, const hx_element_read *e);

extern const hx_attr_spec hx_diff_attrs[];
void hx_build_diff(hx_draft *d, const hx_element_read *e);

extern const hx_attr_spec hx_motion_attrs[];
void hx_build_motion(hx_draft *d, const hx_element_read *e);

/* A Reference_Variable of type USERSUB. */
void hx_build_user_variable(hx_draft *d, const hx_element_read *e);

#endif
