/*
 * The built-in linear force statements (docs/interface.md §9.5):
 * SPRINGDAMPER into Force_SpringDamper, BUSHING into Force_Bushing, BEAM into
 * Force_Beam, the elements MotionSolve's pre-processor maps them to, built
 * by the XML reader's builders (model/builtin_forces.h).
 */
#include "model/adm/translate.h"

#include <stdio.h>
#include <strings.h>

static const char *const rotation_keys[4] = {"KT", "CT", "ANGLE", "TORQUE"};
static const char *const translation_keys[4] = {"K", "C", "LENGTH", "FORCE"};
static const char *const springdamper_attrs[4] = {"stiffness", "damping", "length", "preload"};

int hx_adm_build_springdamper(hx_adm_reader *r, hx_adm_entry *e)
{
    /* Adams' words, which TRANSLATION and ROTATION abbreviate */
    const int translation = hx_adm_has(e, "TRANSLATIONAL"), rotation = hx_adm_has(e, "ROTATIONAL");
    if (translation == rotation)
        return hx_adm_fail(r, e, e->line, "give TRANSLATIONAL (a force along the line from J to"
                           " I) or ROTATIONAL (a torque about J's z axis)");
    const char *const *own = rotation ? rotation_keys : translation_keys;
    const char *const *other = rotation ? translation_keys : rotation_keys;
    for (int k = 0; k < 4; ++k)
        if (hx_adm_has(e, other[k]))
            return hx_adm_fail(r, e, hx_adm_get(e, other[k])->line, "%s is a %s one's; this one"
                               " is %s", other[k], rotation ? "TRANSLATIONAL" : "ROTATIONAL",
                               rotation ? "ROTATIONAL" : "TRANSLATIONAL");
    if (!hx_adm_has(e, own[0]))
        return hx_adm_fail(r, e, e->line, "%s: no stiffness %s= given", rotation ? "ROTATIONAL"
                           : "TRANSLATIONAL", own[0]);
    hx_adm_element el;
    hx_adm_element_init(&el, "Force_SpringDamper");
    hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
    hx_adm_element_number(&el, "j_marker_id", hx_adm_ref(e, "J"));
    hx_adm_element_text(&el, "type", rotation ? "ROTATIONAL" : "TRANSLATIONAL");
    for (int k = 0; k < 4; ++k)
        hx_adm_element_number(&el, springdamper_attrs[k], hx_adm_number(e, own[k], 0, 0.0));
    return hx_adm_element_build(r, e, &el, NULL);
}

int hx_adm_build_bushing(hx_adm_reader *r, hx_adm_entry *e)
{
    static const char *const keys[6] = {"K", "KT", "C", "CT", "FORCE", "TORQUE"};
    static const char *const attrs[6][3] = {
        {"kx", "ky", "kz"},   {"ktx", "kty", "ktz"}, {"cx", "cy", "cz"},
        {"ctx", "cty", "ctz"}, {"preload_x", "preload_y", "preload_z"},
        {"preload_tx", "preload_ty", "preload_tz"}};
    hx_adm_element el;
    hx_adm_element_init(&el, "Force_Bushing");
    hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
    hx_adm_element_number(&el, "j_marker_id", hx_adm_ref(e, "J"));
    for (int k = 0; k < 6; ++k)
        for (int n = 0; n < 3; ++n)
            hx_adm_element_number(&el, attrs[k][n], hx_adm_number(e, keys[k], n, 0.0));
    return hx_adm_element_build(r, e, &el, NULL);
}

int hx_adm_build_beam(hx_adm_reader *r, hx_adm_entry *e)
{
    static const char *const keys[10] = {"LENGTH", "EMODULUS", "GMODULUS", "AREA", "IXX",
                                         "IYY",    "IZZ",      "ASY",      "ASZ",  "CRATIO"};
    static const char *const attrs[10] = {"length", "E",   "G",   "area", "ixx",
                                          "iyy",    "izz", "ASY", "ASZ",  "cratio"};
    const char *formulation = hx_adm_text(e, "FORMULATION");
    if (formulation != NULL && strcasecmp(formulation, "LINEAR") != 0)
        return hx_adm_fail(r, e, hx_adm_get(e, "FORMULATION")->line, "FORMULATION=%s: the"
                           " harness simulates the LINEAR one only", formulation);
    if (hx_adm_has(e, "CMATRIX") && hx_adm_has(e, "CRATIO"))
        return hx_adm_fail(r, e, hx_adm_get(e, "CRATIO")->line, "give CMATRIX or CRATIO, not"
                           " both");
    hx_adm_element el;
    hx_adm_element_init(&el, "Force_Beam");
    hx_adm_element_number(&el, "i_marker_id", hx_adm_ref(e, "I"));
    hx_adm_element_number(&el, "j_marker_id", hx_adm_ref(e, "J"));
    for (int k = 0; k < 10; ++k)
        if (hx_adm_has(e, keys[k]))
            hx_adm_element_number(&el, attrs[k], hx_adm_number(e, keys[k], 0, 0.0));
    char cmatrix[21 * 26]; /* 21 numbers of %.17g and a space each */
    if (hx_adm_has(e, "CMATRIX")) {
        size_t used = 0;
        for (int k = 0; k < 21; ++k)
            used += (size_t)snprintf(cmatrix + used, sizeof cmatrix - used, "%.17g ",
                                     hx_adm_number(e, "CMATRIX", k, 0.0));
        hx_adm_element_text(&el, "cmatrix", cmatrix);
    }
    return hx_adm_element_build(r, e, &el, NULL);
}
