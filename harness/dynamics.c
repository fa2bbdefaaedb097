/* Equations of motion of the harness (dynamics.h). */
#include "dynamics.h"

#include "host.h"

#include <math.h>
#include <stdint.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "element_probe.h"
#include "linalg.h"
#include "vecmath.h"

static const hx_frame world_axes = {{0, 0, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0}};

#define PROJECTION_ITERATIONS 25
#define PHI_TOLERANCE 1e-13

/* ---- set-up --------------------------------------------------------------------- */

static int setup_bodies(hx_dynamics *d, usrsub_message *msg)
{
    const hx_model *m = d->m;
    hx_frame *f = d->s->frames;
    hx_initial_frames(m, f);
    int nq = 0, nu = 0;
    for (int k = 0; k < m->nbodies; ++k) {
        const hx_body *b = &m->bodies[k];
        hx_body_dof *dof = &d->dof[k];
        v3_copy(dof->p0, b->p0);
        m3_copy(dof->R0, b->R0);
        if (b->is_ground) {
            dof->kind = HX_DOF_GROUND;
            continue;
        }
        if (b->joint < 0) {
            dof->kind = HX_DOF_FREE;
            dof->mass = b->mass;
            m3_copy(dof->inertia, b->inertia);
            double inv[9];
            m3_copy(inv, b->inertia);
            for (int c = 0; c < 3; ++c) { /* inverse column by column */
                double A[9], e[3] = {0, 0, 0};
                m3_copy(A, b->inertia);
                e[c] = 1.0;
                if (hx_solve(3, A, e) != 0)
                    return usrsub_fail(msg, "Body_Rigid %d: singular inertia", b->id);
                inv[c] = e[0], inv[3 + c] = e[1], inv[6 + c] = e[2];
            }
            m3_copy(dof->inertia_inv, inv);
            dof->q = nq, dof->u = nu;
            nq += 7, nu += 6;
            continue;
        }
        const hx_joint *j = &m->joints[b->joint];
        const hx_marker *mj = &m->markers[j->j_marker];
        v3_set(dof->axis, mj->R0[2], mj->R0[5], mj->R0[8]);
        v3_copy(dof->origin, mj->pos0);
        dof->coord0 = hx_joint_coordinate(m, f, b->joint);
        if (j->type == HX_JOINT_REVOLUTE) {
            dof->kind = HX_DOF_REVOLUTE;
            double Iw[9], tmp[9], Ia[3], r[3], axr[3];
            m3_mul(tmp, b->R0, b->inertia);
            m3_mult(Iw, tmp, b->R0);
            m3_apply(Ia, Iw, dof->axis);
            v3_sub(r, b->p0, dof->origin);
            v3_cross(axr, dof->axis, r);
            dof->mass = v3_dot(dof->axis, Ia) + b->mass * v3_dot(axr, axr);
        } else {
            dof->kind = HX_DOF_SLIDER;
            dof->mass = b->mass;
        }
        dof->q = nq++, dof->u = nu++;
    }
    d->nq = nq;
    d->nu = nu;
    d->load_work = nq + nu;
    d->element_work = nq + nu + 1;
    d->n = nq + nu + 2;
    return 0;
}

