/*
 * COUSUB, COUXX, COUXX2: the coupler's solver entries. Decode once per
 * element (element cache), then a call is a few flops per term.
 */
#include <math.h>
#include <stdlib.h>

#include "element_cache.h"
#include "entry_report.h"
#include "host.h"
#include "usrsub/coupler.h"
#include "usrsub/solver_abi.h"

typedef enum { COUPLER_PHI, COUPLER_GRADIENT, COUPLER_HESSIAN } coupler_output;

static const char *const routine_names[] = {"COUSUB", "COUXX", "COUXX2"};

static int lookup_string(void *ctx, int string_id, char *text, int capacity)
{
    (void)ctx;
    return host_read_string(string_id, text, capacity);
}

static void *setup_coupler(const element_signature *sig, void *ctx,
                           element_setup_report *report)
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

static void coupler_entry(coupler_output what, const int *id, const double *par,
                          const int *npar, const double *disp, const int *ndisp, double *out)
{
    const char *routine = routine_names[what];
    if (out == NULL)
        return;
    const int n = ndisp != NULL ? *ndisp : 0;
    const int valid_n = n >= 2 && n <= USRSUB_COUPLER_MAX_TERMS;
    const int nout = what == COUPLER_PHI ? 1 : !valid_n ? 0 : what == COUPLER_GRADIENT ? n : n * n;
    for (int k = 0; k < nout; ++k)
        out[k] = 0.0;
    const int element = id != NULL ? *id : 0;
    const int count = npar != NULL ? *npar : -1;
    if (id == NULL || ndisp == NULL || disp == NULL || npar == NULL || count < 0 ||
        (count > 0 && par == NULL)) {
        entry_report_error(routine, element, "called with a missing argument (id, par, npar,"
                           " disp or ndisp) or a negative npar");
        return;
    }
    element_signature sig = {ELEMENT_COUPLER, element, n, par, count};
    element_setup_report report;
    int set_up_now;
    const usrsub_coupler *c =
        element_cache_get(&sig, setup_coupler, release_coupler, NULL, &set_up_now, &report);
    entry_report_setup(routine, element, set_up_now, c, &report);
    if (c == NULL)
        return;
    for (int k = 0; k < n; ++k)
        if (!isfinite(disp[k])) {
            entry_report_error(routine, element, "disp[%d] (joint %d of %d) is %g: a joint"
                               " displacement must be finite; the output is zero", k, k + 1,
                               n, disp[k]);
            return;
        }
    switch (what) {
    case COUPLER_PHI: *out = usrsub_coupler_phi(c, disp); break;
    case COUPLER_GRADIENT: usrsub_coupler_gradient(c, disp, out); break;
    case COUPLER_HESSIAN: usrsub_coupler_hessian(c, disp, out); break;
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
