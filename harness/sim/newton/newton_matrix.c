/* The Newton matrix from the elements' own partials (newton_matrix.h). */
#include "sim/newton/newton_matrix.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/finite.h"
#include "state/measures.h"

#define TWIN_TOLERANCE 1e-9

/* The perturbation of column c: relative above 1, absolute below (the
 * kinematics and the frozen right-hand side are smooth: central differences
 * of this size are good to about 1e-10). */
static double column_step(const double *y, int c)
{
    return 1e-5 * fmax(1.0, fabs(y[c]));
}

static void mark_body(hx_newton_matrix *nm, int k, int marker)
{
    if (marker >= 0)
        nm->touches[k * nm->d->m->nbodies + nm->d->m->markers[marker].body] = 1;
}

/* The twin's results are in J's axes; the GFOSUB result in the reference
 * marker's: the two compare only when those axes coincide for good. */
static int same_axes(const hx_model *m, const hx_force *f)
{
    if (f->ref_marker == f->j_marker)
        return 1;
    if (f->ref_marker < 0)
        return 0;
    const hx_marker *r = &m->markers[f->ref_marker], *j = &m->markers[f->j_marker];
    return r->body == j->body && memcmp(r->R_local, j->R_local, sizeof r->R_local) == 0;
}

int hx_newton_matrix_init(hx_newton_matrix *nm, hx_dynamics *d, hx_message *msg)
{
    memset(nm, 0, sizeof *nm);
    nm->d = d;
    nm->n = d->n;
    nm->m = d->nq + d->nu;
    const hx_model *m = d->m;
    const int nf = nm->nf = m->nforces, n = nm->n;
    nm->ne = m->nstate_eqns;
    const size_t f1 = (size_t)nf + 1, o1 = f1 + (size_t)nm->ne; /* output groups */
    nm->source = calloc(f1, sizeof *nm->source);
    nm->why = calloc(f1 * HX_NEWTON_WHY, 1);
    nm->column_body = calloc((size_t)nm->m + 1, sizeof *nm->column_body);
    nm->touches = calloc(f1 * (size_t)m->nbodies, 1);
    nm->outputs = calloc(6 * o1, sizeof(double));
    nm->partials = calloc(72 * f1, sizeof(double));
    nm->dout = calloc(6 * f1 * ((size_t)nm->m + 1), sizeof(double));
    nm->response = calloc(6 * o1 * (size_t)n, sizeof(double));
    nm->unit = calloc(6 * o1, sizeof(double));
    nm->y = calloc(3 * (size_t)n, sizeof(double));
    nm->plus = calloc(24 * f1, sizeof(double));
    hx_messages_init(&nm->twin_messages, NULL);
    if (!nm->source || !nm->why || !nm->column_body || !nm->touches || !nm->outputs ||
        !nm->partials || !nm->dout || !nm->response || !nm->unit || !nm->y || !nm->plus ||
        hx_state_jacobian_init(&nm->states, d, msg) != 0) {
        hx_newton_matrix_free(nm);
        return hx_fail(msg, "out of memory");
    }
    nm->fp = nm->y + n;
    nm->fm = nm->fp + n;
    nm->minus = nm->plus + 12 * f1;
    for (int b = 0; b < m->nbodies; ++b) {
        const hx_body_dof *dof = &d->dof[b];
        const int nq = dof->kind == HX_DOF_FREE ? 7 : dof->kind == HX_DOF_GROUND ? 0 : 1;
        const int nu = dof->kind == HX_DOF_FREE ? 6 : nq;
        for (int i = 0; i < nq; ++i)
            nm->column_body[dof->q + i] = b;
        for (int i = 0; i < nu; ++i)
            nm->column_body[d->nq + dof->u + i] = b;
    }
    for (int k = 0; k < nf; ++k) {
        const hx_force *f = &m->forces[k];
        const hx_binding *b = d->force_binding[k];
        mark_body(nm, k, f->i_marker);
        mark_body(nm, k, f->j_marker);
        char *why = nm->why + k * HX_NEWTON_WHY;
        if (f->interface == HX_FORCE_FIESUB) {
            nm->source[k] = HX_PARTIALS_FIESUB;
        } else if (b->twin == NULL) {
            nm->source[k] = HX_PARTIALS_DIFFERENCES;
            snprintf(why, HX_NEWTON_WHY, "its library exports no FIESUB twin of %s", b->names[0]);
        } else if (!same_axes(m, f)) {
            nm->source[k] = HX_PARTIALS_DIFFERENCES;
            snprintf(why, HX_NEWTON_WHY, "its ref_marker_id is not its J marker, whose axes the"
                     " twin %s answers in", b->twin_name);
        } else {
            nm->source[k] = HX_PARTIALS_TWIN;
        }
        if (nm->source[k] == HX_PARTIALS_DIFFERENCES)
            mark_body(nm, k, f->ref_marker); /* its result turns with that frame */
    }
    return 0;
}