int hx_dynamics_init(hx_dynamics *d, hx_session *s, usrsub_message *msg)
{
    memset(d, 0, sizeof *d);
    d->s = s;
    d->m = s->model;
    const hx_model *m = d->m;
    d->ucf = m->has_units ? m->unit_scales[USRSUB_UNIT_MASS] * m->unit_scales[USRSUB_UNIT_LENGTH] /
                                (m->unit_scales[USRSUB_UNIT_TIME] * m->unit_scales[USRSUB_UNIT_TIME] *
                                 m->unit_scales[USRSUB_UNIT_FORCE])
                          : 1.0;
    d->ucf = 1.0 / d->ucf; /* acceleration = ucf * force / mass */
    const int nb = m->nbodies, nc = m->ncouplers, nf = m->nforces;
    d->dof = calloc((size_t)nb, sizeof *d->dof);
    d->coupler_binding = calloc((size_t)(nc + 1), sizeof *d->coupler_binding);
    d->force_binding = calloc((size_t)(nf + 1), sizeof *d->force_binding);
    d->lambda = calloc((size_t)(nc + 1), sizeof *d->lambda);
    d->element_load = calloc((size_t)(6 * nf + 1), sizeof *d->element_load);
    d->force = calloc((size_t)(3 * nb), sizeof *d->force);
    d->torque = calloc((size_t)(3 * nb), sizeof *d->torque);
    if (!d->dof || !d->coupler_binding || !d->force_binding || !d->lambda || !d->element_load ||
        !d->force || !d->torque)
        return usrsub_fail(msg, "out of memory");
    if (setup_bodies(d, msg) != 0)
        return -1;
    /* scratch: G (nc x nu), A (nc x nc), several vectors of nu and nc */
    d->scratch = calloc((size_t)(nc * d->nu + nc * nc + 6 * (d->nu + nc) + 16), sizeof(double));
    if (d->scratch == NULL)
        return usrsub_fail(msg, "out of memory");
    for (int k = 0; k < nc; ++k)
        d->coupler_binding[k] = hx_binding_of_coupler(&s->bindings, k);
    for (int k = 0; k < nf; ++k)
        d->force_binding[k] = hx_binding_of_force(&s->bindings, k);
    /* the frames an element needs, kept by the host per state (set in
     * hx_dynamics_frames): looked up once here rather than per evaluation */
    d->element_frames = calloc((size_t)(3 * nf + 1), sizeof *d->element_frames);
    d->world_aligned = calloc((size_t)(nf + 1), 1);
    d->element_bodies = calloc((size_t)(2 * nf + 1), sizeof *d->element_bodies);
    if (d->element_frames == NULL || d->world_aligned == NULL || d->element_bodies == NULL)
        return usrsub_fail(msg, "out of memory");
    for (int k = 0; k < nf; ++k) {
        const hx_force *f = &m->forces[k];
        const int axes = f->interface == HX_FORCE_GFOSUB ? f->ref_marker : f->j_marker;
        d->element_frames[3 * k] = hx_host_marker_slot(f->i_marker);
        d->element_frames[3 * k + 1] = hx_host_marker_slot(f->j_marker);
        d->element_frames[3 * k + 2] = axes >= 0 ? hx_host_marker_slot(axes) : &world_axes;
        for (int i = 0; i < 3; ++i)
            if (d->element_frames[3 * k + i] == NULL)
                return usrsub_fail(msg, "force element %d: the host keeps no frame of its markers",
                                   f->id);
        int aligned = axes < 0 || m->bodies[m->markers[axes].body].is_ground;
        for (int i = 0; aligned && axes >= 0 && i < 9; ++i)
            aligned = m->markers[axes].R0[i] == (i % 4 == 0 ? 1.0 : 0.0);
        d->world_aligned[k] = (unsigned char)aligned;
        const int bi = m->markers[f->i_marker].body, bj = m->markers[f->j_marker].body;
        d->element_bodies[2 * k] = m->bodies[bi].is_ground ? -1 : bi;
        d->element_bodies[2 * k + 1] = m->bodies[bj].is_ground ? -1 : bj;
    }
    return 0;
}

void hx_dynamics_free(hx_dynamics *d)
{
    free(d->dof);
    free(d->coupler_binding);
    free(d->force_binding);
    free(d->lambda);
    free(d->element_load);
    free(d->element_frames);
    free(d->world_aligned);
    free(d->element_bodies);
    free(d->force);
    free(d->torque);
    free(d->scratch);
    memset(d, 0, sizeof *d);
}

/* ---- frames ------------------------------------------------------------------------ */

void hx_dynamics_frames(hx_dynamics *d, double t, const double *y)
{
    const double *q = y, *u = y + d->nq;
    hx_frame *frames = d->s->frames;
    for (int k = 0; k < d->m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        hx_frame *f = &frames[k];
        switch (dof->kind) {
        case HX_DOF_GROUND:
            break;
        case HX_DOF_FREE:
            v3_copy(f->p, q + dof->q);
            quat_to_matrix(f->R, q + dof->q + 3);
            v3_copy(f->v, u + dof->u);
            m3_apply(f->w, f->R, u + dof->u + 3);
            break;
        case HX_DOF_REVOLUTE: {
            double Rot[9], r0[3], r[3];
            m3_axis_angle(Rot, dof->axis, q[dof->q] - dof->coord0);
            m3_mul(f->R, Rot, dof->R0);
            v3_sub(r0, dof->p0, dof->origin);
            m3_apply(r, Rot, r0);
            v3_add(f->p, dof->origin, r);
            v3_scale(f->w, dof->axis, u[dof->u]);
            v3_cross(f->v, f->w, r);
            break;
        }
        case HX_DOF_SLIDER:
            m3_copy(f->R, dof->R0);
            v3_copy(f->p, dof->p0);
            v3_axpy(f->p, q[dof->q] - dof->coord0, dof->axis);
            v3_scale(f->v, dof->axis, u[dof->u]);
            v3_set(f->w, 0, 0, 0);
            break;
        }
    }
    hx_host_set_frames(frames, t);
}

