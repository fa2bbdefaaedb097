/*
 * The state queries a library may make (docs/interface.md §5): c_sysary's
 * DISP, TDISP, RDISP, VEL, TVEL, RVEL, ARRAY and c_sysfnc's scalar measures
 * (frames/measure_functions.h), DIF and DIF1, with their arguments, and the
 * answers computed from a state; and the accelerations (c_sysary's ACC TACC
 * RACC, c_sysfnc's ACCX .. WDTM) and the forces (c_sysfnc's JOINT .. SPDP of
 * (id, jflag, comp, rm) and FX .. TM of (I[, J[, K]]; FM, TM of I[, J]), as the function
 * language's), whose values the algebraic loop gives (host/loop_queries.h),
 * not the state.
 */
#ifndef HX_HOST_QUERIES_H
#define HX_HOST_QUERIES_H

#include <stddef.h>

#include "frames/frames.h"

typedef struct hx_query {
    char fnc[8];
    int function; /* the host's code for fnc, -1 when unknown */
    int ipar[4];
    int nsize;
    int is_array; /* c_sysary (1) or c_sysfnc (0) */
} hx_query;

/* A query as a library asked it (fnc truncated to 7 characters). */
void hx_query_make(hx_query *q, const char *fnc, const int *ipar, int nsize, int is_array);
int hx_query_same(const hx_query *a, const hx_query *b);
/* What a query's ids name: markers (the measures), a Control_Diff (DIF,
 * DIF1), an array (ARRAY), the loop's accelerations, a Reference_Variable
 * (VARVAL), the loop's forces; -1 for a query the host does not answer. */
enum hx_query_reads {
    HX_READS_MARKERS, HX_READS_DIFF, HX_READS_ARRAY, HX_READS_ACCELERATIONS, HX_READS_VARIABLE,
    HX_READS_FORCES
};
int hx_query_reads(const hx_query *q);
/* "DISP(11,21,21)" */
const char *hx_query_text(const hx_query *q, char *text, size_t size);

/* An acceleration's count of values (ACC 6, TACC RACC 3, ACCX .. WDTM 1)
 * and the measure of each (frames/acceleration_measures.h); 0 for any other
 * query. */
int hx_query_accelerations(const hx_query *q, int measures[6]);
/* A force's function (model/expr/functions.h: HX_FN_JOINT .. HX_FN_TM), one
 * value; -1 for any other query. */
int hx_query_force(const hx_query *q);

/* Answers a query at frames fr: the number of values written, or -1 for a
 * function the host does not answer (unknown, or asked through the wrong
 * utility), a bad nsize or an unknown marker. An acceleration's values are
 * zeros, and a force's a zero: the frames hold none, its caller answers from
 * the loop. */
int hx_answer(const hx_frames *fr, const hx_query *q, const int *ipar, double *values);
/* The three components of a measure family at once: 'D' (DX DY DZ, markers
 * I J K), 'A' (AX AY AZ, I J), 'V' (VX VY VZ, I J K L), 'W' (WX WY WZ, I J K),
 * with ipar's four ids (0: the world); 0, or -1 for an unknown marker. */
int hx_answer_family(const hx_frames *fr, char family, const int ipar[4], double v[3]);
/* The most values any query on model m can write: 6 (DISP, VEL), or the
 * count of its largest IC Reference_Array (ARRAY). */
int hx_query_capacity(const hx_model *m);
/* The same from its text and arguments. */
int hx_answer_query(const hx_frames *fr, const char *fnc, const int *ipar, int nsize,
                    int is_array, double *values);

#endif
