/*
 * Reads a .gbi mount-limits file: HEADER (FILE_TYPE 'gbi'), UNITS, and
 * MOUNT_LIMITS with the twelve IMPACT_PARAMETERS_{TRA|ROT}_{X|Y|Z}_{POS|NEG}
 * = K E C D L lines (commas, spaces or tabs between) and an optional ACTIVE.
 * K is converted as force per length^E (force length per angle^E for a
 * rotation), so that K (q - L)^E is a force in the model's units.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "usrsub/readers/mount_limits_reader.h"

static int read_limits(const usrsub_teim_file *f, const usrsub_unit_factors *u, void *ctx,
                       usrsub_read_report *report, usrsub_message *msg)
{
    (void)report;
    usrsub_mount_limits *m = ctx;
    const usrsub_teim_block *b = usrsub_teim_find_block(f, "MOUNT_LIMITS");
    if (b == NULL)
        return usrsub_fail(msg, "'%s': no [MOUNT_LIMITS] block", f->path);
    static const char *const kinds[2] = {"TRA", "ROT"}, *const axes[3] = {"X", "Y", "Z"},
                             *const sides[2] = {"POS", "NEG"};
    /* every key must be one we know, so that a misspelled name is not lost */
    for (int e = 0; e < b->nentries; ++e) {
        const char *key = b->entry[e].key;
        int known = strcmp(key, "ACTIVE") == 0;
        for (int k = 0; k < 12 && !known; ++k) {
            char name[48];
            snprintf(name, sizeof name, "IMPACT_PARAMETERS_%s_%s_%s", kinds[k / 6],
                     axes[(k / 2) % 3], sides[k % 2]);
            known = strcmp(key, name) == 0;
        }
        if (!known)
            return usrsub_fail(msg, "'%s' line %d: '%s' is not a mount-limits keyword (expected"
                               " IMPACT_PARAMETERS_{TRA|ROT}_{X|Y|Z}_{POS|NEG} or ACTIVE)",
                               f->path, b->entry[e].line, key);
    }
    const usrsub_teim_entry *active = usrsub_teim_find_entry(b, "ACTIVE");
    double on = 1.0;
    if (active != NULL && (usrsub_teim_number(active->value, &on) != 0 || (on != 0.0 && on != 1.0)))
        return usrsub_fail(msg, "'%s' line %d: ACTIVE = '%s': expected 0 or 1", f->path,
                           active->line, active->value);
    m->nsides = 0;
    for (int k = 0; k < 12; ++k) {
        const int direction = (k / 6) * 3 + (k / 2) % 3, sign = k % 2 ? -1 : 1;
        char name[48];
        snprintf(name, sizeof name, "IMPACT_PARAMETERS_%s_%s_%s", kinds[k / 6],
                 axes[(k / 2) % 3], sides[k % 2]);
        const usrsub_teim_entry *e = usrsub_teim_find_entry(b, name);
        if (e == NULL)
            return usrsub_fail(msg, "'%s' line %d: [MOUNT_LIMITS] has no %s = K E C D L (a side"
                               " that should not act has K and C zero)", f->path, b->line, name);
        double v[5];
        if (usrsub_teim_numbers(e->value, v, 5) != 5)
            return usrsub_fail(msg, "'%s' line %d: %s: expected five numbers K E C D L, got '%s'",
                               f->path, e->line, name, e->value);
        static const char *const names[5] = {"K", "E", "C", "D", "L"};
        for (int i = 0; i < 5; ++i)
            if (i != 1 && v[i] < 0.0)
                return usrsub_fail(msg, "'%s' line %d: %s: %s = %g must not be negative",
                                   f->path, e->line, name, names[i], v[i]);
        if (v[1] < 1.0)
            return usrsub_fail(msg, "'%s' line %d: %s: E = %g must be at least 1 (a rising"
                               " stiffness)", f->path, e->line, name, v[1]);
        if ((v[0] == 0.0 && v[2] == 0.0) || on == 0.0)
            continue; /* inactive: costs nothing */
        const double fd = direction < 3 ? u->length : u->angle;
        const double ff = direction < 3 ? u->force : u->force * u->length;
        usrsub_limit_side *s = &m->side[m->nsides++];
        s->direction = direction;
        s->sign = sign;
        s->k = v[0] * ff / pow(fd, v[1]);
        s->e = v[1];
        s->c = v[2] * ff * u->time / fd;
        s->d = v[3] * fd;
        s->l = v[4] * fd;
    }
    usrsub_mount_limits_prepare(m);
    return 0;
}

int usrsub_mount_limits_read(const char *path, const double *model_scales,
                             usrsub_mount_limits **out, usrsub_read_report *report,
                             usrsub_message *msg)
{
    usrsub_mount_limits *m = calloc(1, sizeof *m);
    if (m == NULL)
        return usrsub_fail(msg, "out of memory");
    if (usrsub_property_file_read(path, "gbi", "a mount-limits file", model_scales, read_limits, m,
                                  report, msg) != 0) {
        usrsub_mount_limits_free(m);
        return -1;
    }
    *out = m;
    return 0;
}
