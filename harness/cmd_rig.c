/*
 * usrsub-harness rig: a virtual test rig for one force element, without
 * dynamics. Deformation-controlled, it prescribes the deformation of I
 * relative to J (and its rate); force-controlled, it applies a load to I and
 * solves each step for the deformation that balances it, by Newton's method
 * with the element's partials (FIESUB) or central differences (GFOSUB).
 */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "element_probe.h"
#include "linalg.h"
#include "plot.h"
#include "rig_path.h"
#include "session.h"

typedef struct rig {
    hx_session *s;
    int force;            /* element index */
    int force_controlled;
    hx_rig_path path;
    double end, step;
    FILE *csv;
    long element_calls;
    int max_iterations;
    double worst_residual;
    double radius_min[2], radius_max[2]; /* |F| and |d| in the plane of the path */
    unsigned moving;      /* directions whose deformation or force is not zero */
    int a, b;             /* the path's plane */
} rig;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: usrsub-harness rig MODEL.xml --element ID --end T --step H PATH [options]\n"
            "\n"
            "Drives one force element (Force_Vector_TwoBody or Force_Field ID; write\n"
            "vector:ID or field:ID when both kinds use ID) without dynamics.\n"
            "Deformation-controlled PATH (of I relative to J, in J axes; terms add up):\n"
            "  --circle R,W[,PLANE]      R (cos Wt, sin Wt) in PLANE xy (default), yz, zx,\n"
            "                            axay, ayaz or azax\n"
            "  --line K,FROM,TO          direction K (x y z ax ay az) from FROM to TO\n"
            "  --sine K,AMP,FREQ[,PHASE] AMP sin(2 pi FREQ t + PHASE) in direction K\n"
            "  --history FILE.csv        rows t,x,y,z,ax,ay,az\n"
            "Force-controlled PATH (a load applied to I; the deformation is solved for):\n"
            "  --force-circle, --force-line, --force-sine, --force-history (same forms,\n"
            "                            forces and torques instead of deformations)\n"
            "Options:\n"
            "  --out FILE.csv            t, deformation (6), rate (6), element force on I\n"
            "                            (6, J axes), applied load (6), residual, iterations\n"
            "  --plot PREFIX             PNG plots with gnuplot: PREFIX_force_path.png,\n"
            "                            PREFIX_deformation_path.png, PREFIX_force_deformation.png\n");
}

static int evaluate(rig *r, double t, const double d[6], const double v[6], double F[6],
                    double *J, double *Jv)
{
    r->element_calls++;
    return hx_element_at(r->s, r->force, t, d, v, F, J, Jv);
}

