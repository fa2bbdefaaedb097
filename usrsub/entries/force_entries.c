/*
 * GFOSUB and FIESUB (dispatching on par[0]) and the named force entries
 * ABM_BUSHING(_FIELD), MOUNT_LIMITS(_FIELD), FLEX_JOINT(_FIELD): set up once
 * per element, then measure (GFOSUB form) or take (FIESUB form) the
 * deformation and evaluate.
 */
#include <math.h>
#include <string.h>

#include "element_cache.h"
#include "entry_alias.h"
#include "entry_report.h"
#include "finite.h"
#include "force_model.h"
#include "usrsub/solver_abi.h"

static void gfosub_entry(const char *routine, int code, int *id, double *time, double *par,
                         int *npar, int *dflag, int *iflag, double *result)
{
    (void)time, (void)dflag, (void)iflag; /* no history; the dependency pass asks the same */
    if (result == NULL)
        return;
    memset(result, 0, 6 * sizeof(double));
    if (!usrsub_entry_report_arguments_ok(routine, id, par, npar))
        return;
    const usrsub_force_model *m =
        usrsub_force_model_of(routine, USRSUB_ELEMENT_GFOSUB, code, *id, par, *npar);
    if (m == NULL)
        return;
    double d[6] = {0, 0, 0, 0, 0, 0}, v[6] = {0, 0, 0, 0, 0, 0}, R[9];
    char failed[64];
    const int wants_rotation = m->rotation_measure == USRSUB_ROTATION_VECTOR;
    if (usrsub_deformation_measure(m->i_marker, m->j_marker, m->needs, d, v, wants_rotation ? R : NULL,
                            failed) != 0) {
        usrsub_entry_report_error(routine, *id, "query", "the host could not answer %s (markers %d and %d);"
                           " the output is zero", failed, m->i_marker, m->j_marker);
        return;
    }
    if (!usrsub_finite_all(d, 6) || !usrsub_finite_all(v, 6)) {
        usrsub_entry_report_error(routine, *id, "state", "the host's deformation (%g %g %g %g %g %g) or rate"
                           " (%g %g %g %g %g %g) is not finite; the output is zero", d[0], d[1],
                           d[2], d[3], d[4], d[5], v[0], v[1], v[2], v[3], v[4], v[5]);
        return;
    }
    usrsub_force_model_evaluate(m, d, v, wants_rotation && m->needs.rotation ? R : NULL, result, NULL,
                         NULL);
    if (!usrsub_finite_all(result, 6)) {
        memset(result, 0, 6 * sizeof(double));
        usrsub_entry_report_error(routine, *id, "result", "the force at deformation (%g %g %g %g %g %g) is not"
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
    if (!usrsub_entry_report_arguments_ok(routine, id, par, npar)) {
        zero_field(field, partials ? dfddis : NULL, dfdvel);
        return;
    }
    if (disp == NULL || velo == NULL) {
        zero_field(field, partials ? dfddis : NULL, dfdvel);
        usrsub_entry_report_error(routine, *id, NULL, "called without disp or velo");
        return;
    }
    const usrsub_force_model *m =
        usrsub_force_model_of(routine, USRSUB_ELEMENT_FIESUB, code, *id, par, *npar);
    if (m == NULL) {
        zero_field(field, partials ? dfddis : NULL, dfdvel);
        return;
    }
    if (!usrsub_finite_all(disp, 6) || !usrsub_finite_all(velo, 6)) {
        zero_field(field, partials ? dfddis : NULL, dfdvel);
        usrsub_entry_report_error(routine, *id, "state", "disp (%g %g %g %g %g %g) or velo (%g %g %g %g %g %g)"
                           " is not finite; the output is zero", disp[0], disp[1], disp[2],
                           disp[3], disp[4], disp[5], velo[0], velo[1], velo[2], velo[3],
                           velo[4], velo[5]);
        return;
    }
    if (usrsub_force_model_evaluate(m, disp, velo, NULL, field, partials ? dfddis : NULL,
                             partials ? dfdvel : NULL) != 0) {
        usrsub_entry_report_error(routine, *id, "angles", "the projection angles (%g %g %g) belong to no"
                           " rotation near them (the rotation-vector measure needs one); the"
                           " output is zero", disp[3], disp[4], disp[5]);
        return;
    }
    /* constant partials were checked finite when the file was read */
    if (!usrsub_finite_all(field, 6) || (partials && !m->constant_partials &&
                                  (!usrsub_finite_all(dfddis, 36) || !usrsub_finite_all(dfdvel, 36)))) {
        zero_field(field, partials ? dfddis : NULL, dfdvel);
        usrsub_entry_report_error(routine, *id, "result", "the force at disp (%g %g %g %g %g %g) is not finite (a"
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

NAMED_ENTRIES(ABM_BUSHING, USRSUB_FORCE_BUSHING)
NAMED_ENTRIES(MOUNT_LIMITS, USRSUB_FORCE_MOUNT_LIMITS)
NAMED_ENTRIES(FLEX_JOINT, USRSUB_FORCE_FLEX_JOINT)

USRSUB_ENTRY_ALIAS(usrsub_gfosub_fn, gfosub_, GFOSUB)
USRSUB_ENTRY_ALIAS(usrsub_fiesub_fn, fiesub_, FIESUB)
USRSUB_ENTRY_ALIAS(usrsub_gfosub_fn, abm_bushing_, ABM_BUSHING)
USRSUB_ENTRY_ALIAS(usrsub_fiesub_fn, abm_bushing_field_, ABM_BUSHING_FIELD)
USRSUB_ENTRY_ALIAS(usrsub_gfosub_fn, mount_limits_, MOUNT_LIMITS)
USRSUB_ENTRY_ALIAS(usrsub_fiesub_fn, mount_limits_field_, MOUNT_LIMITS_FIELD)
USRSUB_ENTRY_ALIAS(usrsub_gfosub_fn, flex_joint_, FLEX_JOINT)
USRSUB_ENTRY_ALIAS(usrsub_fiesub_fn, flex_joint_field_, FLEX_JOINT_FIELD)
