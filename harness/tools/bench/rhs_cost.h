/*
 * The harness's own cost per right-hand-side evaluation. The evaluation is
 * timed twice in the same rounds: as it is, and with every user entry swapped
 * for a stand-in that only replays the outputs the entry gave at that state,
 * and the stand-ins are timed alone. The second less the third is the
 * harness's share (the equations of motion, frames, force application, the
 * calls); the rest of the first is what the user entries cost inside a real
 * evaluation (their host queries included, as in the cost per call). Taking both round by round lets a slow spell of the
 * machine cancel out.
 */
#ifndef HX_TOOLS_BENCH_RHS_COST_H
#define HX_TOOLS_BENCH_RHS_COST_H

#include "tools/bench/entry_cost.h"
#include "sim/dynamics/dynamics.h"

typedef struct hx_rhs_cost {
    double rhs_ns;     /* median per evaluation */
    double harness_ns; /* median over rounds of (stand-in evaluation - stand-ins alone) */
    double user_ns;    /* median over rounds of (evaluation - harness) */
    int user_calls;    /* entry calls per evaluation */
} hx_rhs_cost;

/* Whether the cost split can be measured on s's model: 0, or -1 with msg
 * naming the first element it cannot split (its stand-ins replay the classic
 * forms of force, coupler and state-equation routines only). */
int hx_rhs_cost_supported(const hx_session *s, hx_message *msg);

/* Fills costs (as hx_measure_entry_costs; *ncosts rows) and out at the
 * model's initial state. Returns 0, or -1 with msg. */
int hx_measure_rhs_cost(hx_session *s, int repeats, hx_entry_cost *costs, int capacity,
                        int *ncosts, hx_rhs_cost *out, hx_message *msg);

/* The split as bench prints it, into text (size bytes): "right-hand side:
 * 812.0 ns per evaluation: the 4 user entry calls in it 600.0 ns, the
 * harness's own share 212.0 ns (35 % of the user entries)". The two shares
 * are differences of separately timed rounds: a share at or below zero is
 * below the timings' noise (a loaded machine) and is said so, never printed
 * as a negative cost. */
void hx_rhs_cost_text(const hx_rhs_cost *rc, char *text, size_t size);

#endif
