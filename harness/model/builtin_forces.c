/*
 * The built-in linear force elements as expression loads (builtin_forces.h).
 * The expression text is generated here and parsed at the element's line,
 * so a fault names the element and its line; the load is tagged so that
 * messages and the force functions (BUSHING, SFORCE) name the element.
 */
#include "model/builtin_forces.h"

#include <stdio.h>
#include <strings.h>

#include "model/load_elements.h"
#include "model/xml_attrs.h"

const hx_attr_spec hx_springdamper_attrs[] = {
    ID, REQUIRED("i_marker_id", HX_ATTR_INT), REQUIRED("j_marker_id", HX_ATTR_INT),
    REQUIRED("type", HX_ATTR_TEXT), REQUIRED("stiffness", HX_ATTR_REAL), REAL("damping"),
    REAL("length"), REAL("preload"), END};

const hx_attr_spec hx_bushing_attrs[] = {
    ID, REQUIRED("i_marker_id", HX_ATTR_INT), REQUIRED("j_marker_id", HX_ATTR_INT),
    REAL("kx"), REAL("ky"), REAL("kz"), REAL("ktx"), REAL("kty"), REAL("ktz"),
    REAL("cx"), REAL("cy"), REAL("cz"), REAL("ctx"), REAL("cty"), REAL("ctz"),
    REAL("preload_x"), REAL("preload_y"), REAL("preload_z"), REAL("preload_tx"),
    REAL("preload_ty"), REAL("preload_tz"), END};

/* The attributes the load builders read, for the load made of the element. */
static const hx_attr_spec scalar_load[] = {INT("i_marker_id"), INT("j_marker_id"),
                                           TEXT("val_expression"), END};
static const hx_attr_spec vector_load[] = {TEXT("fx_expression"), TEXT("fy_expression"),
                                           TEXT("fz_expression"), TEXT("tx_expression"),
                                           TEXT("ty_expression"), TEXT("tz_expression"), END};

#define TEXT_MAX 256

/* A stiffness or damping below 0 feeds energy in: refused, as the pages do. */
static int refuse_negative(hx_draft *d, const hx_element_read *e, const char *const *names,
                           int n)
{
    for (int k = 0; k < n; ++k)
        if (hx_attr_number(e, names[k], 0.0) < 0.0) {
            hx_draft_fail(d, e->line, "%s %d: %s = %g: it must not be negative", e->name, e->id,
                          names[k], hx_attr_number(e, names[k], 0.0));
            return -1;
        }
    return 0;
}

/* The load read as e (its name, id, line), from the generated texts. */
static hx_element_read as_load(const hx_element_read *e, const hx_attr_spec *spec, int n,
                               char text[][TEXT_MAX])
{
    hx_element_read x = {.name = e->name, .line = e->line, .id = e->id, .spec = spec};
    while (spec[x.nspec].name != NULL)
        ++x.nspec;
    for (int k = 0; k < n; ++k) {
        x.value[x.nspec - n + k].present = 1;
        x.value[x.nspec - n + k].text = text[k];
    }
    return x;
}

/* The load just built (if it was) tagged as the element it stands for. */
static void tag_last(hx_draft *d, int before, enum hx_load_builtin builtin)
{
    if (d->m->nloads > before)
        d->m->loads[d->m->nloads - 1].builtin = builtin;
}

void hx_build_springdamper(hx_draft *d, const hx_element_read *e)
{
    const char *type = hx_attr_text(e, "type");
    const int rotational = strcasecmp(type, "ROTATIONAL") == 0;
    if (!rotational && strcasecmp(type, "TRANSLATIONAL") != 0) {
        hx_draft_fail(d, e->line, "%s %d: type \"%s\": expected TRANSLATIONAL or ROTATIONAL",
                      e->name, e->id, type);
        return;
    }
    static const char *const signs[2] = {"stiffness", "damping"};
    if (refuse_negative(d, e, signs, 2) != 0)
        return;
    const int i = hx_attr_int(e, "i_marker_id", 0), j = hx_attr_int(e, "j_marker_id", 0);
    const double k = hx_attr_number(e, "stiffness", 0.0), c = hx_attr_number(e, "damping", 0.0);
    const double free = hx_attr_number(e, "length", 0.0), pre = hx_attr_number(e, "preload", 0.0);
    char text[1][TEXT_MAX];
    if (rotational) /* AZ in (-pi, pi]: no full turns counted (docs/interface.md §7.17) */
        snprintf(text[0], TEXT_MAX, "-(%.17g)*WZ(%d,%d,%d)-(%.17g)*(AZ(%d,%d)-(%.17g))+(%.17g)",
                 c, i, j, j, k, i, j, free, pre);
    else
        snprintf(text[0], TEXT_MAX, "-(%.17g)*VR(%d,%d)-(%.17g)*(DM(%d,%d)-(%.17g))+(%.17g)", c,
                 i, j, k, i, j, free, pre);
    hx_element_read x = as_load(e, scalar_load, 1, text);
    x.value[0].present = x.value[1].present = 1;
    x.value[0].number = i, x.value[1].number = j;
    const int before = d->m->nloads;
    hx_build_scalar_load(d, &x, rotational, "val_expression");
    tag_last(d, before, HX_LOAD_SPRINGDAMPER);
}

void hx_build_bushing(hx_draft *d, const hx_element_read *e)
{
    static const char *const k_names[6] = {"kx", "ky", "kz", "ktx", "kty", "ktz"};
    static const char *const c_names[6] = {"cx", "cy", "cz", "ctx", "cty", "ctz"};
    static const char *const preloads[6] = {"preload_x", "preload_y", "preload_z",
                                            "preload_tx", "preload_ty", "preload_tz"};
    if (refuse_negative(d, e, k_names, 6) != 0 || refuse_negative(d, e, c_names, 6) != 0)
        return;
    const int i = hx_attr_int(e, "i_marker_id", 0), j = hx_attr_int(e, "j_marker_id", 0);
    char text[6][TEXT_MAX];
    for (int n = 0; n < 6; ++n) {
        const double k = hx_attr_number(e, k_names[n], 0.0), c = hx_attr_number(e, c_names[n], 0.0);
        const double pre = hx_attr_number(e, preloads[n], 0.0);
        const char axis = (char)('X' + n % 3);
        if (n < 3) /* I's displacement and velocity from J, seen by J, in J's axes */
            snprintf(text[n], TEXT_MAX, "-(%.17g)*D%c(%d,%d,%d)-(%.17g)*V%c(%d,%d,%d,%d)+(%.17g)",
                     k, axis, i, j, j, c, axis, i, j, j, j, pre);
        else /* the projected angles (§8.3) and I's angular velocity from J in J's axes */
            snprintf(text[n], TEXT_MAX, "-(%.17g)*A%c(%d,%d)-(%.17g)*W%c(%d,%d,%d)+(%.17g)", k,
                     axis, i, j, c, axis, i, j, j, pre);
    }
    hx_element_read x = as_load(e, vector_load, 6, text);
    const int before = d->m->nloads;
    hx_build_vector_load(d, &x, i, j, j);
    tag_last(d, before, HX_LOAD_BUSHING);
}
