/* What the host notes of the utilities a call uses (utilities.h). */
#include "host/utilities.h"

#include <stdarg.h>
#include <stdio.h>

#include "host/call.h"

static const char *const names[HX_UTILITY_COUNT] = {
    [HX_UTILITY_RCNVRT] = "c_rcnvrt", [HX_UTILITY_STEP] = "c_step",
    [HX_UTILITY_STEP5] = "c_step5", [HX_UTILITY_HAVSIN] = "c_havsin",
    [HX_UTILITY_IMPACT] = "c_impact", [HX_UTILITY_BISTOP] = "c_bistop",
    [HX_UTILITY_POLY] = "c_poly", [HX_UTILITY_CHEBY] = "c_cheby",
    [HX_UTILITY_FORCOS] = "c_forcos", [HX_UTILITY_FORSIN] = "c_forsin",
    [HX_UTILITY_SHF] = "c_shf", [HX_UTILITY_GTARAY] = "c_gtaray",
    [HX_UTILITY_GETSTM] = "c_getstm", [HX_UTILITY_TIMGET] = "c_timget",
    [HX_UTILITY_GETINM] = "c_getinm", [HX_UTILITY_AKISPL] = "c_akispl",
    [HX_UTILITY_CUBSPL] = "c_cubspl", [HX_UTILITY_TCNVRT] = "c_tcnvrt",
    [HX_UTILITY_QUISPL] = "c_quispl", [HX_UTILITY_FITSPL] = "c_fitspl",
    [HX_UTILITY_GETMOD] = "c_getmod", [HX_UTILITY_GETINT] = "c_getint",
    [HX_UTILITY_GETVER] = "c_getver", [HX_UTILITY_GETSLV] = "c_getslv",
    [HX_UTILITY_GETCPU] = "c_getcpu", [HX_UTILITY_MODINF] = "c_modinf",
    [HX_UTILITY_SYSPAR] = "c_syspar", [HX_UTILITY_CUSFNC] = "c_cusfnc",
    [HX_UTILITY_GTCMAT] = "c_gtcmat", [HX_UTILITY_GET_STEP_INFO] = "c_get_step_info",
    [HX_UTILITY_GET_POST_STATES] = "c_get_post_states",
    [HX_UTILITY_PUT_SPLINE] = "c_put_spline", [HX_UTILITY_ANALYS] = "c_analys",
    [HX_UTILITY_DATOUT] = "c_datout", [HX_UTILITY_MODIFY] = "c_modify",
    [HX_UTILITY_ISTRNG] = "c_istrng", [HX_UTILITY_RSTRNG] = "c_rstrng"};

_Static_assert(HX_UTILITY_COUNT <= 64, "one bit per utility in the call's masks");

const char *hx_utility_name(hx_utility u)
{
    return u >= 0 && u < HX_UTILITY_COUNT ? names[u] : "c_?";
}

/* Notes bit u in the call's mask; 1 when the element has not reported it yet. */
static int note(hx_call *c, unsigned long long *mask, unsigned long long *reported,
                hx_utility u)
{
    const unsigned long long bit = 1ull << u;
    *mask |= bit;
    if (reported == NULL)
        return 1;
    const int fresh = !(*reported & bit);
    *reported |= bit;
    (void)c;
    return fresh;
}

void hx_utility_unoffered(hx_utility u)
{
    hx_call *c = hx_host_bound();
    if (c == NULL) {
        fprintf(stderr, "host: %s called outside any entry: this host does not offer it\n",
                hx_utility_name(u));
        return;
    }
    if (note(c, &c->unoffered, c->reported_unoffered, u) && c->messages != NULL)
        hx_messages_host(c->messages, "%s %d (%s) needs %s, which this host does not offer"
                         " (docs/interface.md §5.2); the call returned without an answer",
                         c->element, c->id, c->routine != NULL ? c->routine : "?",
                         hx_utility_name(u));
}

void hx_utility_refused(hx_utility u, const char *fmt, ...)
{
    char why[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, sizeof why, fmt, ap);
    va_end(ap);
    hx_call *c = hx_host_bound();
    if (c == NULL) {
        fprintf(stderr, "host: %s (outside any entry): %s; errflg = 1\n", hx_utility_name(u),
                why);
        return;
    }
    if (note(c, &c->misused, c->reported_misused, u) && c->messages != NULL)
        hx_messages_host(c->messages, "%s %d (%s) called %s with %s; it answered errflg = 1",
                         c->element, c->id, c->routine != NULL ? c->routine : "?",
                         hx_utility_name(u), why);
}

int hx_utility_non_finite(hx_utility u, const char *fmt, ...)
{
    char what[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    hx_call *c = hx_host_bound();
    if (c == NULL || !c->dependency_pass) {
        hx_utility_refused(u, "%s", what);
        return 0;
    }
    if (note(c, &c->non_finite, c->reported_non_finite, u) && c->messages != NULL)
        hx_messages_host(c->messages, "note: %s %d (%s) called %s with %s in its dependency pass"
                         " (iflag set, where the state queries answer zeros and a solver discards"
                         " what the routine returns): not a fault; it answered NaN", c->element,
                         c->id, c->routine != NULL ? c->routine : "?", hx_utility_name(u), what);
    return 1;
}

const char *hx_utilities_text(unsigned long long mask, char *text, size_t size)
{
    size_t n = 0;
    text[0] = '\0';
    for (int u = 0; u < HX_UTILITY_COUNT && n < size; ++u)
        if (mask & (1ull << u)) {
            const int w = snprintf(text + n, size - n, "%s%s", n > 0 ? ", " : "", names[u]);
            n += w > 0 ? (size_t)w : 0;
        }
    return text;
}
