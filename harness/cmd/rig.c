/* usrsub-harness rig: drive one force element through a deformation or
 * force history (tools/rig/rig.h), with CSV and plots. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cmd/commands.h"
#include "cmd/crash_report.h"
#include "cmd/options.h"
#include "tools/plot.h"
#include "tools/rig/rig.h"
#include "tools/rig/stateeqn_rig.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: usrsub-harness rig MODEL.xml --element ID --end T --step H PATH [options]\n"
            "\n"
            "Drives one force element (Force_Vector_TwoBody or Force_Field ID; write\n"
            "vector:ID or field:ID when both kinds use ID) without dynamics. A Force_StateEqn\n"
            "(ID, or stateeqn:ID) is driven along a deformation path with its states\n"
            "integrated along it (BDF): force against deformation shows its hysteresis.\n"
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
            "                            PREFIX_deformation_path.png, PREFIX_force_deformation.png\n"
            "                            (and PREFIX_states.png for a Force_StateEqn)\n"
            "A Force_StateEqn's CSV: t, deformation (6), rate (6), its outputs on I (6, J\n"
            "axes), its states.\n");
}

/* The element ID names: a force element (0), a Force_StateEqn (1), or
 * neither or both (-1, msg). */
static int find_element(const hx_model *m, const char *text, int *index, hx_message *msg)
{
    if (strncasecmp(text, "stateeqn:", 9) == 0)
        return hx_model_find_stateeqn(m, text, index, msg) == 0 ? 1 : -1;
    hx_message none;
    int state = -1;
    const int plain = strchr(text, ':') == NULL;
    if (plain && hx_model_find_stateeqn(m, text, &state, &none) != 0)
        state = -1;
    const int force = hx_model_find_force(m, text, index, msg) == 0;
    if (force && state >= 0)
        return hx_fail(msg, "element %s is both a Force_StateEqn and a force element: write"
                       " stateeqn:%s, or vector:%s or field:%s", text, text, text, text);
    if (state >= 0) {
        *index = state;
        return 1;
    }
    return force ? 0 : -1;
}

