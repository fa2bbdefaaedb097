/* Param_Unit names and sizes (units.h). */
#include "model/units.h"

#include <ctype.h>
#include <stddef.h>
#include <string.h>

typedef struct unit_name {
    const char *name; /* lower case, without underscores */
    double si;
} unit_name;

#define INCH 0.0254
#define FOOT 0.3048
#define POUND_MASS 0.45359237
#define STANDARD_GRAVITY 9.80665
#define POUND_FORCE (POUND_MASS * STANDARD_GRAVITY)

static const unit_name lengths[] = {
    {"millimeter", 1e-3}, {"mm", 1e-3}, {"centimeter", 1e-2}, {"cm", 1e-2}, {"meter", 1.0},
    {"m", 1.0}, {"kilometer", 1e3}, {"km", 1e3}, {"micrometer", 1e-6}, {"inch", INCH},
    {"foot", FOOT}, {"mile", 1609.344}, {NULL, 0}};
static const unit_name forces[] = {
    {"newton", 1.0}, {"knewton", 1e3}, {"kilonewton", 1e3}, {"millinewton", 1e-3},
    {"meganewton", 1e6}, {"dyne", 1e-5}, {"kilogramforce", STANDARD_GRAVITY},
    {"kgforce", STANDARD_GRAVITY}, {"poundforce", POUND_FORCE},
    {"kpoundforce", 1e3 * POUND_FORCE}, {"ounceforce", POUND_FORCE / 16.0}, {NULL, 0}};
static const unit_name masses[] = {
    {"kilogram", 1.0}, {"kg", 1.0}, {"gram", 1e-3}, {"milligram", 1e-6}, {"megagram", 1e3},
    {"tonne", 1e3}, {"poundmass", POUND_MASS}, {"kpoundmass", 1e3 * POUND_MASS},
    {"ouncemass", POUND_MASS / 16.0}, {"slug", POUND_FORCE / FOOT}, {NULL, 0}};
static const unit_name times[] = {
    {"second", 1.0}, {"sec", 1.0}, {"millisecond", 1e-3}, {"microsecond", 1e-6},
    {"minute", 60.0}, {"hour", 3600.0}, {NULL, 0}};
static const unit_name angles[] = {{"radian", 1.0}, {"degree", 0.017453292519943295}, {NULL, 0}};

static const unit_name *table_of(enum usrsub_unit_kind kind)
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

int hx_unit_size(enum usrsub_unit_kind kind, const char *name, double *si)
{
    const unit_name *t = table_of(kind);
    if (t == NULL || name == NULL)
        return -1;
    char folded[32];
    size_t n = 0;
    for (const char *p = name; *p != '\0'; ++p) {
        if (*p == '_')
            continue;
        if (n + 1 == sizeof folded)
            return -1;
        folded[n++] = (char)tolower((unsigned char)*p);
    }
    folded[n] = '\0';
    for (; t->name != NULL; ++t)
        if (strcmp(t->name, folded) == 0) {
            *si = t->si;
            return 0;
        }
    return -1;
}

const char *hx_unit_names(enum usrsub_unit_kind kind)
{
    switch (kind) {
    case USRSUB_UNIT_LENGTH: return "MILLIMETER, CENTIMETER, METER, KILOMETER, INCH, FOOT, MILE";
    case USRSUB_UNIT_FORCE:
        return "NEWTON, KILO_NEWTON, MILLI_NEWTON, DYNE, KILOGRAM_FORCE, POUND_FORCE,"
               " KPOUND_FORCE, OUNCE_FORCE";
    case USRSUB_UNIT_MASS:
        return "KILOGRAM, GRAM, MEGAGRAM, POUND_MASS, KPOUND_MASS, OUNCE_MASS, SLUG";
    case USRSUB_UNIT_TIME: return "SECOND, MILLISECOND, MINUTE, HOUR";
    case USRSUB_UNIT_ANGLE: return "RADIAN, DEGREE";
    default: return "";
    }
}