void hx_newton_matrix_free(hx_newton_matrix *nm)
{
    free(nm->source);
    free(nm->why);
    free(nm->column_body);
    free(nm->touches);
    free(nm->outputs);
    free(nm->partials);
    free(nm->dout);
    free(nm->response);
    free(nm->unit);
    free(nm->y);
    free(nm->plus);
    hx_state_jacobian_free(&nm->states);
    hx_messages_destroy(&nm->twin_messages);
    memset(nm, 0, sizeof *nm);
}

/* The twin agrees with the GFOSUB result: each of force and torque to 1e-9
 * of its size (rounding of the two angle measures allowed for). */
static int twin_agrees(const double gfo[6], const double twin[6], double *worst)
{
    *worst = 0.0;
    for (int g = 0; g < 6; g += 3) {
        double size = 0.0;
        for (int i = g; i < g + 3; ++i)
            size = fmax(size, fmax(fabs(gfo[i]), fabs(twin[i])));
        for (int i = g; i < g + 3; ++i)
            if (size > 0.0)
                *worst = fmax(*worst, fabs(gfo[i] - twin[i]) / size);
    }
    return *worst <= TWIN_TOLERANCE;
}

/* Each element's outputs at the dynamics' state (set to y), and the partials
 * of those that have them. */
static int outputs_and_partials(hx_newton_matrix *nm)
{
    hx_dynamics *d = nm->d;
    const hx_state *s = &d->state;
    for (int k = 0; k < nm->nf; ++k) {
        hx_binding *b = d->force_binding[k];
        double *out = nm->outputs + 6 * k, *dfd = nm->partials + 72 * k, *dfv = dfd + 36;
        double disp[6], velo[6];
        hx_force_deformation(s, k, disp, velo);
        if (nm->source[k] == HX_PARTIALS_FIESUB) {
            hx_call_fiesub(b, s, disp, velo, 0, 0, out, dfd, dfv, NULL);
            nm->partial_calls++;
        } else {
            hx_call_gfosub(b, s, 0, 0, out, NULL);
            nm->partial_calls++;
        }
        if (hx_dynamics_check_stop(d, b) != 0)
            return -1;
        if (!hx_all_finite(out, 6))
            return hx_dynamics_fail(d, "%s %d returned a non-finite force at t = %g", b->element,
                                    b->id, s->time);
        if (nm->source[k] != HX_PARTIALS_TWIN)
            continue;
        double field[6], worst = 0.0;
        hx_call_twin(b, s, disp, velo, field, dfd, dfv, &nm->twin_messages);
        nm->partial_calls++;
        const int refused = hx_messages_stopped(&nm->twin_messages);
        const int finite = hx_all_finite(dfd, 72);
        if (refused || !finite || !twin_agrees(out, field, &worst)) {
            /* for good: a twin that disagrees once is not the element's */
            nm->source[k] = HX_PARTIALS_DIFFERENCES;
            mark_body(nm, k, d->m->forces[k].ref_marker);
            if (refused)
                snprintf(nm->why + k * HX_NEWTON_WHY, HX_NEWTON_WHY, "its twin %s refused the"
                         " list: %.80s", b->twin_name, nm->twin_messages.stop_message);
            else if (!finite)
                snprintf(nm->why + k * HX_NEWTON_WHY, HX_NEWTON_WHY, "its twin %s returned"
                         " non-finite partials at t = %g", b->twin_name, s->time);
            else
                snprintf(nm->why + k * HX_NEWTON_WHY, HX_NEWTON_WHY, "its twin %s differs from"
                         " it by %.2g (relative) at t = %g", b->twin_name, worst, s->time);
            hx_messages_reset(&nm->twin_messages);
        }
    }
    return 0;
}

