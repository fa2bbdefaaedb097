/*
 * The resolve passes of a draft model: marker frames (through rm_id chains),
 * body frames and inertia about the centre of mass, joints, couplers, force
 * elements and loads by index, and the markers states keep frames of.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "model/draft.h"
#include "model/load_elements.h"
#include "model/loop_inputs.h"

static int resolve_marker(hx_draft *r, int k)
{
    hx_model *m = r->m;
    raw_marker *rm = &r->rmarkers[k];
    hx_marker *mk = &m->markers[k];
    if (rm->state == 2)
        return 0;
    if (rm->state == 1) {
        hx_draft_fail(r, mk->line, "Reference_Marker %d: its rm_id chain leads back to itself", mk->id);
        return -1;
    }
    rm->state = 1;
    mk->body = hx_draft_find_body(r, rm->body_id);
    if (mk->body < 0) {
        hx_draft_fail(r, mk->line, "Reference_Marker %d: body_id %d is not a Body_Rigid or Body_Ground",
             mk->id, rm->body_id);
        return -1;
    }
    if (rm->rm_id != 0) {
        int base = -1;
        for (int j = 0; j < m->nmarkers; ++j)
            if (m->markers[j].id == rm->rm_id)
                base = j;
        if (base < 0) {
            hx_draft_fail(r, mk->line, "Reference_Marker %d: rm_id %d is not a marker", mk->id, rm->rm_id);
            return -1;
        }
        if (resolve_marker(r, base) != 0)
            return -1;
        const hx_marker *b = &m->markers[base];
        m3_apply(mk->pos0, b->R0, rm->pos);
        v3_add(mk->pos0, mk->pos0, b->pos0);
        m3_mul(mk->R0, b->R0, rm->R);
    } else {
        v3_copy(mk->pos0, rm->pos);
        m3_copy(mk->R0, rm->R);
    }
    rm->state = 2;
    return 0;
}

static int marker_ref(hx_draft *r, int id, int line, const char *owner, int owner_id,
                      const char *what, int *index)
{
    *index = hx_model_marker(r->m, id);
    if (*index < 0) {
        hx_draft_fail(r, line, "%s %d: %s %d is not a Reference_Marker", owner, owner_id, what, id);
        return -1;
    }
    return 0;
}

static int build_marker_index(hx_draft *r)
{
    hx_model *m = r->m;
    m->marker_slot_count = 4;
    while (m->marker_slot_count < 2 * m->nmarkers)
        m->marker_slot_count *= 2;
    m->marker_slots = malloc(sizeof(int) * (size_t)m->marker_slot_count);
    if (m->marker_slots == NULL) {
        hx_draft_fail(r, 0, "out of memory");
        return -1;
    }
    for (int s = 0; s < m->marker_slot_count; ++s)
        m->marker_slots[s] = -1;
    for (int k = 0; k < m->nmarkers; ++k) {
        const unsigned mask = (unsigned)m->marker_slot_count - 1u;
        unsigned s = ((unsigned)m->markers[k].id * 2654435761u) & mask;
        while (m->marker_slots[s] >= 0)
            s = (s + 1) & mask;
        m->marker_slots[s] = k;
    }
    return 0;
}

/* A body's local part reference frame: the harness reads every position and
 * orientation in the world frame, which is right when that frame is the
 * world's; any other is refused rather than silently misread. */
static int check_lprf(hx_draft *r, const hx_body *b, int lprf_id)
{
    int index;
    if (marker_ref(r, lprf_id, b->line, "Body_Rigid", b->id, "lprf_id", &index) != 0)
        return -1;
    const hx_marker *mk = &r->m->markers[index];
    double off = v3_norm(mk->pos0);
    for (int i = 0; i < 9; ++i)
        off = fmax(off, fabs(mk->R0[i] - (i % 4 == 0 ? 1.0 : 0.0)));
    if (off > 1e-12) {
        hx_draft_fail(r, b->line, "Body_Rigid %d: lprf_id %d is a frame other than the world's;"
                      " the harness reads positions and orientations in the world frame only"
                      " (give them in the world frame and leave lprf_id out)", b->id, lprf_id);
        return -1;
    }
    return 0;
}

