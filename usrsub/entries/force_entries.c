/*
 * GFOSUB and FIESUB (dispatching on par[0]) and the named force entries
 * ABM_BUSHING(_FIELD), MOUNT_LIMITS(_FIELD), FLEX_JOINT(_FIELD): set up once
 * per element, then measure (GFOSUB form) or take (FIESUB form) the
 * deformation and evaluate.
 */
#include <math.h>
#include <string.h>

#include "element_cache.h"
#include "entry_report.h"
#include "finite.h"
#include "force_model.h"
#include "usrsub/solver_abi.h"

static int gfosub_interface = ELEMENT_GFOSUB;
static int fiesub_interface = ELEMENT_FIESUB;

static int arguments_ok(const char *routine, const int *id, const double *par, const int *npar)
{
    if (id != NULL && npar != NULL && *npar >= 0 && (*npar == 0 || par != NULL))
        return 1;
    entry_report_error(routine, id != NULL ? *id : 0, NULL, "called with a missing argument (id,"
                       " par or npar) or a negative npar");
    return 0;
}

static const force_model *model_of(const char *routine, int interface, int code, int id,
                                   const double *par, int npar)
{
    element_signature sig = {interface, id, code, par, npar};
    element_setup_report report;
    int set_up_now;
    const force_model *m = element_cache_lookup(
        &sig, force_model_setup, force_model_release,
        interface == ELEMENT_GFOSUB ? &gfosub_interface : &fiesub_interface, &set_up_now, &report);
    if (set_up_now)
        entry_report_setup(routine, id, set_up_now, m, &report);
    return m;
}

static void gfosub_entry(const char *routine, int code, int *id, double *time, double *par,
                         int *npar, int *dflag, int *iflag, double *result)
{
    (void)time, (void)dflag, (void)iflag; /* no history; the dependency pass asks the same */
    if (result == NULL)
        return;
    memset(result, 0, 6 * sizeof(double));
    if (!arguments_ok(routine, id, par, npar))
        return;
    const force_model *m = model_of(routine, ELEMENT_GFOSUB, code, *id, par, *npar);
    if (m == NULL)
        return;
    double d[6] = {0, 0, 0, 0, 0, 0}, v[6] = {0, 0, 0, 0, 0, 0};
    char failed[64];
    if (measure_deformation(m->i_marker, m->j_marker, m->needs, d, v, failed) != 0) {
        entry_report_error(routine, *id, "query", "the host could not answer %s (markers %d and %d);"
                           " the output is zero", failed, m->i_marker, m->j_marker);
        return;
    }
    if (!all_finite(d, 6) || !all_finite(v, 6)) {
        entry_report_error(routine, *id, "state", "the host's deformation (%g %g %g %g %g %g) or rate"
                           " (%g %g %g %g %g %g) is not finite; the output is zero", d[0], d[1],
                           d[2], d[3], d[4], d[5], v[0], v[1], v[2], v[3], v[4], v[5]);
        return;
    }
    force_model_evaluate(m, d, v, result, NULL, NULL);
    if (!all_finite(result, 6)) {
        memset(result, 0, 6 * sizeof(double));
        entry_report_error(routine, *id, "result", "the force at deformation (%g %g %g %g %g %g) is not"
                           " finite (a state out of any sensible range); the output is zero",
                           d[0], d[1], d[2], d[3], d[4], d[5]);
    }
}

static void zero_field(double *field, double *dfddis, double *dfdvel)
{
    memset(field, 0, 6 * sizeof(double));
    if (dfddis != NULL) {
        memset(dfddis, 0, 36 * sizeof(double));
        memset(dfdvel, 0, 36 * sizeof(double));
    }
}

static void fiesub_entry(const char *routine, int code, int *id, double *time, double *par,
                         int *npar, double *disp, double *velo, int *dflag, int *iflag,
                         double *field, double *dfddis, double *dfdvel)
{
    (void)time, (void)dflag, (void)iflag;
    if (field == NULL)
        return;
    const int partials = dfddis != NULL && dfdvel != NULL;
    /* the evaluation writes every output; each way out before it zeros them */
    if (!arguments_ok(routine, id, par, npar)) {
        zero_field(field, partials ? dfddis : NULL, dfdvel);
        return;
    }
    if (disp == NULL || velo == NULL) {
        zero_field(field, partials ? dfddis : NULL, dfdvel);
        entry_report_error(routine, *id, NULL, "called without disp or velo");
        return;
    }
    const force_model *m = model_of(routine, ELEMENT_FIESUB, code, *id, par, *npar);
    if (m == NULL) {
        zero_field(field, partials ? dfddis : NULL, dfdvel);
        return;
    }
    if (!all_finite(disp, 6) || !all_finite(velo, 6)) {
        zero_field(field, partials ? dfddis : NULL, dfdvel);
        entry_report_error(routine, *id, "state", "disp (%g %g %g %g %g %g) or velo (%g %g %g %g %g %g)"
                           " is not finite; the output is zero", disp[0], disp[1], disp[2],
                           disp[3], disp[4], disp[5], velo[0], velo[1], velo[2], velo[3],
                           velo[4], velo[5]);
        return;
    }
    force_model_evaluate(m, disp, velo, field, partials ? dfddis : NULL, partials ? dfdvel : NULL);
    if (!all_finite(field, 6) || (partials && (!all_finite(dfddis, 36) || !all_finite(dfdvel, 36)))) {
        zero_field(field, partials ? dfddis : NULL, dfdvel);
        entry_report_error(routine, *id, "result", "the force at disp (%g %g %g %g %g %g) is not finite (a"
                           " state out of any sensible range); the output is zero", disp[0],
                           disp[1], disp[2], disp[3], disp[4], disp[5]);
    }
}

void STDCALL GFOSUB(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                    double *result)
{
    gfosub_entry("GFOSUB", 0, id, time, par, npar, dflag, iflag, result);
}

void STDCALL FIESUB(int *id, double *time, double *par, int *npar, double *disp, double *velo,
                    int *dflag, int *iflag, double *field, double *dfddis, double *dfdvel)
{
    fiesub_entry("FIESUB", 0, id, time, par, npar, disp, velo, dflag, iflag, field, dfddis, dfdvel);
}

#define NAMED_ENTRIES(NAME, CODE)                                                               \
    void STDCALL NAME(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,     \
                      double *result)                                                            \
    {                                                                                            \
        gfosub_entry(#NAME, CODE, id, time, par, npar, dflag, iflag, result);                    \
    }                                                                                            \
    void STDCALL NAME##_FIELD(int *id, double *time, double *par, int *npar, double *disp,       \
                              double *velo, int *dflag, int *iflag, double *field,               \
                              double *dfddis, double *dfdvel)                                    \
    {                                                                                            \
        fiesub_entry(#NAME "_FIELD", CODE, id, time, par, npar, disp, velo, dflag, iflag, field, \
                     dfddis, dfdvel);                                                            \
    }

NAMED_ENTRIES(ABM_BUSHING, FORCE_BUSHING)
NAMED_ENTRIES(MOUNT_LIMITS, FORCE_MOUNT_LIMITS)
NAMED_ENTRIES(FLEX_JOINT, FORCE_FLEX_JOINT)