/* The Force_StateEqn rig's run and summary lines; 0 or -1. */
static int run_state_rig(hx_rig *r, const char *plot, const char *csv_path, const char *prefix)
{
    const hx_stateeqn *f = &r->s->model->stateeqns[r->force];
    hx_stateeqn_rig_result result;
    hx_crash_report_begin();
    const int status = hx_stateeqn_rig_run(r, &result);
    hx_crash_report_end();
    if (r->csv != NULL)
        fclose(r->csv);
    r->csv = NULL;
    printf("rig: Force_StateEqn %d, deformation-controlled, %ld steps of %g to t = %g, %ld"
           " element calls\n", f->id, lround(r->end / r->step), r->step, r->end, r->element_calls);
    if (f->nstate > 0)
        printf("  %d states integrated by bdf (CVODE, rtol 1e-8): %ld steps, %ld Newton"
               " iterations, %ld Jacobians (%s)\n", f->nstate, result.stats.steps,
               result.stats.newton_iterations, result.stats.jacobians,
               hx_binding_of_stateeqn(&r->s->bindings, r->force)->state_partial[0] != NULL
                   ? "YFOXX" : "differences of YFOSUB");
    printf("  work done on the element over the path (stored or dissipated): %.8g\n", result.work);
    if (status != 0) {
        fprintf(stderr, "usrsub-harness rig: %s\n", result.message);
        return -1;
    }
    if (plot == NULL)
        return 0;
    char title[128];
    /* no underscore: gnuplot's titles are enhanced text */
    snprintf(title, sizeof title, "state equation %d", f->id);
    int plot_status = hx_plot_rig(csv_path, prefix, title, r->a, r->b, r->moving);
    if (plot_status == 0 && f->nstate > 0)
        plot_status = hx_plot_states(csv_path, prefix, title, 20, f->nstate);
    if (plot_status == 1)
        fprintf(stderr, "rig: gnuplot is not installed; no plots\n");
    else if (plot_status == 0)
        printf("  plots: %s_force_path.png, %s_deformation_path.png,"
               " %s_force_deformation.png%s%s%s\n", prefix, prefix, prefix,
               f->nstate > 0 ? ", " : "", f->nstate > 0 ? prefix : "",
               f->nstate > 0 ? "_states.png" : "");
    return plot_status < 0 ? -1 : 0;
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
    hx_rig r;
    memset(&r, 0, sizeof r);
    const char *element = NULL, *out = NULL, *plot = NULL;
    int deformation_terms = 0, force_terms = 0, kind_error = 0, opt;
    hx_message msg = {{0}};
    optind = 1;
    while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
        int status = 0;
        switch (opt) {
        case 'e': element = optarg; break;
        case 'E': status = hx_option_positive("rig", "end", optarg, &r.end); break;
        case 's': status = hx_option_positive("rig", "step", optarg, &r.step); break;
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
        if (status != 0 && (opt == 'E' || opt == 's')) {
            hx_rig_path_free(&r.path);
            return 2;
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
    if (hx_session_open(&s, argv[optind], stderr, &msg) != 0) {
        fprintf(stderr, "usrsub-harness rig: %s\n", msg.text);
        hx_rig_path_free(&r.path);
        return 1;
    }
    const int kind = find_element(s.model, element, &r.force, &msg);
    if (kind == 1 && r.force_controlled) {
        kind_error = 1;
        hx_fail(&msg, "Force_StateEqn %s: the rig drives a Force_StateEqn along deformation"
                " paths only (its states follow the path)", element);
    }
    if (kind < 0 || kind_error || hx_frames_clone(&r.scratch, &s.frames) != 0) {
        fprintf(stderr, "usrsub-harness rig: %s\n", msg.text);
        hx_session_close(&s);
        hx_rig_path_free(&r.path);
        return 1;
    }
    r.s = &s;
    char prefix[4096] = "", csv_path[sizeof prefix + 8]; /* room for prefix ".csv" */
    if (plot != NULL)
        hx_session_path(&s, plot, prefix, sizeof prefix);
    if (out != NULL)
        hx_session_path(&s, out, csv_path, sizeof csv_path);
    else if (plot != NULL)
        snprintf(csv_path, sizeof csv_path, "%s.csv", prefix);
    if ((out != NULL || plot != NULL) && (r.csv = hx_open_output(csv_path, &msg)) == NULL) {
        fprintf(stderr, "usrsub-harness rig: %s\n", msg.text);
        hx_frames_free(&r.scratch);
        hx_session_close(&s);
        hx_rig_path_free(&r.path);
        return 1;
    }
    if (kind == 1) {
        const int state_status = run_state_rig(&r, plot, csv_path, prefix);
        hx_frames_free(&r.scratch);
        hx_session_close(&s);
        hx_rig_path_free(&r.path);
        return state_status == 0 ? 0 : 1;
    }
    hx_crash_report_begin();
    const int status = hx_rig_run(&r);
    hx_crash_report_end();
    if (r.csv != NULL)
        fclose(r.csv);
    const hx_force *f = &s.model->forces[r.force];
    static const char *const names[6] = {"x", "y", "z", "ax", "ay", "az"};
    printf("rig: %s %d, %s-controlled, %ld steps of %g to t = %g, %ld element calls\n",
           hx_force_element_name(f), f->id,
           r.force_controlled ? "force" : "deformation", lround(r.end / r.step), r.step, r.end,
           r.element_calls);
    printf("  in the %s%s plane: |F| from %.8g to %.8g, |d| from %.8g to %.8g\n", names[r.a],
           names[r.b], r.radius_min[0], r.radius_max[0], r.radius_min[1], r.radius_max[1]);
    if (r.force_controlled)
        printf("  Newton: at most %d iterations a step, worst residual %.3g\n", r.max_iterations,
               r.worst_residual);
    if (status != 0)
        fprintf(stderr, "usrsub-harness rig: the element %s\n",
                hx_messages_stopped(&s.messages) ? "stopped the run (c_errmes STOP)" : "could not be evaluated");
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
    hx_frames_free(&r.scratch);
    hx_session_close(&s);
    hx_rig_path_free(&r.path);
    return status == 0 && plot_status <= 0 ? (plot_status < 0 ? 1 : 0) : 1;
}
