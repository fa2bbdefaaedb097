/*
 * The constraint system (constraints.h): the couplers' rows (COUSUB/COUXX for the
 * constraint and its Jacobian, COUXX2 for the velocity-squared term) and the joints'
 * equations (joint_equations.c) in one G, and the multipliers from G M^-1 G^T lambda =
 * rhs (docs/architecture.md, the constraint system; the projections back onto phi = 0
 * and G u = r after a step are constraint_projection.c's). Each row of G touches a few blocks of
 * velocities (a coupler's joints, a joint's two free bodies): it keeps their values, 12 a
 * row (36 when a coupler spans joints between bodies: up to 6 bodies); M is block-diagonal
 * per body, so M^-1 G^T has the same blocks. Sums run in the order of the dense products
 * over u they replaced, and a coupler of reduced joints alone keeps its former arithmetic
 * (a value a joint, no convective term): the couplers' runs are unchanged.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraint_matrix.h"
#include "sim/dynamics/constraint_parts.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/coordinate_rows.h"
#include "sim/dynamics/expression_rows.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/joint_equations.h"


/* The coupled joints' position/velocity offsets (jointed bodies: q and u agree). */
static int coupler_joints(const hx_dynamics *d, int k, int body[3])
{
    const hx_coupler *c = &d->m->couplers[k];
    for (int i = 0; i < c->njoints; ++i)
        body[i] = d->m->markers[d->m->joints[c->joint[i]].i_marker].body;
    return c->njoints;
}

static void add_block(hx_constraint_row *r, const hx_dynamics *d, int body, int slot)
{
    const hx_body_dof *dof = &d->dof[body];
    if (dof->kind == HX_DOF_GROUND)
        return;
    const int n = r->nblocks++;
    r->body[n] = body, r->u[n] = dof->u, r->slot[n] = slot;
    r->width[n] = dof->kind == HX_DOF_FREE ? 6 : 1;
}

/* A coupler's block of a body: its slot, the body added at *next when new. */
static int coupler_slot(hx_constraint_row *r, const hx_dynamics *d, int body, int *next)
{
    for (int b = 0; b < r->nblocks; ++b)
        if (r->body[b] == body)
            return r->slot[b];
    const int slot = *next;
    add_block(r, d, body, slot);
    *next += d->dof[body].kind == HX_DOF_FREE ? 6 : 1;
    return slot;
}

/* Whether coupler k couples a joint that is not reduced. */
static int coupler_is_general(const hx_model *m, int k)
{
    for (int i = 0; i < m->couplers[k].njoints; ++i)
        if (!m->joints[m->couplers[k].joint[i]].reduced)
            return 1;
    return 0;
}

/* A general coupler's blocks: each joint's I and J bodies (a reduced joint's
 * body alone), each body once. */
static void coupler_blocks(hx_dynamics *d, int k)
{
    const hx_model *m = d->m;
    const hx_coupler *c = &m->couplers[k];
    hx_constraint_row *r = &d->rows[k];
    int next = 0;
    for (int i = 0; i < c->njoints; ++i) {
        const hx_joint *j = &m->joints[c->joint[i]];
        coupler_slot(r, d, m->markers[j->i_marker].body, &next);
        if (!j->reduced)
            coupler_slot(r, d, m->markers[j->j_marker].body, &next);
    }
}

/* The model's length: the scale of the joints' translational rows. */
static double length_scale(const hx_model *m)
{
    double L = 1.0;
    for (int k = 0; k < m->nmarkers; ++k)
        L = fmax(L, v3_norm(m->markers[k].pos0));
    return L;
}

