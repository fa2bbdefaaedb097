/*
 * What the rig prescribes over time, per direction (x, y, z, ax, ay, az):
 * a deformation (value and rate) or, force-controlled, a load applied to I.
 *   circle R,W[,PLANE]     R (cos Wt, sin Wt) in a plane (xy, yz, zx, axay)
 *   line K,FROM,TO         direction K from FROM to TO over the run
 *   sine K,AMP,FREQ[,PHASE]  AMP sin(2 pi FREQ t + PHASE) added to K
 *   history FILE.csv       rows t,x,y,z,ax,ay,az, linear in between
 */
#ifndef HX_TOOLS_RIG_RIG_PATH_H
#define HX_TOOLS_RIG_RIG_PATH_H

#include "base/message.h"

#define HX_RIG_MAX_TERMS 16

typedef struct hx_rig_term {
    enum { HX_RIG_CIRCLE, HX_RIG_LINE, HX_RIG_SINE } kind;
    int a, b;                 /* directions (b: circle's second) */
    double p1, p2, p3;        /* circle R W; line FROM TO; sine AMP FREQ PHASE */
} hx_rig_term;

typedef struct hx_rig_path {
    int nterms;
    hx_rig_term term[HX_RIG_MAX_TERMS];
    int nrows;                /* history */
    double *rows;             /* nrows x 7 */
    unsigned directions;      /* bit k: direction k is prescribed (or, force-controlled, solved) */
} hx_rig_path;

/* Adds "circle", "line", "sine" with its comma-separated text. */
int hx_rig_path_add(hx_rig_path *p, const char *kind, const char *text, hx_message *msg);
int hx_rig_path_history(hx_rig_path *p, const char *csv, hx_message *msg);
void hx_rig_path_free(hx_rig_path *p);

/* Value and rate at t of a run that ends at t_end. */
void hx_rig_path_at(const hx_rig_path *p, double t, double t_end, double value[6], double rate[6]);

/* Index of "x", "y", "z", "ax", "ay", "az" (or fx..tz), else -1. */
int hx_direction_index(const char *name);

#endif