/* ---- forces ------------------------------------------------------------------------- */

static int fail_run(hx_dynamics *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int fail_run(hx_dynamics *d, const char *fmt, ...)
{
    if (!d->failed) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(d->message, sizeof d->message, fmt, ap);
        va_end(ap);
        d->failed = 1;
    }
    return -1;
}

static int check_stop(hx_dynamics *d, const hx_binding *b, double t)
{
    if (hx_host_stop_requested())
        return fail_run(d, "%s %d stopped the run (c_errmes STOP) at t = %g: %s", b->element,
                        b->id, t, hx_host_stop_message());
    return 0;
}

/* Adds a force F (and couple T) acting at a world point of a body; returns its power. */
/* Adds F at point (and T) to a moving body's force and torque about its
 * centre; returns their power. */
static inline double push(hx_dynamics *d, int body, const double point[3], const double F[3],
                          const double T[3], double sign)
{
    const hx_frame *f = &d->s->frames[body];
    double r[3], moment[3], vp[3];
    v3_sub(r, point, f->p);
    v3_cross(moment, r, F);
    double power = 0.0;
    if (T != NULL) {
        v3_add(moment, moment, T); /* one update of the torque, not two */
        power = v3_dot(T, f->w);
    }
    double *force = d->force + 3 * body, *torque = d->torque + 3 * body;
    v3_axpy(force, sign, F);
    v3_axpy(torque, sign, moment);
    v3_cross(vp, f->w, r);
    v3_add(vp, vp, f->v);
    return sign * (v3_dot(F, vp) + power);
}

static double apply(hx_dynamics *d, int body, const double point[3], const double F[3],
                    const double T[3], double sign)
{
    if (d->dof[body].kind == HX_DOF_GROUND)
        return 0.0;
    return push(d, body, point, F, T, sign);
}

static double apply_loads(hx_dynamics *d, double t)
{
    const hx_model *m = d->m;
    double power = 0.0;
    for (int k = 0; k < m->nloads; ++k) {
        const hx_load *l = &m->loads[k];
        hx_frame scratch[3];
        const hx_frame *I = hx_host_marker_frame(d->s->frames, l->i_marker, &scratch[0]);
        const int bi = m->markers[l->i_marker].body;
        if (l->kind == HX_LOAD_VECTOR) {
            double F[3], T[3], f[3] = {0, 0, 0}, tq[3] = {0, 0, 0};
            for (int i = 0; i < 3; ++i) { /* components left out are constant zeros */
                if (l->force[i].kind != 0 || l->force[i].a[0] != 0.0)
                    f[i] = hx_time_function_at(&l->force[i], t);
                if (l->torque[i].kind != 0 || l->torque[i].a[0] != 0.0)
                    tq[i] = hx_time_function_at(&l->torque[i], t);
            }
            const hx_frame *ref = hx_host_marker_frame(d->s->frames, l->ref_marker, &scratch[2]);
            m3_apply(F, ref->R, f);
            m3_apply(T, ref->R, tq);
            power += apply(d, bi, I->p, F, T, 1.0);
            continue;
        }
        const hx_frame *J = hx_host_marker_frame(d->s->frames, l->j_marker, &scratch[1]);
        const int bj = m->markers[l->j_marker].body;
        double F[3] = {0, 0, 0}, T[3] = {0, 0, 0};
        const double value = hx_time_function_at(&l->value, t);
        if (l->kind == HX_LOAD_SCALAR_TORQUE) {
            v3_set(T, J->R[2] * value, J->R[5] * value, J->R[8] * value);
        } else {
            double r[3];
            v3_sub(r, I->p, J->p);
            const double len = v3_norm(r);
            if (len > 0.0)
                v3_scale(F, r, value / len); /* positive pushes I away from J */
        }
        power += apply(d, bi, I->p, F, T, 1.0);
        if (!l->action_only)
            power += apply(d, bj, J->p, F, T, -1.0);
    }
    return power;
}

