/* Gravity and the model's loads on the bodies. */
#ifndef HX_SIM_DYNAMICS_LOADS_H
#define HX_SIM_DYNAMICS_LOADS_H

#include "sim/dynamics/dynamics.h"

/* What one load puts on the bodies at a state: a force F at a world point
 * and a couple T (world axes) on each of one or two bodies (the second the
 * reaction). */
typedef struct hx_load_share {
    int count;
    int body[2];
    double point[2][3], F[2][3], T[2][3];
} hx_load_share;

/* Load k at frames fr (at their time): its expressions evaluated
 * (docs/interface.md §8), a ROTATIONAL Force_SpringDamper's AZ unwrapped
 * against its angle held in turn (a data's turn + njoints, joint_turns.h).
 * 0, or -1 with "file:line:column: element: what at t = ..." in msg when an
 * expression faults (a division by zero, a value that is not finite, ...). */
int hx_load_share_at(const hx_model *m, const hx_frames *fr, const double *turn, int k,
                     hx_load_share *share, hx_message *msg);

/* The most bodies hx_load_bodies lists: the three markers the load names and
 * the four of each of its expressions' inputs (a variable read adds those it
 * reads, which are distinct bodies of the model: more only in a model of
 * more bodies than this). */
#define HX_LOAD_BODIES_MAX (3 + 7 * 64 * 4)

/* The bodies load k depends on, each once (ground included): those of the
 * markers it names (I, J or the reference marker) and of every marker its
 * expressions measure, known from the parse (docs/interface.md §8.6),
 * and of those the variables they read measure, through the variables those
 * read in turn (a USERSUB variable's: those its VARSUB declared).
 * Returns their count; bodies holds HX_LOAD_BODIES_MAX. */
int hx_load_bodies(const hx_dynamics *d, int k, int *bodies);
/* The bodies variable k reads, as above (ground included); their count
 * (bodies holds HX_LOAD_BODIES_MAX). */
int hx_variable_bodies(const hx_dynamics *d, int k, int *bodies);

/* The Control_Diff states (their slots) load k's expressions read by DIF,
 * directly or through the variables they read, each once; their count
 * (slots holds HX_LOAD_BODIES_MAX). */
int hx_load_diffs(const hx_dynamics *d, int k, int *slots);

/* Load k's force at dd's frames as the outputs give it (expr/evaluate.h's
 * hx_expr_outputs.loads), twelve values: on I at I's origin, then on J where
 * the load puts its reaction (zeros for an action-only or a switched-off
 * load). 0, or -1 with an expression's fault in msg. */
int hx_loads_output(const hx_dynamics *d, const hx_dynamics_data *dd, int k, double out[12],
                    hx_message *msg);

/* The forces stage's gravity and loads at dd->frames, onto the bodies, and
 * their power; 0, or -1 with the failure recorded in dd (an expression's
 * fault). */
int hx_loads_apply(const hx_dynamics *d, hx_dynamics_data *dd, double *power);

#endif