/* Newton on the controlled directions: element force + applied load = 0. */
static int solve(rig *r, double t, const double applied[6], const double *d_prev, double d[6],
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

static void track(rig *r, const double d[6], const double F[6], int first)
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

static int run_rig(rig *r)
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
        track(r, d, F, i == 0);
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

int hx_command_rig(int argc, char **argv)
{
    static const struct option options[] = {
        {"element", required_argument, NULL, 'e'}, {"end", required_argument, NULL, 'E'},
        {"step", required_argument, NULL, 's'},    {"out", required_argument, NULL, 'o'},
        {"plot", required_argument, NULL, 'p'},    {"circle", required_argument, NULL, 'c'},
        {"line", required_argument, NULL, 'l'},    {"sine", required_argument, NULL, 'S'},
        {"history", required_argument, NULL, 'H'}, {"force-circle", required_argument, NULL, 'C'},
        {"force-line", required_argument, NULL, 'L'}, {"force-sine", required_argument, NULL, 'W'},
        {"force-history", required_argument, NULL, 'Y'}, {"help", no_argument, NULL, 'h'},
        {0, 0, 0, 0}};
    rig r;
    memset(&r, 0, sizeof r);
    const char *element = NULL, *out = NULL, *plot = NULL;
    int deformation_terms = 0, force_terms = 0, opt;
    usrsub_message msg = {{0}};
    optind = 1;
    while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
        int status = 0;
        switch (opt) {
        case 'e': element = optarg; break;
        case 'E': r.end = atof(optarg); break;
        case 's': r.step = atof(optarg); break;
        case 'o': out = optarg; break;
        case 'p': plot = optarg; break;
        case 'c': status = hx_rig_path_add(&r.path, "circle", optarg, &msg), ++deformation_terms; break;
        case 'l': status = hx_rig_path_add(&r.path, "line", optarg, &msg), ++deformation_terms; break;
        case 'S': status = hx_rig_path_add(&r.path, "sine", optarg, &msg), ++deformation_terms; break;
        case 'H': status = hx_rig_path_history(&r.path, optarg, &msg), ++deformation_terms; break;
        case 'C': status = hx_rig_path_add(&r.path, "circle", optarg, &msg), ++force_terms; break;
        case 'L': status = hx_rig_path_add(&r.path, "line", optarg, &msg), ++force_terms; break;
        case 'W': status = hx_rig_path_add(&r.path, "sine", optarg, &msg), ++force_terms; break;
        case 'Y': status = hx_rig_path_history(&r.path, optarg, &msg), ++force_terms; break;
        case 'h': usage(stdout); return 0;
        default: usage(stderr); return 2;
        }
        if (status != 0) {
            fprintf(stderr, "usrsub-harness rig: %s\n", msg.text);
            hx_rig_path_free(&r.path);
            return 2;
        }
    }
    if (optind != argc - 1 || element == NULL || !(r.end > 0.0) || !(r.step > 0.0) ||
        (deformation_terms > 0) == (force_terms > 0)) {
        if (deformation_terms > 0 && force_terms > 0)
            fprintf(stderr, "usrsub-harness rig: a path is either deformation- or force-controlled\n");
        usage(stderr);
        hx_rig_path_free(&r.path);
        return 2;
    }
    r.force_controlled = force_terms > 0;
    for (int k = 0, found = 0; k < 6 && found < 2; ++k)
        if (r.path.directions & (1u << k))
            *(found++ == 0 ? &r.a : &r.b) = k;
    if (r.b <= r.a)
        r.b = (r.a + 1) % 6;
    hx_session s;
    if (hx_session_open(&s, argv[optind], &msg) != 0 || hx_model_find_force(s.model, element, &r.force, &msg) != 0) {
        fprintf(stderr, "usrsub-harness rig: %s\n", msg.text);
        if (s.model != NULL)
            hx_session_close(&s);
        hx_rig_path_free(&r.path);
        return 1;
    }
    r.s = &s;
    char csv_path[4096], prefix[4096] = "";
    if (plot != NULL)
        hx_session_path(&s, plot, prefix, sizeof prefix);
    if (out != NULL)
        hx_session_path(&s, out, csv_path, sizeof csv_path);
    else if (plot != NULL)
        snprintf(csv_path, sizeof csv_path, "%s.csv", prefix);
    if ((out != NULL || plot != NULL) && (r.csv = fopen(csv_path, "w")) == NULL) {
        fprintf(stderr, "usrsub-harness rig: cannot write %s\n", csv_path);
        hx_session_close(&s);
        hx_rig_path_free(&r.path);
        return 1;
    }
    const int status = run_rig(&r);
    if (r.csv != NULL)
        fclose(r.csv);
    const hx_force *f = &s.model->forces[r.force];
    static const char *const names[6] = {"x", "y", "z", "ax", "ay", "az"};
    printf("rig: %s %d, %s-controlled, %ld steps of %g to t = %g, %ld element calls\n",
           f->interface == HX_FORCE_GFOSUB ? "Force_Vector_TwoBody" : "Force_Field", f->id,
           r.force_controlled ? "force" : "deformation", lround(r.end / r.step), r.step, r.end,
           r.element_calls);
    printf("  in the %s%s plane: |F| from %.8g to %.8g, |d| from %.8g to %.8g\n", names[r.a],
           names[r.b], r.radius_min[0], r.radius_max[0], r.radius_min[1], r.radius_max[1]);
    if (r.force_controlled)
        printf("  Newton: at most %d iterations a step, worst residual %.3g\n", r.max_iterations,
               r.worst_residual);
    if (status != 0)
        fprintf(stderr, "usrsub-harness rig: the element %s\n",
                hx_host_stop_requested() ? "stopped the run (c_errmes STOP)" : "could not be evaluated");
    int plot_status = 0;
    if (status == 0 && plot != NULL) {
        char title[128];
        snprintf(title, sizeof title, "element %d", f->id);
        plot_status = hx_plot_rig(csv_path, prefix, title, r.a, r.b, r.moving);
        if (plot_status == 1)
            fprintf(stderr, "rig: gnuplot is not installed; no plots\n");
        else if (plot_status == 0)
            printf("  plots: %s_force_path.png, %s_deformation_path.png, %s_force_deformation.png\n",
                   prefix, prefix, prefix);
    }
    hx_session_close(&s);
    hx_rig_path_free(&r.path);
    return status == 0 && plot_status <= 0 ? (plot_status < 0 ? 1 : 0) : 1;
}
