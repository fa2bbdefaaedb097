/*
 * Helpers of the tests that open a model, run it and compare states (the
 * Jacobian, BDF and energy tests): a session with its dynamics and a data of
 * the test's own, runs to a time, and a difference of two states that is
 * fair to every kind of coordinate.
 */
#ifndef MODEL_RUNS_H
#define MODEL_RUNS_H

#include <dirent.h>

#include "expr/evaluate.h"
#include "sim/jacobian/jacobian.h"
#include "sim/simulation/simulation.h"

typedef struct model {
    hx_session session;
    hx_dynamics d;
    hx_dynamics_data data; /* the test's own evaluations */
} model;

/* Opens the model at path; fails the test when it does not open. */
void open_model(model *m, const char *path);
void close_model(model *m);
/* A state of the model's size (calloc'ed; the caller frees it). */
double *model_state(const model *m);
/* The model's initial state into y; fails the test on an error. */
void model_initial_state(model *m, double *y);

/* The model from its initial state to t_end; y receives the end state.
 * atol = rtol * atol_ratio. */
hx_simulation_result simulate_with(model *m, hx_method method, hx_jacobian_method jacobian,
                                   double rtol, double atol_ratio, double t_end, double *y);
/* The same with atol = rtol * 1e-3. */
hx_simulation_result simulate(model *m, hx_method method, hx_jacobian_method jacobian,
                              double rtol, double t_end, double *y);

/* Writes text as name in the temporary folder, opens it into m and runs it
 * from its initial state to t_end (simulate); fails the test with the run's
 * message unless it finishes. The end state (calloc'ed; the caller frees it). */
double *model_run_text(const char *name, const char *text, hx_method method,
                       hx_jacobian_method jacobian, double rtol, double t_end, model *m);
/* The state of Control_Diff id in y (fails the test when there is none). */
double model_diff_state(const model *m, const double *y, int id);

/* text (name in the temporary folder) run with BDF on its own Jacobian to
 * t = 0.4 at rtol 1e-9 into m: the Jacobian there against differences of the
 * whole right-hand side (no entry outside its sparsity, the worst below
 * 1e-6; what names it in the printed line), and the same run with BDF's
 * differences ending with Control_Diffs first .. last within 1e-6 of it.
 * Fails the test otherwise; the end state (the caller frees it). */
double *model_diffs_jacobian_checked(const char *name, const char *text, const char *what,
                                     int first, int last, model *m);

/* Largest difference of positions and velocities, relative to the largest
 * of each kind (translations, quaternions, velocities, angular velocities and
 * joint coordinates apart): excursions from y0, and velocities at the end or
 * at the start (a motion that has died away is measured against its start). */
double state_difference(const hx_dynamics *d, const double *a, const double *b, const double *y0);

/* scandir's filter of model files (.xml). */
int is_model(const struct dirent *e);

/* A 1 kg body on the element written in `element` (a field or spring of
 * tests/implicit_support/scaled_field.c: soft, damped translations, and
 * rotations on a stiff overdamped spring), written to the temporary folder
 * as name; its path. */
const char *scaled_field_model(const char *name, const char *element);
/* BDF on the model at path to t_end at rtol, its result in r: the end state
 * (malloc'ed; the caller frees it); source (may be NULL) where the first
 * element's partials came from after the run, description (may be NULL,
 * 1024 characters) the run's account of its Jacobian. */
double *bdf_on(const char *path, double rtol, double t_end, hx_simulation_result *r,
               hx_partials_source *source, char *description);

/* A model evaluated at its initial state, with what an output time knows
 * there: its reactions, accelerations, loads, force elements' forces and
 * the other constraint elements' forces. */
typedef struct evaluated {
    model m;
    double *y, *ydot, *r, *a, *loads, *forces, *constraints;
    hx_expr_outputs outputs;
} evaluated;

/* The model text written as name, opened and evaluated; fails the test on an
 * error. */
void evaluate_text(evaluated *e, const char *name, const char *text);
/* The same of the model at path. */
void evaluate_path(evaluated *e, const char *path);
void release(evaluated *e);
/* An output expression's value at e's state; fails the test on an error. */
double output(const evaluated *e, const char *text);

/* Each case's model (head, the case's statements [0], END) refused when read
 * as `name`, its message holding [1] and [2]. */
void expect_read_errors(const char *name, const char *head, const char *const (*cases)[3],
                        size_t count);
/* The same of an XML element: `element` (its start, "<Force_Beam id=\"3\" ...")
 * closed after each case's attributes (cases[k][0]), on the ground of bad.xml
 * with its marker 10, at line 4; the reader refuses each with cases[k][1]. */
void expect_xml_errors(const char *element, const char *const (*cases)[2], size_t count);

#define EXPECT(e, text, want, tol)                                                              \
    do {                                                                                        \
        const double got_ = output(e, text);                                                    \
        if (!(fabs(got_ - (want)) <= (tol)))                                                    \
            fail_msg("%s = %.15g, expected %.15g", text, got_, (double)(want));                 \
    } while (0)

/* A two-marker element's force f (force, torque) on I in J's axes, read by
 * its function `name` (BEAM, FIELD, ...) of element id: on I in J's (jmarker)
 * axes, on J at J (-F and -T - L x F, L I's place from J in J's axes), and on
 * I in the world's axes (RJ J's axes, columns, in the world's); within tol. */
void expect_sides(const evaluated *e, const char *name, int id, int jmarker, const double f[6],
                  const double L[3], const double RJ[9], double tol);

/* At e's state, marker i's place from marker j (L), its velocity seen by j
 * and its angular velocity from j (v), in j's axes, worked from the two
 * frames rather than from the measures: L = R^T dp, v = (R^T (v_I - v_J - w_J
 * x dp), R^T (w_I - w_J)), R = RJ j's axes (columns) in the world's; and its
 * angles from j, the projected ones of §8.5 as the measures AX AY AZ give
 * them. */
void marker_motion(const evaluated *e, int i, int j, double L[3], double angles[3], double v[6],
                   double RJ[9]);

#endif
