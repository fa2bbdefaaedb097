/*
 * The virtual test rig: one force element driven without dynamics.
 * Deformation-controlled, it prescribes the deformation of I relative to J
 * (and its rate); force-controlled, it applies a load to I and solves each
 * step for the deformation that balances it, by Newton's method with the
 * element's partials (FIESUB) or central differences (GFOSUB).
 */
#ifndef HX_TOOLS_RIG_RIG_H
#define HX_TOOLS_RIG_RIG_H

#include <stdio.h>

#include "session/session.h"
#include "tools/rig/rig_path.h"

typedef struct hx_rig {
    hx_session *s;
    hx_frames scratch;     /* where a GFOSUB element's body is placed */
    int force;            /* element index (the model's forces[], or its stateeqns[] for a
                           * Force_StateEqn: tools/rig/stateeqn_rig.h) */
    int force_controlled;
    hx_rig_path path;
    double end, step;
    FILE *csv;
    long element_calls;
    int max_iterations;
    double worst_residual;
    double radius_min[2], radius_max[2]; /* |F| and |d| in the plane of the path */
    unsigned moving;      /* directions whose deformation or force is not zero */
    int a, b;             /* the path's plane */
} hx_rig;


/* Runs the path from 0 to end in steps of step, writing CSV rows when csv is
 * set; returns 0, or -1 when the element could not be evaluated. */
int hx_rig_run(hx_rig *r);

/* Notes a step's deformation d and force F: the directions that move or
 * carry force, and the ranges of |F| and |d| in the path's plane. */
void hx_rig_track(hx_rig *r, const double d[6], const double F[6], int first);

#endif
