/*
 * The bushing with its internal states (bushing_states.h).
 *
 * Two layers. The law: the force on I, the bristle rates and the rubber
 * filters' rates as functions of what the bushing sees (q, qdot), the
 * bristles z and the filters x, with its Jacobian. The mounts: q = d - s,
 * qdot = v - sdot, where sdot (balanced mounts) and s (following ones) are
 * the unknowns w of the series balance G(w) = K s + C sdot + F = 0, solved by
 * Newton's method on the law's Jacobian; the partials with respect to the
 * inputs p = (d, v, x) follow from the implicit function theorem,
 * dw/dp = -(dG/dw)^-1 dG/dp. An inertial mount's s and sdot are states, so
 * its sddot is explicit. Friction enters no balanced row: dG/dw is the
 * mounts' and the bushing's damping (or the springs'), so with rising
 * characteristics and uncoupled rows the balance rises in w and its root is
 * one.
 */
#include "usrsub/core/bushing_states.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* the law's columns (what it depends on) and rows (what it gives) */
enum { COL_Q = 0, COL_QD = 6, COL_Z = 12, COL_X = 15, MAX_COLS = 21 };
enum { ROW_F = 0, ROW_Z = 6, ROW_X = 9, MAX_ROWS = 15 };
/* the inputs p = (d, v, x) of the partials */
enum { P_D = 0, P_V = 6, P_X = 12, MAX_P = 12 + USRSUB_MAX_STATES };

typedef struct law_value {
    double F[6], zdot[3], xdot[6];
    double J[MAX_ROWS * MAX_COLS]; /* [row + MAX_ROWS col] */
} law_value;

/* The direction's own force has a rate term: a damper a series spring caps. */
static int rate_dependent(const usrsub_bushing_direction *d)
{
    return d->active && ((d->damped && d->c > 0.0) || (d->rubber && d->rubber_c > 0.0));
}

void usrsub_bushing_state_layout(const usrsub_bushing *b, usrsub_state_layout *l)
{
    memset(l, 0, sizeof *l);
    l->friction = b->friction.active ? 3 : 0;
    for (int k = 0; k < 6; ++k) {
        const usrsub_bushing_direction *d = &b->dir[k];
        if (d->mount && k >= 3 && b->friction.active)
            l->inertial[l->ninertial++] = k;
        else if (d->mount && (d->mount_c > 0.0 || rate_dependent(d)))
            l->mount[l->nmount++] = k;
        else if (d->mount)
            l->follow[l->nfollow++] = k;
        if (d->rubber)
            l->rubber[l->nrubber++] = k;
    }
    l->n = l->friction + l->nmount + 2 * l->ninertial + l->nrubber;
}

static void law(const usrsub_bushing *b, const usrsub_mount_limits *limits,
                const usrsub_state_layout *l, const double q[6], const double qd[6],
                const double *z, const double *xr, law_value *out)
{
    double Aq[36], Av[36];
    memset(out->J, 0, sizeof out->J);
    usrsub_bushing_force(b, q, qd, out->F, Aq, Av);
    if (limits != NULL)
        usrsub_mount_limits_add(limits, q, qd, out->F, Aq, Av);
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i) {
            out->J[ROW_F + i + MAX_ROWS * (COL_Q + j)] = Aq[i + 6 * j];
            out->J[ROW_F + i + MAX_ROWS * (COL_QD + j)] = Av[i + 6 * j];
        }
    /* the rubber filters: the dynamic part of each direction's deformation */
    for (int r = 0; r < l->nrubber; ++r) {
        const int k = l->rubber[r];
        const usrsub_bushing_direction *d = &b->dir[k];
        const double H = d->disp_scale, V = d->force_scale;
        out->xdot[r] = H * qd[k] - d->rubber_r * xr[r];
        out->F[k] -= V * (d->rubber_k * xr[r] + d->rubber_c * out->xdot[r]);
        out->J[ROW_F + k + MAX_ROWS * (COL_QD + k)] -= V * d->rubber_c * H;
        out->J[ROW_F + k + MAX_ROWS * (COL_X + r)] = -V * (d->rubber_k - d->rubber_c * d->rubber_r);
        out->J[ROW_X + r + MAX_ROWS * (COL_QD + k)] = H;
        out->J[ROW_X + r + MAX_ROWS * (COL_X + r)] = -d->rubber_r;
    }
    if (l->friction == 0)
        return;
    /* friction: the translational force (bushing, rubber, limits) loads the
     * ball; the rotational rates slip */
    double tau[3];
    usrsub_friction_partials p;
    usrsub_friction_eval(&b->friction, out->F, z, qd + 3, tau, out->zdot, &p);
    for (int c = 0; c < MAX_COLS; ++c)
        for (int i = 0; i < 3; ++i) {
            double t = 0.0;
            for (int k = 0; k < 3; ++k)
                t += p.dtau_dF[i + 3 * k] * out->J[ROW_F + k + MAX_ROWS * c];
            out->J[ROW_F + 3 + i + MAX_ROWS * c] += t;
        }
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            out->J[ROW_F + 3 + i + MAX_ROWS * (COL_Z + j)] += p.dtau_dz[i + 3 * j];
            out->J[ROW_F + 3 + i + MAX_ROWS * (COL_QD + 3 + j)] += p.dtau_dw[i + 3 * j];
            out->J[ROW_Z + i + MAX_ROWS * (COL_Z + j)] = p.dzdot_dz[i + 3 * j];
            out->J[ROW_Z + i + MAX_ROWS * (COL_QD + 3 + j)] = p.dzdot_dw[i + 3 * j];
        }
    for (int i = 0; i < 3; ++i)
        out->F[3 + i] += tau[i];
}

