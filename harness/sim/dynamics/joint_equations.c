/*
 * The equations of each joint type (joint_equations.h), built from three
 * primitives between the markers' origins x_I, x_J and their axes:
 *   point     x_I - x_J = 0                    (3 rows)
 *   dot-1     a_I . b_J = 0, a on I, b on J     (1 row: the axes stay perpendicular)
 *   dot-2     b_J . (x_I - x_J) = 0, b on J     (1 row: x_I stays in b's normal plane)
 * With r = R s the marker's lever from its body's centre, the marker moves at
 * v + omega x r and an axis a turns at omega x a; c . (omega x r) = omega . (r x c)
 * gives G's rows. gamma = -(d/dt G) w: the terms in omega x (omega x .) and the
 * cross terms of two turning vectors, negated. CONVEL's row is the sum of two
 * dot-1 rows; RACKPIN's and SCREW's relate a dot-2 (a travel) to an angle
 * atan2 of two dot-1 rows (docs/interface.md §7.14).
 */
#include "sim/dynamics/joint_equations.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/vecmath.h"

/* A side's marker at the body's frame: origin, lever r (world), axes (columns). */
typedef struct side {
    double x[3], r[3], axes[9], v[3], w[3], xdot[3], wwr[3]; /* wwr = w x (w x r) */
} side;

static void place(side *s, const hx_joint_side *j)
{
    const hx_frame *f = j->body;
    double wr[3];
    m3_apply(s->r, f->R, j->r_local);
    v3_add(s->x, f->p, s->r);
    m3_mul(s->axes, f->R, j->R_local);
    v3_copy(s->v, f->v);
    v3_copy(s->w, f->w);
    v3_cross(wr, f->w, s->r);
    v3_add(s->xdot, f->v, wr);
    v3_cross(s->wwr, f->w, wr);
}

static void axis(double a[3], const side *s, int k)
{
    v3_set(a, s->axes[k], s->axes[3 + k], s->axes[6 + k]);
}

/* One row: phi, its G columns and c, the velocity-squared part of phi_ddot
 * (phi_ddot = G w_dot + c, so gamma = -c). */
typedef struct term {
    double phi, vi[3], wi[3], vj[3], wj[3], c;
} term;

/* One row's writer: phi, G's 12 columns and gamma at row n. */
typedef struct rows {
    double *phi, *G, *gamma;
    int n;
} rows;

static void put(rows *o, const term *t)
{
    o->phi[o->n] = t->phi;
    if (o->G != NULL) {
        double *g = o->G + 12 * o->n;
        v3_copy(g, t->vi), v3_copy(g + 3, t->wi), v3_copy(g + 6, t->vj), v3_copy(g + 9, t->wj);
    }
    if (o->gamma != NULL)
        o->gamma[o->n] = -t->c;
    o->n++;
}

/* x_I - x_J = 0, its component k: e_k . (v_I + w_I x r_I - v_J - w_J x r_J). */
static void point(term *t, const side *i, const side *j, int k)
{
    double e[3] = {0, 0, 0};
    e[k] = 1.0;
    v3_copy(t->vi, e);
    v3_cross(t->wi, i->r, e);
    v3_cross(t->wj, j->r, e);
    v3_scale(t->wj, t->wj, -1.0);
    v3_scale(t->vj, e, -1.0);
    t->phi = i->x[k] - j->x[k];
    t->c = i->wwr[k] - j->wwr[k];
}

/* a_I . b_J = 0: d/dt = w_I . (a x b) + w_J . (b x a). */
static void dot1(term *t, const side *i, int ka, const side *j, int kb)
{
    double a[3], b[3], wa[3], wb[3], wwa[3], wwb[3];
    axis(a, i, ka);
    axis(b, j, kb);
    v3_set(t->vi, 0, 0, 0), v3_set(t->vj, 0, 0, 0);
    v3_cross(t->wi, a, b);
    v3_scale(t->wj, t->wi, -1.0);
    v3_cross(wa, i->w, a);
    v3_cross(wb, j->w, b);
    v3_cross(wwa, i->w, wa);
    v3_cross(wwb, j->w, wb);
    t->phi = v3_dot(a, b);
    t->c = v3_dot(wwa, b) + 2.0 * v3_dot(wa, wb) + v3_dot(a, wwb);
}

