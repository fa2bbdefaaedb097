/*
 * The Force_StateEqn elements' blocks of the Newton matrix (newton_matrix.h).
 * With x an element's states, U(y) its inputs (the harness's own measures),
 * xdot = F(x, U) and out = G(x, U):
 *
 *   rows of x:  by a body's column F_u dU/dy, by its own states F_x
 *   outputs:    G_u dU/dy and G_x, applied as a GFOSUB's force (on I at the
 *               I marker, reversed on J's body, in ref_marker's axes)
 *
 * F_x, F_u, G_x, G_u are YFOXX, YFOXU, YFOYX and YFOYU when the library
 * exports them, else central differences of YFOSUB (dflag set); dU/dy are
 * differences of the harness's measures alone (no library call), on the
 * columns of the bodies the inputs measure.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/finite.h"
#include "base/vecmath.h"
#include "host/invoke.h"
#include "host/state_inputs.h"
#include "model/expr/expr.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/loads.h"
#include "sim/dynamics/stateeqns.h"
#include "sim/jacobian/jacobian_parts.h"

#define MAX_INPUT_BODIES 32

static const char *const routine_names[4] = {"YFOXX", "YFOXU", "YFOYX", "YFOYU"};

struct hx_stateeqn_blocks {
    size_t *block;       /* per element: where its F_x, F_u, G_x, G_u start in partials */
    double *partials;
    double *x, *u, *xdot, *xdotm, *out, *outm, *up, *um, *du, *g; /* scratch */
    unsigned char exported[4];    /* the library's partial routine r was used */
    unsigned char differenced[4]; /* routine r was differenced for some element */
};

/* Body b (not the ground) added to bodies[0 .. *count) unless there. */
static void add_input_body(const hx_dynamics *d, int b, int *bodies, int *count, int max)
{
    if (b < 0 || d->dof[b].kind == HX_DOF_GROUND)
        return;
    for (int l = 0; l < *count; ++l)
        if (bodies[l] == b)
            return;
    if (*count < max)
        bodies[(*count)++] = b;
}

int hx_stateeqn_input_bodies(const hx_dynamics *d, int k, int *bodies, int max)
{
    const hx_model *m = d->m;
    const hx_stateeqn *f = &m->stateeqns[k];
    int count = 0;
    for (int i = 0; i < f->ninput; ++i) {
        const hx_variable *v = &m->variables[f->inputs[i]];
        if (v->varsub) { /* the bodies its VARSUB declared it reads (loads.h) */
            int read[HX_LOAD_BODIES_MAX];
            const int nread = hx_variable_bodies(d, f->inputs[i], read);
            for (int j = 0; j < nread; ++j)
                add_input_body(d, read[j], bodies, &count, max);
            continue;
        }
        /* the markers of its measure, or of every measure its expression reads */
        int markers[4 * 64], nmarkers = 0;
        if (v->program == NULL)
            for (int j = 0; j < v->nmarkers; ++j)
                markers[nmarkers++] = v->marker_ids[j] != 0 ? hx_model_marker(m, v->marker_ids[j])
                                                            : -1;
        const hx_expr_input *in = v->program != NULL ? hx_expr_inputs(v->program) : NULL;
        for (int l = 0; v->program != NULL && l < hx_expr_input_count(v->program); ++l)
            for (int j = 0; in[l].kind == HX_EXPR_INPUT_MEASURE && j < in[l].nids && j < 4; ++j)
                markers[nmarkers++] = in[l].index[j];
        for (int j = 0; j < nmarkers; ++j)
            add_input_body(d, markers[j] >= 0 ? m->markers[markers[j]].body : -1, bodies, &count,
                           max);
    }
    return count;
}

int hx_stateeqn_blocks_init(hx_jacobian *jac, hx_message *msg)
{
    const hx_model *m = jac->d->m;
    struct hx_stateeqn_blocks *sb = jac->stateeqn_blocks = calloc(1, sizeof *sb);
    if (sb == NULL)
        return hx_fail(msg, "out of memory");
    sb->block = calloc((size_t)m->nstateeqns + 1, sizeof *sb->block);
    size_t partials = 0;
    int widest = 6;
    for (int k = 0; k < m->nstateeqns; ++k) {
        const hx_stateeqn *f = &m->stateeqns[k];
        sb->block[k] = partials;
        partials += ((size_t)f->nstate + 6) * ((size_t)f->nstate + (size_t)f->ninput);
        if (f->nstate + f->ninput + 6 > widest)
            widest = f->nstate + f->ninput + 6;
    }
    sb->partials = calloc(partials + 1, sizeof(double));
    sb->x = calloc(10 * (size_t)widest, sizeof(double));
    if (sb->block == NULL || sb->partials == NULL || sb->x == NULL)
        return hx_fail(msg, "out of memory");
    double *p = sb->x;
    double **scratch[] = {&sb->u, &sb->xdot, &sb->xdotm, &sb->out, &sb->outm, &sb->up, &sb->um,
                          &sb->du, &sb->g};
    for (size_t i = 0; i < sizeof scratch / sizeof *scratch; ++i)
        *scratch[i] = (p += widest);
    return 0;
}