/* Solves A X = B in place (A n x n, B n x m, column-major, leading
 * dimensions n); -1 when A is singular. */
static int solve(int n, double *A, double *B, int m)
{
    for (int c = 0; c < n; ++c) {
        int pivot = c;
        for (int r = c + 1; r < n; ++r)
            if (fabs(A[r + n * c]) > fabs(A[pivot + n * c]))
                pivot = r;
        if (!(fabs(A[pivot + n * c]) > 0.0))
            return -1;
        for (int j = 0; j < n; ++j) {
            const double t = A[c + n * j];
            A[c + n * j] = A[pivot + n * j], A[pivot + n * j] = t;
        }
        for (int j = 0; j < m; ++j) {
            const double t = B[c + n * j];
            B[c + n * j] = B[pivot + n * j], B[pivot + n * j] = t;
        }
        for (int r = c + 1; r < n; ++r) {
            const double f = A[r + n * c] / A[c + n * c];
            for (int j = c; j < n; ++j)
                A[r + n * j] -= f * A[c + n * j];
            for (int j = 0; j < m; ++j)
                B[r + n * j] -= f * B[c + n * j];
        }
    }
    for (int j = 0; j < m; ++j)
        for (int r = n - 1; r >= 0; --r) {
            double t = B[r + n * j];
            for (int c = r + 1; c < n; ++c)
                t -= A[r + n * c] * B[c + n * j];
            B[r + n * j] = t / A[r + n * r];
        }
    return 0;
}

/* The mounts' unknowns: w[a] is sdot of balanced mount a, w[nmount + b] is s
 * of following mount b; dir[] their directions; damped[] marks an sdot. */
typedef struct mount_unknowns {
    int n, dir[6];
    int damped[6];
} mount_unknowns;

/* dG/dw of the series balance (nw x nw, column-major) at the law's Jacobian. */
static void balance_jacobian(const usrsub_bushing *b, const mount_unknowns *m,
                             const law_value *v, double *A)
{
    for (int j = 0; j < m->n; ++j)
        for (int i = 0; i < m->n; ++i) {
            const int ki = m->dir[i], kj = m->dir[j];
            const usrsub_bushing_direction *d = &b->dir[ki];
            /* sdot_j enters through qdot = v - sdot, s_j through q = d - s */
            const double own = i != j ? 0.0 : m->damped[j] ? d->mount_c : d->mount_k;
            const int col = (m->damped[j] ? COL_QD : COL_Q) + kj;
            A[i + m->n * j] = own - v->J[ROW_F + ki + MAX_ROWS * col];
        }
}

/* The law where the mounts' unknowns are w, and the balance's residual G
 * (max |G_i| in *residual, the size of its terms in *size; NaN-safe: a
 * non-finite G gives an infinite residual). */
typedef struct balance_point {
    double s[6], sd[6], q[6], qd[6];
    double G[6], residual, size;
    double term[6]; /* each row's size: |K s| + |C sdot| + |F| */
    law_value v;
} balance_point;

/* Newton's merit: the rows' residuals over their own sizes, squared and
 * summed: its decrease along the Newton step is guaranteed for a short
 * enough step (the max norm's is not) */
static double merit(const balance_point *pt, int n)
{
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double r = pt->G[i] / (pt->term[i] > 0.0 ? pt->term[i] : 1.0);
        sum += r * r;
    }
    return isfinite(sum) ? sum : INFINITY;
}

