/*
 * The equations of each joint type (joint_equations.h), built from three
 * primitives between the markers' origins x_I, x_J and their axes:
 *   point     x_I - x_J = 0                    (3 rows)
 *   dot-1     a_I . b_J = 0, a on I, b on J     (1 row: the axes stay perpendicular)
 *   dot-2     b_J . (x_I - x_J) = 0, b on J     (1 row: x_I stays in b's normal plane)
 * With r = R s the marker's lever from its body's centre, the marker moves at
 * v + omega x r and an axis a turns at omega x a; c . (omega x r) = omega . (r x c)
 * gives G's rows. gamma = -(d/dt G) w: the terms in omega x (omega x .) and the
 * cross terms of two turning vectors, negated.
 */
#include "sim/dynamics/joint_equations.h"

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

/* One row's writer: phi, G's 12 columns and gamma at row n. */
typedef struct rows {
    double *phi, *G, *gamma;
    int n;
} rows;

static void put(rows *o, double phi, const double vi[3], const double wi[3], const double vj[3],
                const double wj[3], double gamma)
{
    o->phi[o->n] = phi;
    if (o->G != NULL) {
        double *g = o->G + 12 * o->n;
        v3_copy(g, vi), v3_copy(g + 3, wi), v3_copy(g + 6, vj), v3_copy(g + 9, wj);
    }
    if (o->gamma != NULL)
        o->gamma[o->n] = gamma;
    o->n++;
}

/* x_I - x_J = 0, its component k: e_k . (v_I + w_I x r_I - v_J - w_J x r_J). */
static void point(rows *o, const side *i, const side *j, int k)
{
    double e[3] = {0, 0, 0}, wi[3], wj[3], ve[3];
    e[k] = 1.0;
    v3_cross(wi, i->r, e);
    v3_cross(wj, j->r, e);
    v3_scale(wj, wj, -1.0);
    v3_scale(ve, e, -1.0);
    put(o, i->x[k] - j->x[k], e, wi, ve, wj, -(i->wwr[k] - j->wwr[k]));
}

/* a_I . b_J = 0: d/dt = w_I . (a x b) + w_J . (b x a). */
static void dot1(rows *o, const side *i, int ka, const side *j, int kb)
{
    static const double zero[3] = {0, 0, 0};
    double a[3], b[3], axb[3], bxa[3], wa[3], wb[3], wwa[3], wwb[3];
    axis(a, i, ka);
    axis(b, j, kb);
    v3_cross(axb, a, b);
    v3_scale(bxa, axb, -1.0);
    v3_cross(wa, i->w, a);
    v3_cross(wb, j->w, b);
    v3_cross(wwa, i->w, wa);
    v3_cross(wwb, j->w, wb);
    const double c = v3_dot(wwa, b) + 2.0 * v3_dot(wa, wb) + v3_dot(a, wwb);
    put(o, v3_dot(a, b), zero, axb, zero, bxa, -c);
}

/* b_J . d = 0 with d = x_I - x_J: d/dt = (w_J x b) . d + b . d_dot. */
static void dot2(rows *o, const side *i, const side *j, int kb)
{
    double b[3], d[3], ddot[3], wi[3], wj[3], vj[3], rjb[3], wb[3], wwb[3], dacc[3];
    axis(b, j, kb);
    v3_sub(d, i->x, j->x);
    v3_sub(ddot, i->xdot, j->xdot);
    v3_cross(wi, i->r, b);
    v3_cross(wj, b, d);
    v3_cross(rjb, j->r, b);
    v3_sub(wj, wj, rjb);
    v3_scale(vj, b, -1.0);
    v3_cross(wb, j->w, b);
    v3_cross(wwb, j->w, wb);
    v3_sub(dacc, i->wwr, j->wwr);
    const double c = v3_dot(wwb, d) + 2.0 * v3_dot(wb, ddot) + v3_dot(b, dacc);
    put(o, v3_dot(b, d), b, wi, vj, wj, -c);
}

enum { X, Y, Z };
enum { POINT, DOT1, DOT2 };

/* A row: its primitive and axes (POINT: component a; DOT1: a_I . b_J; DOT2: b_J . d). */
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
    return recipes[type].row[e].kind != DOT1;
}

const char *hx_joint_equation_name(enum hx_joint_type type, int e, char *text, size_t size)
{
    static const char axis_name[3] = {'x', 'y', 'z'};
    const recipe_row *w = &recipes[type].row[e];
    if (w->kind == POINT)
        snprintf(text, size, "x_I - x_J along %c", axis_name[w->a]);
    else if (w->kind == DOT1)
        snprintf(text, size, "%c_I . %c_J", axis_name[w->a], axis_name[w->b]);
    else
        snprintf(text, size, "%c_J . (x_I - x_J)", axis_name[w->b]);
    return text;
}

void hx_joint_equations_eval(enum hx_joint_type type, const hx_joint_side *ji,
                             const hx_joint_side *jj, double *phi, double *G, double *gamma)
{
    side i, j;
    place(&i, ji);
    place(&j, jj);
    rows o = {phi, G, gamma, 0};
    const recipe *r = &recipes[type];
    for (int e = 0; e < r->n; ++e) {
        const recipe_row *w = &r->row[e];
        if (w->kind == POINT)
            point(&o, &i, &j, w->a);
        else if (w->kind == DOT1)
            dot1(&o, &i, w->a, &j, w->b);
        else
            dot2(&o, &i, &j, w->b);
    }
}
