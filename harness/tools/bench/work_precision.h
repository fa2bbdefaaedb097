/*
 * Work-precision of the integrators on a model: for each series a sweep of
 * fixed steps (Euler, symplectic Euler, RK4) or of tolerances (DOPRI5,
 * ARKODE's Dormand-Prince, BDF with the Newton matrix from the elements'
 * partials and BDF with differences of the whole right-hand side); for each
 * run its error at the end and its largest error over the trajectory against
 * a reference, its run time (median of repeated runs), its right-hand-side
 * evaluations and, for BDF, its Newton iterations and Jacobians. The
 * reference is the closed form when the model has one (linear_reference.h),
 * else DOPRI5 at tolerance 1e-13, confirmed by DOPRI5 and by BDF at 1e-12.
 *
 * Errors are relative, per kind of state: positions against the largest
 * excursion of that kind over the trajectory, velocities against the largest
 * velocity of that kind (translations, rotations, joint angles and slides
 * apart, so that units never mix). They are taken on the slow outputs, the
 * states of the bodies named (all bodies by default); the largest error over
 * all states (a fast mode's included) is kept beside them.
 */
#ifndef HX_TOOLS_BENCH_WORK_PRECISION_H
#define HX_TOOLS_BENCH_WORK_PRECISION_H

#include <stdio.h>

#include "session/session.h"
#include "tools/bench/stability.h"

#define HX_WP_MAX_POINTS 96
#define HX_WP_GRID 50 /* output times at which errors are taken */
#define HX_WP_MAX_OUTPUTS 16

typedef struct hx_wp_options {
    double t_end;
    int repeats;       /* timed runs per point; the median is kept */
    int quick;         /* fewer and cheaper points (CI) */
    double atol_ratio; /* adaptive methods: atol = rtol * atol_ratio (0: 1e-3) */
    int noutputs;      /* the slow outputs: these bodies' states (0: every body) */
    int outputs[HX_WP_MAX_OUTPUTS]; /* body ids */
    int max_order;     /* BDF's highest order (0: 5) */
} hx_wp_options;

/* The series of the sweep, in the order they run (and are plotted). */
typedef enum hx_wp_series {
    HX_WP_EULER, HX_WP_SYMPLECTIC_EULER, HX_WP_RK4, HX_WP_DOPRI5, HX_WP_DOPRI5_ARKODE,
    HX_WP_BDF, HX_WP_BDF_FD, HX_WP_SERIES
} hx_wp_series;

/* "rk4", "bdf" (the elements' partials), "bdf-fd" (differences), ... */
const char *hx_wp_series_name(hx_wp_series series);

typedef struct hx_wp_point {
    hx_wp_series series;
    hx_method method;
    double setting;  /* the step, or the relative tolerance */
    double end_error, max_error; /* of the slow outputs */
    double all_error;            /* largest over the trajectory, every state */
    double seconds;
    long evaluations, steps;
    /* BDF: Newton iterations, Jacobians, what they cost */
    long newton_iterations, jacobians, fd_evaluations, partial_calls;
    double jacobian_seconds;
    hx_status status;
} hx_wp_point;

typedef struct hx_wp_result {
    int npoints;
    hx_wp_point point[HX_WP_MAX_POINTS];
    int analytic;               /* the reference is a closed form */
    int restricted;             /* the slow outputs are some bodies only */
    char reference[1024];       /* how the reference was made */
    hx_stability stability;     /* at the initial state */
} hx_wp_result;

/* Runs the sweep on the session's model. Returns 0, or -1 with msg. */
int hx_work_precision(hx_session *s, const hx_wp_options *o, hx_wp_result *r,
                      hx_message *msg);

/* Right-hand-side evaluations a method needs for an end-point error of
 * target, by log-log interpolation between its sweep's points (0 when its
 * sweep does not reach it); BDF: with the elements' partials. */
double hx_wp_evaluations_at(const hx_wp_result *r, hx_method method, double target);
/* The same for a series, with the run time too (either may be NULL), for
 * an error at the end or (largest) over the whole trajectory; returns 0, or
 * -1 when the series does not reach the target. */
int hx_wp_work_at(const hx_wp_result *r, hx_wp_series series, double target, int largest,
                  double *evaluations, double *seconds);

void hx_wp_print(FILE *f, const hx_wp_result *r);

/* PREFIX_work_precision.csv, and with gnuplot PREFIX_error_time.png and
 * PREFIX_error_evaluations.png. Returns 0, or 1 when gnuplot is missing, or
 * -1 when a file cannot be written. */
int hx_wp_write(const char *prefix, const char *title, const hx_wp_result *r);

#endif
