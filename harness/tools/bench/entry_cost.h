/*
 * Cost per call of every user-subroutine entry of a session, through the
 * dlopen'd function pointers: pinned to one processor, after a warm-up, the
 * median over rounds of timed batches (one batch per entry per round), with
 * the host calls one evaluation makes.
 */
#ifndef HX_TOOLS_BENCH_ENTRY_COST_H
#define HX_TOOLS_BENCH_ENTRY_COST_H

#include <stdio.h>

#include "session/session.h"

typedef struct hx_entry_cost {
    char element[64];
    char function[32];
    double median_ns, min_ns, max_ns;
    int host_calls;       /* per evaluation */
    int dependency_calls; /* in the dependency pass */
    int force_index;      /* the model's force element, or -1 (a coupler, a Force_StateEqn) */
    int in_rhs;           /* the right-hand side calls it (a state equation's partial
                           * routines: only the Newton matrix does) */
    double *rounds;       /* ns per call in each round, in round order */
    /* the floor (tools/bench/call_floor.h): an empty call, the host alone
     * answering one evaluation's queries (0 for FIESUB and couplers), and the
     * median over rounds of the cost over the floor */
    double empty_ns, host_ns, floor_ratio;
} hx_entry_cost;

/* Further bodies timed in the same rounds as the entries (one call per
 * iteration), e.g. a right-hand side that calls them. */
typedef struct hx_timed_body {
    void (*run)(void *ctx, long calls);
    void *ctx;
    double *rounds; /* out: ns per call in each round (repeats values, caller's array) */
} hx_timed_body;

/* Times each entry of each user element (COUSUB, COUXX and COUXX2 separately),
 * and the extra bodies in the same rounds. Returns the number of rows written
 * into costs (at most capacity), or -1 when out of memory (nothing timed). */
int hx_measure_entry_costs_with(hx_session *s, int repeats, hx_entry_cost *costs, int capacity,
                               hx_timed_body *extra, int nextra);

void hx_print_entry_costs(FILE *f, const hx_entry_cost *costs, int count);

/* The median of n timings (sorts v in place; v[0] and v[n-1] are then the
 * extremes). */
double hx_median(double *v, int n);
void hx_entry_costs_free(hx_entry_cost *costs, int count);

/* Median over rounds of other's cost minus base's in the same round: a slow
 * spell of the machine cancels out of the difference. */
double hx_added_cost(const hx_entry_cost *base, const hx_entry_cost *other, int repeats);

#endif
