/* Param_Unit names and sizes (units.h). */
#include "model/units.h"

#include <ctype.h>
#include <stddef.h>
#include <string.h>

typedef struct unit_name {
    const char *name; /* lower case, without underscores */
    double si;
    const char *abbreviation; /* three characters; NULL on a second spelling */
} unit_name;

#define INCH 0.0254
#define FOOT 0.3048
#define POUND_MASS 0.45359237
#define STANDARD_GRAVITY 9.80665
#define POUND_FORCE (POUND_MASS * STANDARD_GRAVITY)

static const unit_name lengths[] = {
    {"millimeter", 1e-3, "MM "}, {"mm", 1e-3, NULL}, {"centimeter", 1e-2, "CM "},
    {"cm", 1e-2, NULL}, {"meter", 1.0, "M  "}, {"m", 1.0, NULL}, {"kilometer", 1e3, "KM "},
    {"km", 1e3, NULL}, {"micrometer", 1e-6, "UM "}, {"inch", INCH, "IN "},
    {"foot", FOOT, "FT "}, {"mile", 1609.344, "MI "}, {NULL, 0, NULL}};
static const unit_name forces[] = {
    {"newton", 1.0, "N  "}, {"knewton", 1e3, "KN "}, {"kilonewton", 1e3, NULL},
    {"millinewton", 1e-3, "MLN"}, {"meganewton", 1e6, "MGN"}, {"dyne", 1e-5, "DYN"},
    {"kilogramforce", STANDARD_GRAVITY, "KGF"}, {"kgforce", STANDARD_GRAVITY, NULL},
    {"poundforce", POUND_FORCE, "LBF"}, {"kpoundforce", 1e3 * POUND_FORCE, "KLF"},
    {"ounceforce", POUND_FORCE / 16.0, "OZF"}, {NULL, 0, NULL}};
static const unit_name masses[] = {
    {"kilogram", 1.0, "KG "}, {"kg", 1.0, NULL}, {"gram", 1e-3, "G  "},
    {"milligram", 1e-6, "MG "}, {"megagram", 1e3, "T  "}, {"tonne", 1e3, NULL},
    {"poundmass", POUND_MASS, "LBM"}, {"kpoundmass", 1e3 * POUND_MASS, "KLM"},
    {"ouncemass", POUND_MASS / 16.0, "OZM"}, {"slug", POUND_FORCE / FOOT, "SLG"},
    {NULL, 0, NULL}};
static const unit_name times[] = {
    {"second", 1.0, "S  "}, {"sec", 1.0, NULL}, {"millisecond", 1e-3, "MS "},
    {"microsecond", 1e-6, "US "}, {"minute", 60.0, "MIN"}, {"hour", 3600.0, "HR "},
    {NULL, 0, NULL}};
static const unit_name angles[] = {{"radian", 1.0, "RAD"},
                                   {"degree", 0.017453292519943295, "DEG"},
                                   {NULL, 0, NULL}};

static const unit_name *table_of(enum hx_unit_kind kind)
{
    switch (kind) {
    case HX_UNIT_LENGTH: return lengths;
    case HX_UNIT_FORCE: return forces;
    case HX_UNIT_MASS: return masses;
    case HX_UNIT_TIME: return times;
    case HX_UNIT_ANGLE: return angles;
    default: return NULL;
    }
}

int hx_unit_size(enum hx_unit_kind kind, const char *name, double *si)
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

const char *hx_unit_abbreviation(enum hx_unit_kind kind, double si)
{
    for (const unit_name *t = table_of(kind); t != NULL && t->name != NULL; ++t)
        if (t->abbreviation != NULL && t->si == si)
            return t->abbreviation;
    return "   ";
}

const char *hx_unit_names(enum hx_unit_kind kind)
{
    switch (kind) {
    case HX_UNIT_LENGTH: return "MILLIMETER, CENTIMETER, METER, KILOMETER, INCH, FOOT, MILE";
    case HX_UNIT_FORCE:
        return "NEWTON, KILO_NEWTON, MILLI_NEWTON, DYNE, KILOGRAM_FORCE, POUND_FORCE,"
               " KPOUND_FORCE, OUNCE_FORCE";
    case HX_UNIT_MASS:
        return "KILOGRAM, GRAM, MEGAGRAM, POUND_MASS, KPOUND_MASS, OUNCE_MASS, SLUG";
    case HX_UNIT_TIME: return "SECOND, MILLISECOND, MINUTE, HOUR";
    case HX_UNIT_ANGLE: return "RADIAN, DEGREE";
    default: return "";
    }
}
