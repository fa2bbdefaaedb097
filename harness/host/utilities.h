/*
 * The utilities a library may call beyond the state queries and messages
 * (docs/interface.md §5.2): which ones the host answers, which it only
 * names, and how a call of one it does not offer, or one with arguments it
 * refuses, is noted on the bound call and reported once per element.
 */
#ifndef HX_HOST_UTILITIES_H
#define HX_HOST_UTILITIES_H

#include <stddef.h>

/* Every utility of the Adams-compatible interface the host knows by name. */
typedef enum hx_utility {
    /* answered */
    HX_UTILITY_RCNVRT, HX_UTILITY_STEP, HX_UTILITY_STEP5, HX_UTILITY_HAVSIN,
    HX_UTILITY_IMPACT, HX_UTILITY_BISTOP, HX_UTILITY_POLY, HX_UTILITY_CHEBY,
    HX_UTILITY_FORCOS, HX_UTILITY_FORSIN, HX_UTILITY_SHF, HX_UTILITY_GTARAY,
    HX_UTILITY_GETSTM, HX_UTILITY_TIMGET, HX_UTILITY_GETINM, HX_UTILITY_AKISPL,
    HX_UTILITY_CUBSPL,
    /* not offered: named in the verdict */
    HX_UTILITY_TCNVRT, HX_UTILITY_QUISPL,
    HX_UTILITY_FITSPL, HX_UTILITY_GETMOD, HX_UTILITY_GETINT, HX_UTILITY_GETVER,
    HX_UTILITY_GETSLV, HX_UTILITY_GETCPU, HX_UTILITY_MODINF, HX_UTILITY_SYSPAR,
    HX_UTILITY_CUSFNC, HX_UTILITY_GTCMAT, HX_UTILITY_GET_STEP_INFO,
    HX_UTILITY_GET_POST_STATES, HX_UTILITY_PUT_SPLINE, HX_UTILITY_ANALYS,
    HX_UTILITY_DATOUT, HX_UTILITY_MODIFY, HX_UTILITY_ISTRNG, HX_UTILITY_RSTRNG,
    HX_UTILITY_COUNT
} hx_utility;

/* "c_rcnvrt" */
const char *hx_utility_name(hx_utility u);

/* The library called a utility the host does not offer: noted on the bound
 * call; reported once per element ("needs c_X, which this host does not
 * offer"). */
void hx_utility_unoffered(hx_utility u);

/* The library called an offered utility with arguments it refuses: the
 * utility sets its error flag; reported once per element and utility. */
void hx_utility_refused(hx_utility u, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* The library called an offered utility with a non-finite argument (`fmt`
 * names it). In a dependency pass, where the state queries answer zeros and a
 * solver discards what the routine returns, computing with zeros may give
 * NaN and is no fault: noted once per element, and 1 (the utility answers
 * NaN with its error flag clear, as a solver computing with it would). At
 * any other call it is a refusal (hx_utility_refused), and 0. */
int hx_utility_non_finite(hx_utility u, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Utilities documented by name only: defined (unoffered_utilities.c) so that
 * a library referring to them loads, called without touching arguments. */
void c_fitspl(void);
void c_getslv(void);
void c_getcpu(void);
void c_modinf(void);
void c_gtcmat(void);
void c_get_post_states(void);
void c_put_spline(void);
void c_istrng(void);
void c_rstrng(void);

/* "c_analys, c_modify" for the utilities set in mask. */
const char *hx_utilities_text(unsigned long long mask, char *text, size_t size);

#endif