int hx_constraints_init(hx_dynamics *d, hx_message *msg)
{
    const hx_model *m = d->m;
    int n = m->ncouplers;
    d->joint_row = malloc(sizeof(int) * ((size_t)m->njoints + 1));
    if (d->joint_row == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < m->njoints; ++k) {
        d->joint_row[k] = m->joints[k].reduced ? -1 : n;
        n += m->joints[k].reduced ? 0 : hx_joint_equations_count(m->joints[k].type);
    }
    /* a Motion_Joint on a joint that is not reduced: a row a(q) - f(t) = 0 */
    d->motion_first = n, d->nmotions = 0;
    d->motion_routine = malloc(sizeof(int) * ((size_t)m->nroutines + 1));
    if (d->motion_routine == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < m->nroutines; ++k)
        if (m->routines[k].kind == HX_ROUTINE_MOTION && !m->joints[m->routines[k].joint].reduced)
            d->motion_routine[d->nmotions++] = k;
    n += d->nmotions;
    d->gcon_first = n; /* a Constraint_General: a row f(q, t) = 0 (expression_rows.h) */
    n += m->ngcons;
    d->nrows = n;
    d->rows = calloc((size_t)n + 1, sizeof *d->rows);
    d->u_body = malloc(sizeof(int) * ((size_t)d->nu + 1));
    d->active = malloc(sizeof(int) * ((size_t)n + 1));
    d->removed = malloc(sizeof(int) * ((size_t)n + 1));
    if (d->rows == NULL || d->u_body == NULL || d->active == NULL || d->removed == NULL)
        return hx_fail(msg, "out of memory");
    /* every row takes part until hx_redundancy_find removes the redundant ones */
    for (int i = 0; i < n; ++i)
        d->active[i] = i;
    d->nactive = n, d->nremoved = 0;
    for (int b = 0; b < m->nbodies; ++b)
        if (d->dof[b].kind != HX_DOF_GROUND)
            for (int c = 0; c < (d->dof[b].kind == HX_DOF_FREE ? 6 : 1); ++c)
                d->u_body[d->dof[b].u + c] = b;
    d->coupler_general = calloc((size_t)m->ncouplers + 1, 1);
    if (d->coupler_general == NULL)
        return hx_fail(msg, "out of memory");
    d->row_values = 12;
    for (int k = 0; k < m->ncouplers; ++k)
        if ((d->coupler_general[k] = (unsigned char)coupler_is_general(m, k)) != 0)
            d->row_values = 6 * HX_CONSTRAINT_ROW_BLOCKS;
    for (int k = 0; k < m->ncouplers; ++k) {
        d->rows[k].scale = 1.0;
        if (d->coupler_general[k]) {
            coupler_blocks(d, k);
        } else {
            int body[3];
            const int nj = coupler_joints(d, k, body);
            for (int i = 0; i < nj; ++i)
                add_block(&d->rows[k], d, body[i], i);
        }
        hx_constraint_row_sort(&d->rows[k]);
    }
    const double L = length_scale(m);
    for (int k = 0; k < m->njoints; ++k) {
        if (d->joint_row[k] < 0)
            continue;
        const hx_joint *j = &m->joints[k];
        const int count = hx_joint_equations_count(j->type);
        for (int e = 0; e < count; ++e) {
            hx_constraint_row *r = &d->rows[d->joint_row[k] + e];
            add_block(r, d, m->markers[j->i_marker].body, 0);
            add_block(r, d, m->markers[j->j_marker].body, 6);
            hx_constraint_row_sort(r);
            r->scale = 1.0;
        }
        for (int e = 0; e < count; ++e) /* the rows of positions (joint_equations.h) */
            if (hx_joint_equation_is_length(j->type, e))
                d->rows[d->joint_row[k] + e].scale = L;
    }
    for (int k = 0; k < d->nmotions; ++k) {
        const hx_routine *rt = &m->routines[d->motion_routine[k]];
        const hx_joint *j = &m->joints[rt->joint];
        hx_constraint_row *r = &d->rows[d->motion_first + k];
        add_block(r, d, m->markers[j->i_marker].body, 0);
        add_block(r, d, m->markers[j->j_marker].body, 6);
        hx_constraint_row_sort(r);
        r->scale = rt->motion_type == 'T' ? L : 1.0;
    }
    return hx_expression_rows_init(d, L, msg);
}

void hx_constraints_free(hx_dynamics *d)
{
    free(d->joint_row);
    free(d->rows);
    free(d->u_body);
    free(d->active);
    free(d->removed);
    free(d->removed_placed);
    free(d->assembled_q);
    free(d->envelope_first);
    free(d->envelope_start);
    free(d->coupler_general);
    free(d->motion_routine);
}


size_t hx_constraints_work_size(const hx_dynamics *d)
{
    const size_t n = (size_t)d->nrows, nu = (size_t)d->nu, v = (size_t)d->row_values;
    return 2 * v * n + n * n + 4 * n + 2 * nu + 16 /* G, W, A, phi, gamma, step, spare; x, y */
           + hx_expression_rows_work_size(d);
}

