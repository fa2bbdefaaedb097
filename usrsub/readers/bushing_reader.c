/*
 * Reads a .gbs bushing property file (TeimOrbit) into a bushing in the
 * model's units: HEADER, UNITS, GLOBAL, DIRECTIONS (ACTIVITY), the
 * SPLINE/CONSTANT/CUBIC_STIFFNESS_<dir> and CONSTANT_DAMPING_<dir> blocks,
 * PRELOAD_OFFSET_SCALE, and the blocks with internal states (docs/interface.md
 * §3.8): FRICTION, MOUNT_STIFFNESS and RUBBER_DAMPING_<dir>. An active
 * hydromount, or a rubber parameter whose equations are not published, is an
 * error that names it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "usrsub/readers/bushing_reader.h"
#include "usrsub/readers/case_compare.h"

static const char *const direction_names[6] = {"FX", "FY", "FZ", "TX", "TY", "TZ"};

enum method { SPLINE_STIFFNESS, CONSTANT_STIFFNESS, CUBIC_STIFFNESS, CONSTANT_DAMPING,
              RUBBER_DAMPING, HYDROMOUNT_DAMPING, FRICTION, METHOD_COUNT };
static const char *const method_names[METHOD_COUNT] = {
    "SPLINE_STIFFNESS", "CONSTANT_STIFFNESS", "CUBIC_STIFFNESS", "CONSTANT_DAMPING",
    "RUBBER_DAMPING", "HYDROMOUNT_DAMPING", "FRICTION"};

typedef struct reader {
    const usrsub_teim_file *f;
    usrsub_unit_factors units;
    usrsub_message *msg;
} reader;

static int direction_of(const char *name)
{
    for (int k = 0; k < 6; ++k)
        if (usrsub_strcasecmp(name, direction_names[k]) == 0)
            return k;
    return -1;
}

/* A keyword's value as a number; missing or not a number is an error. */
static int number(reader *r, const usrsub_teim_block *b, const char *key, double *value)
{
    const usrsub_teim_entry *e = usrsub_teim_find_entry(b, key);
    if (e == NULL)
        return usrsub_fail(r->msg, "'%s' line %d: [%s] has no %s", r->f->path, b->line, b->name,
                           key);
    if (usrsub_teim_number(e->value, value) != 0)
        return usrsub_fail(r->msg, "'%s' line %d: %s = '%s' is not a finite number", r->f->path,
                           e->line, key, e->value);
    return 0;
}

static const usrsub_teim_block *method_block(reader *r, int method, int k, int activity_line)
{
    char name[64];
    snprintf(name, sizeof name, "%s_%s", method_names[method], direction_names[k]);
    const usrsub_teim_block *b = usrsub_teim_find_block(r->f, name);
    if (b == NULL)
        usrsub_fail(r->msg, "'%s' line %d: DIRECTIONS makes %s active for %s, but there is no"
                    " [%s] block", r->f->path, activity_line, method_names[method],
                    direction_names[k], name);
    return b;
}

static int read_global(reader *r, usrsub_bushing *b)
{
    b->coupling = USRSUB_UNCOUPLED;
    b->group_epsilon[0] = b->group_epsilon[1] = 1e-9;
    const usrsub_teim_block *g = usrsub_teim_find_block(r->f, "GLOBAL");
    const usrsub_teim_entry *c = usrsub_teim_find_entry(g, "COUPLING");
    if (c != NULL) {
        if (usrsub_strcasecmp(c->value, "UNCOUPLED") == 0 || usrsub_strcasecmp(c->value, "NONE") == 0)
            b->coupling = USRSUB_UNCOUPLED;
        else if (usrsub_strcasecmp(c->value, "CYLINDRICAL") == 0)
            b->coupling = USRSUB_CYLINDRICAL;
        else if (usrsub_strcasecmp(c->value, "SPHERICAL") == 0)
            b->coupling = USRSUB_SPHERICAL;
        else
            return usrsub_fail(r->msg, "'%s' line %d: COUPLING = '%s': expected UNCOUPLED,"
                               " CYLINDRICAL or SPHERICAL", r->f->path, c->line, c->value);
    }
    if (usrsub_property_file_rotation_measure(r->f, &b->rotation_measure, r->msg) != 0)
        return -1;
    if (usrsub_teim_find_entry(g, "EPSILON") != NULL) {
        double eps;
        if (number(r, g, "EPSILON", &eps) != 0)
            return -1;
        if (!(eps > 0.0))
            return usrsub_fail(r->msg, "'%s' line %d: EPSILON = %g must be positive",
                               r->f->path, usrsub_teim_find_entry(g, "EPSILON")->line, eps);
        b->group_epsilon[0] = eps * r->units.length;
        b->group_epsilon[1] = eps * r->units.angle;
    }
    return 0;
}

