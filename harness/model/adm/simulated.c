/*
 * Which statements the harness simulates (docs/interface.md §9.8), decided
 * once every statement is read and before any is built: a joint of a type the
 * model holds (FIXED, REVOLUTE, TRANSLATIONAL, CYLINDRICAL, SPHERICAL,
 * UNIVERSAL, HOOKE, PLANAR, CONVEL, RACKPIN, SCREW; between any parts; no initial conditions; a
 * JPRIM always), forces
 * given by function expressions (docs/interface.md §8) or by a user routine,
 * a VARIABLE by any expression or a user routine; then what names an
 * element that is not simulated (the COUPLER or MOTION of such a joint, the
 * ARRAY of such a VARIABLE, the FORCE_STATEEQN of such an ARRAY). Each is
 * named in a warning with its line and why, and counted as the XML reader
 * counts an element it does not model.
 */
#include <ctype.h>
#include <string.h>
#include <strings.h>

#include "model/adm/reader.h"

int hx_adm_is_user(const char *expression)
{
    if (expression == NULL)
        return 0;
    const char *p = expression;
    while (isspace((unsigned char)*p))
        ++p;
    if (strncasecmp(p, "USER", 4) != 0)
        return 0;
    p += 4;
    while (isspace((unsigned char)*p))
        ++p;
    return *p == '(';
}

static int is(const hx_adm_entry *e, const char *name)
{
    return strcmp(e->spec->name, name) == 0;
}

/* Why an entry is not simulated on its own ("" when it is). */
static const char *why_not(const hx_adm_entry *e, char *why, size_t size)
{
    why[0] = '\0';
    if (e->spec->role == HX_ADM_UNSIMULATED)
        return snprintf(why, size, "%s", e->spec->why), why;
    const char *function = hx_adm_text(e, "FUNCTION");
    if (is(e, "JOINT")) {
        const char *type = hx_adm_joint_type(e);
        if (type == NULL)
            return why; /* the builder's error: no type */
        const int jt = hx_joint_type_from_name(type);
        if (jt >= 0 && hx_joint_type_is_primitive((enum hx_joint_type)jt))
            snprintf(why, size, "a %s joint, a primitive, which the harness simulates as a"
                     " JPRIM (JPRIM/id, I=, J=, %s)", type, type);
        else if (jt < 0)
            snprintf(why, size, "a %s joint, which the harness does not simulate yet (it"
                     " simulates FIXED, REVOLUTE, TRANSLATIONAL, CYLINDRICAL, SPHERICAL,"
                     " UNIVERSAL, HOOKE, PLANAR, CONVEL, RACKPIN and SCREW joints)", type);
        else if (hx_adm_has(e, "IC") || hx_adm_has(e, "ICTRAN") || hx_adm_has(e, "ICROT"))
            snprintf(why, size, "initial conditions on a joint (IC, ICTRAN, ICROT), which the"
                     " harness does not apply");
    } else if (is(e, "MOTION")) {
        if (!hx_adm_has(e, "JOINT"))
            snprintf(why, size, "a motion between markers (I, J), which the harness does not"
                     " simulate yet (it simulates a joint's MOTION)");
    } else if (is(e, "FIELD")) { /* linear (no FUNCTION), or USER(...) calling FIESUB */
        if (function != NULL && !hx_adm_is_user(function))
            snprintf(why, size, "a FUNCTION expression, which this harness does not evaluate yet");
    }
    return why;
}

/* An element that names one not simulated: why, or "". */
static const char *why_named(hx_adm_reader *r, const hx_adm_entry *e, char *why, size_t size)
{
    why[0] = '\0';
    const hx_adm_keyword *kw = e->spec->keywords;
    for (int k = 0; kw != NULL && kw[k].name != NULL; ++k) {
        if (kw[k].kind != HX_ADM_ID || kw[k].refers == NULL || !e->values[k].present ||
            strcmp(kw[k].refers, "MARKER") == 0 || strcmp(kw[k].refers, "PART") == 0)
            continue;
        for (int i = 0; i < e->values[k].count; ++i) {
            const hx_adm_entry *o = hx_adm_find(r, kw[k].refers, (int)e->values[k].numbers[i]);
            if (o != NULL && o->unsimulated) {
                char label[48];
                snprintf(why, size, "it names %s, which is not simulated",
                         hx_adm_label(o, label, sizeof label));
                return why;
            }
        }
    }
    return why;
}

int hx_adm_decide_simulated(hx_adm_reader *r)
{
    char why[320];
    for (int k = 0; k < r->nentries; ++k) {
        hx_adm_entry *e = &r->entries[k];
        if (e->spec->role != HX_ADM_BUILD && e->spec->role != HX_ADM_UNSIMULATED)
            continue;
        if (why_not(e, why, sizeof why)[0] != '\0')
            hx_adm_unsimulated(r, e, "%s", why);
    }
    for (int changed = 1; changed;) { /* what names those, and what names that, ... */
        changed = 0;
        for (int k = 0; k < r->nentries; ++k) {
            hx_adm_entry *e = &r->entries[k];
            if (e->unsimulated || e->spec->role != HX_ADM_BUILD || e->spec->keywords == NULL ||
                is(e, "PINPUT") || is(e, "POUTPUT"))
                continue;
            if (why_named(r, e, why, sizeof why)[0] != '\0') {
                hx_adm_unsimulated(r, e, "%s", why);
                changed = 1;
            }
        }
    }
    return r->d->failed ? -1 : 0;
}