static int resolve_bodies(hx_draft *r)
{
    hx_model *m = r->m;
    for (int k = 0; k < m->nbodies; ++k) {
        hx_body *b = &m->bodies[k];
        raw_body *rb = &r->rbodies[k];
        if (rb->lprf_id != 0 && check_lprf(r, b, rb->lprf_id) != 0)
            return -1;
        if (b->is_ground)
            continue;
        int cg, im;
        if (marker_ref(r, rb->cg_id, b->line, "Body_Rigid", b->id, "cg_id", &cg) != 0 ||
            marker_ref(r, rb->im_id, b->line, "Body_Rigid", b->id, "im_id", &im) != 0)
            return -1;
        if (m->markers[cg].body != k || m->markers[im].body != k) {
            hx_draft_fail(r, b->line, "Body_Rigid %d: its cg_id and im_id markers must belong to it", b->id);
            return -1;
        }
        b->cg_marker = cg;
        v3_copy(b->p0, m->markers[cg].pos0);
        m3_copy(b->R0, m->markers[cg].R0);
        /* Inertia given in IM axes about the IM origin: rotate to body axes and move
         * to the centre of mass (parallel axes). */
        double Rbi[9], tmp[9];
        m3_tmul(Rbi, b->R0, m->markers[im].R0);
        m3_mul(tmp, Rbi, rb->inertia);
        m3_mult(b->inertia, tmp, Rbi);
        double d_world[3], d[3];
        v3_sub(d_world, b->p0, m->markers[im].pos0);
        m3_tapply(d, b->R0, d_world);
        const double dd = v3_dot(d, d);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                b->inertia[3 * i + j] -= b->mass * ((i == j ? dd : 0.0) - d[i] * d[j]);
    }
    for (int k = 0; k < m->nmarkers; ++k) {
        hx_marker *mk = &m->markers[k];
        const hx_body *b = &m->bodies[mk->body];
        double d[3];
        v3_sub(d, mk->pos0, b->p0);
        m3_tapply(mk->r_local, b->R0, d);
        m3_tmul(mk->R_local, b->R0, mk->R0);
        /* the common cases, marked so that frames skip their products; an
         * orientation equal to the body's up to rounding is taken as equal */
        double off = 0.0;
        for (int i = 0; i < 9; ++i)
            off = fmax(off, fabs(mk->R_local[i] - (i % 4 == 0 ? 1.0 : 0.0)));
        mk->local_axes = off <= 4.0 * DBL_EPSILON;
        if (mk->local_axes)
            m3_identity(mk->R_local);
        mk->at_body_origin = mk->r_local[0] == 0.0 && mk->r_local[1] == 0.0 && mk->r_local[2] == 0.0;
    }
    return 0;
}

/* A reduced joint (model.h): its I body moves in the joint's coordinate, so
 * its markers must already satisfy the joint. */
static int check_reduced(hx_draft *r, const hx_joint *j)
{
    const hx_model *m = r->m;
    const hx_marker *mi = &m->markers[j->i_marker], *mj = &m->markers[j->j_marker];
    const double zi[3] = {mi->R0[2], mi->R0[5], mi->R0[8]};
    const double zj[3] = {mj->R0[2], mj->R0[5], mj->R0[8]};
    const char *what = NULL;
    double d[3], off[3];
    v3_sub(d, mi->pos0, mj->pos0);
    v3_cross(off, d, zj);
    const double xi[3] = {mi->R0[0], mi->R0[3], mi->R0[6]}, xj[3] = {mj->R0[0], mj->R0[3], mj->R0[6]};
    if (v3_dot(zi, zj) < 1.0 - 1e-9)
        what = "the z axes of the I and J markers must be aligned";
    else if (j->type == HX_JOINT_REVOLUTE && v3_norm(d) > 1e-9 * (1.0 + v3_norm(mj->pos0)))
        what = "a revolute joint's I and J markers must coincide";
    else if (j->type == HX_JOINT_TRANSLATIONAL && v3_norm(off) > 1e-9 * (1.0 + v3_norm(mj->pos0)))
        what = "a translational joint's I marker must lie on the J marker's z axis";
    else if (j->type == HX_JOINT_TRANSLATIONAL && v3_dot(xi, xj) < 1.0 - 1e-9)
        what = "a translational joint's I and J markers must have the same orientation";
    if (what != NULL) {
        hx_draft_fail(r, j->line, "Constraint_Joint %d: %s", j->id, what);
        return -1;
    }
    return 0;
}

