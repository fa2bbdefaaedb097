/*
 * The scalar measures of markers the harness answers (docs/interface.md
 * §5.1, §8.5): one enum and one function computing each from up to four
 * marker frames. The one implementation behind c_sysfnc (host/queries.c)
 * and the function expressions (expr/).
 */
#ifndef HX_FRAMES_MEASURE_FUNCTIONS_H
#define HX_FRAMES_MEASURE_FUNCTIONS_H

#include "frames/frames.h"

typedef enum hx_measure {
    HX_MEASURE_DX, HX_MEASURE_DY, HX_MEASURE_DZ,       /* (I[, J[, K]]) */
    HX_MEASURE_DM,                                     /* (I[, J]) */
    HX_MEASURE_AX, HX_MEASURE_AY, HX_MEASURE_AZ,       /* (I[, J]) */
    HX_MEASURE_PSI, HX_MEASURE_THETA, HX_MEASURE_PHI,  /* (I[, J]) */
    HX_MEASURE_YAW, HX_MEASURE_PITCH, HX_MEASURE_ROLL, /* (I[, J]) */
    HX_MEASURE_INCANG,                                 /* (I, J, K) */
    HX_MEASURE_VX, HX_MEASURE_VY, HX_MEASURE_VZ,       /* (I[, J[, K[, L]]]) */
    HX_MEASURE_VM, HX_MEASURE_VR,                      /* (I[, J[, L]]) */
    HX_MEASURE_WX, HX_MEASURE_WY, HX_MEASURE_WZ,       /* (I[, J[, K]]) */
    HX_MEASURE_WM,                                     /* (I[, J]) */
    HX_MEASURE_COUNT, /* the named measures, those c_sysfnc answers */
    /* ORIENT(system, component, I[, J]) (base/orientation_systems.h): one
     * measure per system and component, HX_MEASURE_ORIENT +
     * hx_orientation_code(system, component), of the frames I and J */
    HX_MEASURE_ORIENT = HX_MEASURE_COUNT
} hx_measure;

/* ORIENT's measure for system and component (both checked by the caller). */
hx_measure hx_measure_orient(int system, int component);

/* "DX" .. "WM", "ORIENT" */
const char *hx_measure_name(hx_measure m);
/* The measure named (upper case, exactly), or -1. */
int hx_measure_find(const char *name);
/* How many marker ids it takes: at least *least, at most *most. */
void hx_measure_markers(hx_measure m, int *least, int *most);

/* The measure of the frames given in the order of its arguments (I, J, then
 * K or L as the function takes them; the world frame for those left out).
 * Where a direction is undefined (VR of coincident I and J, INCANG with J on
 * I or K) the value is 0. */
double hx_measure_value(hx_measure m, const hx_frame *const f[4]);

#endif
