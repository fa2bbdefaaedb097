/* Helpers of the tests that simulate bundled example models in-process. */
#ifndef SIM_SUPPORT_H
#define SIM_SUPPORT_H

#include "sim/simulation/simulation.h"

typedef struct trajectory {
    int n;          /* state size */
    int rows, capacity;
    double *t, *y;  /* rows x n states */
    double *lambda; /* rows x (couplers) multipliers */
    int ncouplers;
} trajectory;

typedef struct sim {
    hx_session session;
    hx_dynamics dynamics;
    hx_dynamics_data data;  /* the test's own evaluations (sim_evaluate) */
    hx_simulation_result result;
    trajectory path;
} sim;

/* Opens EXAMPLES_DIR/name (or a path), simulates with the method, fixed step h
 * (or tolerance for dopri5 in rtol), to t_end, keeping the states every
 * output_interval. Fails the test on any error. */
void sim_run(sim *s, const char *model, hx_method method, double h, double t_end,
             double output_interval);
void sim_close(sim *s);
/* The dynamics evaluated at (t, y) on s->data (its multipliers, loads and
 * frames then belong to that state); fails the test on an error. */
void sim_evaluate(sim *s, double t, const double *y);
/* Value of state component k of a row. */
double sim_state(const sim *s, int row, int k);
/* Multiplier of a coupler at a row. */
double sim_lambda(const sim *s, int row, int coupler);
/* Offset of a jointed body's coordinate (position) by joint id. */
int sim_joint_q(const sim *s, int joint_id);
int sim_joint_u(const sim *s, int joint_id);
/* The assembled Jacobian (sim/jacobian/) at (t, y) against central
 * differences of the whole right-hand side, entry by entry relative to each
 * row's largest entry (the work accumulators' rows apart: the matrix leaves
 * them out): returns the largest difference; *outside receives the count of
 * entries the differences find nonzero (above 1e-9 of their row) where the
 * sparsity says zero, or that the build itself found outside it. Prints a
 * line naming what. */
double jacobian_against_differences(const hx_dynamics *d, double t, const double *y,
                                    const char *what, long *outside);

/* A model read from text with its dynamics and one evaluator's data. */
typedef struct sim_opened {
    hx_session s;
    hx_dynamics d;
    hx_dynamics_data dd;
} sim_opened;
/* Writes text as name in the temporary folder and opens it; fails the test on
 * an error. */
void sim_open_text(sim_opened *o, const char *name, const char *text);
void sim_close_opened(sim_opened *o);
/* The model of text (written as name) run with RK4 at a fixed step from 0 to
 * t_end, outputs every step: the run must fail; its message (static
 * storage, overwritten by the next call). */
const char *sim_rk4_refused(const char *name, const char *text, double step, double t_end);
/* Uniform in [-1, 1] (rand()). */
double sim_uniform(void);

/* Parses text as a model named name; fails the test with the reader's message
 * if it does not read. */
hx_model *sim_parse(const char *name, const char *text);
/* Parses text as name; fails the test if it reads or its message lacks a
 * needle (NULL-terminated). */
void sim_expect_parse_error(const char *name, const char *text, const char *const *needles);

/* Runs "usrsub-harness check" in-process; returns its exit status. */
int sim_check(const char *model);

/* Runs "usrsub-harness rig MODEL --out CSV ARGS..." in-process; returns its
 * exit status. */
int sim_rig(const char *model, const char *csv, const char *const *args);
/* The same with "usrsub-harness run". */
int sim_run_csv(const char *model, const char *csv, const char *const *args);

/* Force elements between marker 20 (I) and 10 (J) of the tests' models, on the
 * library being tested: GFO(id, "(USER list)", "ENTRY") and the same FIE. */
#define GFO(id, list, fnc)                                                                      \
    "<Force_Vector_TwoBody id=\"" #id "\" type=\"ForceAndTorque\" i_marker_id=\"20\" "          \
    "j_floating_marker_id=\"10\" ref_marker_id=\"10\" usrsub_param_string=\"USER" list "\" "    \
    "usrsub_fnc_name=\"" fnc "\" usrsub_dll_name=\"" USRSUB_LIBRARY "\"/>\n"
#define FIE(id, list, fnc)                                                                      \
    "<Force_Field id=\"" #id "\" i_marker_id=\"20\" j_marker_id=\"10\" usrsub_param_string=\"USER" \
    list "\" usrsub_fnc_name=\"" fnc "\" usrsub_dll_name=\"" USRSUB_LIBRARY "\"/>\n"

/* A model from XML text (written to the temporary folder as name) bound to
 * the harness host, its bodies at their initial frames: entries of a library
 * loaded directly then query it, as they would a solver's. */
typedef struct host_model {
    hx_model *model;
    hx_frames frames;
    hx_messages messages; /* printed on stderr unless the test silences them */
    hx_call call;         /* bound: entries called directly answer from state */
} host_model;
void host_model_attach(host_model *h, const char *name, const char *xml);
void host_model_detach(host_model *h);
/* dlopen of the library being tested, as a solver loads it; fails the test
 * when it cannot. */
void *load_library(void);

/* A model with one faulty element: its session does not open, and the host
 * got exactly one error, holding every needle. */
void expect_one_setup_error(const char *model_path, const char *const needles[3]);

/* Column of a CSV file's header by name (-1 when absent). */
int csv_column(const char *path, const char *name);

/* A numeric CSV with a header line: rows x columns values (malloc'ed). */
typedef struct csv_table {
    int rows, columns;
    double *v;
} csv_table;
void csv_read(const char *path, csv_table *t);
double csv_at(const csv_table *t, int row, int column);
void csv_free(csv_table *t);

#endif