/* What the balance is evaluated at, besides the unknowns. */
typedef struct balance_problem {
    const usrsub_bushing *b;
    const usrsub_mount_limits *limits;
    const usrsub_state_layout *l;
    mount_unknowns m;
    const double *u, *z, *sm, *si, *xr; /* si: the inertial mounts' (s, sdot) pairs */
} balance_problem;

static void balance_at(const balance_problem *bp, const double *w, balance_point *pt)
{
    const usrsub_state_layout *l = bp->l;
    memset(pt->s, 0, sizeof pt->s);
    memset(pt->sd, 0, sizeof pt->sd);
    for (int a = 0; a < l->nmount; ++a)
        pt->s[l->mount[a]] = bp->sm[a];
    for (int a = 0; a < l->ninertial; ++a)
        pt->s[l->inertial[a]] = bp->si[2 * a], pt->sd[l->inertial[a]] = bp->si[2 * a + 1];
    for (int i = 0; i < bp->m.n; ++i)
        (bp->m.damped[i] ? pt->sd : pt->s)[bp->m.dir[i]] = w[i];
    for (int k = 0; k < 6; ++k)
        pt->q[k] = bp->u[k] - pt->s[k], pt->qd[k] = bp->u[6 + k] - pt->sd[k];
    law(bp->b, bp->limits, l, pt->q, pt->qd, bp->z, bp->xr, &pt->v);
    pt->residual = pt->size = 0.0;
    for (int i = 0; i < bp->m.n; ++i) {
        const int k = bp->m.dir[i];
        const usrsub_bushing_direction *d = &bp->b->dir[k];
        const double spring = d->mount_k * pt->s[k], damper = d->mount_c * pt->sd[k];
        pt->G[i] = spring + damper + pt->v.F[k];
        pt->term[i] = fabs(spring) + fabs(damper) + fabs(pt->v.F[k]);
        pt->size = fmax(pt->size, pt->term[i]);
        pt->residual = isfinite(pt->G[i]) ? fmax(pt->residual, fabs(pt->G[i])) : INFINITY;
    }
}

static int converged(const balance_point *pt)
{
    return pt->residual <= 1e-15 * pt->size || pt->residual == 0.0;
}

/* Newton's method with a backtracking line search on the merit, from w; stops
 * at rounding or where no step lowers the merit. Returns the steps taken. */
static int newton(const balance_problem *bp, double *w, balance_point *pt)
{
    const int n = bp->m.n;
    int iteration = 0;
    while (!converged(pt) && iteration < 40) {
        double A[36], step[6];
        memcpy(step, pt->G, sizeof step);
        balance_jacobian(bp->b, &bp->m, &pt->v, A);
        if (solve(n, A, step, 1) != 0)
            break;
        int accepted = 0;
        const double before = merit(pt, n);
        for (double lambda = 1.0; lambda > 1e-12 && !accepted; lambda *= 0.5) {
            double wt[6];
            int negligible = 1;
            for (int i = 0; i < n; ++i) {
                wt[i] = w[i] - lambda * step[i];
                negligible &= fabs(lambda * step[i]) <= 4e-16 * fabs(w[i]);
            }
            if (negligible)
                break;
            balance_point trial;
            balance_at(bp, wt, &trial);
            if (merit(&trial, n) < before) {
                memcpy(w, wt, sizeof wt);
                *pt = trial;
                accepted = 1;
            }
        }
        if (!accepted)
            break;
        ++iteration;
    }
    return iteration;
}

/* Unknown i alone, the others held: its own row rises with it without bound
 * (the mount's and the bushing's dampers for a rate, the springs for a
 * deflection), so a root is bracketed by stepping out and found by the
 * Illinois form of regula falsi. A limit's contact can bend a row so that
 * Newton's method from the far side stalls; this cannot. */
static void one_unknown(const balance_problem *bp, int i, double *w, balance_point *pt)
{
    double a = w[i], fa = pt->G[i];
    if (!isfinite(fa) || fa == 0.0)
        return;
    double wt[6], step = 1e-3 * (fabs(a) + 1e-3);
    memcpy(wt, w, sizeof wt);
    double c = a, fc = fa;
    balance_point trial;
    for (int k = 0; k < 200; ++k, step *= 2.0) { /* out to where the sign turns */
        c = a - (fa > 0.0 ? step : -step);
        wt[i] = c;
        balance_at(bp, wt, &trial);
        fc = trial.G[i];
        if (!isfinite(fc))
            return;
        if ((fc > 0.0) != (fa > 0.0))
            break;
        a = c, fa = fc;
    }
    if ((fc > 0.0) == (fa > 0.0))
        return;
    for (int k = 0, side = 0; k < 200 && fc != 0.0; ++k) {
        const double x = (a * fc - c * fa) / (fc - fa);
        if (!(fabs(c - a) > 1e-15 * fmax(fabs(a), fabs(c))) || !isfinite(x))
            break;
        wt[i] = x;
        balance_at(bp, wt, &trial);
        const double fx = trial.G[i];
        if ((fx > 0.0) == (fc > 0.0)) {
            c = x, fc = fx;
            if (side == -1)
                fa *= 0.5;
            side = -1;
        } else {
            a = x, fa = fx;
            if (side == 1)
                fc *= 0.5;
            side = 1;
        }
    }
    w[i] = fabs(fa) < fabs(fc) ? a : c;
    balance_at(bp, w, pt);
}