/* DIRECTIONS (ACTIVITY): active[method][direction]; returns the table's line. */
static int read_activity(reader *r, int active[METHOD_COUNT][6], int *line)
{
    memset(active, 0, sizeof(int) * METHOD_COUNT * 6);
    const usrsub_teim_block *d = usrsub_teim_find_block(r->f, "DIRECTIONS");
    const usrsub_teim_table *t = usrsub_teim_find_table(d, "ACTIVITY");
    if (t == NULL)
        t = usrsub_teim_find_table(d, NULL);
    if (t == NULL)
        return usrsub_fail(r->msg, "'%s': no [DIRECTIONS] block with an (ACTIVITY) table",
                           r->f->path);
    *line = t->line;
    int column[6];
    for (int k = 0; k < 6; ++k)
        if ((column[k] = usrsub_teim_column(t, direction_names[k])) < 1)
            return usrsub_fail(r->msg, "'%s' line %d: the ACTIVITY table has no %s column (expected"
                               " { formulation FX FY FZ TX TY TZ })", r->f->path, t->line,
                               direction_names[k]);
    for (int row = 0; row < t->nrows; ++row) {
        const usrsub_teim_row *rw = &t->row[row];
        char label[96];
        snprintf(label, sizeof label, "%s", rw->ncells > 0 ? rw->cell[0] : "");
        for (char *p = label; *p; ++p)
            *p = (char)(*p >= 'a' && *p <= 'z' ? *p - 32 : *p);
        if (strcmp(label, "CUBIC_SIFFNESS") == 0)
            snprintf(label, sizeof label, "CUBIC_STIFFNESS");
        if (strcmp(label, "RUBER_DAMPING") == 0 || strcmp(label, "RUBBER_BUSHING") == 0)
            snprintf(label, sizeof label, "RUBBER_DAMPING");
        int method = -1;
        for (int m = 0; m < METHOD_COUNT; ++m)
            if (strcmp(label, method_names[m]) == 0)
                method = m;
        if (method < 0)
            return usrsub_fail(r->msg, "'%s' line %d: '%s' is not a formulation this library"
                               " knows (SPLINE_STIFFNESS, CONSTANT_STIFFNESS, CUBIC_STIFFNESS,"
                               " CONSTANT_DAMPING, RUBBER_DAMPING, HYDROMOUNT_DAMPING)",
                               r->f->path, rw->line, label);
        for (int k = 0; k < 6; ++k) {
            double v;
            if (column[k] >= rw->ncells || usrsub_teim_number(rw->cell[column[k]], &v) != 0 ||
                (v != 0.0 && v != 1.0))
                return usrsub_fail(r->msg, "'%s' line %d: %s, column %s: expected 0 or 1", r->f->path,
                                   rw->line, label, direction_names[k]);
            active[method][k] = v == 1.0;
            if (v == 1.0 && method == FRICTION)
                return usrsub_fail(r->msg, "'%s' line %d: friction is switched on by ACTIVE = 1"
                                   " in its [FRICTION] block, not in DIRECTIONS", r->f->path,
                                   rw->line);
            if (v == 1.0 && method == HYDROMOUNT_DAMPING)
                return usrsub_fail(r->msg, "'%s' line %d: %s is active for %s, but this library"
                                   " does not model %s (its fluid equations are not published;"
                                   " docs/interface.md §3.8); set it to 0 in DIRECTIONS",
                                   r->f->path, rw->line, label, direction_names[k], label);
        }
    }
    for (int k = 0; k < 6; ++k) {
        const int stiff = active[SPLINE_STIFFNESS][k] + active[CONSTANT_STIFFNESS][k] +
                          active[CUBIC_STIFFNESS][k];
        if (stiff > 1)
            return usrsub_fail(r->msg, "'%s' line %d: %s has more than one active stiffness"
                               " (at most one of SPLINE, CONSTANT and CUBIC_STIFFNESS)",
                               r->f->path, t->line, direction_names[k]);
        if (active[CONSTANT_DAMPING][k] + active[RUBBER_DAMPING][k] > 1)
            return usrsub_fail(r->msg, "'%s' line %d: %s has more than one active damping"
                               " (at most one of CONSTANT and RUBBER_DAMPING)", r->f->path,
                               t->line, direction_names[k]);
    }
    return 0;
}

