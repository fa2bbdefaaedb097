/*
 * One simulation of a session's model: the dynamics integrated by the chosen
 * method (BDF with its Jacobian from the elements' partials,
 * sim/jacobian/jacobian.h, unless differences are asked for), CSV rows at the
 * output times, and a summary (steps, evaluations, Newton iterations, run
 * time, constraint residuals, energy error and the elements' dissipation).
 * The run evaluates the dynamics on a data of its own.
 */
#ifndef HX_SIM_SIMULATION_SIMULATION_H
#define HX_SIM_SIMULATION_SIMULATION_H

#include <stdio.h>

#include "sim/dynamics/dynamics.h"
#include "model/variable_definitions.h"
#include "sim/dynamics/energy.h"
#include "sim/ode/integrator.h"
#include "sim/simulation/equilibrium.h"

/* Called at each output time after the CSV row, with the run's data (its
 * kinematics at (t, y)); non-zero stops the run. */
typedef int hx_observer_fn(void *ctx, const hx_dynamics *d, hx_dynamics_data *dd, double t,
                           const double *y);

typedef struct hx_simulation_options {
    hx_integrator_options integration;
    FILE *csv;               /* may be NULL */
    int progress;            /* print a progress line on runs longer than a second */
    hx_observer_fn *observer;
    void *observer_ctx;
    int skip_energy;         /* no energy at the output times (timed runs; no CSV) */
    int static_start;        /* the static equilibrium first (run --static, equilibrium.h) */
    int keep_redundant;      /* the redundant rows not found again at a static
                              * equilibrium (tests: what the re-examination changes) */
} hx_simulation_options;

typedef struct hx_simulation_result {
    hx_status status;
    hx_integrator_stats stats;
    double seconds;          /* wall time of the integration */
    double output_seconds;   /* of which at the output times (energy, CSV rows, observer) */
    long outputs;
    hx_energy energy0, energy_end;
    double energy_error_max;  /* largest |E(t) - E(0)| at the output times */
    double balance_error_max; /* the same of the energy balance (dissipation counted) */
    double energy_scale;      /* max(|E(0)|, largest kinetic energy): relative errors use it */
    double dissipated;        /* energy the force elements took out by the end */
    double max_phi, max_phidot;
    char jacobian[1024];      /* BDF with analytic partials: where they came from */
    long jacobian_outside;    /* entries the Jacobian found outside its sparsity (0) */
    int n;                    /* the state's size */
    int statics;              /* static equilibria found (SIMULATE/STATIC, run --static) */
    hx_equilibrium_result equilibrium; /* the last one's */
    int redundancy_changes;  /* redundant rows a static equilibrium changed (redundancy.h) */
    double t_redundancy;     /* the last equilibrium that changed them */
    char no_longer[1024], now[1024]; /* their names: redundant before and not at the
                                      * equilibrium, and the other way round */
    char message[1024];
} hx_simulation_result;

/* Integrates from the model's initial state (its static equilibrium with
 * opt->static_start); y_end (may be NULL) receives
 * the final state (d->n values). A static equilibrium finds d's redundant
 * rows again where it leaves the parts and the run goes on with that set
 * (result's redundancy_changes, no_longer, now); d has the set-up's set
 * again after the run. */
int hx_simulate(hx_dynamics *d, const hx_simulation_options *opt, double *y_end,
                hx_simulation_result *result);

/* One segment of a run (a command file's SIMULATE/DYNAMIC, docs/interface.md
 * §9.9): its end time (absolute), the time between its CSV rows (0: every
 * step), its tolerances, the elements switched off during it (a flag per
 * load of the model, then per force element; NULL: none), its gravity (3; NULL: the model's),
 * whether it starts with the static equilibrium (a SIMULATE/STATIC before it; a
 * segment that ends where it starts is that equilibrium alone), and its
 * variables' definitions (a VARIABLE/id, FUNCTION= before it; NULL: the
 * model's own). */
typedef struct hx_segment {
    double t_end, output_interval, rtol, atol;
    const unsigned char *switched_off;
    const double *gravity;
    int equilibrium;
    const hx_variable_definitions *variables;
} hx_segment;

/* The same run in segments, one after the other: each from the state the one
 * before it ended in (the integrator restarted there), with its own output
 * times (none at its start: the segment before wrote that row; a segment
 * that starts with the static equilibrium writes its row there); one CSV and
 * one result, counts summed. opt's t_end is the progress line's; the
 * segments' own times and tolerances are those integrated. */
int hx_simulate_segments(hx_dynamics *d, const hx_simulation_options *opt,
                         const hx_segment *segments, int nsegments, double *y_end,
                         hx_simulation_result *result);

/* Prints the summary lines of a result. */
void hx_simulation_summary(FILE *f, const hx_dynamics *d, const hx_simulation_options *opt,
                           const hx_simulation_result *result);

/* The CSV header and one row of a state (evaluating the dynamics there on
 * dd, so that multipliers and element loads belong to it). */
void hx_csv_header(FILE *f, const hx_dynamics *d);
int hx_csv_row(FILE *f, const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
               const hx_energy *energy, const hx_energy *energy0);

#endif
