/*
 * The description and builder of Reference_Spline (docs/interface.md §7.11):
 * a curve given by its x y pairs between the element's tags, checked and
 * made ready for c_akispl and c_cubspl (its knot slopes by both methods)
 * when its end tag is read. A row of the element table (elements.c).
 */
#ifndef HX_MODEL_SPLINE_ELEMENTS_H
#define HX_MODEL_SPLINE_ELEMENTS_H

#include "model/xml_schema.h"

extern const hx_attr_spec hx_spline_attrs[];
void hx_build_spline(hx_draft *d, const hx_element_read *e);
/* The x y pairs written between the spline's tags. */
void hx_spline_text(hx_draft *d, int line, const char *text);

#endif