static int read_spline(reader *r, usrsub_bushing_direction *dir, int k, int line)
{
    const usrsub_teim_block *b = method_block(r, SPLINE_STIFFNESS, k, line);
    if (b == NULL)
        return -1;
    const usrsub_teim_table *t = usrsub_teim_find_table(b, "SPLINE_DATA");
    if (t == NULL)
        t = usrsub_teim_find_table(b, NULL);
    if (t == NULL)
        return usrsub_fail(r->msg, "'%s' line %d: [%s] has no (SPLINE_DATA) { disp force } table",
                           r->f->path, b->line, b->name);
    int cx = usrsub_teim_column(t, "DISP"), cy = usrsub_teim_column(t, "FORCE");
    if (cx < 0 || cy < 0)
        cx = 0, cy = 1;
    double *x = malloc(sizeof(double) * (size_t)(t->nrows + 1));
    double *y = malloc(sizeof(double) * (size_t)(t->nrows + 1));
    int status = x && y ? 0 : usrsub_fail(r->msg, "out of memory");
    const double fx = usrsub_property_units_displacement_factor(&r->units, k);
    const double fy = usrsub_property_units_force_factor(&r->units, k);
    for (int i = 0; i < t->nrows && status == 0; ++i) {
        const usrsub_teim_row *rw = &t->row[i];
        if (rw->ncells != t->ncolumns || cx >= rw->ncells || cy >= rw->ncells ||
            usrsub_teim_number(rw->cell[cx], &x[i]) != 0 ||
            usrsub_teim_number(rw->cell[cy], &y[i]) != 0)
            status = usrsub_fail(r->msg, "'%s' line %d: expected a row of %d numbers {disp force}",
                                 r->f->path, rw->line, t->ncolumns);
        x[i] *= fx;
        y[i] *= fy;
    }
    if (status == 0 && usrsub_spline_init(&dir->spline, t->nrows, x, y, r->msg) != 0) {
        usrsub_message_prefix(r->msg, "'%s' line %d: [%s]", r->f->path, t->line, b->name);
        status = -1;
    }
    free(x);
    free(y);
    return status;
}

static int read_cubic(reader *r, usrsub_bushing_direction *dir, int k, int line)
{
    const usrsub_teim_block *b = method_block(r, CUBIC_STIFFNESS, k, line);
    if (b == NULL)
        return -1;
    usrsub_cubic_characteristic *c = &dir->cubic;
    if (number(r, b, "EN", &c->en) || number(r, b, "ENS", &c->ens) ||
        number(r, b, "RNF", &c->rnf) || number(r, b, "O", &c->o) || number(r, b, "OF", &c->of) ||
        number(r, b, "OS", &c->os) || number(r, b, "RPF", &c->rpf) || number(r, b, "EP", &c->ep) ||
        number(r, b, "EPS", &c->eps))
        return -1;
    /* the reference points default to the middle of their side */
    c->rp = 0.5 * (c->o + c->ep);
    c->rn = 0.5 * (c->o + c->en);
    if ((usrsub_teim_find_entry(b, "RP") && number(r, b, "RP", &c->rp)) ||
        (usrsub_teim_find_entry(b, "RN") && number(r, b, "RN", &c->rn)))
        return -1;
    const double fd = usrsub_property_units_displacement_factor(&r->units, k);
    const double ff = usrsub_property_units_force_factor(&r->units, k);
    c->en *= fd, c->rn *= fd, c->o *= fd, c->rp *= fd, c->ep *= fd;
    c->rnf *= ff, c->of *= ff, c->rpf *= ff;
    c->ens *= ff / fd, c->os *= ff / fd, c->eps *= ff / fd;
    if (usrsub_cubic_fit(c, r->msg) != 0) {
        usrsub_message_prefix(r->msg, "'%s' line %d: [%s]", r->f->path, b->line, b->name);
        return -1;
    }
    return 0;
}

