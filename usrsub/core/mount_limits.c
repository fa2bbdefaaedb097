/* Mount-limit forces and partials (mount_limits.h). */
#include "usrsub/core/mount_limits.h"

#include <math.h>
#include <stdlib.h>


/* p^E and E p^(E-1) for p > 0, with the common exponents multiplied out. */
static inline double power(const usrsub_limit_side *s, double p, double *derivative)
{
    switch (s->power) {
    case USRSUB_POWER_1:
        *derivative = 1.0;
        return p;
    case USRSUB_POWER_2:
        *derivative = 2.0 * p;
        return p * p;
    case USRSUB_POWER_3_2: {
        const double r = sqrt(p);
        *derivative = 1.5 * r;
        return p * r;
    }
    case USRSUB_POWER_3:
        *derivative = 3.0 * p * p;
        return p * p * p;
    default: {
        const double v = pow(p, s->e);
        *derivative = s->e * v / p;
        return v;
    }
    }
}

/* A prepared side at penetration p > 0 (mirrored to the positive side: x, xdot). */
static inline double side_force(const usrsub_limit_side *s, double p, double xdot, double *dx,
                                double *dxdot)
{
    double dpow;
    const double spring = s->k * power(s, p, &dpow);
    /* STEP(p, 0, 0, D, 1) = a^2 (3 - 2a), a = p/D, written out */
    double ramp = 1.0, dramp = 0.0;
    if (p < s->d) {
        const double a = p * s->inv_d;
        ramp = a * a * (3.0 - 2.0 * a);
        dramp = 6.0 * a * (1.0 - a) * s->inv_d;
    }
    const double f = -spring - s->c * xdot * ramp;
    if (!(f < 0.0)) { /* separating fast: no pulling force */
        *dx = *dxdot = 0.0;
        return 0.0;
    }
    *dx = -s->k * dpow - s->c * xdot * dramp;
    *dxdot = -s->c * ramp;
    return f;
}

static void prepare_side(usrsub_limit_side *s)
{
    s->power = s->e == 1.0   ? USRSUB_POWER_1
               : s->e == 1.5 ? USRSUB_POWER_3_2
               : s->e == 2.0 ? USRSUB_POWER_2
               : s->e == 3.0 ? USRSUB_POWER_3
                             : USRSUB_POWER_GENERAL;
    s->inv_d = s->d > 0.0 ? 1.0 / s->d : 0.0;
}

double usrsub_limit_side_force(const usrsub_limit_side *side, double q, double qdot, double *dq,
                               double *dqdot)
{
    *dq = *dqdot = 0.0;
    usrsub_limit_side s = *side;
    prepare_side(&s);
    /* the negative side is the positive one mirrored: input and output negated */
    const double p = s.sign * q - s.l;
    if (!(p > 0.0))
        return 0.0;
    /* F = sign f(x, xdot) with x = sign q: dF/dq = df/dx, dF/dqdot = df/dxdot */
    return s.sign * side_force(&s, p, s.sign * qdot, dq, dqdot);
}

void usrsub_mount_limits_add(const usrsub_mount_limits *m, const double d[6], const double v[6],
                             double F[6], double *dFdd, double *dFdv)
{
    for (unsigned bits = m->directions; bits != 0; bits &= bits - 1) {
        const int k = __builtin_ctz(bits);
        const int negative = d[k] < 0.0;
        const usrsub_limit_side *s = &m->by_direction[k][negative];
        const double x = negative ? -d[k] : d[k];
        const double p = x - s->l;
        if (!(p > 0.0))
            continue; /* in the gap: nothing to add */
        double dx, dxdot;
        const double f = side_force(s, p, negative ? -v[k] : v[k], &dx, &dxdot);
        F[k] += negative ? -f : f;
        if (dFdd != NULL) {
            dFdd[k + 6 * k] += dx;
            dFdv[k + 6 * k] += dxdot;
        }
    }
}

void usrsub_mount_limits_prepare(usrsub_mount_limits *m)
{
    m->uses_translation = m->uses_rotation = m->uses_velocity = m->uses_twist = 0;
    m->directions = 0;
    for (int k = 0; k < 6; ++k)
        for (int side = 0; side < 2; ++side)
            m->by_direction[k][side] = (usrsub_limit_side){
                .direction = k, .sign = side ? -1 : 1, .e = 1.0, .l = INFINITY};
    for (int n = 0; n < m->nsides; ++n) {
        usrsub_limit_side *s = &m->side[n];
        prepare_side(s);
        m->by_direction[s->direction][s->sign < 0] = *s;
        m->directions |= 1u << s->direction;
        if (s->direction < 3)
            m->uses_translation = 1;
        else
            m->uses_rotation = 1;
        if (s->c > 0.0)
            m->uses_velocity = 1;
        if (s->direction == 5)
            m->uses_twist = 1;
    }
}

void usrsub_mount_limits_free(usrsub_mount_limits *m)
{
    free(m);
}