/* A RACK_PINION's or SCREW's turn is an angle in a plane (docs/interface.md
 * §7.14): at t = 0 its axis must not lie in the plane's normal, x_I . z_J,
 * y_I . z_J (RACK_PINION) or x_I . x_J, x_I . y_J (SCREW) not both near 0. */
static int check_gearing(hx_draft *r, const hx_joint *j)
{
    const hx_marker *mi = &r->m->markers[j->i_marker], *mj = &r->m->markers[j->j_marker];
    const int rack = j->type == HX_JOINT_RACKPIN;
    if (!rack && j->type != HX_JOINT_SCREW)
        return 0;
    double a = 0.0, b = 0.0;
    for (int k = 0; k < 3; ++k) {
        a += mi->R0[3 * k] * mj->R0[3 * k + (rack ? 2 : 0)];
        b += mi->R0[3 * k + (rack ? 1 : 0)] * mj->R0[3 * k + (rack ? 2 : 1)];
    }
    if (a * a + b * b >= 1e-6)
        return 0;
    hx_draft_fail(r, j->line, "Constraint_Joint %d: %s", j->id,
                  rack ? "a RACK_PINION's rack axis z_J must be across the pinion's axis z_I"
                         " (x_I along z_J at assembly)"
                       : "a SCREW's x_I must be across z_J (z_I along z_J at assembly)");
    return -1;
}

/* Joints between any two bodies; a revolute or translational joint from a
 * body to ground that is the body's only joint is reduced (model.h). */
static int resolve_joints(hx_draft *r)
{
    hx_model *m = r->m;
    int *count = calloc((size_t)m->nbodies + 1, sizeof *count);
    if (count == NULL) {
        hx_draft_fail(r, 0, "out of memory");
        return -1;
    }
    int status = 0;
    for (int k = 0; k < m->njoints && status == 0; ++k) {
        hx_joint *j = &m->joints[k];
        const raw_refs *refs = &r->rjoints[k];
        const char *element = hx_joint_element_name(j->type);
        status = marker_ref(r, refs->ids[0], j->line, element, j->id, "i_marker_id",
                            &j->i_marker) != 0 ||
                 marker_ref(r, refs->ids[1], j->line, element, j->id, "j_marker_id",
                            &j->j_marker) != 0;
        if (status != 0)
            break;
        const int bi = m->markers[j->i_marker].body, bj = m->markers[j->j_marker].body;
        if (bi == bj || (m->bodies[bi].is_ground && m->bodies[bj].is_ground)) {
            hx_draft_fail(r, j->line, "%s %d: its I and J markers (%d, %d) are on the same body%s",
                          element, j->id, refs->ids[0], refs->ids[1],
                          bi == bj ? "" : " (ground)");
            status = 1;
        }
        count[bi]++, count[bj]++;
        if (check_gearing(r, j) != 0)
            status = 1;
    }
    for (int k = 0; k < m->njoints && status == 0; ++k) {
        hx_joint *j = &m->joints[k];
        const int bi = m->markers[j->i_marker].body, bj = m->markers[j->j_marker].body;
        j->reduced = (j->type == HX_JOINT_REVOLUTE || j->type == HX_JOINT_TRANSLATIONAL) &&
                     m->bodies[bj].is_ground && !m->bodies[bi].is_ground && count[bi] == 1;
        if (j->reduced) {
            status = check_reduced(r, j);
            m->bodies[bi].joint = k;
        }
    }
    free(count);
    return status != 0 ? -1 : 0;
}

