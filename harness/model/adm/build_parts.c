/*
 * PART and MARKER (docs/interface.md §9.3): a part's frame (QG, REULER or
 * XG/ZG) and its mass, inertia and initial velocities; a marker's position
 * and orientation in its part's frame (QP, REULER or ZP/XP), or in the
 * frame of its RM marker; FLOATING markers placed where the force that
 * floats them puts them at t = 0. The harness reads markers in the world
 * frame at t = 0: every marker's world frame is worked out here and handed
 * to the draft as such.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "model/adm/translate.h"
#include "model/orientation.h"

static const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

static int is_identity(const double R[9])
{
    for (int k = 0; k < 9; ++k)
        if (R[k] != identity[k])
            return 0;
    return 1;
}

/* out = base * local (frames as p[3] then R[9]); a base that is the world's
 * leaves local as it is, to the bit. */
static void compose(double out[12], const double base[12], const double local[12])
{
    if (is_identity(base + 3)) {
        memcpy(out + 3, local + 3, 9 * sizeof(double));
        if (base[0] == 0.0 && base[1] == 0.0 && base[2] == 0.0)
            memcpy(out, local, 3 * sizeof(double));
        else
            v3_add(out, base, local);
        return;
    }
    double p[3], R[9];
    m3_apply(p, base + 3, local);
    v3_add(p, p, base);
    m3_mul(R, base + 3, local + 3);
    memcpy(out, p, sizeof p);
    memcpy(out + 3, R, sizeof R);
}

/* An orientation from a point on the z axis and a point in the x-z plane
 * (relative to the origin); with usexp the x axis lies along the second. */
static int axes_from_points(const double z_point[3], const double x_point[3], int has_x, int usexp,
                            double R[9], const char **why)
{
    double z[3], x[3], y[3];
    memcpy(z, z_point, sizeof z);
    if (has_x)
        memcpy(x, x_point, sizeof x);
    else { /* no XP: the reference frame's x axis, or its y axis when z lies along it */
        x[0] = 1.0, x[1] = 0.0, x[2] = 0.0;
        if (fabs(z[1]) + fabs(z[2]) <= 1e-9 * fabs(z[0]))
            x[0] = 0.0, x[1] = 1.0;
    }
    double *first = usexp ? x : z, *second = usexp ? z : x;
    const double n1 = v3_norm(first);
    if (!(n1 > 0.0)) {
        *why = usexp ? "XP is the marker's origin" : "ZP is the marker's origin";
        return -1;
    }
    v3_scale(first, first, 1.0 / n1);
    double along[3];
    v3_scale(along, first, v3_dot(second, first));
    v3_sub(second, second, along);
    const double n2 = v3_norm(second);
    if (!(n2 > 1e-12 * v3_norm(has_x ? x_point : second) && n2 > 0.0)) {
        *why = "XP lies on the z axis (ZP): it gives no x axis";
        return -1;
    }
    v3_scale(second, second, 1.0 / n2);
    /* the axes made orthonormal as direction cosines are (orientation.h) */
    v3_cross(y, z, x);
    hx_axes_from_xy(x, y, R);
    return 0;
}

/* A frame (p, R) of QP/QG and REULER or ZP/XP (ZG/XG) of an entry. */
static int local_frame(hx_adm_reader *r, hx_adm_entry *e, const char *q, const char *euler,
                       const char *zp, const char *xp, double frame[12])
{
    for (int k = 0; k < 3; ++k)
        frame[k] = hx_adm_number(e, q, k, 0.0);
    memcpy(frame + 3, identity, sizeof identity);
    const int has_euler = hx_adm_has(e, euler), has_z = hx_adm_has(e, zp),
              has_x = hx_adm_has(e, xp);
    if (has_euler && (has_z || has_x))
        return hx_adm_fail(r, e, e->line, "%s and %s/%s both orient it: give one", euler, zp, xp);
    if (has_euler) {
        hx_rotation_313(hx_adm_number(e, euler, 0, 0.0), hx_adm_number(e, euler, 1, 0.0),
                        hx_adm_number(e, euler, 2, 0.0), frame + 3);
        return 0;
    }
    if (!has_z && !has_x)
        return 0;
    if (!has_z)
        return hx_adm_fail(r, e, hx_adm_get(e, xp)->line, "%s without %s: the z axis is"
                           " given by %s", xp, zp, zp);
    double z[3], x[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
        z[k] = hx_adm_number(e, zp, k, 0.0) - frame[k];
        if (has_x)
            x[k] = hx_adm_number(e, xp, k, 0.0) - frame[k];
    }
    const char *why = "";
    if (axes_from_points(z, x, has_x, hx_adm_has(e, "USEXP"), frame + 3, &why) != 0)
        return hx_adm_fail(r, e, e->line, "%s", why);
    return 0;
}