/* No NaN or Inf in v (on the bits: an all-ones exponent plus one carries
 * into the sign bit; no branch per value). */
static int all_finite(const double *v, int n)
{
    uint64_t carry = 0;
    for (int k = 0; k < n; ++k) {
        uint64_t bits;
        memcpy(&bits, &v[k], sizeof bits);
        carry |= (bits & 0x7ff0000000000000u) + 0x0010000000000000u;
    }
    return (carry >> 63) == 0;
}

/* Applies every force element; *power receives the power of their forces. */
static int apply_elements(hx_dynamics *d, double t, double *power)
{
    const hx_model *m = d->m;
    *power = 0.0;
    for (int k = 0; k < m->nforces; ++k) {
        const hx_force *f = &m->forces[k];
        hx_binding *b = d->force_binding[k];
        const hx_frame *I = d->element_frames[3 * k], *J = d->element_frames[3 * k + 1];
        const double *axes = d->element_frames[3 * k + 2]->R;
        double out[6] = {0};
        if (f->interface == HX_FORCE_GFOSUB) {
            hx_call_gfosub(b, t, 0, 0, out, NULL);
        } else {
            double disp[6], velo[6], dfd[36], dfv[36];
            hx_field_state(I, J, disp, velo);
            hx_call_fiesub(b, t, disp, velo, 0, 0, out, dfd, dfv, NULL);
        }
        if (check_stop(d, b, t) != 0)
            return -1;
        if (!all_finite(out, 6))
            return fail_run(d, "%s %d returned a non-finite force at t = %g", b->element, b->id, t);
        double *F = d->element_load + 6 * k, *T = F + 3;
        if (d->world_aligned[k]) {
            v3_copy(F, out);
            v3_copy(T, out + 3);
        } else {
            m3_apply(F, axes, out);
            m3_apply(T, axes, out + 3);
        }
        const int bi = d->element_bodies[2 * k], bj = d->element_bodies[2 * k + 1];
        if (bi >= 0)
            *power += push(d, bi, I->p, F, T, 1.0);
        if (bj >= 0)
            *power += push(d, bj, I->p, F, T, -1.0); /* reaction at I's point */
    }
    return 0;
}

/* ---- couplers -------------------------------------------------------------------------- */

/* The coupled joints' position/velocity offsets (jointed bodies: q and u agree). */
static int coupler_joints(const hx_dynamics *d, int k, int u_index[3])
{
    const hx_coupler *c = &d->m->couplers[k];
    for (int i = 0; i < c->njoints; ++i) {
        const int body = d->m->markers[d->m->joints[c->joint[i]].i_marker].body;
        u_index[i] = d->dof[body].u;
    }
    return c->njoints;
}

/* phi, dphi/dM and the velocity term qdot^T H qdot of coupler k. */
static int coupler_terms(hx_dynamics *d, int k, double t, const double *y, double *phi,
                         double grad[3], double *gamma)
{
    const hx_coupler *c = &d->m->couplers[k];
    int ui[3];
    const int n = coupler_joints(d, k, ui);
    double disp[3], rate[3];
    for (int i = 0; i < n; ++i) {
        disp[i] = y[d->dof[d->m->markers[d->m->joints[c->joint[i]].i_marker].body].q];
        rate[i] = y[d->nq + ui[i]];
    }
    hx_binding *b = d->coupler_binding[k];
    if (b == NULL) {
        *phi = 0.0;
        for (int i = 0; i < n; ++i) {
            *phi += c->coefficients[i] * disp[i];
            grad[i] = c->coefficients[i];
        }
        if (gamma != NULL)
            *gamma = 0.0;
        return n;
    }
    double hess[9] = {0};
    hx_call_coupler(b, 0, t, disp, n, 0, phi, NULL);
    hx_call_coupler(b, 1, t, disp, n, 0, grad, NULL);
    if (gamma != NULL)
        hx_call_coupler(b, 2, t, disp, n, 0, hess, NULL);
    if (check_stop(d, b, t) != 0)
        return -1;
    if (!isfinite(*phi) || !all_finite(grad, n) || !all_finite(hess, n * n))
        return fail_run(d, "%s %d returned a non-finite value at t = %g", b->element, b->id, t);
    if (gamma != NULL) {
        *gamma = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                *gamma += rate[i] * hess[i + n * j] * rate[j];
    }
    return n;
}