/* b_J . d = 0 with d = x_I - x_J: d/dt = (w_J x b) . d + b . d_dot. */
static void dot2(term *t, const side *i, const side *j, int kb)
{
    double b[3], d[3], ddot[3], rjb[3], wb[3], wwb[3], dacc[3];
    axis(b, j, kb);
    v3_sub(d, i->x, j->x);
    v3_sub(ddot, i->xdot, j->xdot);
    v3_copy(t->vi, b);
    v3_cross(t->wi, i->r, b);
    v3_cross(t->wj, b, d);
    v3_cross(rjb, j->r, b);
    v3_sub(t->wj, t->wj, rjb);
    v3_scale(t->vj, b, -1.0);
    v3_cross(wb, j->w, b);
    v3_cross(wwb, j->w, wb);
    v3_sub(dacc, i->wwr, j->wwr);
    t->phi = v3_dot(b, d);
    t->c = v3_dot(wwb, d) + 2.0 * v3_dot(wb, ddot) + v3_dot(b, dacc);
}

/* r = a + s b, term by term */
static void combine(term *r, const term *a, double s, const term *b)
{
    r->phi = a->phi + s * b->phi, r->c = a->c + s * b->c;
    for (int k = 0; k < 3; ++k) {
        r->vi[k] = a->vi[k] + s * b->vi[k], r->wi[k] = a->wi[k] + s * b->wi[k];
        r->vj[k] = a->vj[k] + s * b->vj[k], r->wj[k] = a->wj[k] + s * b->wj[k];
    }
}

static void scale(term *t, double s)
{
    const term zero = {0};
    combine(t, &zero, s, t);
}

/* G w: the row's rate at the sides' velocities */
static double rate(const term *t, const side *i, const side *j)
{
    return v3_dot(t->vi, i->v) + v3_dot(t->wi, i->w) + v3_dot(t->vj, j->v) +
           v3_dot(t->wj, j->w);
}

/* theta = atan2(a, b) of two rows: theta_dot = (b a_dot - a b_dot) / n with
 * n = a^2 + b^2, and theta_ddot's velocity part (b c_a - a c_b) / n
 * - 2 theta_dot (a a_dot + b b_dot) / n (the a_dot b_dot terms cancel). */
static void angle(term *t, const term *a, const term *b, const side *i, const side *j)
{
    /* a and b both 0 (the turn undefined: refused at t = 0, resolve.c): a zero
     * row, which the set-up or the step names as singular, no NaN */
    const double n = fmax(a->phi * a->phi + b->phi * b->phi, 1e-300);
    const double ad = rate(a, i, j), bd = rate(b, i, j);
    term g;
    const term zero = {0};
    combine(&g, &zero, b->phi / n, a);
    combine(&g, &g, -a->phi / n, b);
    const double thetadot = (b->phi * ad - a->phi * bd) / n;
    *t = g;
    t->phi = atan2(a->phi, b->phi);
    t->c = (b->phi * a->c - a->phi * b->c) / n - 2.0 * thetadot * (a->phi * ad + b->phi * bd) / n;
}

/* s - s0 = k (theta - theta0) as k wrap((s - s0) / k - (theta - theta0)),
 * wrap into (-pi, pi]: the same equation on every turn of theta
 * (docs/interface.md §7.14). */
static void gearing(term *t, const term *s, const term *theta, const hx_joint_law *law)
{
    const double k = law->ratio;
    combine(t, s, -k, theta);
    const double x = (s->phi - law->s0) / k - (theta->phi - law->theta0);
    t->phi = k * (x - 2.0 * M_PI * nearbyint(x / (2.0 * M_PI)));
}

enum { X, Y, Z };
enum { POINT, DOT1, DOT2, CONVEL, RACKPIN, SCREW };

/* A row: its primitive and axes (POINT: component a; DOT1: a_I . b_J; DOT2:
 * b_J . d; CONVEL, RACKPIN, SCREW: their own equation, below). */
