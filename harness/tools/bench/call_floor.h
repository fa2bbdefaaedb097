/*
 * The floor under an entry's cost, timed in the same rounds as the entries:
 * an empty call through a pointer that dlsym returned (what any entry costs
 * before it does anything), and the host alone answering the queries one
 * evaluation of a GFOSUB element asks (what the library cannot avoid paying
 * for its state). An entry's ratio to its floor says how much of its cost is
 * its own arithmetic.
 */
#ifndef HX_TOOLS_BENCH_CALL_FLOOR_H
#define HX_TOOLS_BENCH_CALL_FLOOR_H

#include "base/message.h"
#include "host/call.h"
#include "usrsub/solver_abi.h"

/* An entry of GFOSUB's signature that does nothing, exported so that the
 * floor reaches it through dlsym as a host reaches a library's entries. */
USRSUB_EXPORT usrsub_gfosub_fn hx_floor_empty_entry;

typedef struct hx_empty_call {
    usrsub_gfosub_fn *fn;
    double out[6];
} hx_empty_call;

/* Looks the empty entry up through dlopen(NULL) and dlsym; -1 with msg. */
int hx_empty_call_init(hx_empty_call *e, hx_message *msg);
void hx_run_empty_call(void *ctx, long calls);

/* The queries an evaluation asked (the declared ones it used), replayed
 * through c_sysary and c_sysfnc with the evaluation's call record bound. */
typedef struct hx_host_replay {
    hx_call *call;
    int count;
    hx_query query[HX_MAX_QUERIES];
    double sink;
} hx_host_replay;

void hx_host_replay_init(hx_host_replay *r, hx_call *evaluation);
void hx_run_host_replay(void *ctx, long calls);

#endif
