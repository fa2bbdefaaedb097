/*
 * Work-precision of the integrators on a model: for each method a sweep of
 * fixed steps (or of tolerances for DOPRI5); for each run its error at the
 * end and its largest error over the trajectory against a reference, its run
 * time (median of repeated runs) and its right-hand-side evaluations. The
 * reference is the closed form when the model has one (linear_reference.h),
 * else an adaptive run at tolerance 1e-12 confirmed by a second at 1e-13.
 *
 * Errors are relative, per kind of state: positions against the largest
 * excursion of that kind over the trajectory, velocities against the largest
 * velocity of that kind (translations, rotations, joint angles and slides
 * apart, so that units never mix).
 */
#ifndef HX_WORK_PRECISION_H
#define HX_WORK_PRECISION_H

#include <stdio.h>

#include "host/session.h"
#include "tools/bench/stability.h"

#define HX_WP_MAX_POINTS 64
#define HX_WP_GRID 50 /* output times at which errors are taken */

typedef struct hx_wp_options {
    double t_end;
    int repeats; /* timed runs per point; the median is kept */
    int quick;   /* fewer and cheaper points (CI) */
} hx_wp_options;

typedef struct hx_wp_point {
    hx_method method;
    double setting;  /* the step, or DOPRI5's relative tolerance */
    double end_error, max_error;
    double seconds;
    long evaluations, steps;
    hx_status status;
} hx_wp_point;

typedef struct hx_wp_result {
    int npoints;
    hx_wp_point point[HX_WP_MAX_POINTS];
    int analytic;               /* the reference is a closed form */
    double reference_error;     /* numerical reference: its two runs apart */
    char reference[1024];       /* how the reference was made */
    hx_stability stability;     /* at the initial state */
} hx_wp_result;

/* Runs the sweep on the session's model. Returns 0, or -1 with msg. */
int hx_work_precision(hx_session *s, const hx_wp_options *o, hx_wp_result *r,
                      hx_message *msg);

/* Right-hand-side evaluations a method needs for an end-point error of
 * target, by log-log interpolation between its sweep's points (0 when its
 * sweep does not reach it). */
double hx_wp_evaluations_at(const hx_wp_result *r, hx_method method, double target);

void hx_wp_print(FILE *f, const hx_wp_result *r);

/* PREFIX_work_precision.csv, and with gnuplot PREFIX_error_time.png and
 * PREFIX_error_evaluations.png. Returns 0, or 1 when gnuplot is missing, or
 * -1 when a file cannot be written. */
int hx_wp_write(const char *prefix, const char *title, const hx_wp_result *r);

#endif
