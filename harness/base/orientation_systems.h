/*
 * The orientation systems of ORIENT(system, component, I[, J])
 * (docs/interface.md §8.5): what each of the 29 numbers stands for, the
 * axes of its rotation sequence and how many components it has. The one
 * table the expression parser checks a call against (model/expr/) and the
 * measure computes from (frames/measure_functions.c).
 */
#ifndef HX_BASE_ORIENTATION_SYSTEMS_H
#define HX_BASE_ORIENTATION_SYSTEMS_H

#define HX_ORIENTATION_SYSTEMS 29
#define HX_ORIENTATION_COMPONENTS 9 /* the most components a system has */

typedef enum hx_orientation_kind {
    HX_ORIENTATION_BODY,        /* body-fixed a-b-c: R = R_a(t1) R_b(t2) R_c(t3) */
    HX_ORIENTATION_SPACE,       /* space-fixed a-b-c: R = R_c(t3) R_b(t2) R_a(t1) */
    HX_ORIENTATION_PROJECTION,  /* AX, AY, AZ */
    HX_ORIENTATION_YPR,         /* YAW, PITCH, ROLL */
    HX_ORIENTATION_PARAMETERS,  /* Euler parameters e0, e1, e2, e3 */
    HX_ORIENTATION_RODRIGUES,   /* e1/e0, e2/e0, e3/e0 */
    HX_ORIENTATION_COSINES      /* x_I.x_J, x_I.y_J, x_I.z_J, y_I.x_J, ... z_I.z_J */
} hx_orientation_kind;

typedef struct hx_orientation_system {
    hx_orientation_kind kind;
    int axes[3];     /* BODY, SPACE: the sequence's axes in the order named, 0 x, 1 y, 2 z */
    int components;  /* 3, 4 or 9 */
    const char *what; /* "body-fixed 3-1-3 Euler angles" */
} hx_orientation_system;

/* System 1 .. 29, or NULL for a number that names none. */
const hx_orientation_system *hx_orientation_system_at(int system);

/* A number for each system and component, 0 .. 29 * 9 - 1 (the caller has
 * checked both). */
static inline int hx_orientation_code(int system, int component)
{
    return HX_ORIENTATION_COMPONENTS * (system - 1) + component - 1;
}

#endif