static int resolve_couplers(hx_draft *r)
{
    hx_model *m = r->m;
    for (int k = 0; k < m->ncouplers; ++k) {
        hx_coupler *c = &m->couplers[k];
        const raw_refs *refs = &r->rcouplers[k];
        for (int i = 0; i < c->njoints; ++i) {
            c->joint[i] = hx_model_joint(m, refs->ids[i]);
            if (c->joint[i] < 0) {
                hx_draft_fail(r, c->line, "Constraint_Coupler %d: joint%d_id %d is not a Constraint_Joint",
                     c->id, i + 1, refs->ids[i]);
                return -1;
            }
            /* any joint with a coordinate, between any bodies (docs/interface.md §2) */
            const hx_joint *joint = &m->joints[c->joint[i]];
            const char own = joint->type == HX_JOINT_REVOLUTE        ? 'R'
                             : joint->type == HX_JOINT_TRANSLATIONAL ? 'T'
                                                                     : 0;
            if (joint->type == HX_JOINT_CYLINDRICAL && refs->freedom[i] == 0) {
                hx_draft_fail(r, c->line, "Constraint_Coupler %d: joint %d is cylindrical:"
                              " freedom_%d must say which of its coordinates is coupled"
                              " (\"R\" its rotation, \"T\" its translation)", c->id,
                              refs->ids[i], i + 1);
                return -1;
            }
            if (joint->type != HX_JOINT_CYLINDRICAL && own == 0) {
                hx_draft_fail(r, c->line, "Constraint_Coupler %d: joint %d is %s, which has no"
                              " coordinate to couple (REVOLUTE, TRANSLATIONAL or CYLINDRICAL"
                              " joints only)", c->id, refs->ids[i],
                              hx_joint_type_name(joint->type));
                return -1;
            }
            if (own != 0 && refs->freedom[i] != 0 && refs->freedom[i] != own) {
                hx_draft_fail(r, c->line, "Constraint_Coupler %d: freedom_%d is \"%c\" but joint %d is %s",
                     c->id, i + 1, refs->freedom[i], refs->ids[i],
                     own == 'R' ? "revolute (\"R\")" : "translational (\"T\")");
                return -1;
            }
            c->freedom[i] = own != 0 ? own : refs->freedom[i];
            for (int j = 0; j < i; ++j)
                if (c->joint[j] == c->joint[i]) {
                    hx_draft_fail(r, c->line, "Constraint_Coupler %d: joint %d is coupled twice", c->id,
                         refs->ids[i]);
                    return -1;
                }
        }
    }
    return 0;
}

static int resolve_forces(hx_draft *r)
{
    hx_model *m = r->m;
    for (int k = 0; k < m->nforces; ++k) {
        hx_force *f = &m->forces[k];
        const raw_refs *refs = &r->rforces[k];
        const char *owner = hx_force_element_name(f);
        if (f->one_body) {
            f->ref_marker = -1;
            f->j_marker = hx_model_marker(m, 0);
            if (marker_ref(r, refs->ids[0], f->line, owner, f->id, "marker_id", &f->i_marker) != 0 ||
                (refs->ids[2] != 0 && marker_ref(r, refs->ids[2], f->line, owner, f->id,
                                                 "ref_marker_id", &f->ref_marker) != 0))
                return -1;
            continue;
        }
        if (marker_ref(r, refs->ids[0], f->line, owner, f->id, "i_marker_id", &f->i_marker) != 0 ||
            marker_ref(r, refs->ids[1], f->line, owner, f->id,
                       f->interface == HX_FORCE_GFOSUB && f->part < HX_OUTPUT_SCALAR_FORCE
                           ? "j_floating_marker_id"
                           : "j_marker_id",
                       &f->j_marker) != 0)
            return -1;
        f->ref_marker = -1;
        if (f->interface == HX_FORCE_GFOSUB && refs->ids[2] != 0 &&
            marker_ref(r, refs->ids[2], f->line, owner, f->id, "ref_marker_id", &f->ref_marker) != 0)
            return -1;
        if (m->markers[f->i_marker].body == m->markers[f->j_marker].body) {
            hx_draft_fail(r, f->line, "%s %d: its I and J markers are on the same body", owner, f->id);
            return -1;
        }
    }
    for (int k = 0; k < m->nloads; ++k) {
        hx_load *l = &m->loads[k];
        const raw_refs *refs = &r->rloads[k];
        const int two_body = l->kind == HX_LOAD_VECTOR && refs->ids[1] != 0;
        const char *owner = l->builtin != HX_LOAD_AS_WRITTEN ? hx_load_element_name(l)
                            : l->kind != HX_LOAD_VECTOR        ? "Force_Scalar_TwoBody"
                            : two_body                         ? "Force_Vector_TwoBody"
                                                               : "Force_Vector_OneBody";
        l->j_marker = l->ref_marker = -1;
        if (marker_ref(r, refs->ids[0], l->line, owner, l->id,
                       l->kind == HX_LOAD_VECTOR && !two_body ? "marker_id" : "i_marker_id",
                       &l->i_marker) != 0)
            return -1;
        if ((l->kind != HX_LOAD_VECTOR || two_body) &&
            marker_ref(r, refs->ids[1], l->line, owner, l->id,
                       two_body && l->builtin == HX_LOAD_AS_WRITTEN ? "j_floating_marker_id"
                                                                    : "j_marker_id",
                       &l->j_marker) != 0)
            return -1;
        if (l->kind == HX_LOAD_VECTOR && refs->ids[2] != 0 &&
            marker_ref(r, refs->ids[2], l->line, owner, l->id, "ref_marker_id", &l->ref_marker) != 0)
            return -1;
    }
    return 0;
}