static int read_constant(reader *r, int method, const char *key, int k, int line, double factor,
                         double *value)
{
    const usrsub_teim_block *b = method_block(r, method, k, line);
    if (b == NULL || number(r, b, key, value) != 0)
        return -1;
    if (*value < 0.0)
        return usrsub_fail(r->msg, "'%s' line %d: %s = %g in [%s] must not be negative",
                           r->f->path, usrsub_teim_find_entry(b, key)->line, key, *value, b->name);
    *value *= factor;
    return 0;
}

static int read_preload_offset_scale(reader *r, usrsub_bushing *b)
{
    for (int k = 0; k < 6; ++k) {
        b->dir[k].disp_scale = b->dir[k].force_scale = 1.0;
        b->dir[k].preload = b->dir[k].offset = 0.0;
    }
    const usrsub_teim_block *blk = usrsub_teim_find_block(r->f, "PRELOAD_OFFSET_SCALE");
    if (blk == NULL)
        return 0;
    const usrsub_teim_table *t = usrsub_teim_find_table(blk, NULL);
    if (t == NULL)
        return usrsub_fail(r->msg, "'%s' line %d: [PRELOAD_OFFSET_SCALE] has no"
                           " { direction P Q H V } table", r->f->path, blk->line);
    static const char *const cols[5] = {"DIRECTION", "P", "Q", "H", "V"};
    int c[5];
    for (int i = 0; i < 5; ++i)
        if ((c[i] = usrsub_teim_column(t, cols[i])) < 0)
            return usrsub_fail(r->msg, "'%s' line %d: the PRELOAD_OFFSET_SCALE table has no %s"
                               " column (expected { direction P Q H V })", r->f->path, t->line,
                               cols[i]);
    unsigned seen = 0;
    for (int i = 0; i < t->nrows; ++i) {
        const usrsub_teim_row *rw = &t->row[i];
        const int k = rw->ncells == t->ncolumns ? direction_of(rw->cell[c[0]]) : -1;
        if (k < 0)
            return usrsub_fail(r->msg, "'%s' line %d: expected a direction (FX FY FZ TX TY TZ)"
                               " and four numbers P Q H V", r->f->path, rw->line);
        if (seen & (1u << k))
            return usrsub_fail(r->msg, "'%s' line %d: %s appears twice in PRELOAD_OFFSET_SCALE",
                               r->f->path, rw->line, direction_names[k]);
        seen |= 1u << k;
        double v[4];
        for (int j = 0; j < 4; ++j)
            if (usrsub_teim_number(rw->cell[c[j + 1]], &v[j]) != 0)
                return usrsub_fail(r->msg, "'%s' line %d: %s = '%s' is not a finite number",
                                   r->f->path, rw->line, cols[j + 1], rw->cell[c[j + 1]]);
        usrsub_bushing_direction *d = &b->dir[k];
        d->preload = v[0] * usrsub_property_units_force_factor(&r->units, k);
        d->offset = v[1] * usrsub_property_units_displacement_factor(&r->units, k);
        d->disp_scale = v[2];
        d->force_scale = v[3];
    }
    return 0;
}

/* A keyword that must lie in [low, high] (inclusive bounds unless open). */
static int bounded(reader *r, const usrsub_teim_block *b, const char *key, double low,
                   int open_low, double high, double *value)
{
    if (number(r, b, key, value) != 0)
        return -1;
    if (*value < low || (open_low && *value == low) || *value > high)
        return usrsub_fail(r->msg, "'%s' line %d: %s = %g in [%s] must be %s %g%s", r->f->path,
                           usrsub_teim_find_entry(b, key)->line, key, *value, b->name,
                           open_low ? "greater than" : "at least", low,
                           isinf(high) ? "" : " and at most the static coefficient");
    return 0;
}

/* An optional keyword: its default when absent. */
static int optional(reader *r, const usrsub_teim_block *b, const char *key, double fallback,
                    double *value)
{
    *value = fallback;
    return usrsub_teim_find_entry(b, key) != NULL ? number(r, b, key, value) : 0;
}

/* A text keyword among choices: its index, the default when absent, -1 on error. */
static int choice(reader *r, const usrsub_teim_block *b, const char *key,
                  const char *const *choices, int count, int fallback)
{
    const usrsub_teim_entry *e = usrsub_teim_find_entry(b, key);
    if (e == NULL)
        return fallback;
    for (int k = 0; k < count; ++k)
        if (usrsub_strcasecmp(e->value, choices[k]) == 0)
            return k;
    return usrsub_fail(r->msg, "'%s' line %d: %s = '%s' in [%s]: expected '%s' or '%s'",
                       r->f->path, e->line, key, e->value, b->name, choices[0], choices[1]);
}

