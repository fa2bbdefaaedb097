/*
 * The assembly's report (assembly.h): the model's initial state and the
 * projected one, part by part (docs/architecture.md, the constraint system).
 */
#include <math.h>
#include <stdlib.h>

#include "base/vecmath.h"
#include "sim/dynamics/assembly.h"
#include "sim/dynamics/bodies.h"

/* The angle of R0^T R1: atan2(|axial vector|, (trace - 1) / 2), good near 0 and pi. */
static double turn_angle(const double R0[9], const double R1[9])
{
    double R[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double s = 0.0;
            for (int k = 0; k < 3; ++k)
                s += R0[3 * k + i] * R1[3 * k + j];
            R[3 * i + j] = s;
        }
    const double axial[3] = {R[7] - R[5], R[2] - R[6], R[3] - R[1]};
    return atan2(0.5 * v3_norm(axial), 0.5 * (R[0] + R[4] + R[8] - 1.0));
}

int hx_assembly_moves(const hx_dynamics *d, hx_assembly_move *moves, hx_message *msg)
{
    const hx_model *m = d->m;
    double L = 1.0; /* the model's length, as the constraints' rows take it */
    for (int k = 0; k < m->nmarkers; ++k)
        L = fmax(L, v3_norm(m->markers[k].pos0));
    hx_dynamics_data dd;
    if (hx_dynamics_data_init(&dd, d, msg) != 0)
        return -1;
    double *y0 = malloc(sizeof(double) * ((size_t)d->n + 1));
    double *y1 = malloc(sizeof(double) * ((size_t)d->n + 1));
    int count = -1;
    if (y0 == NULL || y1 == NULL)
        hx_fail(msg, "out of memory");
    else if (hx_dynamics_model_state(d, &dd, y0) != 0 ||
             hx_dynamics_initial_state(d, &dd, y1) != 0)
        hx_fail(msg, "the assembly failed: %s", dd.message);
    else {
        count = 0;
        for (int b = 0; b < m->nbodies; ++b) {
            if (d->dof[b].kind == HX_DOF_GROUND)
                continue;
            hx_frame f0, f1;
            hx_bodies_frame(d, b, y0, &f0);
            hx_bodies_frame(d, b, y1, &f1);
            double dp[3];
            v3_sub(dp, f1.p, f0.p);
            const double moved = v3_norm(dp), turned = turn_angle(f0.R, f1.R);
            if (moved > HX_ASSEMBLY_REPORTED_LENGTH * L || turned > HX_ASSEMBLY_REPORTED_ANGLE)
                moves[count++] = (hx_assembly_move){b, moved, turned};
        }
    }
    free(y0), free(y1);
    hx_dynamics_data_free(&dd);
    return count;
}
