/*
 * The parts of the Jacobian's assembly (jacobian.h), for its own files only:
 * the blocks' builders (one file each) and the one way they add into J
 * (assembly.c).
 */
#ifndef HX_SIM_JACOBIAN_JACOBIAN_PARTS_H
#define HX_SIM_JACOBIAN_JACOBIAN_PARTS_H

#include "sim/jacobian/body_motion.h"
#include "sim/jacobian/jacobian.h"

/* J[row0 .. row0 + count - 1, col] += v (count rows of one body or element). */
void hx_jacobian_add(hx_jacobian *jac, int row0, int count, int col, const double *v);

/* Where rows row0 .. row0 + count - 1 of column col sit in the values when
 * the pattern holds them all, one after another; else -1 (hx_jacobian_add
 * then looks each up). A build can keep it: the pattern is fixed. */
int hx_jacobian_rows_at(const hx_jacobian *jac, int row0, int count, int col);

/* The y columns of body b (positions, then velocities); returns their count
 * (0 on ground, 2 jointed, 13 free). */
int hx_jacobian_body_columns(const hx_dynamics *d, int b, int columns[13]);

/* A change of the loads on body b (dF, and dT about its centre, world axes)
 * per unit of column col: into the rows of b's accelerations, which sit at
 * `at` in the values (hx_jacobian_body_rows_at; -1: looked up). */
void hx_jacobian_body_load(hx_jacobian *jac, int b, int col, int at, const double dF[3],
                         const double dT[3]);

/* hx_jacobian_body_load of sign dF, sign dT for a free body whose rows sit at
 * values (known), map its jac->load_map: the hot case, inline. */
static inline void hx_jacobian_free_body_load(double *values, const double map[12], double sign,
                                            const double dF[3], const double dT[3])
{
    const double c = sign * map[0];
    values[0] += c * dF[0];
    values[1] += c * dF[1];
    values[2] += c * dF[2];
    for (int i = 0; i < 3; ++i)
        values[3 + i] += sign * (map[3 + 3 * i] * dT[0] + map[4 + 3 * i] * dT[1] +
                                 map[5 + 3 * i] * dT[2]);
}

/* hx_jacobian_rows_at for the rows of body b's accelerations (-1 on ground). */
int hx_jacobian_body_rows_at(const hx_jacobian *jac, int b, int col);

/* The moved frames (jac->moved): body b moved to its frame at y (its tracked
 * markers with it), and back to the build's. */
void hx_jacobian_move_body(hx_jacobian *jac, int b, const double *y);
void hx_jacobian_restore_body(hx_jacobian *jac, int b);
/* Each body's tracked markers (jac->body_markers, body_marker_start); 0 or -1. */
int hx_jacobian_marker_lists(hx_jacobian *jac);

/* The relative step of the Jacobian's central differences: its partials are
 * good to about 1e-10 (base/difference_step.h). */
#define HX_JACOBIAN_EPS 1e-5
/* The central-difference step of column c. */
double hx_jacobian_step(const double *y, int c);

/* A force that outputs (6, in axes R_A turning with body ba) put on I's body
 * bi at I's point and, reversed, on bj: the change that column col (of body
 * b, motion mo; b = -1 for none) and a change dout of the outputs make, into
 * J. F, T: the force and couple at the build's state, world axes. at: where
 * bi's and bj's rows sit in column col (hx_jacobian_body_rows_at), or NULL. */
typedef struct hx_applied_force {
    int bi, bj, ba;
    const hx_frame *I;     /* the application point's marker */
    const double *R_A;     /* the outputs' axes */
    double F[3], T[3];
} hx_applied_force;
void hx_jacobian_applied_force(hx_jacobian *jac, const hx_applied_force *a, int col, int b,
                             const hx_motion *mo, const double dout[6], const int at[2]);

/* The blocks: 0, or -1 (jac->dd.message). */
void hx_body_blocks(hx_jacobian *jac, const double *y);
int hx_element_blocks_init(hx_jacobian *jac, hx_message *msg);
/* After the pattern: where each element's rows sit in its columns. */
void hx_element_blocks_locate(hx_jacobian *jac);
int hx_element_blocks(hx_jacobian *jac, double t, const double *y);
/* The loads' expressions' scratch (load_blocks.c), grown to the variables'
 * definitions in force when called again (hx_jacobian_widen); 0, or -1 with msg. */
int hx_load_blocks_init(hx_jacobian *jac, hx_message *msg);
int hx_load_blocks(hx_jacobian *jac, double t, const double *y);
int hx_stateeqn_blocks_init(hx_jacobian *jac, hx_message *msg);
void hx_stateeqn_blocks_free(hx_jacobian *jac);
int hx_stateeqn_blocks(hx_jacobian *jac, double t, const double *y);
void hx_stateeqn_blocks_describe(const hx_jacobian *jac, char *text, size_t size);
/* The constraint system's groups (before the pattern) and where their rows
 * sit (after it, again after each change of the pattern); 0, or -1 with msg
 * (out of memory). */
int hx_coupler_blocks_init(hx_jacobian *jac, hx_message *msg);
int hx_coupler_blocks_locate(hx_jacobian *jac, hx_message *msg);
void hx_coupler_blocks_free(hx_jacobian *jac);
int hx_coupler_blocks(hx_jacobian *jac, double t, const double *y);
/* Control_Diff rows and driven joints' rows (routine_blocks.c): the driven
 * rows marked once (0, or -1 with msg); at a build, last: its differences set
 * jac->dd's kinematics elsewhere and put them back. */
int hx_routine_blocks_init(hx_jacobian *jac, hx_message *msg);
int hx_routine_blocks(hx_jacobian *jac, double t, const double *y);

/* The columns the row of Control_Diff routine `routine` depends on: its own
 * state's, and those its DIFSUB's declared queries read; their count (at
 * most max). DIFF_COLUMNS_MAX holds them all: at most HX_MAX_QUERIES queries
 * of four markers' bodies (13 columns each) or one Control_Diff each. */
#define DIFF_COLUMNS_MAX (1 + HX_MAX_QUERIES * 4 * 13)
int hx_diff_columns(const hx_dynamics *d, int routine, int *cols, int max);

/* The pattern from the model's structure (pattern.c); 0, or -1 with msg.
 * With widen set, the one built before united with the one under the
 * variables' definitions now in force (hx_jacobian_widen). */
int hx_jacobian_pattern(hx_jacobian *jac, int widen, hx_message *msg);

/* The bodies (non-ground, distinct) Force_StateEqn k measures its inputs on;
 * returns their count, at most max. */
int hx_stateeqn_input_bodies(const hx_dynamics *d, int k, int *bodies, int max);

#endif