static double angle_difference(double a, double b)
{
    double x = a - b;
    if (x > M_PI)
        x -= 2.0 * M_PI;
    else if (x < -M_PI)
        x += 2.0 * M_PI;
    return x;
}

/* What column c moves of each element it touches, at y + sign h e_c: the
 * deformation and rates (12 values) or, for elements differenced alone, their
 * outputs (GFOSUB with dflag set). */
static int perturbed(hx_newton_matrix *nm, double t, int c, double h, double *into)
{
    hx_dynamics *d = nm->d;
    const int body = nm->column_body[c], nb = d->m->nbodies;
    const double keep = nm->y[c];
    nm->y[c] = keep + h;
    hx_dynamics_set_state(d, t, nm->y);
    nm->y[c] = keep;
    for (int k = 0; k < nm->nf; ++k) {
        if (!nm->touches[k * nb + body])
            continue;
        double *v = into + 12 * k;
        if (nm->source[k] != HX_PARTIALS_DIFFERENCES) {
            hx_force_deformation(&d->state, k, v, v + 6);
            continue;
        }
        hx_binding *b = d->force_binding[k];
        hx_call_gfosub(b, &d->state, 1, 0, v, NULL);
        nm->partial_calls++;
        if (hx_dynamics_check_stop(d, b) != 0)
            return -1;
        if (!hx_all_finite(v, 6))
            return hx_dynamics_fail(d, "%s %d returned a non-finite force at t = %g", b->element,
                                    b->id, t);
    }
    return 0;
}

/* dOut_k/dy column by column (positions and velocities). */
static int output_derivatives(hx_newton_matrix *nm, double t)
{
    const int m = nm->m, nb = nm->d->m->nbodies;
    memset(nm->dout, 0, sizeof(double) * 6 * (size_t)nm->nf * (size_t)m);
    for (int c = 0; c < m; ++c) {
        const int body = nm->column_body[c];
        int any = 0;
        for (int k = 0; k < nm->nf && !any; ++k)
            any = nm->touches[k * nb + body];
        if (!any)
            continue;
        const double h = column_step(nm->y, c);
        if (perturbed(nm, t, c, h, nm->plus) != 0 || perturbed(nm, t, c, -h, nm->minus) != 0)
            return -1;
        for (int k = 0; k < nm->nf; ++k) {
            if (!nm->touches[k * nb + body])
                continue;
            const double *p = nm->plus + 12 * k, *q = nm->minus + 12 * k;
            double *col = nm->dout + 6 * ((size_t)k * (size_t)m + (size_t)c);
            if (nm->source[k] == HX_PARTIALS_DIFFERENCES) {
                for (int i = 0; i < 6; ++i)
                    col[i] = (p[i] - q[i]) / (2.0 * h);
                continue;
            }
            double rate[12]; /* d(disp, velo)/dy_c */
            for (int i = 0; i < 12; ++i)
                rate[i] = (i >= 3 && i < 6 ? angle_difference(p[i], q[i]) : p[i] - q[i]) / (2.0 * h);
            const double *dfd = nm->partials + 72 * k, *dfv = dfd + 36;
            for (int i = 0; i < 6; ++i) {
                double s = 0.0;
                for (int j = 0; j < 6; ++j)
                    s += dfd[i + 6 * j] * rate[j] + dfv[i + 6 * j] * rate[6 + j];
                col[i] = s;
            }
        }
    }
    return 0;
}

