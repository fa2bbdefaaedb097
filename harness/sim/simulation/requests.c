/*
 * The requests' values and columns (requests.h): DISPLACEMENT and VELOCITY
 * from the harness's own measures (frames/measure_functions.h), the
 * expressions by the evaluator (expr/evaluate.h), the variables they read
 * by the host's own answers (host/state_inputs.h), the joints' reactions
 * (JOINT, JPRIM), the bodies' accelerations (ACCX .. WDTM) and the elements'
 * forces (SFORCE .. FIELD, FX .. TM, FORCE) from the caller's.
 */
#include <stdlib.h>

#include "base/vecmath.h"
#include "expr/evaluate.h"
#include "expr/marker_forces.h"
#include "frames/acceleration_measures.h"
#include "frames/measure_functions.h"
#include "host/state_inputs.h"
#include "host/variable_values.h"
#include "sim/simulation/requests.h"

/* One measure of the frames named, in the order of its arguments. */
static double measure(hx_measure which, const hx_frame *a, const hx_frame *b, const hx_frame *c,
                      const hx_frame *e)
{
    const hx_frame *const f[4] = {a, b, c, e};
    return hx_measure_value(which, f);
}

/* Adams' order (docs/interface.md §7.13): F1 the translational magnitude,
 * F2..F4 its x, y, z in RM's axes, F5 the rotational magnitude (none for a
 * displacement: 0), F6..F8 the rotational part. */
static void marker_values(const hx_frames *fr, const hx_request *q, double out[8])
{
    hx_frame scratch[3];
    const hx_frame *i = hx_frames_marker(fr, q->markers[0], &scratch[0]);
    const hx_frame *j = hx_frames_marker(fr, q->markers[1], &scratch[1]);
    const hx_frame *rm = hx_frames_marker(fr, q->markers[2], &scratch[2]);
    const hx_frame *world = &hx_world_frame;
    if (q->kind == HX_REQUEST_DISPLACEMENT) {
        out[0] = measure(HX_MEASURE_DM, i, j, world, world);
        out[1] = measure(HX_MEASURE_DX, i, j, rm, world);
        out[2] = measure(HX_MEASURE_DY, i, j, rm, world);
        out[3] = measure(HX_MEASURE_DZ, i, j, rm, world);
        out[4] = 0.0;
        out[5] = measure(HX_MEASURE_PSI, i, j, world, world);
        out[6] = measure(HX_MEASURE_THETA, i, j, world, world);
        out[7] = measure(HX_MEASURE_PHI, i, j, world, world);
    } else { /* the time derivatives taken in the ground's frame */
        out[0] = measure(HX_MEASURE_VM, i, j, world, world);
        out[1] = measure(HX_MEASURE_VX, i, j, rm, world);
        out[2] = measure(HX_MEASURE_VY, i, j, rm, world);
        out[3] = measure(HX_MEASURE_VZ, i, j, rm, world);
        out[4] = measure(HX_MEASURE_WM, i, j, world, world);
        out[5] = measure(HX_MEASURE_WX, i, j, rm, world);
        out[6] = measure(HX_MEASURE_WY, i, j, rm, world);
        out[7] = measure(HX_MEASURE_WZ, i, j, rm, world);
    }
}

/* ACCELERATION in the same order: ACCM, ACCX .. ACCZ (I, J, RM), WDTM,
 * WDTX .. WDTZ, the time derivatives in the ground's frame; each marker's
 * from its body's (the world's at rest). */
