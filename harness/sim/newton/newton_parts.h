/*
 * The parts of the Newton matrix's assembly (newton_matrix.h), for its own
 * files only: the blocks' builders and the one way they add into J.
 */
#ifndef HX_SIM_NEWTON_NEWTON_PARTS_H
#define HX_SIM_NEWTON_NEWTON_PARTS_H

#include "sim/newton/body_motion.h"
#include "sim/newton/newton_matrix.h"

/* J[row0 .. row0 + count - 1, col] += v (count rows of one body or element). */
void hx_newton_add(hx_newton_matrix *nm, int row0, int count, int col, const double *v);

/* Where rows row0 .. row0 + count - 1 of column col sit in the values when
 * the pattern holds them all, one after another; else -1 (hx_newton_add
 * then looks each up). A build can keep it: the pattern is fixed. */
int hx_newton_rows_at(const hx_newton_matrix *nm, int row0, int count, int col);

/* The y columns of body b (positions, then velocities); returns their count
 * (0 on ground, 2 jointed, 13 free). */
int hx_newton_body_columns(const hx_dynamics *d, int b, int columns[13]);

/* A change of the loads on body b (dF, and dT about its centre, world axes)
 * per unit of column col: into the rows of b's accelerations, which sit at
 * `at` in the values (hx_newton_body_rows_at; -1: looked up). */
void hx_newton_body_load(hx_newton_matrix *nm, int b, int col, int at, const double dF[3],
                         const double dT[3]);

/* hx_newton_body_load of sign dF, sign dT for a free body whose rows sit at
 * values (known), map its nm->load_map: the hot case, inline. */
static inline void hx_newton_free_body_load(double *values, const double map[12], double sign,
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

/* hx_newton_rows_at for the rows of body b's accelerations (-1 on ground). */
int hx_newton_body_rows_at(const hx_newton_matrix *nm, int b, int col);

/* The probe state: body b moved to its frame at y (its tracked markers with
 * it), and back to the state of the build. */
void hx_newton_probe_move(hx_newton_matrix *nm, int b, const double *y);
void hx_newton_probe_restore(hx_newton_matrix *nm, int b);

/* The central-difference step of column c. */
double hx_newton_step(const double *y, int c);

/* A force that outputs (6, in axes R_A turning with body ba) put on I's body
 * bi at I's point and, reversed, on bj: the change that column col (of body
 * b, motion mo; b = -1 for none) and a change dout of the outputs make, into
 * J. F, T: the force and couple at the build's state, world axes. at: where
 * bi's and bj's rows sit in column col (hx_newton_body_rows_at), or NULL. */
typedef struct hx_applied_force {
    int bi, bj, ba;
    const hx_frame *I;     /* the application point's marker */
    const double *R_A;     /* the outputs' axes */
    double F[3], T[3];
} hx_applied_force;
void hx_newton_applied_force(hx_newton_matrix *nm, const hx_applied_force *a, int col, int b,
                             const hx_motion *mo, const double dout[6], const int at[2]);

/* The blocks: 0, or -1 (d->message). */
void hx_body_blocks(hx_newton_matrix *nm, const double *y);
int hx_element_blocks_init(hx_newton_matrix *nm, hx_message *msg);
/* After the pattern: where each element's rows sit in its columns. */
void hx_element_blocks_locate(hx_newton_matrix *nm);
int hx_element_blocks(hx_newton_matrix *nm, double t, const double *y);
int hx_load_blocks(hx_newton_matrix *nm, double t, const double *y);
int hx_stateeqn_blocks_init(hx_newton_matrix *nm, hx_message *msg);
void hx_stateeqn_blocks_free(hx_newton_matrix *nm);
int hx_stateeqn_blocks(hx_newton_matrix *nm, double t, const double *y);
void hx_stateeqn_blocks_describe(const hx_newton_matrix *nm, char *text, size_t size);
int hx_coupler_blocks(hx_newton_matrix *nm, double t, const double *y);
/* Control_Diff rows and driven joints' rows (routine_blocks.c): last, as it
 * moves the dynamics' state and puts it back. */
int hx_routine_blocks(hx_newton_matrix *nm, double t, const double *y);

/* The columns the row of Control_Diff routine `routine` depends on: its own
 * state's, and those its DIFSUB's declared queries read; their count (at
 * most max). DIFF_COLUMNS_MAX holds them all: at most HX_MAX_QUERIES queries
 * of four markers' bodies (13 columns each) or one Control_Diff each. */
#define DIFF_COLUMNS_MAX (1 + HX_MAX_QUERIES * 4 * 13)
int hx_diff_columns(const hx_dynamics *d, int routine, int *cols, int max);

/* The pattern from the model's structure (pattern.c); 0 or -1. */
int hx_newton_pattern(hx_newton_matrix *nm);

/* The bodies (non-ground, distinct) Force_StateEqn k measures its inputs on;
 * returns their count, at most max. */
int hx_stateeqn_input_bodies(const hx_dynamics *d, int k, int *bodies, int max);

#endif