/* Whether a state block is switched on: its ACTIVE flag (default on). */
static int block_active(reader *r, const usrsub_teim_block *b, int *active)
{
    double on = 1.0;
    if (optional(r, b, "ACTIVE", 1.0, &on) != 0)
        return -1;
    if (on != 0.0 && on != 1.0)
        return usrsub_fail(r->msg, "'%s' line %d: ACTIVE = %g in [%s]: expected 0 or 1",
                           r->f->path, usrsub_teim_find_entry(b, "ACTIVE")->line, on, b->name);
    *active = on == 1.0;
    return 0;
}

/* [FRICTION] (docs/interface.md §3.8): LuGre on the rotations. */
static int read_friction(reader *r, usrsub_bushing *b, const usrsub_teim_block *f)
{
    usrsub_friction *fr = &b->friction;
    if (block_active(r, f, &fr->active) != 0 || !fr->active)
        return 0;
    static const char *const effects[2] = {"SLIDING", "STICTION"};
    static const char *const modes[2] = {"DYNAMICS_ONLY", "STATICS_AND_DYNAMICS"};
    double use_reaction;
    const double L = r->units.length, T = r->units.time;
    if (bounded(r, f, "MU_STATIC", 0.0, 1, INFINITY, &fr->mu_static) != 0 ||
        bounded(r, f, "MU_DYNAMIC", 0.0, 1, fr->mu_static, &fr->mu_dynamic) != 0 ||
        bounded(r, f, "TRANSITION_VELOCITY", 0.0, 1, INFINITY, &fr->transition_velocity) != 0 ||
        bounded(r, f, "BRISTLE_STIFFNESS", 0.0, 1, INFINITY, &fr->bristle_stiffness) != 0 ||
        bounded(r, f, "BALL_RADIUS", 0.0, 1, INFINITY, &fr->ball_radius) != 0 ||
        optional(r, f, "BRISTLE_DAMPING", 0.0, &fr->bristle_damping) != 0 ||
        optional(r, f, "SLIP_DAMPING", 0.0, &fr->slip_damping) != 0 ||
        optional(r, f, "PRELOAD_TORQUE", 0.0, &fr->preload_torque) != 0 ||
        optional(r, f, "USE_REACTION_FORCE", 1.0, &use_reaction) != 0)
        return -1;
    if ((fr->stiction = choice(r, f, "EFFECT", effects, 2, 1)) < 0 ||
        choice(r, f, "ANALYSIS_MODES", modes, 2, 0) < 0)
        return -1;
    if (fr->bristle_damping < 0.0 || fr->slip_damping < 0.0 || fr->preload_torque < 0.0)
        return usrsub_fail(r->msg, "'%s' line %d: BRISTLE_DAMPING, SLIP_DAMPING and PRELOAD_TORQUE"
                           " in [FRICTION] must not be negative", r->f->path, f->line);
    if (use_reaction != 1.0)
        return usrsub_fail(r->msg, "'%s' line %d: USE_REACTION_FORCE = %g: this library takes the"
                           " bushing's own force as the normal force (1); another joint's"
                           " reaction is not available to it", r->f->path,
                           usrsub_teim_find_entry(f, "USE_REACTION_FORCE")->line, use_reaction);
    /* to the model's units: velocities L/T, sigma0 1/L, sigma1 and sigma2 T/L */
    fr->transition_velocity *= L / T;
    fr->bristle_stiffness /= L;
    fr->bristle_damping *= T / L;
    fr->slip_damping *= T / L;
    fr->ball_radius *= L;
    fr->preload_torque *= usrsub_property_units_force_factor(&r->units, 3);
    return 0;
}

/* The node between a rotational mount and a bushing with friction carries an
 * inertia (docs/interface.md §3.8): the mount's K over this frequency squared,
 * in rad/s, so that the node's mode lies above the bands a vehicle model
 * resolves, whatever the file's units. */
#define MOUNT_NODE_FREQUENCY 1e4

