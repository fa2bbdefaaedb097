/* Set-up and evaluation of force elements (force_model.h). */
#include "force_model.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "entry_report.h"
#include "host.h"
#include "property_cache.h"
#include "usrsub/readers/bushing_reader.h"
#include "usrsub/readers/flex_joint_reader.h"
#include "usrsub/readers/mount_limits_reader.h"
#include "usrsub/readers/user_list.h"

#define PATH_TEXT_MAX 4096

static int read_bushing(const char *path, const double *units, void **property,
                        usrsub_read_report *report, usrsub_message *msg)
{
    usrsub_bushing *b;
    if (usrsub_bushing_read(path, units, &b, report, msg) != 0)
        return -1;
    *property = b;
    return 0;
}

static void free_bushing(void *property)
{
    usrsub_bushing_free(property);
}

static int read_limits(const char *path, const double *units, void **property,
                       usrsub_read_report *report, usrsub_message *msg)
{
    usrsub_mount_limits *m;
    if (usrsub_mount_limits_read(path, units, &m, report, msg) != 0)
        return -1;
    *property = m;
    return 0;
}

static void free_limits(void *property)
{
    usrsub_mount_limits_free(property);
}

static int read_joint(const char *path, const double *units, void **property,
                      usrsub_read_report *report, usrsub_message *msg)
{
    usrsub_flex_joint *j;
    if (usrsub_flex_joint_read(path, units, &j, report, msg) != 0)
        return -1;
    *property = j;
    return 0;
}

static void free_joint(void *property)
{
    usrsub_flex_joint_free(property);
}

/* The property file named by the Reference_String whose id is the next value. */
static const void *property_named(usrsub_user_list *u, const char *what, const char *kind,
                                  usrsub_property_read_fn *read, usrsub_property_free_fn *release,
                                  usrsub_element_setup_report *report)
{
    int string_id;
    if (usrsub_user_list_int(u, what, 1, INT_MAX, &string_id, &report->error) != 0)
        return NULL;
    char path[PATH_TEXT_MAX];
    if (usrsub_host_read_string(string_id, path, (int)sizeof path) != 0) {
        usrsub_fail(&report->error, "USER parameter %d (par[%d]): there is no Reference_String"
                    " %d (expected %s)", u->next + u->offset, u->next - 1, string_id, what);
        return NULL;
    }
    double scales[USRSUB_UNIT_COUNT];
    const int has_units = usrsub_host_model_units(scales);
    if (has_units < 0) {
        usrsub_fail(&report->error, "the host's c_gtunts reported unit sizes that are not"
                    " positive and finite (time %g s, length %g m, force %g N, mass %g kg)",
                    scales[USRSUB_UNIT_TIME], scales[USRSUB_UNIT_LENGTH],
                    scales[USRSUB_UNIT_FORCE], scales[USRSUB_UNIT_MASS]);
        return NULL;
    }
    const void *p = usrsub_property_cache_get(kind, path, has_units ? scales : NULL, read, release,
                                       &report->notices, &report->error);
    if (p == NULL)
        usrsub_message_prefix(&report->error, "Reference_String %d", string_id);
    return p;
}

static const char *const code_names = "1 (ABM_BUSHING), 2 (MOUNT_LIMITS) or 3 (FLEX_JOINT)";

/* Mount limits named by the next value; a file with no active side is
 * dropped, so that the element runs exactly as without it. */
static int limits_named(usrsub_force_model *m, usrsub_user_list *u, usrsub_element_setup_report *report)
{
    const usrsub_mount_limits *l = property_named(u, "the Reference_String id of the .gbi"
                                                  " mount-limits file", "gbi", read_limits,
                                                  free_limits, report);
    if (l == NULL)
        return -1;
    if (l->nsides > 0) {
        m->limits = l;
        m->needs.translation |= l->uses_translation;
        m->needs.rotation |= l->uses_rotation;
        m->needs.velocity |= l->uses_velocity;
        m->needs.twist |= l->uses_twist;
    }
    return 0;
}