void hx_stateeqn_blocks_free(hx_jacobian *jac)
{
    struct hx_stateeqn_blocks *sb = jac->stateeqn_blocks;
    if (sb == NULL)
        return;
    free(sb->block);
    free(sb->partials);
    free(sb->x);
    free(sb);
    jac->stateeqn_blocks = NULL;
}

/* The four blocks of element k by the library's partial routines where it
 * exports them; which[r] is set for the routines that must be differenced. */
static int library_partials(hx_jacobian *jac, int k, double *blocks[4], int which[4])
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    struct hx_stateeqn_blocks *sb = jac->stateeqn_blocks;
    const hx_stateeqn *f = &d->m->stateeqns[k];
    hx_binding *b = d->stateeqns->binding[k];
    const int size[4] = {f->nstate * f->nstate, f->nstate * f->ninput, 6 * f->nstate,
                         6 * f->ninput};
    for (int r = 0; r < 4; ++r) {
        which[r] = b->fn.stateeqn.partial[r] == NULL;
        if (which[r]) {
            sb->differenced[r] = 1;
            continue;
        }
        sb->exported[r] = 1;
        memcpy(sb->xdot, sb->x, sizeof(double) * (size_t)f->nstate); /* copies it may write */
        memcpy(sb->xdotm, sb->u, sizeof(double) * (size_t)f->ninput);
        hx_invoke_stateeqn_partial(b, r, &dd->frames, sb->xdot, sb->xdotm, blocks[r], NULL);
        jac->partial_calls++;
        if (hx_dynamics_check_call(d, dd, b, NULL, 0, "", dd->frames.time) != 0)
            return -1;
        if (!hx_all_finite(blocks[r], size[r]))
            return hx_dynamics_fail(dd, "Force_StateEqn %d: %s returned non-finite partials at t ="
                                    " %g", f->id, b->names[1 + r], dd->frames.time);
    }
    return 0;
}

/* The step of a difference in value v: relative above 1e-3, absolute below
 * (states and inputs are lengths, angles and their rates in model units). */
static double step_of(double v)
{
    return 1e-6 * fmax(fabs(v), 1e-3);
}

/* Central differences of YFOSUB for the blocks the library does not give:
 * states perturbed for F_x and G_x, inputs for F_u and G_u. */
static int differenced_partials(hx_jacobian *jac, int k, double *blocks[4],
                                const int which[4])
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    struct hx_stateeqn_blocks *sb = jac->stateeqn_blocks;
    const hx_stateeqn *f = &d->m->stateeqns[k];
    const int ns = f->nstate, ni = f->ninput;
    for (int group = 0; group < 2; ++group) {
        if (!which[group] && !which[group + 2])
            continue;
        double *v = group == 0 ? sb->x : sb->u;
        const int columns = group == 0 ? ns : ni;
        for (int j = 0; j < columns; ++j) {
            const double keep = v[j], h = step_of(keep);
            v[j] = keep + h;
            int status = hx_stateeqn_call(d, dd, k, sb->x, sb->u, 1, sb->xdot, sb->out);
            v[j] = keep - h;
            if (status == 0)
                status = hx_stateeqn_call(d, dd, k, sb->x, sb->u, 1, sb->xdotm, sb->outm);
            v[j] = keep;
            jac->partial_calls += 2;
            if (status != 0)
                return -1;
            for (int i = 0; i < ns && which[group]; ++i)
                blocks[group][i + ns * j] = (sb->xdot[i] - sb->xdotm[i]) / (2.0 * h);
            for (int i = 0; i < 6 && which[group + 2]; ++i)
                blocks[group + 2][i + 6 * j] = (sb->out[i] - sb->outm[i]) / (2.0 * h);
        }
    }
    return 0;
}

/* dU/dy along column c of body b: differences of the harness's measures. */
static void input_slope(hx_jacobian *jac, int k, int b, int c)
{
    struct hx_stateeqn_blocks *sb = jac->stateeqn_blocks;
    const hx_model *m = jac->d->m;
    const hx_stateeqn *f = &m->stateeqns[k];
    const double keep = jac->y[c], h = hx_jacobian_step(jac->y, c);
    for (int side = 0; side < 2; ++side) {
        jac->y[c] = keep + (side == 0 ? h : -h);
        hx_jacobian_move_body(jac, b, jac->y);
        hx_stateeqn_inputs(&jac->moved, k, side == 0 ? sb->up : sb->um);
    }
    jac->y[c] = keep;
    hx_jacobian_restore_body(jac, b);
    for (int i = 0; i < f->ninput; ++i) {
        double delta = sb->up[i] - sb->um[i];
        if (hx_variable_is_angle(&m->variables[f->inputs[i]]))
            delta = remainder(delta, 2.0 * M_PI);
        sb->du[i] = delta / (2.0 * h);
    }
}

