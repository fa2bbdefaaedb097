/*
 * The dependency pass: every element called once with iflag set, at the
 * model's initial state, as a solver does before an analysis; each
 * GFOSUB-style element declares there the state queries it makes (host/call.h).
 */
#ifndef HX_HOST_DEPENDENCY_PASS_H
#define HX_HOST_DEPENDENCY_PASS_H

#include "host/binding.h"

/* Every element's pass at frames fr; what the library kept allocated across an
 * element's pass goes to its setup_bytes; a non-finite output is a warning.
 * Returns -1 when an element stopped the run (or memory ran out). */
int hx_dependency_passes(hx_bindings *b, const hx_frames *fr);

#endif