void *usrsub_force_model_setup(const usrsub_element_signature *sig, void *ctx, usrsub_element_setup_report *report)
{
    (void)ctx;
    const int form = sig->form;
    usrsub_user_list u;
    int code = sig->code;
    if (code == 0) { /* GFOSUB/FIESUB: the code comes first */
        usrsub_user_list_init(&u, sig->par, sig->npar, 0);
        char what[96];
        snprintf(what, sizeof what, "the element code %s", code_names);
        if (usrsub_user_list_int(&u, what, 1, 3, &code, &report->error) != 0)
            return NULL;
        usrsub_user_list_init(&u, sig->par + 1, sig->npar - 1, 1);
    } else {
        usrsub_user_list_init(&u, sig->par, sig->npar, 0);
    }
    usrsub_force_model *m = calloc(1, sizeof *m);
    if (m == NULL) {
        usrsub_fail(&report->error, "out of memory");
        return NULL;
    }
    m->code = code;
    if (form == USRSUB_ELEMENT_YFOSUB && code != USRSUB_FORCE_BUSHING) {
        usrsub_fail(&report->error, "element code %d: the state-equation form (YFOSUB) carries"
                    " only the bushing, code 1 (ABM_BUSHING)", code);
        free(m);
        return NULL;
    }
    if (form == USRSUB_ELEMENT_GFOSUB &&
        (usrsub_user_list_int(&u, "the I marker id", 1, INT_MAX, &m->i_marker, &report->error) != 0 ||
         usrsub_user_list_int(&u, "the J marker id", 1, INT_MAX, &m->j_marker, &report->error) != 0)) {
        free(m);
        return NULL;
    }
    int status = 0, string_id = 0;
    const char *ends = "the list";
    switch (code) {
    case USRSUB_FORCE_BUSHING:
        m->bushing = property_named(&u, "the Reference_String id of the .gbs bushing file", "gbs",
                                    read_bushing, free_bushing, report);
        status = m->bushing != NULL ? 0 : -1;
        if (status == 0) /* checked a whole id by property_named */
            string_id = (int)u.par[u.next - 1];
        if (status == 0 && m->bushing->has_states && form != USRSUB_ELEMENT_YFOSUB)
            status = usrsub_fail(&report->error, "Reference_String %d: the bushing has internal"
                                 " states (friction, a mount or a rubber filter): it runs as a"
                                 " state equation, Force_StateEqn with YFOSUB (docs/interface.md"
                                 " §3.8)", string_id);
        if (status == 0 && form == USRSUB_ELEMENT_YFOSUB &&
            m->bushing->rotation_measure == USRSUB_ROTATION_VECTOR)
            status = usrsub_fail(&report->error, "Reference_String %d: ROTATION_MEASURE ="
                                 " 'ROTATION_VECTOR' is not available in the state-equation form"
                                 " (docs/interface.md §3.8)", string_id);
        if (status == 0) {
            usrsub_bushing_state_layout(m->bushing, &m->states);
            m->needs.translation = m->bushing->uses_translation;
            m->needs.rotation = m->bushing->uses_rotation;
            m->needs.velocity = m->bushing->uses_velocity;
            m->needs.twist = m->bushing->uses_twist;
            m->rotation_measure = m->bushing->rotation_measure;
        }
        if (status == 0 && u.next < u.npar)
            status = limits_named(m, &u, report);
        ends = "an ABM_BUSHING list (markers, .gbs id, optional .gbi id)";
        break;
    case USRSUB_FORCE_MOUNT_LIMITS:
        status = limits_named(m, &u, report);
        ends = "a MOUNT_LIMITS list (markers, .gbi id)";
        break;
    case USRSUB_FORCE_FLEX_JOINT:
        m->joint = property_named(&u, "the Reference_String id of the .gfj flexible-joint file",
                                  "gfj", read_joint, free_joint, report);
        status = m->joint != NULL ? 0 : -1;
        if (status == 0) {
            m->needs.translation = m->joint->uses_translation;
            m->needs.rotation = m->joint->uses_rotation;
            m->needs.velocity = m->joint->uses_velocity;
            m->needs.twist = m->joint->uses_twist;
            m->rotation_measure = m->joint->rotation_measure;
        }
        ends = "a FLEX_JOINT list (markers, .gfj id)";
        break;
    default:
        status = usrsub_fail(&report->error, "element code %d is not one of %s", code, code_names);
        break;
    }
    /* the host's split of psi and phi goes wrong only where the tilt is of the
     * size of rounding, and there phi moves ax and ay by that size alone: only
     * az needs the rest rule; every component of the rotation vector does */
    if (m->rotation_measure == USRSUB_ROTATION_VECTOR)
        m->needs.twist |= m->needs.rotation;
    m->constant_partials = code == USRSUB_FORCE_FLEX_JOINT &&
                           m->rotation_measure != USRSUB_ROTATION_VECTOR;
    if (status == 0)
        status = usrsub_user_list_end(&u, ends, &report->error);
    if (status != 0) {
        free(m);
        return NULL;
    }
    return m;
}