static int frozen_rhs(hx_newton_matrix *nm, double t, const double *y, const double *outputs,
                      double *f)
{
    nm->d->frozen_outputs = outputs;
    const int status = hx_dynamics_rhs(nm->d, t, y, f);
    nm->d->frozen_outputs = NULL;
    nm->frozen_evaluations++;
    return status;
}

int hx_newton_matrix_build(hx_newton_matrix *nm, double t, const double *y, double *J)
{
    hx_dynamics *d = nm->d;
    const int n = nm->n, m = nm->m, nf = nm->nf;
    memcpy(nm->y, y, sizeof(double) * (size_t)n);
    hx_dynamics_set_state(d, t, y);
    if (outputs_and_partials(nm) != 0 || output_derivatives(nm, t) != 0 ||
        hx_state_jacobian_outputs(&nm->states, t, y, nm->outputs + 6 * nf, &nm->partial_calls) != 0)
        return -1;
    /* J_frozen, column by column; the work accumulators' columns are zero */
    memset(J, 0, sizeof(double) * (size_t)n * (size_t)n);
    for (int c = 0; c < m; ++c) {
        const double h = column_step(y, c);
        nm->y[c] = y[c] + h;
        int status = frozen_rhs(nm, t, nm->y, nm->outputs, nm->fp);
        nm->y[c] = y[c] - h;
        status |= frozen_rhs(nm, t, nm->y, nm->outputs, nm->fm);
        nm->y[c] = y[c];
        if (status != 0)
            return -1;
        for (int r = 0; r < n; ++r)
            J[r + (size_t)n * c] = (nm->fp[r] - nm->fm[r]) / (2.0 * h);
    }
    const int groups = nf + nm->ne; /* the force elements', then the state elements' */
    if (groups == 0)
        return 0;
    /* B_k: the response to each unit output, less the response to none */
    memset(nm->unit, 0, sizeof(double) * 6 * (size_t)groups);
    if (frozen_rhs(nm, t, y, nm->unit, nm->fm) != 0)
        return -1;
    for (int k = 0; k < groups; ++k)
        for (int j = 0; j < 6; ++j) {
            nm->unit[6 * k + j] = 1.0;
            const int status = frozen_rhs(nm, t, y, nm->unit, nm->fp);
            nm->unit[6 * k + j] = 0.0;
            if (status != 0)
                return -1;
            double *col = nm->response + (size_t)n * (6 * (size_t)k + (size_t)j);
            for (int r = 0; r < n; ++r)
                col[r] = nm->fp[r] - nm->fm[r];
        }
    /* J += B_k dOut_k/dy */
    for (int k = 0; k < nf; ++k)
        for (int c = 0; c < m; ++c) {
            const double *dout = nm->dout + 6 * ((size_t)k * (size_t)m + (size_t)c);
            for (int j = 0; j < 6; ++j) {
                if (dout[j] == 0.0)
                    continue;
                const double *B = nm->response + (size_t)n * (6 * (size_t)k + (size_t)j);
                double *col = J + (size_t)n * c;
                for (int r = 0; r < n; ++r)
                    col[r] += B[r] * dout[j];
            }
        }
    hx_state_jacobian_add(&nm->states, nm->response + (size_t)n * 6 * (size_t)nf, J);
    return 0;
}

void hx_newton_matrix_describe(const hx_newton_matrix *nm, char *text, size_t size)
{
    int counts[3] = {0, 0, 0};
    for (int k = 0; k < nm->nf; ++k)
        counts[nm->source[k]]++;
    int len = snprintf(text, size, "Newton matrix from the elements' partials: %d by FIESUB's own,"
                       " %d by their FIESUB twin, %d by differences of the element alone",
                       counts[0], counts[1], counts[2]);
    for (int k = 0; k < nm->nf && len > 0 && (size_t)len < size; ++k)
        if (nm->source[k] == HX_PARTIALS_DIFFERENCES)
            len += snprintf(text + len, size - (size_t)len, "\n    %s %d by differences: %s",
                            nm->d->force_binding[k]->element, nm->d->force_binding[k]->id,
                            nm->why + k * HX_NEWTON_WHY);
    hx_state_jacobian_describe(&nm->states, text, size);
}