hx_constraint_work hx_constraint_work_parts(const hx_dynamics *d, hx_dynamics_data *dd)
{
    const size_t n = (size_t)d->nrows, v = (size_t)d->row_values;
    hx_constraint_work w;
    w.G = dd->constraint_work, w.W = w.G + v * n, w.A = w.W + v * n, w.phi = w.A + n * n;
    w.gamma = w.phi + n, w.step = w.gamma + n, w.x = w.step + 2 * n;
    w.expression = w.x + 2 * (size_t)d->nu + 16;
    return w;
}

/* A joint's rows: G's world twists into the bodies' velocities (omega in body axes). */
static void joint_terms(const hx_dynamics *d, int k, const double *y, double *G, double *phi,
                        double *gamma)
{
    const hx_joint *j = &d->m->joints[k];
    hx_frame fi, fj;
    hx_bodies_frame(d, d->m->markers[j->i_marker].body, y, &fi);
    hx_bodies_frame(d, d->m->markers[j->j_marker].body, y, &fj);
    hx_joint_equations_of(d->m, k, &fi, &fj, phi, G, gamma);
    const int count = hx_joint_equations_count(j->type);
    for (int e = 0; e < count; ++e) {
        double *g = G + 12 * e, body[3];
        m3_tapply(body, fi.R, g + 3);
        v3_copy(g + 3, body);
        m3_tapply(body, fj.R, g + 9);
        v3_copy(g + 9, body);
    }
}

int hx_constraint_rows_eval(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                            double *G, double *phi, double *gamma)
{
    const int nc = d->m->ncouplers, V = d->row_values;
    memset(G, 0, sizeof(double) * (size_t)V * (size_t)d->nrows);
    for (int k = 0; k < nc; ++k) {
        if (hx_coordinate_rows_coupler(d, dd, k, t, y, &phi[k], G + V * k,
                                       gamma ? &gamma[k] : NULL) != 0)
            return -1;
    }
    double joint_G[12 * HX_JOINT_MAX_EQUATIONS];
    for (int k = 0; k < d->m->njoints; ++k) {
        const int r = d->joint_row[k];
        if (r < 0)
            continue;
        if (V == 12) {
            joint_terms(d, k, y, G + 12 * r, phi + r, gamma ? gamma + r : NULL);
            continue;
        }
        joint_terms(d, k, y, joint_G, phi + r, gamma ? gamma + r : NULL);
        for (int e = 0; e < hx_joint_equations_count(d->m->joints[k].type); ++e)
            memcpy(G + V * (r + e), joint_G + 12 * e, sizeof(double) * 12);
    }
    for (int k = 0; k < d->nmotions; ++k) {
        const int r = d->motion_first + k;
        if (hx_coordinate_rows_motion(d, dd, k, t, y, phi + r, joint_G, gamma ? gamma + r : NULL) != 0)
            return -1;
        memcpy(G + V * r, joint_G, sizeof(double) * 12);
    }
    for (int k = 0; k < d->m->ngcons; ++k) {
        const int r = d->gcon_first + k;
        double *work = hx_constraint_work_parts(d, dd).expression;
        if (hx_expression_rows_eval(d, dd, k, t, y, work, phi + r, G + V * r,
                                    gamma ? gamma + r : NULL) != 0)
            return -1;
    }
    return 0;
}

int hx_constraint_row_rate(const hx_dynamics *d, hx_dynamics_data *dd, int i, double t,
                           const double *y, double *rate)
{
    *rate = 0.0;
    if (i >= d->gcon_first)
        return hx_expression_rows_rate(d, dd, i - d->gcon_first, t, y,
                                       hx_constraint_work_parts(d, dd).expression,
                                       rate);
    if (i >= d->motion_first)
        return hx_coordinate_rows_rate(d, dd, i, t, y, rate);
    return 0;
}

double hx_constraint_row_dot(const hx_dynamics *d, const double *G, int i, const double *v,
                             double start)
{
    const hx_constraint_row *r = &d->rows[i];
    const double *Gi = G + (size_t)d->row_values * (size_t)i;
    double s = start;
    for (int b = 0; b < r->nblocks; ++b)
        for (int c = 0; c < r->width[b]; ++c)
            s += Gi[r->slot[b] + c] * v[r->u[b] + c];
    return s;
}