void usrsub_force_model_release(void *model)
{
    free(model); /* the property data belongs to the property cache */
}

/* The force law on the generalized deformation (x, rotation measure). */
static void evaluate_law(const usrsub_force_model *m, const double d[6], const double v[6], double F[6],
                         double *dFdd, double *dFdv)
{
    switch (m->code) {
    case USRSUB_FORCE_BUSHING:
        usrsub_bushing_force(m->bushing, d, v, F, dFdd, dFdv);
        break;
    case USRSUB_FORCE_FLEX_JOINT:
        usrsub_flex_joint_force(m->joint, d, v, F, dFdd, dFdv);
        break;
    default:
        memset(F, 0, 6 * sizeof(double));
        if (dFdd != NULL) {
            memset(dFdd, 0, 36 * sizeof(double));
            memset(dFdv, 0, 36 * sizeof(double));
        }
        break;
    }
    if (m->limits != NULL) /* on the raw deformation: never offset, scaled or coupled */
        usrsub_mount_limits_add(m->limits, d, v, F, dFdd, dFdv);
}

int usrsub_force_model_evaluate(const usrsub_force_model *m, const double d[6], const double v[6],
                         const double *R, double F[6], double *dFdd, double *dFdv)
{
    if (m->rotation_measure != USRSUB_ROTATION_VECTOR || !m->needs.rotation) {
        evaluate_law(m, d, v, F, dFdd, dFdv);
        return 0;
    }
    /* the law on (x, r) and (v, rdot); its rotational forces become torques */
    double rotation[9], A[9];
    if (R == NULL) {
        if (usrsub_rotation_of_projection_angles(d + 3, rotation, dFdd != NULL ? A : NULL) != 0) {
            memset(F, 0, 6 * sizeof(double));
            if (dFdd != NULL) {
                memset(dFdd, 0, 36 * sizeof(double));
                memset(dFdv, 0, 36 * sizeof(double));
            }
            return -1;
        }
        R = rotation;
    }
    usrsub_rotation_map map;
    usrsub_rotation_map_make(&map, R, v + 3, R == rotation && dFdd != NULL ? A : NULL);
    const double dm[6] = {d[0], d[1], d[2], map.r[0], map.r[1], map.r[2]};
    const double vm[6] = {v[0], v[1], v[2], map.rdot[0], map.rdot[1], map.rdot[2]};
    double Q[6], dQdd[36], dQdv[36];
    evaluate_law(m, dm, vm, Q, dFdd != NULL ? dQdd : NULL, dFdd != NULL ? dQdv : NULL);
    usrsub_rotation_map_forces(&map, Q, dFdd != NULL ? dQdd : NULL, dQdv, F, dFdd, dFdv);
    return 0;
}

const usrsub_force_model *usrsub_force_model_of(const char *routine, int form, int code, int id,
                                                const double *par, int npar)
{
    usrsub_element_signature sig = {form, id, code, par, npar};
    usrsub_element_setup_report report;
    int set_up_now;
    const usrsub_force_model *m = usrsub_element_cache_lookup(
        &sig, usrsub_force_model_setup, usrsub_force_model_release, NULL, &set_up_now, &report);
    if (set_up_now)
        usrsub_entry_report_setup(routine, id, set_up_now, m, &report);
    return m;
}