int hx_adm_build_part(hx_adm_reader *r, hx_adm_entry *e)
{
    hx_adm_element el;
    if (hx_adm_has(e, "GROUND")) {
        static const char *const not_on_ground[] = {"MASS", "CM", "IM", "IP", "QG", "REULER",
                                                    "XG", "ZG", "VX", "VY", "VZ", "WX", "WY",
                                                    "WZ", "VM", "WM"};
        for (size_t k = 0; k < sizeof not_on_ground / sizeof not_on_ground[0]; ++k)
            if (hx_adm_has(e, not_on_ground[k]))
                return hx_adm_fail(r, e, hx_adm_get(e, not_on_ground[k])->line, "%s on the ground"
                                   " part: the ground is the world frame, at rest", not_on_ground[k]);
        memset(e->frame, 0, sizeof e->frame);
        memcpy(e->frame + 3, identity, sizeof identity);
        hx_adm_element_init(&el, "Body_Ground");
    } else {
        static const char *const needed[] = {"MASS", "CM", "IP"};
        for (size_t k = 0; k < 3; ++k)
            if (!hx_adm_has(e, needed[k]))
                return hx_adm_fail(r, e, e->line, "%s is missing: the harness simulates parts with"
                                   " mass, a centre-of-mass marker and inertia (MASS, CM, IP)",
                                   needed[k]);
        if (local_frame(r, e, "QG", "REULER", "ZG", "XG", e->frame) != 0)
            return -1;
        hx_adm_element_init(&el, "Body_Rigid");
        hx_adm_element_number(&el, "cg_id", hx_adm_ref(e, "CM"));
        if (hx_adm_has(e, "IM"))
            hx_adm_element_number(&el, "im_id", hx_adm_ref(e, "IM"));
        hx_adm_element_number(&el, "mass", hx_adm_number(e, "MASS", 0, 0.0));
        /* IP = xx, yy, zz [, xy, xz, yz]: Adams' order; both take the products as the
         * positive integrals (docs/interface.md §7.8, §9.3) */
        static const char *const inertia[6] = {"inertia_xx", "inertia_yy", "inertia_zz",
                                               "inertia_xy", "inertia_xz", "inertia_yz"};
        for (int k = 0; k < hx_adm_get(e, "IP")->count; ++k)
            hx_adm_element_number(&el, inertia[k], hx_adm_number(e, "IP", k, 0.0));
    }
    if (hx_adm_element_build(r, e, &el, NULL) != 0)
        return -1;
    e->index = r->d->m->nbodies - 1;
    return 0;
}

int hx_adm_build_marker(hx_adm_reader *r, hx_adm_entry *e)
{
    if (hx_adm_has(e, "FLOATING")) {
        static const char *const placed[] = {"QP", "REULER", "ZP", "XP", "USEXP", "RM"};
        for (size_t k = 0; k < sizeof placed / sizeof placed[0]; ++k)
            if (hx_adm_has(e, placed[k]))
                return hx_adm_fail(r, e, hx_adm_get(e, placed[k])->line, "%s on a FLOATING marker:"
                                   " the force that floats it places it", placed[k]);
    }
    hx_adm_element el;
    hx_adm_element_init(&el, "Reference_Marker");
    hx_adm_element_number(&el, "body_id", hx_adm_ref(e, "PART"));
    if (hx_adm_element_build(r, e, &el, NULL) != 0)
        return -1;
    e->index = r->d->m->nmarkers - 1;
    return 0;
}

/* The world frame of a marker entry at t = 0 (RM chains followed). */
static int place(hx_adm_reader *r, hx_adm_entry *e)
{
    if (e->frame_state == 2)
        return 0;
    if (e->frame_state == 1)
        return hx_adm_fail(r, e, hx_adm_get(e, "RM")->line, "its RM chain leads back to itself");
    e->frame_state = 1;
    double local[12];
    if (local_frame(r, e, "QP", "REULER", "ZP", "XP", local) != 0)
        return -1;
    const double *base;
    if (hx_adm_has(e, "RM")) {
        hx_adm_entry *rm = hx_adm_find(r, "MARKER", hx_adm_ref(e, "RM"));
        if (place(r, rm) != 0)
            return -1;
        base = rm->frame;
    } else {
        base = hx_adm_find(r, "PART", hx_adm_ref(e, "PART"))->frame;
    }
    compose(e->frame, base, local);
    e->frame_state = 2;
    return 0;
}

