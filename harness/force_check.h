/*
 * Checks of force elements for usrsub-harness check:
 *  - FIESUB: dfddis and dfdvel against central differences of the field at
 *    the initial state and at sampled deformations around it (0.5 to 10 mm and
 *    0.01 to 0.2 rad, in the model's units), column by column;
 *  - GFOSUB: a dependency audit. Every body state (position, orientation,
 *    velocity, angular velocity) the force depends on, by finite differences,
 *    must be reached by a query declared in the dependency pass; every
 *    declared query must change the force, at one of the sampled states at
 *    least, when its answer changes; and no query may be made outside the
 *    declared ones.
 * Each prints its findings and returns 0 (pass) or 1.
 */
#ifndef HX_FORCE_CHECK_H
#define HX_FORCE_CHECK_H

#include "binding.h"
#include "session.h"

int hx_check_field_partials(hx_session *s, hx_binding *b);
int hx_audit_dependencies(hx_session *s, hx_binding *b);

/* Sampled state k (0: the element's state at the session's frames). */
void hx_sample_element_state(const hx_session *s, int force, int k, double disp[6],
                             double velo[6], double scale[12]);

#define HX_FORCE_SAMPLES 12

#endif