/* The mounts' balance: Newton's method; where it stalls, sweeps of the one-
 * unknown solve (the rows are dominated by their own unknowns) and Newton's
 * method again to finish. */
static int solve_balance(const balance_problem *bp, double *w, balance_point *pt)
{
    int steps = newton(bp, w, pt);
    for (int sweep = 0; sweep < 30 && !converged(pt); ++sweep) {
        for (int i = 0; i < bp->m.n; ++i)
            one_unknown(bp, i, w, pt);
        steps += newton(bp, w, pt);
    }
    return steps;
}

int usrsub_bushing_states_eval(const usrsub_bushing *b, const usrsub_mount_limits *limits,
                               const usrsub_state_layout *l, const double u[12],
                               const double *x, double *xdot, double y[6],
                               usrsub_state_partials *partials, usrsub_message *msg)
{
    const int inertial_at = l->friction + l->nmount;
    const int rubber_at = inertial_at + 2 * l->ninertial;
    balance_problem bp = {b, limits, l, {0, {0}, {0}}, u, x, x + l->friction, x + inertial_at,
                          x + rubber_at};
    mount_unknowns *mu = &bp.m;
    for (int a = 0; a < l->nmount; ++a)
        mu->dir[mu->n] = l->mount[a], mu->damped[mu->n++] = 1;
    for (int c = 0; c < l->nfollow; ++c)
        mu->dir[mu->n] = l->follow[c], mu->damped[mu->n++] = 0;
    const mount_unknowns *m = &bp.m;
    /* the balance K s + C sdot + F = 0 of each mount, to rounding, or to
     * within 1e-8 of its terms where rounding in the law (a mount far stiffer
     * than its damping, a limit's large terms) keeps it from falling further */
    double w[6] = {0, 0, 0, 0, 0, 0};
    balance_point pt;
    balance_at(&bp, w, &pt);
    const int steps = m->n > 0 ? solve_balance(&bp, w, &pt) : 0;
    if (m->n > 0 && !(pt.residual <= 1e-8 * pt.size || pt.residual == 0.0)) {
        char states[160] = "";
        for (int i = 0, n = 0; i < l->n && n < (int)sizeof states - 16; ++i)
            n += snprintf(states + n, sizeof states - (size_t)n, i ? " %g" : "%g", x[i]);
        return usrsub_fail(msg, "the mounts' series balance has no solution near deformation"
                           " (%g %g %g %g %g %g), rate (%g %g %g %g %g %g) and states (%s):"
                           " residual %g of %g after %d Newton steps", u[0], u[1], u[2], u[3],
                           u[4], u[5], u[6], u[7], u[8], u[9], u[10], u[11], states, pt.residual,
                           pt.size, steps);
    }
    const law_value *v = &pt.v;
    memcpy(y, v->F, sizeof v->F);
    /* a balanced mount's direction carries the mount's force, equal to the
     * law's at the root but free of the solve's rounding (with C = 0 it is
     * -K s exactly, as its partials say) */
    for (int a = 0; a < l->nmount; ++a) {
        const usrsub_bushing_direction *d = &b->dir[l->mount[a]];
        y[l->mount[a]] = -(d->mount_k * x[l->friction + a] + d->mount_c * w[a]);
    }
    for (int i = 0; i < l->friction; ++i)
        xdot[i] = v->zdot[i];
    for (int a = 0; a < l->nmount; ++a)
        xdot[l->friction + a] = w[a];
    for (int a = 0; a < l->ninertial; ++a) {
        const usrsub_bushing_direction *d = &b->dir[l->inertial[a]];
        const double s = x[inertial_at + 2 * a], sd = x[inertial_at + 2 * a + 1];
        xdot[inertial_at + 2 * a] = sd;
        xdot[inertial_at + 2 * a + 1] =
            -(d->mount_k * s + d->mount_c * sd + v->F[l->inertial[a]]) / d->mount_inertia;
    }
    for (int r = 0; r < l->nrubber; ++r)
        xdot[rubber_at + r] = v->xdot[r];
    if (partials == NULL)
        return 0;

    /* the law's outputs against p at fixed w (Dp), and against w (Dw) */
    const int np = 12 + l->n;
    double Dp[MAX_ROWS * MAX_P], Dw[MAX_ROWS * 6];
    for (int p = 0; p < np; ++p) {
        int col = -1;
        double sign = 1.0;
        if (p < 6)
            col = COL_Q + p;
        else if (p < 12)
            col = COL_QD + p - 6;
        else if (p - 12 < l->friction)
            col = COL_Z + p - 12;
        else if (p - 12 < inertial_at)
            col = COL_Q + l->mount[p - 12 - l->friction], sign = -1.0;
        else if (p - 12 < rubber_at) /* an inertial pair: s enters q, sdot qdot */
            col = ((p - 12 - inertial_at) % 2 ? COL_QD : COL_Q) +
                  l->inertial[(p - 12 - inertial_at) / 2], sign = -1.0;
        else
            col = COL_X + p - 12 - rubber_at;
        for (int r = 0; r < MAX_ROWS; ++r)
            Dp[r + MAX_ROWS * p] = sign * v->J[r + MAX_ROWS * col];
    }
    for (int i = 0; i < m->n; ++i) {
        const int col = (m->damped[i] ? COL_QD : COL_Q) + m->dir[i];
        for (int r = 0; r < MAX_ROWS; ++r)
            Dw[r + MAX_ROWS * i] = -v->J[r + MAX_ROWS * col];
    }
    /* dw/dp = -(dG/dw)^-1 dG/dp, with dG/dp = Dp's force rows plus K for a
     * damped mount's own state */
    double dwdp[6 * MAX_P];
    if (m->n > 0) {
        double A[36];
        balance_jacobian(b, m, v, A);
        for (int p = 0; p < np; ++p)
            for (int i = 0; i < m->n; ++i) {
                double g = Dp[ROW_F + m->dir[i] + MAX_ROWS * p];
                if (m->damped[i] && p == 12 + l->friction + i)
                    g += b->dir[m->dir[i]].mount_k;
                dwdp[i + m->n * p] = -g;
            }
        if (solve(m->n, A, dwdp, np) != 0)
            return usrsub_fail(msg, "the mounts' series balance is singular at deformation"
                               " (%g %g %g %g %g %g)", u[0], u[1], u[2], u[3], u[4], u[5]);
    }
    /* total derivative of a law row: Dp + Dw dw/dp */
    double total[MAX_ROWS * MAX_P];
    for (int p = 0; p < np; ++p)
        for (int r = 0; r < MAX_ROWS; ++r) {
            double t = Dp[r + MAX_ROWS * p];
            for (int i = 0; i < m->n; ++i)
                t += Dw[r + MAX_ROWS * i] * dwdp[i + m->n * p];
            total[r + MAX_ROWS * p] = t;
        }
    const int n = l->n;
    for (int p = 0; p < np; ++p) {
        /* the rows of xdot: bristles, damped mounts (w itself), filters */
        double col[USRSUB_MAX_STATES];
        for (int i = 0; i < l->friction; ++i)
            col[i] = total[ROW_Z + i + MAX_ROWS * p];
        for (int a = 0; a < l->nmount; ++a)
            col[l->friction + a] = dwdp[a + m->n * p];
        for (int a = 0; a < l->ninertial; ++a) {
            const int k = l->inertial[a], at = 12 + inertial_at + 2 * a;
            const usrsub_bushing_direction *d = &b->dir[k];
            const double own = (p == at ? d->mount_k : 0.0) + (p == at + 1 ? d->mount_c : 0.0);
            col[inertial_at + 2 * a] = p == at + 1;
            col[inertial_at + 2 * a + 1] =
                -(own + total[ROW_F + k + MAX_ROWS * p]) / d->mount_inertia;
        }
        for (int r = 0; r < l->nrubber; ++r)
            col[rubber_at + r] = total[ROW_X + r + MAX_ROWS * p];
        for (int i = 0; i < n; ++i) {
            if (p < 12)
                partials->dxdot_du[i + n * p] = col[i];
            else
                partials->dxdot_dx[i + n * (p - 12)] = col[i];
        }
        for (int i = 0; i < 6; ++i) {
            if (p < 12)
                partials->dy_du[i + 6 * p] = total[ROW_F + i + MAX_ROWS * p];
            else
                partials->dy_dx[i + 6 * (p - 12)] = total[ROW_F + i + MAX_ROWS * p];
        }
    }
    return 0;
}