void hx_constraint_transpose_apply(const hx_dynamics *d, const double *G, const double *z,
                                   double *x)
{
    memset(x, 0, sizeof(double) * (size_t)d->nu);
    for (int a = 0; a < d->nactive; ++a) {
        const int i = d->active[a];
        const hx_constraint_row *r = &d->rows[i];
        const double *Gi = G + (size_t)d->row_values * (size_t)i;
        for (int b = 0; b < r->nblocks; ++b)
            for (int c = 0; c < r->width[b]; ++c)
                x[r->u[b] + c] += Gi[r->slot[b] + c] * z[a];
    }
}

/* The power lambda r of the rows held at G u = r(t) (docs/architecture.md, the energy balance). */
static int driven_power(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                        double *power)
{
    for (int a = 0; a < d->nactive; ++a) {
        const int i = d->active[a];
        double r;
        if (i < d->motion_first ||
            (i >= d->gcon_first && !hx_expression_rows_timed(d, i - d->gcon_first)))
            continue;
        if (hx_constraint_row_rate(d, dd, i, t, y, &r) != 0)
            return -1;
        *power += dd->lambda[i] * r;
    }
    return 0;
}

int hx_constraints_apply(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                         double *udot, double *power)
{
    const int n = d->nactive;
    if (d->nrows == 0)
        return 0;
    /* M udot = ucf (Q + G^T lambda), G udot = gamma:
     * (G M^-1 G^T) lambda = (gamma - G udot_free) / ucf with udot_free = ucf M^-1 Q. */
    hx_constraint_work w = hx_constraint_work_parts(d, dd);
    if (hx_constraint_rows_eval(d, dd, t, y, w.G, w.phi, w.gamma) != 0)
        return -1;
    const int formed = hx_constraint_matrix_form(d, w.G, w.W, w.A);
    /* the active rows' multipliers solved in w.step, the removed rows' zero */
    for (int a = 0; a < n; ++a) {
        const int i = d->active[a];
        w.step[a] = -hx_constraint_row_dot(d, w.G, i, udot, -w.gamma[i]) / d->ucf;
    }
    if (formed != 0 || hx_constraint_matrix_solve(d, w.A, w.step) != 0)
        return hx_dynamics_fail(dd, "the constraint Jacobian is singular at t = %g (joints or"
                                " couplers that became degenerate after the set-up)", t);
    for (int a = 0; a < n; ++a)
        dd->lambda[d->active[a]] = w.step[a];
    for (int a = 0; a < n; ++a) {
        const int i = d->active[a];
        const hx_constraint_row *r = &d->rows[i];
        for (int b = 0; b < r->nblocks; ++b) {
            const size_t at = (size_t)d->row_values * (size_t)i + (size_t)r->slot[b];
            const double *g = w.G + at, *wi = w.W + at;
            if (r->width[b] == 1)
                udot[r->u[b]] += d->ucf * (1.0 / d->dof[r->body[b]].mass) * g[0] * dd->lambda[i];
            else
                for (int c = 0; c < 6; ++c)
                    udot[r->u[b] + c] += d->ucf * wi[c] * dd->lambda[i];
        }
    }
    return power != NULL && d->motion_first < d->nrows ? driven_power(d, dd, t, y, power) : 0;
}

int hx_constraints_rows(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                        double *phi, double *G, double *gamma)
{
    return hx_constraint_rows_eval(d, dd, t, y, G, phi, gamma);
}

double hx_constraints_coupler_force(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                                    const double *y, int coupler, int joint)
{
    return hx_coordinate_rows_force(d, dd, t, y, coupler, joint);
}

int hx_constraints_coupled(const hx_dynamics *d, int *index)
{
    int count = 0;
    for (int a = 0; a < d->nactive; ++a) {
        const hx_constraint_row *r = &d->rows[d->active[a]];
        for (int b = 0; b < r->nblocks; ++b)
            for (int c = 0; c < r->width[b]; ++c) {
                int seen = 0;
                for (int j = 0; j < count && !seen; ++j)
                    seen = index[j] == r->u[b] + c;
                if (!seen)
                    index[count++] = r->u[b] + c;
            }
    }
    return count;
}
