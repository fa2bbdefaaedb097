/*
 * The rig for a Force_StateEqn: its I marker is driven relative to its J
 * marker along a deformation path (tools/rig/rig_path.h) without dynamics,
 * its inputs measured at each point by the harness, and its states
 * integrated along the path by BDF (CVODE, with YFOXX for the Newton matrix
 * or differences of YFOSUB where the library does not export it), so that
 * force against deformation shows the element's hysteresis (friction,
 * rubber). CSV rows at every rig step: t, deformation (6), rate (6), the
 * outputs on I in the ref_marker's axes (6), the states.
 */
#ifndef HX_TOOLS_RIG_STATEEQN_RIG_H
#define HX_TOOLS_RIG_STATEEQN_RIG_H

#include "sim/ode/integrator.h"
#include "tools/rig/rig.h"

typedef struct hx_stateeqn_rig_result {
    hx_integrator_stats stats; /* the states' integration (none without states) */
    double work;               /* done by the rig on the element over the path: -integral of
                                * F . v dt (trapezoidal at the rig steps): stored or dissipated */
    char message[512];
} hx_stateeqn_rig_result;

/* Drives Force_StateEqn r->force (an index in stateeqns[]) along r->path;
 * returns 0, or -1 (result->message) when it failed or stopped the run. */
int hx_stateeqn_rig_run(hx_rig *r, hx_stateeqn_rig_result *result);

#endif