/* [MOUNT_STIFFNESS] { direction K C }: a series spring and damper per direction. */
static int read_mount(reader *r, usrsub_bushing *b, const usrsub_teim_block *blk)
{
    int active;
    if (block_active(r, blk, &active) != 0 || !active)
        return 0;
    const usrsub_teim_table *t = usrsub_teim_find_table(blk, NULL);
    int c[3] = {-1, -1, -1};
    static const char *const cols[3] = {"DIRECTION", "K", "C"};
    for (int i = 0; t != NULL && i < 3; ++i)
        c[i] = usrsub_teim_column(t, cols[i]);
    if (t == NULL || c[0] < 0 || c[1] < 0 || c[2] < 0)
        return usrsub_fail(r->msg, "'%s' line %d: [MOUNT_STIFFNESS] has no { direction K C }"
                           " table", r->f->path, blk->line);
    for (int i = 0; i < t->nrows; ++i) {
        const usrsub_teim_row *rw = &t->row[i];
        const int k = rw->ncells == t->ncolumns ? direction_of(rw->cell[c[0]]) : -1;
        double K, C;
        if (k < 0 || usrsub_teim_number(rw->cell[c[1]], &K) != 0 ||
            usrsub_teim_number(rw->cell[c[2]], &C) != 0)
            return usrsub_fail(r->msg, "'%s' line %d: expected a direction (FX FY FZ TX TY TZ),"
                               " a stiffness K and a damping C", r->f->path, rw->line);
        if (b->dir[k].mount)
            return usrsub_fail(r->msg, "'%s' line %d: %s appears twice in MOUNT_STIFFNESS",
                               r->f->path, rw->line, direction_names[k]);
        if (!(K > 0.0) || C < 0.0)
            return usrsub_fail(r->msg, "'%s' line %d: the mount of %s needs K > 0 and C >= 0"
                               " (got K = %g, C = %g); leave a rigid direction out",
                               r->f->path, rw->line, direction_names[k], K, C);
        const double ff = usrsub_property_units_force_factor(&r->units, k);
        const double fd = usrsub_property_units_displacement_factor(&r->units, k);
        b->dir[k].mount = 1;
        b->dir[k].mount_k = K * ff / fd;
        b->dir[k].mount_c = C * ff * r->units.time / fd;
        const double node = MOUNT_NODE_FREQUENCY * r->units.model_time_seconds;
        b->dir[k].mount_inertia = b->dir[k].mount_k / (node * node);
    }
    return 0;
}

/* RUBBER_DAMPING_<dir>: the first-order filter with the dynamic part's K0 and
 * C0; the parts the vendor leaves unpublished must be neutral. */
static int read_rubber(reader *r, usrsub_bushing_direction *dir, int k, int line)
{
    const usrsub_teim_block *b = method_block(r, RUBBER_DAMPING, k, line);
    double n, preload, R, rmin, v[12];
    static const char *const neutral[] = {"K1", "K2", "C1", "C2", "P0", "P1", "Q0", "Q1"};
    static const double neutral_value[] = {0, 0, 0, 0, 1, 0, 1, 0};
    if (b == NULL || number(r, b, "NPRELOADS", &n) != 0)
        return -1;
    if (n != 1.0)
        return usrsub_fail(r->msg, "'%s' line %d: NPRELOADS = %g in [%s]: this library models one"
                           " load case (the weights of several are not published)",
                           r->f->path, usrsub_teim_find_entry(b, "NPRELOADS")->line, n, b->name);
    if (optional(r, b, "PRELOAD", 0.0, &preload) != 0 || number(r, b, "R", &R) != 0 ||
        optional(r, b, "RMIN", 0.0, &rmin) != 0 || number(r, b, "K0", &dir->rubber_k) != 0 ||
        number(r, b, "C0", &dir->rubber_c) != 0)
        return -1;
    for (int i = 0; i < 8; ++i) {
        if (optional(r, b, neutral[i], neutral_value[i], &v[i]) != 0)
            return -1;
        if (v[i] != neutral_value[i])
            return usrsub_fail(r->msg, "'%s' line %d: %s = %g in [%s]: this library models the"
                               " rubber's first-order filter with K0 and C0 (docs/interface.md"
                               " §3.8); the equations %s belongs to are not published: set it"
                               " to %g", r->f->path, usrsub_teim_find_entry(b, neutral[i])->line,
                               neutral[i], v[i], b->name, neutral[i], neutral_value[i]);
    }
    if (preload != 0.0)
        return usrsub_fail(r->msg, "'%s' line %d: PRELOAD = %g in [%s]: one load case's preload"
                           " weighs nothing without the (unpublished) multiple-preload rule; set"
                           " it to 0", r->f->path, usrsub_teim_find_entry(b, "PRELOAD")->line,
                           preload, b->name);
    /* the message gives the file's own R and RMIN, not their maximum */
    if (!(fmax(R, rmin) > 0.0) || dir->rubber_k < 0.0 || dir->rubber_c < 0.0)
        return usrsub_fail(r->msg, "'%s' line %d: [%s] needs R (or RMIN) > 0, K0 >= 0 and C0 >= 0"
                           " (got R %g, RMIN %g, K0 %g, C0 %g)", r->f->path, b->line, b->name,
                           R, rmin, dir->rubber_k, dir->rubber_c);
    R = fmax(R, rmin);
    const double ff = usrsub_property_units_force_factor(&r->units, k);
    const double fd = usrsub_property_units_displacement_factor(&r->units, k);
    dir->rubber = 1;
    dir->rubber_r = R / r->units.time;
    dir->rubber_k *= ff / fd;
    dir->rubber_c *= ff * r->units.time / fd;
    return 0;
}