/* Builds G (nc x nu) and, when gamma is not NULL, the velocity terms. */
static int constraint_jacobian(hx_dynamics *d, double t, const double *y, double *G,
                               double *phi, double *gamma)
{
    const int nc = d->m->ncouplers, nu = d->nu;
    memset(G, 0, sizeof(double) * (size_t)(nc * nu));
    for (int k = 0; k < nc; ++k) {
        double grad[3];
        int ui[3];
        if (coupler_terms(d, k, t, y, &phi[k], grad, gamma ? &gamma[k] : NULL) < 0)
            return -1;
        const int n = coupler_joints(d, k, ui);
        for (int i = 0; i < n; ++i)
            G[k * nu + ui[i]] += grad[i];
    }
    return 0;
}

static double inverse_mass(const hx_dynamics *d, int u_index)
{
    for (int k = 0; k < d->m->nbodies; ++k)
        if ((d->dof[k].kind == HX_DOF_REVOLUTE || d->dof[k].kind == HX_DOF_SLIDER) &&
            d->dof[k].u == u_index)
            return 1.0 / d->dof[k].mass;
    return 0.0; /* free-body velocities are not coupled */
}

/* A = G M^-1 G^T */
static void weighted_gram(const hx_dynamics *d, const double *G, const double *minv, double *A)
{
    const int nc = d->m->ncouplers, nu = d->nu;
    for (int i = 0; i < nc; ++i)
        for (int j = 0; j < nc; ++j) {
            double s = 0.0;
            for (int k = 0; k < nu; ++k)
                s += G[i * nu + k] * minv[k] * G[j * nu + k];
            A[i * nc + j] = s;
        }
}

/* ---- right-hand side ---------------------------------------------------------------------- */

int hx_dynamics_rhs(hx_dynamics *d, double t, const double *y, double *ydot)
{
    const hx_model *m = d->m;
    const int nq = d->nq, nb = m->nbodies;
    ++d->evaluations;
    hx_dynamics_frames(d, t, y);
    memset(d->force, 0, sizeof(double) * 3 * (size_t)nb);
    memset(d->torque, 0, sizeof(double) * 3 * (size_t)nb);
    for (int k = 0; k < nb; ++k)
        if (d->dof[k].kind != HX_DOF_GROUND)
            v3_axpy(d->force + 3 * k, m->bodies[k].mass / d->ucf, m->gravity);
    ydot[d->load_work] = apply_loads(d, t);
    if (apply_elements(d, t, &ydot[d->element_work]) != 0)
        return -1;

    const double *u = y + nq;
    double *qdot = ydot, *udot = ydot + nq;
    for (int k = 0; k < nb; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        const hx_frame *f = &d->s->frames[k];
        const double *F = d->force + 3 * k, *T = d->torque + 3 * k;
        switch (dof->kind) {
        case HX_DOF_GROUND:
            break;
        case HX_DOF_FREE: {
            const double *w = u + dof->u + 3, *quat = y + dof->q + 3;
            v3_copy(qdot + dof->q, u + dof->u);
            const double wq[4] = {0, w[0], w[1], w[2]};
            double dq[4];
            quat_mul(dq, quat, wq);
            for (int i = 0; i < 4; ++i)
                qdot[dof->q + 3 + i] = 0.5 * dq[i];
            v3_scale(udot + dof->u, F, d->ucf / dof->mass);
            double tb[3], Iw[3], gyro[3];
            m3_tapply(tb, f->R, T);
            m3_apply(Iw, dof->inertia, w);
            v3_cross(gyro, w, Iw);
            v3_scale(tb, tb, d->ucf);
            v3_sub(tb, tb, gyro);
            m3_apply(udot + dof->u + 3, dof->inertia_inv, tb);
            break;
        }
        case HX_DOF_REVOLUTE: {
            double r[3], rxF[3];
            v3_sub(r, f->p, dof->origin);
            v3_cross(rxF, r, F);
            qdot[dof->q] = u[dof->u];
            udot[dof->u] = d->ucf * (v3_dot(dof->axis, T) + v3_dot(dof->axis, rxF)) / dof->mass;
            break;
        }
        case HX_DOF_SLIDER:
            qdot[dof->q] = u[dof->u];
            udot[dof->u] = d->ucf * v3_dot(dof->axis, F) / dof->mass;
            break;
        }
    }
    const int nc = m->ncouplers;
    if (nc == 0)
        return 0;
    /* M qdd = ucf (Q + G^T lambda), G qdd = -gamma:
     * (G M^-1 G^T) lambda = -gamma/ucf - G qdd_free/ucf with qdd_free = ucf M^-1 Q. */
    double *G = d->scratch, *A = G + nc * d->nu, *minv = A + nc * nc, *phi = minv + d->nu,
           *gamma = phi + nc;
    if (constraint_jacobian(d, t, y, G, phi, gamma) != 0)
        return -1;
    for (int k = 0; k < d->nu; ++k)
        minv[k] = inverse_mass(d, k);
    weighted_gram(d, G, minv, A);
    for (int i = 0; i < nc; ++i) {
        double s = gamma[i];
        for (int k = 0; k < d->nu; ++k)
            s += G[i * d->nu + k] * udot[k];
        d->lambda[i] = -s / d->ucf;
    }
    if (hx_solve(nc, A, d->lambda) != 0)
        return fail_run(d, "the couplers' constraint Jacobian is singular at t = %g (redundant"
                        " or degenerate couplers)", t);
    for (int i = 0; i < nc; ++i)
        for (int k = 0; k < d->nu; ++k)
            udot[k] += d->ucf * minv[k] * G[i * d->nu + k] * d->lambda[i];
    return 0;
}

