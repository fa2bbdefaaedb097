/* Unit names and their SI sizes (units.h). */
#include "usrsub/readers/units.h"

#include <stddef.h>

#include "usrsub/readers/case_compare.h"

typedef struct unit_entry {
    const char *name;
    double si;
} unit_entry;

#define INCH 0.0254
#define FOOT 0.3048
#define POUND_FORCE 4.4482216152605
#define POUND_MASS 0.45359237

static const unit_entry lengths[] = {
    {"mm", 1e-3}, {"millimeter", 1e-3}, {"millimetre", 1e-3}, {"m", 1.0}, {"meter", 1.0},
    {"metre", 1.0}, {"cm", 1e-2}, {"centimeter", 1e-2}, {"km", 1e3}, {"kilometer", 1e3},
    {"mile", 1609.344}, {"foot", FOOT}, {"feet", FOOT}, {"ft", FOOT}, {"inch", INCH},
    {"in", INCH}, {"yard", 0.9144}, {"micrometer", 1e-6}, {"nanometer", 1e-9},
    {"angstrom", 1e-10}, {"mils", 1e-3 * INCH}, {"mills", 1e-3 * INCH},
    {"milliinch", 1e-3 * INCH}, {"microinch", 1e-6 * INCH}, {NULL, 0}};

static const unit_entry forces[] = {
    {"newton", 1.0}, {"n", 1.0}, {"kg_force", 9.80665}, {"kilogram_force", 9.80665},
    {"kgf", 9.80665}, {"knewton", 1e3}, {"kilonewton", 1e3}, {"kn", 1e3},
    {"pound_force", POUND_FORCE}, {"lbf", POUND_FORCE}, {"kpound_force", 1e3 * POUND_FORCE},
    {"kip", 1e3 * POUND_FORCE}, {"dyne", 1e-5}, {"ounce_force", POUND_FORCE / 16.0},
    {"centinewton", 1e-2}, {"millinewton", 1e-3}, {"micronewton", 1e-6},
    {"nanonewton", 1e-9}, {"meganewton", 1e6}, {"poundal", POUND_MASS * FOOT}, {NULL, 0}};

static const unit_entry masses[] = {
    {"kg", 1.0}, {"kilogram", 1.0}, {"gram", 1e-3}, {"g", 1e-3}, {"milligram", 1e-6},
    {"microgram", 1e-9}, {"nanogram", 1e-12}, {"tonne", 1e3}, {"megagram", 1e3},
    {"pound_mass", POUND_MASS}, {"lbm", POUND_MASS}, {"kpound_mass", 1e3 * POUND_MASS},
    {"ounce_mass", POUND_MASS / 16.0}, {"slug", POUND_FORCE / FOOT},
    {"slinch", POUND_FORCE / INCH}, {"us_ton", 2000.0 * POUND_MASS}, {NULL, 0}};

static const unit_entry times[] = {
    {"second", 1.0}, {"sec", 1.0}, {"s", 1.0}, {"millisecond", 1e-3}, {"ms", 1e-3},
    {"microsecond", 1e-6}, {"nanosecond", 1e-9}, {"minute", 60.0}, {"min", 60.0},
    {"hour", 3600.0}, {"h", 3600.0}, {"day", 86400.0}, {NULL, 0}};

static const unit_entry angles[] = {
    {"radian", 1.0}, {"radians", 1.0}, {"rad", 1.0},
    {"degree", 0.017453292519943295}, {"degrees", 0.017453292519943295},
    {"deg", 0.017453292519943295}, {NULL, 0}};

static const unit_entry *table_of(enum usrsub_unit_kind kind)
{
    switch (kind) {
    case USRSUB_UNIT_LENGTH: return lengths;
    case USRSUB_UNIT_FORCE: return forces;
    case USRSUB_UNIT_MASS: return masses;
    case USRSUB_UNIT_TIME: return times;
    case USRSUB_UNIT_ANGLE: return angles;
    default: return NULL;
    }
}

int usrsub_units_size(enum usrsub_unit_kind kind, const char *name, double *si)
{
    const unit_entry *t = table_of(kind);
    if (t == NULL || name == NULL)
        return -1;
    for (; t->name != NULL; ++t)
        if (usrsub_strcasecmp(t->name, name) == 0) {
            *si = t->si;
            return 0;
        }
    return -1;
}

const char *usrsub_units_names(enum usrsub_unit_kind kind)
{
    switch (kind) {
    case USRSUB_UNIT_LENGTH: return "mm, cm, m (meter), km, inch, foot, yard, mile, micrometer";
    case USRSUB_UNIT_FORCE:
        return "newton, knewton, kg_force, pound_force, kpound_force, ounce_force, dyne";
    case USRSUB_UNIT_MASS:
        return "kg, gram, tonne, pound_mass, kpound_mass, ounce_mass, slug, slinch";
    case USRSUB_UNIT_TIME: return "second (sec), millisecond, microsecond, minute, hour";
    case USRSUB_UNIT_ANGLE: return "radian, degree";
    default: return "";
    }
}