static int read_bushing(reader *r, usrsub_bushing *b, usrsub_read_report *report)
{
    int active[METHOD_COUNT][6], line = 0;
    if (read_global(r, b) != 0 || read_activity(r, active, &line) != 0)
        return -1;
    const usrsub_teim_block *friction = usrsub_teim_find_block(r->f, "FRICTION");
    if (friction != NULL && usrsub_teim_find_entry(friction, "ACTIVE") == NULL) {
        usrsub_property_file_notice(report, "'%s': [FRICTION] has no ACTIVE flag and is taken"
                                    " as inactive", r->f->path);
        friction = NULL;
    }
    const usrsub_teim_block *mount = usrsub_teim_find_block(r->f, "MOUNT_STIFFNESS");
    if ((friction != NULL && read_friction(r, b, friction) != 0) ||
        (mount != NULL && read_mount(r, b, mount) != 0) || read_preload_offset_scale(r, b) != 0)
        return -1;
    for (int k = 0; k < 6; ++k) {
        usrsub_bushing_direction *d = &b->dir[k];
        const double ff = usrsub_property_units_force_factor(&r->units, k);
        const double fd = usrsub_property_units_displacement_factor(&r->units, k);
        int status = 0;
        if (active[SPLINE_STIFFNESS][k]) {
            d->stiffness = USRSUB_STIFFNESS_SPLINE;
            status = read_spline(r, d, k, line);
        } else if (active[CONSTANT_STIFFNESS][k]) {
            d->stiffness = USRSUB_STIFFNESS_CONSTANT;
            status = read_constant(r, CONSTANT_STIFFNESS, "K", k, line, ff / fd, &d->k);
        } else if (active[CUBIC_STIFFNESS][k]) {
            d->stiffness = USRSUB_STIFFNESS_CUBIC;
            status = read_cubic(r, d, k, line);
        }
        if (status == 0 && active[CONSTANT_DAMPING][k]) {
            d->damped = 1;
            status = read_constant(r, CONSTANT_DAMPING, "C", k, line, ff * r->units.time / fd, &d->c);
        }
        if (status == 0 && active[RUBBER_DAMPING][k])
            status = read_rubber(r, d, k, line);
        if (status != 0)
            return -1;
    }
    usrsub_bushing_prepare(b);
    return 0;
}

static int read_body(const usrsub_teim_file *f, const usrsub_unit_factors *units, void *ctx,
                     usrsub_read_report *report, usrsub_message *msg)
{
    reader r = {f, *units, msg};
    return read_bushing(&r, ctx, report);
}

int usrsub_bushing_read(const char *path, const double *model_scales, usrsub_bushing **out,
                        usrsub_read_report *report, usrsub_message *msg)
{
    usrsub_bushing *b = calloc(1, sizeof *b);
    if (b == NULL)
        return usrsub_fail(msg, "out of memory");
    if (usrsub_property_file_read(path, "gbs", "a bushing property file", model_scales, read_body,
                                  b, report, msg) != 0) {
        usrsub_bushing_free(b);
        return -1;
    }
    *out = b;
    return 0;
}
