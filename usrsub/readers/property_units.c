/* Property-file units and their conversion (property_units.h). */
#include "usrsub/readers/property_units.h"

#include <math.h>
#include <stdio.h>

#include "usrsub/readers/units.h"

int usrsub_property_units_read(const usrsub_teim_file *f, const double *model_scales,
                               usrsub_unit_factors *factors, usrsub_message *notice,
                               int *has_notice, usrsub_message *msg)
{
    factors->length = factors->force = factors->mass = factors->time = factors->angle = 1.0;
    factors->converted = 0;
    factors->model_time_seconds = model_scales != NULL ? model_scales[USRSUB_UNIT_TIME] : 1.0;
    *has_notice = 0;
    const usrsub_teim_block *units = usrsub_teim_find_block(f, "UNITS");
    static const struct {
        const char *key;
        enum usrsub_unit_kind kind;
    } keys[] = {{"LENGTH", USRSUB_UNIT_LENGTH},
                {"FORCE", USRSUB_UNIT_FORCE},
                {"MASS", USRSUB_UNIT_MASS},
                {"TIME", USRSUB_UNIT_TIME},
                {"ANGLE", USRSUB_UNIT_ANGLE}};
    double file_si[USRSUB_UNIT_COUNT];
    for (int k = 0; units != NULL && k < 5; ++k) {
        const usrsub_teim_entry *e = usrsub_teim_find_entry(units, keys[k].key);
        if (e == NULL)
            return usrsub_fail(msg, "'%s' line %d: [UNITS] has no %s (expected one of %s)",
                               f->path, units->line, keys[k].key, usrsub_units_names(keys[k].kind));
        if (usrsub_units_size(keys[k].kind, e->value, &file_si[keys[k].kind]) != 0)
            return usrsub_fail(msg, "'%s' line %d: %s = '%s' is not a unit this library knows"
                               " (expected one of %s)", f->path, e->line, keys[k].key, e->value,
                               usrsub_units_names(keys[k].kind));
    }
    if (units == NULL) {
        snprintf(notice->text, sizeof notice->text, "'%s' has no [UNITS] block: its values are"
                 " used in the model's units as they are", f->path);
        *has_notice = 1;
        return 0;
    }
    if (model_scales == NULL) {
        snprintf(notice->text, sizeof notice->text, "the model declares no units: the values"
                 " of '%s' are used as they are, without conversion", f->path);
        *has_notice = 1;
        return 0;
    }
    factors->length = file_si[USRSUB_UNIT_LENGTH] / model_scales[USRSUB_UNIT_LENGTH];
    factors->force = file_si[USRSUB_UNIT_FORCE] / model_scales[USRSUB_UNIT_FORCE];
    factors->mass = file_si[USRSUB_UNIT_MASS] / model_scales[USRSUB_UNIT_MASS];
    factors->time = file_si[USRSUB_UNIT_TIME] / model_scales[USRSUB_UNIT_TIME];
    factors->angle = file_si[USRSUB_UNIT_ANGLE] / model_scales[USRSUB_UNIT_ANGLE];
    factors->converted = 1;
    return 0;
}

double usrsub_property_units_factor(const usrsub_unit_factors *u, int f, int l, int t, int a)
{
    return pow(u->force, f) * pow(u->length, l) * pow(u->time, t) * pow(u->angle, a);
}

double usrsub_property_units_displacement_factor(const usrsub_unit_factors *u, int k)
{
    return k < 3 ? u->length : u->angle;
}

double usrsub_property_units_force_factor(const usrsub_unit_factors *u, int k)
{
    return k < 3 ? u->force : u->force * u->length;
}