typedef struct recipe_row {
    unsigned char kind, a, b;
} recipe_row;

typedef struct recipe {
    int n;
    recipe_row row[HX_JOINT_MAX_EQUATIONS];
} recipe;

#define PX {POINT, X, 0}, {POINT, Y, 0}, {POINT, Z, 0}
#define ZALONG {DOT1, Z, X}, {DOT1, Z, Y} /* z_I along z_J */
#define XALONG {DOT1, X, Y}               /* with ZALONG: the same axes */

/* Each type's rows, in the order of phi (docs/interface.md §7.14). */
static const recipe recipes[] = {
    [HX_JOINT_FIXED] = {6, {PX, ZALONG, XALONG}},
    [HX_JOINT_REVOLUTE] = {5, {PX, ZALONG}},
    [HX_JOINT_TRANSLATIONAL] = {5, {ZALONG, XALONG, {DOT2, 0, X}, {DOT2, 0, Y}}},
    [HX_JOINT_CYLINDRICAL] = {4, {ZALONG, {DOT2, 0, X}, {DOT2, 0, Y}}},
    [HX_JOINT_SPHERICAL] = {3, {PX}},
    /* the z axes are the cross's pins: perpendicular */
    [HX_JOINT_UNIVERSAL] = {4, {PX, {DOT1, Z, Z}}},
    /* the z axes are the shafts; x_I and y_J the cross's pins */
    [HX_JOINT_HOOKE] = {4, {PX, {DOT1, X, Y}}},
    [HX_JOINT_PLANAR] = {3, {ZALONG, {DOT2, 0, Z}}},
    /* the z axes are the shafts, pointing away from the centre */
    [HX_JOINT_CONVEL] = {4, {PX, {CONVEL, 0, 0}}},
    [HX_JOINT_RACKPIN] = {1, {{RACKPIN, 0, 0}}},
    [HX_JOINT_SCREW] = {1, {{SCREW, 0, 0}}},
    /* the primitives (Constraint_Jprim, JPRIM) */
    [HX_JOINT_ATPOINT] = {3, {PX}},
    [HX_JOINT_INLINE] = {2, {{DOT2, 0, X}, {DOT2, 0, Y}}},
    [HX_JOINT_INPLANE] = {1, {{DOT2, 0, Z}}},
    [HX_JOINT_ORIENTATION] = {3, {ZALONG, XALONG}},
    [HX_JOINT_PARALLEL_AXES] = {2, {ZALONG}},
    [HX_JOINT_PERPENDICULAR] = {1, {{DOT1, Z, Z}}},
};

int hx_joint_equations_count(enum hx_joint_type type)
{
    return recipes[type].n;
}

int hx_joint_equation_is_length(enum hx_joint_type type, int e)
{
    const int kind = recipes[type].row[e].kind;
    return kind != DOT1 && kind != CONVEL;
}

const char *hx_joint_equation_name(enum hx_joint_type type, int e, char *text, size_t size)
{
    static const char axis_name[3] = {'x', 'y', 'z'};
    const recipe_row *w = &recipes[type].row[e];
    if (w->kind == POINT)
        snprintf(text, size, "x_I - x_J along %c", axis_name[w->a]);
    else if (w->kind == DOT1)
        snprintf(text, size, "%c_I . %c_J", axis_name[w->a], axis_name[w->b]);
    else if (w->kind == DOT2)
        snprintf(text, size, "%c_J . (x_I - x_J)", axis_name[w->b]);
    else if (w->kind == CONVEL)
        snprintf(text, size, "x_I . y_J + y_I . x_J");
    else if (w->kind == RACKPIN)
        snprintf(text, size, "(x_J - x_I) . z_J - PD/2 turn of x_I about z_I");
    else
        snprintf(text, size, "(x_I - x_J) . z_J - PITCH/(2 pi) turn of x_I about z_J");
    return text;
}

/* RACKPIN: the rack's travel s = (x_J - x_I) . z_J and the pinion's turn
 * theta = atan2(-y_I . z_J, x_I . z_J) (x_I from z_J about z_I). */