/* ---- projection ------------------------------------------------------------------------- */

int hx_dynamics_project(hx_dynamics *d, double t, double *y)
{
    for (int k = 0; k < d->m->nbodies; ++k)
        if (d->dof[k].kind == HX_DOF_FREE)
            quat_normalize(y + d->dof[k].q + 3);
    const int nc = d->m->ncouplers, nu = d->nu;
    if (nc == 0)
        return 0;
    double *G = d->scratch, *A = G + nc * nu, *minv = A + nc * nc, *phi = minv + nu,
           *step = phi + nc;
    for (int k = 0; k < nu; ++k)
        minv[k] = inverse_mass(d, k);
    /* positions: Newton on phi(q) = 0 with the mass-weighted least-change step */
    for (int it = 0;; ++it) {
        if (constraint_jacobian(d, t, y, G, phi, NULL) != 0)
            return -1;
        const double err = hx_max_abs(phi, nc);
        if (err <= PHI_TOLERANCE || it == PROJECTION_ITERATIONS)
            break;
        weighted_gram(d, G, minv, A);
        memcpy(step, phi, sizeof(double) * (size_t)nc);
        if (hx_solve(nc, A, step) != 0)
            return fail_run(d, "the couplers' constraint Jacobian is singular at t = %g", t);
        for (int b = 0; b < d->m->nbodies; ++b) {
            const hx_body_dof *dof = &d->dof[b];
            if (dof->kind != HX_DOF_REVOLUTE && dof->kind != HX_DOF_SLIDER)
                continue;
            double s = 0.0;
            for (int i = 0; i < nc; ++i)
                s += G[i * nu + dof->u] * step[i];
            y[dof->q] -= minv[dof->u] * s;
        }
    }
    /* velocities: remove the component that violates G u = 0 */
    weighted_gram(d, G, minv, A);
    for (int i = 0; i < nc; ++i) {
        double s = 0.0;
        for (int k = 0; k < nu; ++k)
            s += G[i * nu + k] * y[d->nq + k];
        step[i] = s;
    }
    if (hx_solve(nc, A, step) != 0)
        return fail_run(d, "the couplers' constraint Jacobian is singular at t = %g", t);
    for (int k = 0; k < nu; ++k) {
        double s = 0.0;
        for (int i = 0; i < nc; ++i)
            s += G[i * nu + k] * step[i];
        y[d->nq + k] -= minv[k] * s;
    }
    double phi_max, phidot_max;
    if (hx_dynamics_residuals(d, t, y, &phi_max, &phidot_max) != 0)
        return -1;
    d->max_phi = fmax(d->max_phi, phi_max);
    d->max_phidot = fmax(d->max_phidot, phidot_max);
    return 0;
}