/* x rows += Fb v and dout = Gb v for one column (v over the states or the inputs). */
static void through(const double *Fb, const double *Gb, int ns, int nv, const double *v,
                    double *xcol, double dout[6])
{
    for (int i = 0; i < ns; ++i) {
        double s = 0.0;
        for (int j = 0; j < nv; ++j)
            s += Fb[i + ns * j] * v[j];
        xcol[i] = s;
    }
    for (int i = 0; i < 6; ++i) {
        double s = 0.0;
        for (int j = 0; j < nv; ++j)
            s += Gb[i + 6 * j] * v[j];
        dout[i] = s;
    }
}

static int element_block(hx_jacobian *jac, int k, const double *y)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    struct hx_stateeqn_blocks *sb = jac->stateeqn_blocks;
    const hx_model *m = d->m;
    const hx_stateeqn *f = &m->stateeqns[k];
    const hx_frames *fr = &dd->frames;
    const int ns = f->nstate, ni = f->ninput, x0 = d->stateeqns->offset[k];
    memcpy(sb->x, y + x0, sizeof(double) * (size_t)ns);
    if (hx_stateeqn_inputs(fr, k, sb->u) != 0)
        return hx_dynamics_fail(dd, "Force_StateEqn %d: an input could not be measured", f->id);
    double *xx = sb->partials + sb->block[k];
    double *blocks[4] = {xx, xx + ns * ns, xx + ns * (ns + ni), xx + ns * (ns + ni) + 6 * ns};
    int which[4];
    if (library_partials(jac, k, blocks, which) != 0 || differenced_partials(jac, k, blocks, which) != 0)
        return -1;
    hx_frame scratch[2];
    hx_applied_force a;
    a.bi = m->markers[f->i_marker].body;
    a.bj = m->markers[f->j_marker].body;
    a.ba = f->ref_marker >= 0 ? m->markers[f->ref_marker].body : -1;
    a.I = hx_frames_marker(fr, f->i_marker, &scratch[0]);
    a.R_A = hx_frames_marker(fr, f->ref_marker, &scratch[1])->R;
    const double *out0 = dd->stateeqn_outputs + 6 * k;
    m3_apply(a.F, a.R_A, out0);
    m3_apply(a.T, a.R_A, out0 + 3);
    static const hx_motion still;
    double dout[6];
    /* the element's own states */
    for (int j = 0; j < ns; ++j) {
        double e[64] = {0};
        if (ns > 64)
            return hx_dynamics_fail(dd, "Force_StateEqn %d: more than 64 states", f->id);
        e[j] = 1.0;
        through(blocks[0], blocks[2], ns, ns, e, sb->g, dout);
        hx_jacobian_add(jac, x0, ns, x0 + j, sb->g);
        hx_jacobian_applied_force(jac, &a, x0 + j, -1, &still, dout, NULL);
    }
    /* the bodies' columns: through the inputs, and the force's geometry */
    int bodies[MAX_INPUT_BODIES + 3];
    const int measured = hx_stateeqn_input_bodies(d, k, bodies, MAX_INPUT_BODIES);
    int count = measured;
    const int geometry[3] = {a.bi, a.bj, a.ba};
    for (int i = 0; i < 3; ++i) {
        int seen = geometry[i] < 0 || d->dof[geometry[i]].kind == HX_DOF_GROUND;
        for (int l = 0; l < count && !seen; ++l)
            seen = bodies[l] == geometry[i];
        if (!seen)
            bodies[count++] = geometry[i];
    }
    for (int l = 0; l < count; ++l) {
        const int b = bodies[l];
        int columns[13];
        const int nc = hx_jacobian_body_columns(d, b, columns);
        for (int j = 0; j < nc; ++j) {
            hx_motion mo;
            hx_body_column_motion(d, b, j, y, &fr->bodies[b], &mo);
            if (l < measured)
                input_slope(jac, k, b, columns[j]);
            else
                memset(sb->du, 0, sizeof(double) * (size_t)ni);
            through(blocks[1], blocks[3], ns, ni, sb->du, sb->g, dout);
            hx_jacobian_add(jac, x0, ns, columns[j], sb->g);
            hx_jacobian_applied_force(jac, &a, columns[j], b, &mo, dout, NULL);
        }
    }
    return 0;
}

int hx_stateeqn_blocks(hx_jacobian *jac, double t, const double *y)
{
    (void)t;
    for (int k = 0; k < jac->d->m->nstateeqns; ++k)
        if (element_block(jac, k, y) != 0)
            return -1;
    return 0;
}

void hx_stateeqn_blocks_describe(const hx_jacobian *jac, char *text, size_t size)
{
    const struct hx_stateeqn_blocks *sb = jac->stateeqn_blocks;
    if (jac->d->m->nstateeqns == 0)
        return;
    size_t len = strlen(text);
    for (int r = 0; r < 4 && len < size; ++r)
        len += (size_t)snprintf(text + len, size - len, "%s%s %s", r == 0 ? "\n    Force_StateEqn"
                                " partials: " : "; ", routine_names[r],
                                sb->exported[r] && sb->differenced[r] ? "the library's and by"
                                " differences of YFOSUB" : sb->exported[r] ? "the library's"
                                : "by differences of YFOSUB (not exported)");
}
