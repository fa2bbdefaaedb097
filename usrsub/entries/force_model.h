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
#include "usrsub/core/flex_joint.h"
#include "usrsub/core/mount_limits.h"

enum force_code { FORCE_BUSHING = 1, FORCE_MOUNT_LIMITS = 2, FORCE_FLEX_JOINT = 3 };

typedef struct force_model {
    int code;                      /* enum force_code */
    int i_marker, j_marker;        /* GFOSUB form */
    const usrsub_bushing *bushing; /* shared; NULL when unused */
    const usrsub_mount_limits *limits; /* shared; NULL when none is active */
    const usrsub_flex_joint *joint;    /* shared; NULL when unused */
    deformation_needs needs;
} force_model;

/* Element cache set-up of a force element; ctx points to the interface
 * (ELEMENT_GFOSUB or ELEMENT_FIESUB). sig->code is the named entry's code, or 0
 * for GFOSUB/FIESUB, whose par[0] holds it. */
void *force_model_setup(const element_signature *sig, void *ctx, element_setup_report *report);
void force_model_release(void *model);

/* Force and torque on I in J axes; partials (may be NULL) column-major.
 * Writes every output. */
void force_model_evaluate(const force_model *m, const double d[6], const double v[6],
                          double F[6], double *dFdd, double *dFdv);

#endif