int hx_dynamics_residuals(hx_dynamics *d, double t, const double *y, double *phi_max,
                          double *phidot_max)
{
    *phi_max = *phidot_max = 0.0;
    const int nc = d->m->ncouplers, nu = d->nu;
    if (nc == 0)
        return 0;
    double *G = d->scratch, *phi = G + nc * nu + nc * nc + nu;
    if (constraint_jacobian(d, t, y, G, phi, NULL) != 0)
        return -1;
    *phi_max = hx_max_abs(phi, nc);
    for (int i = 0; i < nc; ++i) {
        double s = 0.0;
        for (int k = 0; k < nu; ++k)
            s += G[i * nu + k] * y[d->nq + k];
        *phidot_max = fmax(*phidot_max, fabs(s));
    }
    return 0;
}

double hx_dynamics_coupler_force(hx_dynamics *d, double t, const double *y, int coupler,
                                 int joint)
{
    double phi, grad[3];
    if (coupler_terms(d, coupler, t, y, &phi, grad, NULL) < 0)
        return NAN;
    return grad[joint] * d->lambda[coupler];
}

/* ---- initial state, energy, position update ------------------------------------------------ */

int hx_dynamics_initial_state(hx_dynamics *d, double *y)
{
    const hx_model *m = d->m;
    memset(y, 0, sizeof(double) * (size_t)d->n);
    for (int k = 0; k < m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        const hx_body *b = &m->bodies[k];
        double *u = y + d->nq;
        switch (dof->kind) {
        case HX_DOF_GROUND:
            break;
        case HX_DOF_FREE:
            v3_copy(y + dof->q, b->p0);
            quat_from_matrix(y + dof->q + 3, b->R0);
            v3_copy(u + dof->u, b->v0);
            m3_tapply(u + dof->u + 3, b->R0, b->w0);
            break;
        case HX_DOF_REVOLUTE:
            y[dof->q] = dof->coord0;
            u[dof->u] = v3_dot(dof->axis, b->w0);
            break;
        case HX_DOF_SLIDER:
            y[dof->q] = dof->coord0;
            u[dof->u] = v3_dot(dof->axis, b->v0);
            break;
        }
    }
    d->max_phi = d->max_phidot = 0.0;
    return hx_dynamics_project(d, 0.0, y);
}

hx_energy hx_dynamics_energy(hx_dynamics *d, double t, const double *y)
{
    const hx_model *m = d->m;
    hx_dynamics_frames(d, t, y);
    double kinetic = 0.0, potential = 0.0;
    for (int k = 0; k < m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        const hx_frame *f = &d->s->frames[k];
        const double *u = y + d->nq + dof->u;
        if (dof->kind == HX_DOF_GROUND)
            continue;
        if (dof->kind == HX_DOF_FREE) {
            double Iw[3];
            m3_apply(Iw, dof->inertia, u + 3);
            kinetic += 0.5 * dof->mass * v3_dot(u, u) + 0.5 * v3_dot(u + 3, Iw);
        } else {
            kinetic += 0.5 * dof->mass * u[0] * u[0];
        }
        potential -= m->bodies[k].mass * v3_dot(m->gravity, f->p);
    }
    double elastic = 0.0;
    for (int k = 0; k < m->nforces; ++k) {
        double disp[6], velo[6];
        hx_element_state(d->s, k, disp, velo);
        elastic += hx_element_potential(d->s, k, t, disp);
    }
    hx_energy e;
    e.kinetic = kinetic / d->ucf;
    e.elastic = elastic;
    e.total = (kinetic + potential) / d->ucf + elastic - y[d->load_work];
    e.balance = (kinetic + potential) / d->ucf - y[d->load_work] - y[d->element_work];
    return e;
}

void hx_dynamics_advance_positions(hx_dynamics *d, double *y, double h)
{
    const double *u = y + d->nq;
    for (int k = 0; k < d->m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        if (dof->kind == HX_DOF_GROUND)
            continue;
        if (dof->kind != HX_DOF_FREE) {
            y[dof->q] += h * u[dof->u];
            continue;
        }
        v3_axpy(y + dof->q, h, u + dof->u);
        /* q <- q (x) exp(h w / 2), w in body axes */
        const double *w = u + dof->u + 3;
        const double angle = h * v3_norm(w);
        double inc[4] = {1, 0, 0, 0};
        if (angle > 0.0) {
            const double s = sin(0.5 * angle) / v3_norm(w);
            inc[0] = cos(0.5 * angle);
            inc[1] = s * w[0], inc[2] = s * w[1], inc[3] = s * w[2];
        }
        double *quat = y + dof->q + 3, next[4];
        quat_mul(next, quat, inc);
        memcpy(quat, next, sizeof next);
        quat_normalize(quat);
    }
}
