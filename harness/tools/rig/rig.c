/* The virtual test rig (rig.h). */
#include "tools/rig/rig.h"

#include <math.h>
#include <string.h>

#include "base/linalg.h"
#include "sim/dynamics/element_at.h"

static int evaluate(hx_rig *r, double t, const double d[6], const double v[6], double F[6],
                    double *J, double *Jv)
{
    r->element_calls++;
    return hx_element_at(r->s, &r->scratch, &r->s->frames, r->force, t, d, v, F, J, Jv);
}

/* Newton on the controlled directions: element force + applied load = 0. */
static int solve(hx_rig *r, double t, const double applied[6], const double *d_prev, double d[6],
                 double v[6], double F[6], double *residual, int *iterations)
{
    int idx[6], m = 0;
    for (int k = 0; k < 6; ++k)
        if (r->path.directions & (1u << k))
            idx[m++] = k;
    const double h = r->step;
    double scale = 1.0;
    for (int k = 0; k < 6; ++k)
        scale = fmax(scale, fabs(applied[k]));
    const double tolerance = 1e-11 * scale;
    double J[36], Jv[36];
    for (int it = 0;; ++it) {
        for (int k = 0; k < 6; ++k)
            v[k] = d_prev != NULL ? (d[k] - d_prev[k]) / h : 0.0;
        if (evaluate(r, t, d, v, F, J, Jv) != 0)
            return -1;
        double res[6], norm = 0.0;
        for (int i = 0; i < m; ++i) {
            res[i] = F[idx[i]] + applied[idx[i]];
            norm = fmax(norm, fabs(res[i]));
        }
        *residual = norm;
        *iterations = it;
        if (norm <= tolerance || it == 60)
            return 0;
        double A[36], step[6];
        for (int i = 0; i < m; ++i) {
            step[i] = -res[i];
            for (int j = 0; j < m; ++j)
                A[i * m + j] = J[idx[i] + 6 * idx[j]] + (d_prev != NULL ? Jv[idx[i] + 6 * idx[j]] / h : 0.0);
        }
        if (hx_solve(m, A, step) != 0)
            return -1;
        /* halve the step until the residual falls */
        double trial[6], tv[6], tF[6];
        for (double alpha = 1.0;; alpha *= 0.5) {
            memcpy(trial, d, sizeof trial);
            for (int i = 0; i < m; ++i)
                trial[idx[i]] += alpha * step[i];
            for (int k = 0; k < 6; ++k)
                tv[k] = d_prev != NULL ? (trial[k] - d_prev[k]) / h : 0.0;
            if (evaluate(r, t, trial, tv, tF, NULL, NULL) != 0)
                return -1;
            double tnorm = 0.0;
            for (int i = 0; i < m; ++i)
                tnorm = fmax(tnorm, fabs(tF[idx[i]] + applied[idx[i]]));
            if (tnorm < norm || alpha < 1e-6) {
                memcpy(d, trial, sizeof trial);
                break;
            }
        }
    }
}

void hx_rig_track(hx_rig *r, const double d[6], const double F[6], int first)
{
    for (int k = 0; k < 6; ++k)
        if (d[k] != 0.0 || fabs(F[k]) > 1e-9)
            r->moving |= 1u << k;
    const double rf = hypot(F[r->a], F[r->b]), rd = hypot(d[r->a], d[r->b]);
    if (first) {
        r->radius_min[0] = r->radius_max[0] = rf;
        r->radius_min[1] = r->radius_max[1] = rd;
    }
    r->radius_min[0] = fmin(r->radius_min[0], rf);
    r->radius_max[0] = fmax(r->radius_max[0], rf);
    r->radius_min[1] = fmin(r->radius_min[1], rd);
    r->radius_max[1] = fmax(r->radius_max[1], rd);
}

int hx_rig_run(hx_rig *r)
{
    if (r->csv != NULL)
        fprintf(r->csv, "t,x,y,z,ax,ay,az,vx,vy,vz,wx,wy,wz,fx,fy,fz,tx,ty,tz,"
                        "applied_fx,applied_fy,applied_fz,applied_tx,applied_ty,applied_tz,"
                        "residual,iterations\n");
    const long n = lround(r->end / r->step);
    double d[6] = {0}, d_prev[6] = {0}, v[6] = {0}, F[6], path[6], rate[6];
    for (long i = 0; i <= n; ++i) {
        const double t = (double)i * r->step;
        hx_rig_path_at(&r->path, t, r->end, path, rate);
        double applied[6] = {0}, residual = 0.0;
        int iterations = 0;
        if (r->force_controlled) {
            memcpy(applied, path, sizeof applied);
            if (solve(r, t, applied, i > 0 ? d_prev : NULL, d, v, F, &residual, &iterations) != 0)
                return -1;
            r->max_iterations = iterations > r->max_iterations ? iterations : r->max_iterations;
            r->worst_residual = fmax(r->worst_residual, residual);
            memcpy(d_prev, d, sizeof d);
        } else {
            memcpy(d, path, sizeof d);
            memcpy(v, rate, sizeof v);
            if (evaluate(r, t, d, v, F, NULL, NULL) != 0)
                return -1;
        }
        hx_rig_track(r, d, F, i == 0);
        if (r->csv != NULL) {
            fprintf(r->csv, "%.10g", t);
            for (int k = 0; k < 6; ++k)
                fprintf(r->csv, ",%.15g", d[k]);
            for (int k = 0; k < 6; ++k)
                fprintf(r->csv, ",%.15g", v[k]);
            for (int k = 0; k < 6; ++k)
                fprintf(r->csv, ",%.15g", F[k]);
            for (int k = 0; k < 6; ++k)
                fprintf(r->csv, ",%.15g", applied[k]);
            fprintf(r->csv, ",%.3g,%d\n", residual, iterations);
        }
    }
    return 0;
}