static int acceleration_values(const hx_frames *fr, const hx_request *q, const double *bodies,
                               double out[8], hx_message *msg)
{
    if (bodies == NULL)
        return hx_fail(msg, "%s:%d: %s: ACCELERATION: no accelerations were given to read it"
                       " from (they are known at output times only)", fr->model->path,
                       q->line, q->label);
    static const double rest[6] = {0, 0, 0, 0, 0, 0};
    hx_frame scratch[3];
    const hx_frame *f[4];
    double acc[2][6];
    const double *a[4] = {rest, rest, rest, rest};
    for (int j = 0; j < 3; ++j)
        f[j] = hx_frames_marker(fr, q->markers[j], &scratch[j]);
    f[3] = &hx_world_frame;
    for (int j = 0; j < 2; ++j)
        if (q->markers[j] >= 0) {
            const int b = fr->model->markers[q->markers[j]].body;
            hx_point_acceleration(&fr->bodies[b], bodies + 6 * b, f[j]->p, acc[j]);
            a[j] = acc[j];
        }
    const hx_frame *const in_world[4] = {f[0], f[1], &hx_world_frame, &hx_world_frame};
    out[0] = hx_acceleration_value(HX_ACC_M, in_world, a);
    out[4] = hx_acceleration_value(HX_WDT_M, in_world, a);
    for (int j = 0; j < 3; ++j) {
        out[1 + j] = hx_acceleration_value((hx_acceleration_measure)(HX_ACC_X + j), f, a);
        out[5 + j] = hx_acceleration_value((hx_acceleration_measure)(HX_WDT_X + j), f, a);
    }
    return 0;
}

/* FORCE in the same order: FM, FX .. FZ in RM's axes, TM, TX .. TZ, at I from
 * the elements between I and J (J left out: the action-only forces at I). */
static int force_values(const hx_frames *fr, const hx_request *q, const hx_expr_outputs *s,
                        double out[8], hx_message *msg)
{
    double F[3], T[3], rm_F[3], rm_T[3];
    hx_expr_fault fault;
    if (hx_marker_forces_sum(fr, s, q->markers[0], q->markers[1], q->markers[1] < 0, F, T,
                             &fault) != 0)
        return hx_fail(msg, "%s:%d: %s: FORCE: %s", fr->model->path, q->line, q->label,
                       fault.what);
    hx_frame scratch;
    const hx_frame *rm = hx_frames_marker(fr, q->markers[2], &scratch);
    m3_tapply(rm_F, rm->R, F), m3_tapply(rm_T, rm->R, T);
    out[0] = v3_norm(F), out[4] = v3_norm(T);
    for (int j = 0; j < 3; ++j)
        out[1 + j] = rm_F[j], out[5 + j] = rm_T[j];
    return 0;
}

int hx_requests_values(const hx_frames *fr, int k, const double *variables,
                       const hx_expr_outputs *s, double out[8], hx_message *msg)
{
    const hx_request *q = &fr->model->requests[k];
    if (q->kind == HX_REQUEST_FORCE)
        return force_values(fr, q, s, out, msg);
    if (q->kind == HX_REQUEST_ACCELERATION)
        return acceleration_values(fr, q, s != NULL ? s->accelerations : NULL, out, msg);
    if (q->kind != HX_REQUEST_EXPRESSIONS) {
        marker_values(fr, q, out);
        return 0;
    }
    const hx_expr_context c = {fr, variables, s};
    for (int j = 0; j < 8; ++j) {
        out[j] = 0.0;
        hx_expr_fault fault;
        if (q->f[j] != NULL && hx_expr_eval(q->f[j], &c, &out[j], &fault) != 0) {
            char element[48];
            snprintf(element, sizeof element, "%s %s%d", q->label, q->adams ? "F" : "expr", j + 1);
            return hx_expr_fail(msg, q->f[j], &fault, element);
        }
    }
    return 0;
}

void hx_requests_csv_header(FILE *f, const hx_model *m)
{
    for (int k = 0; k < m->nrequests; ++k)
        for (int j = 1; j <= 8; ++j)
            fprintf(f, ",request%d.%d", m->requests[k].id, j);
}

int hx_requests_csv_row(FILE *f, const hx_frames *fr, hx_binding *const *routines,
                        const hx_expr_outputs *s, hx_message *msg)
{
    const hx_model *m = fr->model;
    if (m->nrequests == 0)
        return 0;
    double *variables = NULL;
    if (m->nvariables > 0) {
        if ((variables = malloc(sizeof(double) * (size_t)m->nvariables)) == NULL)
            return hx_fail(msg, "out of memory");
        if (hx_variables_values(fr, routines, variables, msg) != 0) {
            free(variables);
            return -1;
        }
    }
    int status = 0;
    for (int k = 0; k < m->nrequests && status == 0; ++k) {
        double values[8];
        status = hx_requests_values(fr, k, variables, s, values, msg);
        for (int j = 0; j < 8 && status == 0; ++j)
            fprintf(f, ",%.15g", values[j]);
    }
    free(variables);
    return status;
}