static void rackpin(term *t, const side *i, const side *j, const hx_joint_law *law)
{
    term s, a, b, theta;
    dot2(&s, i, j, Z), scale(&s, -1.0);
    dot1(&a, i, Y, j, Z), scale(&a, -1.0);
    dot1(&b, i, X, j, Z);
    angle(&theta, &a, &b, i, j);
    gearing(t, &s, &theta, law);
}

/* SCREW: s = (x_I - x_J) . z_J, theta = atan2(x_I . y_J, x_I . x_J) (x_I from
 * x_J about z_J). */
static void screw(term *t, const side *i, const side *j, const hx_joint_law *law)
{
    term s, a, b, theta;
    dot2(&s, i, j, Z);
    dot1(&a, i, X, j, Y);
    dot1(&b, i, X, j, X);
    angle(&theta, &a, &b, i, j);
    gearing(t, &s, &theta, law);
}

/* The markers' world frames at t = 0 as sides (a body at the world's origin). */
void hx_joint_equations_law(const hx_joint *joint, const hx_marker *mi, const hx_marker *mj,
                            hx_joint_law *law)
{
    law->ratio = law->s0 = law->theta0 = 0.0;
    if (joint->type != HX_JOINT_RACKPIN && joint->type != HX_JOINT_SCREW)
        return;
    law->ratio = joint->type == HX_JOINT_RACKPIN ? 0.5 * joint->pitch_diameter
                                                 : joint->pitch / (2.0 * M_PI);
    hx_frame world;
    memset(&world, 0, sizeof world);
    m3_identity(world.R);
    const hx_joint_side hi = {&world, mi->pos0, mi->R0}, hj = {&world, mj->pos0, mj->R0};
    side i, j;
    place(&i, &hi);
    place(&j, &hj);
    term s, a, b;
    if (joint->type == HX_JOINT_RACKPIN) {
        dot2(&s, &i, &j, Z), scale(&s, -1.0);
        dot1(&a, &i, Y, &j, Z), scale(&a, -1.0);
        dot1(&b, &i, X, &j, Z);
    } else {
        dot2(&s, &i, &j, Z);
        dot1(&a, &i, X, &j, Y);
        dot1(&b, &i, X, &j, X);
    }
    law->s0 = s.phi;
    law->theta0 = atan2(a.phi, b.phi);
}

void hx_joint_equations_eval(enum hx_joint_type type, const hx_joint_law *law,
                             const hx_joint_side *ji, const hx_joint_side *jj, double *phi,
                             double *G, double *gamma)
{
    side i, j;
    place(&i, ji);
    place(&j, jj);
    rows o = {phi, G, gamma, 0};
    const recipe *r = &recipes[type];
    for (int e = 0; e < r->n; ++e) {
        const recipe_row *w = &r->row[e];
        term t, u;
        if (w->kind == POINT)
            point(&t, &i, &j, w->a);
        else if (w->kind == DOT1)
            dot1(&t, &i, w->a, &j, w->b);
        else if (w->kind == DOT2)
            dot2(&t, &i, &j, w->b);
        else if (w->kind == CONVEL)
            dot1(&t, &i, X, &j, Y), dot1(&u, &i, Y, &j, X), combine(&t, &t, 1.0, &u);
        else if (w->kind == RACKPIN)
            rackpin(&t, &i, &j, law);
        else
            screw(&t, &i, &j, law);
        put(&o, &t);
    }
}

void hx_joint_equations_of(const hx_model *m, int joint, const hx_frame *fi, const hx_frame *fj,
                           double *phi, double *G, double *gamma)
{
    const hx_joint *j = &m->joints[joint];
    const hx_marker *mi = &m->markers[j->i_marker], *mj = &m->markers[j->j_marker];
    const hx_joint_side si = {fi, mi->r_local, mi->R_local}, sj = {fj, mj->r_local, mj->R_local};
    hx_joint_law law;
    hx_joint_equations_law(j, mi, mj, &law);
    hx_joint_equations_eval(j->type, &law, &si, &sj, phi, G, gamma);
}