/* The markers states keep frames of: those an element, load or joint names. */
static void track_markers(hx_model *m)
{
    for (int k = 0; k < m->njoints; ++k)
        m->markers[m->joints[k].i_marker].tracked = m->markers[m->joints[k].j_marker].tracked = 1;
    for (int k = 0; k < m->nforces; ++k) {
        const hx_force *f = &m->forces[k];
        m->markers[f->i_marker].tracked = m->markers[f->j_marker].tracked = 1;
        if (f->ref_marker >= 0)
            m->markers[f->ref_marker].tracked = 1;
    }
    for (int k = 0; k < m->nloads; ++k) {
        const hx_load *l = &m->loads[k];
        const int used[3] = {l->i_marker, l->j_marker, l->ref_marker};
        for (int i = 0; i < 3; ++i)
            if (used[i] >= 0)
                m->markers[used[i]].tracked = 1;
    }
}

/* The J marker of the Force_Vector_OneBody user forces: one marker at the
 * ground's origin, with the world's axes, numbered 0 (the id queries take for
 * the world, which it is). */
static int add_ground_origin_marker(hx_draft *r)
{
    hx_model *m = r->m;
    int line = 0;
    for (int k = 0; k < m->nforces && line == 0; ++k)
        if (m->forces[k].one_body)
            line = m->forces[k].line;
    if (line == 0)
        return 0;
    raw_marker *raw = NULL;
    hx_marker *mk = hx_draft_push(r, (void **)&m->markers, &m->nmarkers, &r->cap_markers,
                                  sizeof *mk, (void **)&r->rmarkers, sizeof *raw);
    if (mk == NULL)
        return -1;
    raw = &r->rmarkers[m->nmarkers - 1];
    raw->body_id = m->bodies[m->ground].id;
    static const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    memcpy(raw->R, identity, sizeof identity);
    mk->line = line;
    return 0;
}

int hx_draft_resolve(hx_draft *r)
{
    hx_model *m = r->m;
    if (m->ground < 0) {
        hx_draft_fail(r, 0, "the model has no ground (a Body_Ground, or a Body_Rigid with isground=\"TRUE\")");
        return -1;
    }
    if (add_ground_origin_marker(r) != 0)
        return -1;
    for (int k = 0; k < m->nmarkers; ++k)
        if (resolve_marker(r, k) != 0)
            return -1;
    if (build_marker_index(r) != 0 || resolve_bodies(r) != 0 || resolve_joints(r) != 0 ||
        resolve_couplers(r) != 0 || resolve_forces(r) != 0 || hx_draft_resolve_stateeqns(r) != 0 ||
        /* the general constraints' I markers before the programs that read GCON or
         * FX .. TM (model/expr/link.c) */
        hx_draft_link_gcons(r) != 0 ||
        hx_draft_resolve_routines(r) != 0 || hx_draft_link_variables(r) != 0 ||
        hx_draft_link_loads(r) != 0 ||
        hx_draft_find_loop_inputs(r) != 0 ||
        hx_draft_resolve_requests(r) != 0) /* last: FX .. TM ask what acts at a marker */
        return -1;
    track_markers(m);
    return 0;
}

