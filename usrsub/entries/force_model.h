/*
 * A set-up force element: which physics (bushing, mount limits, flexible
 * joint), its markers in the GFOSUB form, the shared property data, and what
 * it needs measured. Immutable once set up.
 */
#ifndef USRSUB_FORCE_MODEL_H
#define USRSUB_FORCE_MODEL_H

#include "deformation.h"
#include "element_cache.h"
#include "usrsub/core/bushing.h"
#include "usrsub/core/bushing_states.h"
#include "usrsub/core/flex_joint.h"
#include "usrsub/core/mount_limits.h"
#include "usrsub/core/rotation.h"

/* The element code: par[0] of GFOSUB, FIESUB and YFOSUB lists, or the named
 * entry's (docs/interface.md §3.0). */
enum usrsub_force_code {
    USRSUB_FORCE_BUSHING = 1,
    USRSUB_FORCE_MOUNT_LIMITS = 2,
    USRSUB_FORCE_FLEX_JOINT = 3
};

typedef struct usrsub_force_model {
    int code;                      /* enum usrsub_force_code */
    int i_marker, j_marker;        /* GFOSUB form */
    const usrsub_bushing *bushing; /* shared; NULL when unused */
    const usrsub_mount_limits *limits; /* shared; NULL when none is active */
    const usrsub_flex_joint *joint;    /* shared; NULL when unused */
    usrsub_deformation_needs needs;
    int rotation_measure;              /* enum usrsub_rotation_measure */
    usrsub_state_layout states;        /* the YFOSUB form's internal states */
    int constant_partials;             /* -K and -D of a flexible joint on projection angles */
} usrsub_force_model;

/* Element cache set-up of a force element in the form sig->form
 * (USRSUB_ELEMENT_GFOSUB, USRSUB_ELEMENT_FIESUB or USRSUB_ELEMENT_YFOSUB; ctx
 * is unused). sig->code is the named entry's code, or 0 for
 * GFOSUB/FIESUB/YFOSUB, whose par[0] holds it. A bushing with internal states
 * sets up only in the YFOSUB form, which takes only bushings (with or without
 * states) on projection angles. */
void *usrsub_force_model_setup(const usrsub_element_signature *sig, void *ctx, usrsub_element_setup_report *report);
void usrsub_force_model_release(void *model);

/* The element's model from the cache, set up on its first call (whose notices
 * and error are reported under routine); NULL when it could not be. */
const usrsub_force_model *usrsub_force_model_of(const char *routine, int form, int code, int id,
                                                const double *par, int npar);

/* Force and torque on I in J axes at the deformation d (x, y, z, AX, AY, AZ)
 * and rate v; partials (may be NULL) column-major. R: the rotation of I
 * relative to J when the caller measured it (GFOSUB form), else NULL (it is
 * rebuilt from the projection angles when the rotation vector needs it).
 * Writes every output; returns 0, or -1 when the angles are degenerate for
 * the rotation-vector measure (outputs zero). */
int usrsub_force_model_evaluate(const usrsub_force_model *m, const double d[6], const double v[6],
                         const double *R, double F[6], double *dFdd, double *dFdv);

#endif
