/*
 * The model's settings in a dataset (docs/interface.md §9.7): UNITS into
 * Param_Unit, ACCGRAV into Force_Gravity, INTEGRATOR's ERROR (the tolerance
 * the dataset suggests; the rest noted), PINPUT and POUTPUT (a controls
 * plant's inputs and outputs) kept in the model.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "model/adm/translate.h"
#include "model/units.h"

/* UNITS/SYSTEM=: length, mass, force, time (Adams' unit systems). */
static const struct {
    const char *name;
    const char *units[4];
} systems[] = {{"MKS", {"METER", "KILOGRAM", "NEWTON", "SECOND"}},
               {"MMKS", {"MILLIMETER", "KILOGRAM", "NEWTON", "SECOND"}},
               {"CGS", {"CENTIMETER", "GRAM", "DYNE", "SECOND"}},
               {"FPS", {"FOOT", "POUND_MASS", "POUND_FORCE", "SECOND"}},
               {"IPS", {"INCH", "POUND_MASS", "POUND_FORCE", "SECOND"}}};

int hx_adm_build_units(hx_adm_reader *r, hx_adm_entry *e)
{
    static const char *const keywords[4] = {"LENGTH", "MASS", "FORCE", "TIME"};
    static const char *const attrs[4] = {"length_unit", "mass_unit", "force_unit", "time_unit"};
    static const enum hx_unit_kind kinds[4] = {HX_UNIT_LENGTH, HX_UNIT_MASS, HX_UNIT_FORCE,
                                               HX_UNIT_TIME};
    const char *names[4] = {NULL, NULL, NULL, NULL};
    const char *system = hx_adm_text(e, "SYSTEM");
    if (system != NULL) {
        size_t k = 0;
        while (k < sizeof systems / sizeof systems[0] && strcasecmp(systems[k].name, system) != 0)
            ++k;
        if (strcasecmp(system, "NONE") == 0) {
            for (int i = 0; i < 4; ++i)
                if (hx_adm_has(e, keywords[i]))
                    return hx_adm_fail(r, e, e->line, "SYSTEM=NONE and %s: give one",
                                       keywords[i]);
            return 0; /* no units: the numbers as they are, ucf 1 */
        }
        if (k == sizeof systems / sizeof systems[0])
            return hx_adm_fail(r, e, hx_adm_get(e, "SYSTEM")->line, "SYSTEM=%s is not a unit"
                               " system the harness knows (MKS, MMKS, CGS, FPS, IPS, NONE)", system);
        memcpy(names, systems[k].units, sizeof names);
    }
    double size[4];
    for (int i = 0; i < 4; ++i) {
        if (hx_adm_has(e, keywords[i]))
            names[i] = hx_adm_text(e, keywords[i]);
        size[i] = 1.0;
        if (names[i] != NULL && hx_unit_size(kinds[i], names[i], &size[i]) != 0)
            return hx_adm_fail(r, e, hx_adm_get(e, keywords[i])->line, "%s=%s is not a unit the"
                               " harness knows (%s)", keywords[i], names[i],
                               hx_unit_names(kinds[i]));
    }
    if (hx_adm_has(e, "UCF")) {
        /* the harness derives the units consistency factor from the units; a
         * dataset's own must agree (a different one is other physics) */
        const double ucf = hx_adm_number(e, "UCF", 0, 0.0);
        const double derived = size[3] * size[3] * size[2] / (size[1] * size[0]);
        if (!(fabs(ucf - derived) <= 1e-9 * derived))
            return hx_adm_fail(r, e, hx_adm_get(e, "UCF")->line, "UCF=%.10g, but the units give"
                               " %.10g: the harness takes the units' (give the units alone)",
                               ucf, derived);
    }
    hx_adm_element el;
    hx_adm_element_init(&el, "Param_Unit");
    for (int i = 0; i < 4; ++i)
        if (names[i] != NULL)
            hx_adm_element_text(&el, attrs[i], names[i]);
    return hx_adm_element_build(r, e, &el, NULL);
}

int hx_adm_build_accgrav(hx_adm_reader *r, hx_adm_entry *e)
{
    hx_adm_element el;
    hx_adm_element_init(&el, "Force_Gravity");
    hx_adm_element_number(&el, "grav_x", hx_adm_number(e, "IGRAV", 0, 0.0));
    hx_adm_element_number(&el, "grav_y", hx_adm_number(e, "JGRAV", 0, 0.0));
    hx_adm_element_number(&el, "grav_z", hx_adm_number(e, "KGRAV", 0, 0.0));
    return hx_adm_element_build(r, e, &el, NULL);
}

int hx_adm_build_integrator(hx_adm_reader *r, hx_adm_entry *e)
{
    if (hx_adm_has(e, "ERROR")) {
        const double error = hx_adm_number(e, "ERROR", 0, 0.0);
        if (!(error > 0.0))
            return hx_adm_fail(r, e, hx_adm_get(e, "ERROR")->line, "ERROR=%g must be positive",
                               error);
        r->d->m->suggested_error = error;
    }
    const int nk = hx_adm_keyword_count(e->spec);
    for (int k = 0; k < nk; ++k)
        if (e->values[k].present && strcmp(e->spec->keywords[k].name, "ERROR") != 0) {
            hx_adm_note(r, e->line, "INTEGRATOR: %s is read and has no effect (the harness's"
                        " integrators are chosen on its command line; ERROR is kept as the"
                        " tolerance the dataset suggests)", e->spec->keywords[k].name);
            break;
        }
    return 0;
}

int hx_adm_build_plant_port(hx_adm_reader *r, hx_adm_entry *e)
{
    hx_model *m = r->d->m;
    const int input = strcmp(e->spec->name, "PINPUT") == 0;
    hx_plant_port *p = input ? hx_draft_push(r->d, (void **)&m->pinputs, &m->npinputs,
                                             &r->d->cap_pinputs, sizeof *p, NULL, 0)
                             : hx_draft_push(r->d, (void **)&m->poutputs, &m->npoutputs,
                                             &r->d->cap_poutputs, sizeof *p, NULL, 0);
    if (p == NULL)
        return -1;
    const hx_adm_value *v = hx_adm_get(e, "VARIABLES");
    p->id = e->id;
    p->line = e->line;
    p->variable_ids = malloc(sizeof(int) * (size_t)v->count);
    if (p->variable_ids == NULL)
        return hx_adm_fail(r, e, e->line, "out of memory");
    p->nvariables = v->count;
    for (int k = 0; k < v->count; ++k)
        p->variable_ids[k] = (int)v->numbers[k];
    return 0;
}