/* A FLOATING marker floated by a force (JFLOAT): at its I marker, with the
 * axes of its RM marker (I's without one), at t = 0. */
static int float_marker(hx_adm_reader *r, hx_adm_entry *force, hx_adm_entry **placed_by)
{
    const hx_adm_value *jfloat = hx_adm_get(force, "JFLOAT");
    if (!jfloat->present)
        return 0;
    hx_adm_entry *j = hx_adm_find(r, "MARKER", (int)jfloat->numbers[0]);
    if (!hx_adm_has(j, "FLOATING"))
        return 0;
    hx_adm_entry *i = hx_adm_find(r, "MARKER", hx_adm_ref(force, "I"));
    hx_adm_entry *rm = hx_adm_has(force, "RM") ? hx_adm_find(r, "MARKER", hx_adm_ref(force, "RM")) : i;
    const int k = (int)(j - r->entries);
    if (placed_by[k] != NULL) {
        char first[48];
        return hx_adm_fail(r, force, jfloat->line, "JFLOAT=%d: that FLOATING marker is floated by"
                           " %s too; the harness places a floating marker once, at t = 0",
                           j->id, hx_adm_label(placed_by[k], first, sizeof first));
    }
    placed_by[k] = force;
    memcpy(j->frame, i->frame, 3 * sizeof(double));
    memcpy(j->frame + 3, rm->frame + 3, 9 * sizeof(double));
    j->frame_state = 2;
    return 0;
}

/* VX..VZ along the VM marker's axes (the ground's without one), WX..WZ about
 * the WM marker's axes (the CM marker's without one), into world axes. */
static void initial_velocities(hx_adm_reader *r, hx_adm_entry *e)
{
    hx_body *b = &r->d->m->bodies[e->index];
    const double v[3] = {hx_adm_number(e, "VX", 0, 0.0), hx_adm_number(e, "VY", 0, 0.0),
                         hx_adm_number(e, "VZ", 0, 0.0)};
    const double w[3] = {hx_adm_number(e, "WX", 0, 0.0), hx_adm_number(e, "WY", 0, 0.0),
                         hx_adm_number(e, "WZ", 0, 0.0)};
    const double *Rv = hx_adm_has(e, "VM") ? hx_adm_find(r, "MARKER", hx_adm_ref(e, "VM"))->frame + 3
                                           : identity;
    const double *Rw = hx_adm_find(r, "MARKER", hx_adm_has(e, "WM") ? hx_adm_ref(e, "WM")
                                                                     : hx_adm_ref(e, "CM"))->frame + 3;
    if (is_identity(Rv))
        memcpy(b->v0, v, sizeof v);
    else
        m3_apply(b->v0, Rv, v);
    if (is_identity(Rw))
        memcpy(b->w0, w, sizeof w);
    else
        m3_apply(b->w0, Rw, w);
}

int hx_adm_place_markers(hx_adm_reader *r)
{
    hx_adm_entry **placed_by = calloc((size_t)r->nentries + 1, sizeof *placed_by);
    if (placed_by == NULL) {
        hx_draft_fail(r->d, 0, "out of memory");
        return -1;
    }
    int status = 0;
    for (int k = 0; k < r->nentries && status == 0; ++k) {
        hx_adm_entry *e = &r->entries[k];
        if (strcmp(e->spec->name, "MARKER") == 0 && !hx_adm_has(e, "FLOATING"))
            status = place(r, e);
    }
    for (int k = 0; k < r->nentries && status == 0; ++k) {
        hx_adm_entry *e = &r->entries[k];
        if (!e->unsimulated && hx_adm_get(e, "JFLOAT")->present)
            status = float_marker(r, e, placed_by);
    }
    free(placed_by);
    for (int k = 0; k < r->nentries && status == 0; ++k) {
        hx_adm_entry *e = &r->entries[k];
        if (strcmp(e->spec->name, "MARKER") == 0) {
            if (e->frame_state != 2) { /* a FLOATING marker no force floats: its part's frame */
                memcpy(e->frame, hx_adm_find(r, "PART", hx_adm_ref(e, "PART"))->frame,
                       sizeof e->frame);
            }
            raw_marker *raw = &r->d->rmarkers[e->index];
            raw->rm_id = 0;
            memcpy(raw->pos, e->frame, 3 * sizeof(double));
            memcpy(raw->R, e->frame + 3, 9 * sizeof(double));
        }
    }
    for (int k = 0; k < r->nentries && status == 0; ++k) {
        hx_adm_entry *e = &r->entries[k];
        if (strcmp(e->spec->name, "PART") == 0 && !hx_adm_has(e, "GROUND"))
            initial_velocities(r, e);
    }
    return status;
}
