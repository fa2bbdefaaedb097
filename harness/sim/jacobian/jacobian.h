/*
 * The Jacobian J = df/dy of the dynamics, for BDF's Newton matrix I - gamma J
 * (sim/ode/bdf.c), sparse and assembled element by element (as a multibody
 * solver assembles it), never by differences of the whole right-hand side:
 *
 *   - each body's own block, analytic (body_blocks.c): the quaternion
 *     kinematics, the gyroscopic terms, the turning of the body's loads into
 *     its axes, with the loads on it held;
 *   - each force element's block (element_blocks.c): its partials (FIESUB's
 *     own dfddis/dfdvel, the FIESUB twin's for a GFOSUB element, else
 *     differences of that element alone) times the derivatives of its
 *     deformation and rates, and the turning and lever arms of its force,
 *     both analytic in the motions of its bodies (body_motion.h), into the
 *     blocks of the bodies it joins;
 *   - each load (load_blocks.c): its expressions' exact partials times the
 *     slopes of the measures they read (measure_slope.h), through the
 *     variables they read, and of its own geometry, analytic; a load that
 *     reads a variable of another kind by differences of that load alone;
 *   - each Force_StateEqn (stateeqn_blocks.c): its partials (YFOXX..YFOYU, or
 *     differences of YFOSUB) with its inputs' slopes, by differences of the
 *     harness's measures on the bodies they measure;
 *   - the constraint system (coupler_blocks.c): the accelerations it
 *     projects, P J_free, plus its own terms by differences of the
 *     constraint stage, group by group of the bodies its rows join;
 *   - the routines (routine_blocks.c): Control_Diff rows by differences of
 *     DIFSUB (or of the expression, exact in the states it reads by DIF),
 *     with the rates they read by DIF1 computed again; a driven joint's
 *     rows, functions of time alone, zero.
 *
 * Its cost grows with the number of elements. The work accumulators' rows
 * are left out (their diagonal only): nothing depends on them, so Newton's
 * method gives them their exact update without.
 *
 * A build is a function of its arguments: it evaluates the dynamics at
 * (t, y) on its own data (jac->dd, asking Force_Field elements for their
 * partials), and every difference it takes moves its own scratch frames
 * (jac->moved), never the run's evaluation. Each force element's source of
 * partials is decided at set-up; a FIESUB twin that cannot stand in for its
 * GFOSUB at some build sets the element aside for differences for good.
 */
#ifndef HX_SIM_JACOBIAN_JACOBIAN_H
#define HX_SIM_JACOBIAN_JACOBIAN_H

#include "sim/dynamics/dynamics.h"
#include "sim/ode/sparsity.h"

typedef enum hx_partials_source {
    HX_PARTIALS_FIESUB,     /* a Force_Field's own dfddis and dfdvel */
    HX_PARTIALS_TWIN,       /* a GFOSUB element's FIESUB twin */
    HX_PARTIALS_DIFFERENCES /* differences of that GFOSUB element alone */
} hx_partials_source;

#define HX_JACOBIAN_WHY 160

typedef struct hx_jacobian {
    const hx_dynamics *d;
    hx_dynamics_data dd;        /* the dynamics at the build's (t, y), with partials */
    int n, m;                   /* state size; positions and velocities */
    int nf;                     /* force elements */
    hx_sparsity pattern;        /* where J can be nonzero (pattern.c) */
    double *values;             /* the build in progress: J in the pattern's order */
    long outside;               /* entries a build found outside the pattern (a defect) */
    hx_partials_source *source; /* per force element, decided at the first build */
    char *why;                  /* per element, HX_JACOBIAN_WHY: why differences */
    double *twin_partials;      /* 72 per force element: the twins' dfddis, dfdvel */
    double *load_map;           /* per free body, 12: [0] ucf/m, [3..11] ucf I^-1 R^T
                                 * (row-major) at the build's state (body_blocks.c) */
    int *element_rows;          /* per force element, ELEMENT_ROWS: where its bodies' rows
                                 * sit in its columns (element_blocks.c) */
    hx_frames moved;            /* jac->dd's frames with one body moved (differences) */
    int *body_markers, *body_marker_start; /* each body's tracked markers */
    /* Force_StateEqn elements (stateeqn_blocks.c) */
    struct hx_stateeqn_blocks *stateeqn_blocks;
    /* the constraint system (coupler_blocks.c): the coupled velocities in
     * groups that no row joins, each group's accelerations a function of its
     * own bodies' states and free accelerations alone */
    int ncoupled;               /* coupled velocities */
    int *coupled;               /* their indices into u, group by group */
    int ngroups, *group_start;  /* ngroups + 1: each group's first in coupled */
    int *group_columns, *group_column_start; /* each group's bodies' y columns */
    int *group_pattern, *group_pattern_start; /* the columns each group's rows have */
    int *coupled_at;            /* per group and column of it: where its rows sit */
    long *coupled_at_start;     /* ngroups + 1 */
    double *projector, *coupler_work; /* P (ncoupled^2, zero between groups); 4 ncoupled
                                       * and the solves' scratch */
    /* driven joints (routine_blocks.c): the y rows whose rate is a function of
     * time alone, marked once */
    unsigned char *driven;
    double *diff_scratch;       /* the Control_Diff expressions' partials (routine_blocks.c) */
    double *load_scratch;       /* the loads' expressions' partials (load_blocks.c) */
    size_t load_scratch_size;   /* its doubles */
    double *y, *f_plus, *f_minus;     /* scratch: n each */
    hx_messages twin_messages;  /* the twins' own messages, apart from the session's */
    long evaluations;           /* right-hand sides the builds evaluated */
    long partial_calls;         /* element calls made for partials */
} hx_jacobian;

/* Returns 0, or -1 with msg (out of memory, or a callee's reason). */
int hx_jacobian_init(hx_jacobian *jac, const hx_dynamics *d, hx_message *msg);
void hx_jacobian_free(hx_jacobian *jac);
/* The pattern widened to cover the dependencies of the variables' definitions
 * now in force in the model (a command file's VARIABLE/id, FUNCTION=,
 * docs/interface.md §9.9): the union of the pattern before and theirs.
 * Called before a run, once for each segment's definitions. 0, or -1 with msg. */
int hx_jacobian_widen(hx_jacobian *jac, hx_message *msg);

/* J at (t, y) into values (jac->pattern.nnz, the pattern's order); fy =
 * f(t, y) as the integrator has it (the assembly takes every element's
 * outputs at (t, y) itself, with their partials, which fy does not hold).
 * Returns 0, or -1 (jac->dd.message) when an element or the constraints
 * failed. */
int hx_jacobian_build(hx_jacobian *jac, double t, const double *y, const double *fy,
                      double *values);

/* Where each element's partials come from, in a line or two. */
void hx_jacobian_describe(const hx_jacobian *jac, char *text, size_t size);

#endif
