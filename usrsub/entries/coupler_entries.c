/*
 * COUSUB, COUXX, COUXX2: the coupler's solver entries. Decode once per
 * element (element cache), then a call is a few flops per term.
 */
#include <math.h>
#include <stdlib.h>

#include "element_cache.h"
#include "entry_alias.h"
#include "entry_report.h"
#include "finite.h"
#include "host.h"
#include "usrsub/readers/coupler_reader.h"
#include "usrsub/solver_abi.h"

typedef enum { COUPLER_PHI, COUPLER_GRADIENT, COUPLER_HESSIAN } coupler_output;

static const char *const routine_names[] = {"COUSUB", "COUXX", "COUXX2"};

static int lookup_string(void *ctx, int string_id, char *text, int capacity)
{
    (void)ctx;
    return usrsub_host_read_string(string_id, text, capacity);
}

static void *setup_coupler(const usrsub_element_signature *sig, void *ctx,
                           usrsub_element_setup_report *report)
{
    (void)ctx;
    usrsub_coupler *c = malloc(sizeof *c);
    if (c == NULL) {
        usrsub_fail(&report->error, "out of memory");
        return NULL;
    }
    if (usrsub_coupler_decode(c, sig->par, sig->npar, sig->code, lookup_string, NULL,
                              &report->error) != 0) {
        free(c);
        return NULL;
    }
    return c;
}

static void release_coupler(void *model)
{
    usrsub_coupler_free(model);
    free(model);
}

/* Outputs a call writes: 1 (phi), n or n*n, none for an ndisp it cannot trust. */
static int output_count(coupler_output what, int n)
{
    if (what == COUPLER_PHI)
        return 1;
    if (n < 1 || n > USRSUB_COUPLER_MAX_TERMS)
        return 0;
    return what == COUPLER_GRADIENT ? n : n * n;
}

static void zero(double *out, int count)
{
    for (int k = 0; k < count; ++k)
        out[k] = 0.0;
}

/* The cold path: say what is wrong with the arguments, zeros out. */
static void report_bad_call(coupler_output what, const int *id, const double *par,
                            const int *npar, const double *disp, const int *ndisp, double *out)
{
    const int n = ndisp != NULL ? *ndisp : 0;
    zero(out, output_count(what, n));
    const int element = id != NULL ? *id : 0;
    if (id == NULL || ndisp == NULL || disp == NULL || npar == NULL || *npar < 0 ||
        (*npar > 0 && par == NULL)) {
        usrsub_entry_report_error(routine_names[what], element, NULL, "called with a missing argument (id,"
                           " par, npar, disp or ndisp) or a negative npar");
        return;
    }
    for (int k = 0; k < n; ++k)
        if (!isfinite(disp[k])) {
            usrsub_entry_report_error(routine_names[what], element, "state", "disp[%d] (joint %d of %d) is %g:"
                               " a joint displacement must be finite; the output is zero", k,
                               k + 1, n, disp[k]);
            return;
        }
}

static void coupler_entry(coupler_output what, const int *id, const double *par,
                          const int *npar, const double *disp, const int *ndisp, double *out)
{
    if (out == NULL)
        return;
    if (id == NULL || ndisp == NULL || disp == NULL || npar == NULL || *npar < 0 ||
        (*npar > 0 && par == NULL)) {
        report_bad_call(what, id, par, npar, disp, ndisp, out);
        return;
    }
    const int n = *ndisp;
    usrsub_element_signature sig = {USRSUB_ELEMENT_COUPLER, *id, n, par, *npar};
    usrsub_element_setup_report report;
    int set_up_now;
    const usrsub_coupler *c =
        usrsub_element_cache_lookup(&sig, setup_coupler, release_coupler, NULL, &set_up_now, &report);
    if (set_up_now)
        usrsub_entry_report_setup(routine_names[what], *id, set_up_now, c, &report);
    if (c == NULL) {
        zero(out, output_count(what, n));
        return;
    }
    /* a decoded element has 2 or 3 terms, one per joint: n is trusted here */
    double sum = 0.0;
    for (int k = 0; k < n; ++k)
        sum += disp[k];
    if (!isfinite(sum)) { /* a non-finite entry, or finite ones that overflow the sum */
        for (int k = 0; k < n; ++k)
            if (!isfinite(disp[k])) {
                report_bad_call(what, id, par, npar, disp, ndisp, out);
                return;
            }
    }
    switch (what) {
    case COUPLER_PHI: *out = usrsub_coupler_phi(c, disp); break;
    case COUPLER_GRADIENT: usrsub_coupler_gradient(c, disp, out); break;
    case COUPLER_HESSIAN: usrsub_coupler_hessian(c, disp, out); break;
    }
    /* finite displacements far outside the data can still overflow (1e308 times
     * a slope): never pass an infinity on. The Hessian of the separable form is
     * diagonal (the rest written as exact zeros): its diagonal is what can overflow. */
    const int count = output_count(what, n);
    const int checked = what == COUPLER_PHI ? 1 : n, stride = what == COUPLER_HESSIAN ? n + 1 : 1;
    if (!usrsub_finite_all_strided(out, checked, stride)) {
        zero(out, count);
        usrsub_entry_report_error(routine_names[what], *id, "result", "the output at disp (%g %g %g) is"
                           " not finite (a displacement out of any sensible range); the output"
                           " is zero", disp[0], disp[1], n > 2 ? disp[2] : 0.0);
    }
}

void STDCALL COUSUB(int *id, double *time, double *par, int *npar, double *disp, int *ndisp,
                    int *iflag, double *phi)
{
    (void)time, (void)iflag; /* the coupler depends on disp alone */
    coupler_entry(COUPLER_PHI, id, par, npar, disp, ndisp, phi);
}

void STDCALL COUXX(int *id, double *time, double *par, int *npar, double *disp, int *ndisp,
                   int *iflag, double *dfda)
{
    (void)time, (void)iflag;
    coupler_entry(COUPLER_GRADIENT, id, par, npar, disp, ndisp, dfda);
}

void STDCALL COUXX2(int *id, double *time, double *par, int *npar, double *disp, int *ndisp,
                    int *iflag, double *d2fda2)
{
    (void)time, (void)iflag;
    coupler_entry(COUPLER_HESSIAN, id, par, npar, disp, ndisp, d2fda2);
}

USRSUB_ENTRY_ALIAS(usrsub_coupler_fn, cousub_, COUSUB)
USRSUB_ENTRY_ALIAS(usrsub_coupler_fn, couxx_, COUXX)
USRSUB_ENTRY_ALIAS(usrsub_coupler_fn, couxx2_, COUXX2)
