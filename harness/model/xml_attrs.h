/*
 * Shorthand for the attribute lists of the element descriptions
 * (xml_schema.h), private to the files that hold the descriptions.
 */
#ifndef HX_MODEL_XML_ATTRS_H
#define HX_MODEL_XML_ATTRS_H

#include "model/xml_schema.h"

#define REAL(name) {name, HX_ATTR_REAL, 0}
#define INT(name) {name, HX_ATTR_INT, 0}
#define TEXT(name) {name, HX_ATTR_TEXT, 0}
#define IGNORED(name) {name, HX_ATTR_IGNORED, 0}
#define REQUIRED(name, kind) {name, kind, 1}
#define END {NULL, HX_ATTR_IGNORED, 0}
#define ID REQUIRED("id", HX_ATTR_INT), IGNORED("label")
#define USER_CALL                                                                              \
    TEXT("usrsub_param_string"), TEXT("usrsub_dll_name"), TEXT("usrsub_fnc_name"),             \
        TEXT("script_name"), TEXT("interpreter")

#endif
