/* The Jacobian of the dynamics, assembled element by element (jacobian.h). */
#include "sim/jacobian/jacobian_parts.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim/dynamics/constraints.h"
#include "sim/dynamics/implicit_diffs.h"

int hx_jacobian_init(hx_jacobian *jac, const hx_dynamics *d, hx_message *msg)
{
    memset(jac, 0, sizeof *jac);
    hx_messages_init(&jac->twin_messages, NULL);
    jac->d = d;
    jac->n = d->n;
    jac->m = d->nq + d->nu;
    jac->nf = d->m->nforces;
    if (hx_dynamics_data_init(&jac->dd, d, msg) != 0) {
        hx_jacobian_free(jac);
        return -1;
    }
    const int nc = d->nrows;
    jac->y = calloc(3 * (size_t)jac->n + 1, sizeof(double));
    jac->coupled = calloc((size_t)d->nu + 1, sizeof(int));
    jac->load_map = calloc(12 * ((size_t)d->m->nbodies + 1), sizeof(double));
    jac->driven = calloc((size_t)jac->n + 1, 1);
    int ok = jac->y != NULL && jac->coupled != NULL && jac->load_map != NULL &&
             jac->driven != NULL && hx_jacobian_marker_lists(jac) == 0 &&
             hx_frames_clone(&jac->moved, &jac->dd.frames) == 0;
    if (ok) {
        jac->f_plus = jac->y + jac->n;
        jac->f_minus = jac->f_plus + jac->n;
        jac->ncoupled = nc > 0 ? hx_constraints_coupled(d, jac->coupled) : 0;
        const size_t k = (size_t)jac->ncoupled;
        jac->projector = calloc(k * k + 4 * k + (size_t)nc * ((size_t)nc + 1) + 1, sizeof(double));
        jac->coupler_work = jac->projector + k * k;
        ok = jac->projector != NULL;
    }
    if (!ok) {
        hx_jacobian_free(jac);
        return hx_fail(msg, "out of memory");
    }
    /* each part says why it failed */
    if (hx_element_blocks_init(jac, msg) != 0 || hx_load_blocks_init(jac, msg) != 0 ||
        hx_stateeqn_blocks_init(jac, msg) != 0 || hx_routine_blocks_init(jac, msg) != 0 ||
        hx_coupler_blocks_init(jac, msg) != 0 || hx_jacobian_pattern(jac, 0, msg) != 0 ||
        hx_coupler_blocks_locate(jac, msg) != 0) {
        hx_jacobian_free(jac);
        return -1;
    }
    hx_element_blocks_locate(jac);
    return 0;
}

int hx_jacobian_widen(hx_jacobian *jac, hx_message *msg)
{
    if (hx_jacobian_pattern(jac, 1, msg) != 0 || hx_load_blocks_init(jac, msg) != 0)
        return -1;
    hx_element_blocks_locate(jac); /* the blocks' places in the wider pattern */
    return hx_coupler_blocks_locate(jac, msg);
}

void hx_jacobian_free(hx_jacobian *jac)
{
    hx_sparsity_free(&jac->pattern);
    free(jac->source);
    free(jac->why);
    free(jac->twin_partials);
    free(jac->element_rows);
    free(jac->load_map);
    hx_frames_free(&jac->moved);
    free(jac->body_markers);
    free(jac->body_marker_start);
    hx_stateeqn_blocks_free(jac);
    free(jac->coupled);
    hx_coupler_blocks_free(jac);
    free(jac->projector);
    free(jac->driven);
    free(jac->diff_scratch);
    free(jac->load_scratch);
    free(jac->y);
    hx_dynamics_data_free(&jac->dd);
    hx_messages_destroy(&jac->twin_messages);
    memset(jac, 0, sizeof *jac);
}

/* A model with an algebraic loop: every column by central differences of
 * the right-hand side, the loop solved at each (its loads' rows depend on y
 * through the loop's values too, which no element's partials hold). */
static int loop_build(hx_jacobian *jac, double t, const double *y, double *values)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    memcpy(jac->y, y, sizeof(double) * (size_t)jac->n);
    for (int c = 0; c < jac->n; ++c) {
        const double h = hx_jacobian_step(y, c);
        jac->y[c] = y[c] + h;
        int status = hx_dynamics_rhs(d, dd, t, jac->y, jac->f_plus);
        jac->y[c] = y[c] - h;
        status = status != 0 ? status : hx_dynamics_rhs(d, dd, t, jac->y, jac->f_minus);
        jac->y[c] = y[c];
        jac->evaluations += 2;
        if (status != 0)
            return -1;
        for (int i = jac->pattern.colptr[c]; i < jac->pattern.colptr[c + 1]; ++i) {
            const int r = jac->pattern.rowind[i];
            values[i] = (jac->f_plus[r] - jac->f_minus[r]) / (2.0 * h);
        }
    }
    return 0;
}

int hx_jacobian_build(hx_jacobian *jac, double t, const double *y, const double *fy,
                      double *values)
{
    (void)fy; /* the elements' partials come with their outputs, which fy does not hold */
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    if (d->m->nloop_inputs > 0)
        return loop_build(jac, t, y, values);
    jac->evaluations++;
    if (hx_dynamics_evaluate(d, dd, t, y, jac->f_plus, HX_EVALUATE_PARTIALS) != 0)
        return -1;
    /* the implicit Control_Diffs' Newton at the moved states starts from their
     * rates at (t, y) (routine_blocks.c) */
    hx_implicit_diffs_keep(d, dd);
    jac->values = values;
    memset(values, 0, sizeof(double) * (size_t)jac->pattern.nnz);
    memcpy(jac->y, y, sizeof(double) * (size_t)jac->n);
    hx_frames_copy(&jac->moved, &dd->frames);
    hx_body_blocks(jac, y);
    /* the element blocks read dd's outputs of this evaluation; the coupler and
     * routine blocks evaluate stages of dd again at moved states, after them */
    const int status = hx_element_blocks(jac, t, y) != 0 || hx_load_blocks(jac, t, y) != 0 ||
                       hx_stateeqn_blocks(jac, t, y) != 0 || hx_coupler_blocks(jac, t, y) != 0 ||
                       hx_routine_blocks(jac, t, y) != 0;
    return status ? -1 : 0;
}

void hx_jacobian_describe(const hx_jacobian *jac, char *text, size_t size)
{
    const int nz = jac->d->m->nloop_inputs;
    if (nz > 0) {
        snprintf(text, size, "Jacobian by central differences of the whole right-hand side:"
                 " the model's loads read %d input%s of an algebraic loop"
                 " (docs/interface.md §8.8)", nz, nz == 1 ? "" : "s");
        return;
    }
    int counts[3] = {0, 0, 0};
    for (int k = 0; k < jac->nf; ++k)
        counts[jac->source[k]]++;
    int len = snprintf(text, size, "Jacobian from the elements' partials: %d by FIESUB's own,"
                       " %d by their FIESUB twin, %d by differences of the element alone",
                       counts[0], counts[1], counts[2]);
    for (int k = 0; k < jac->nf && len > 0 && (size_t)len < size; ++k)
        if (jac->source[k] == HX_PARTIALS_DIFFERENCES)
            len += snprintf(text + len, size - (size_t)len, "\n    %s %d by differences: %s",
                            jac->d->force_binding[k]->element, jac->d->force_binding[k]->id,
                            jac->why + k * HX_JACOBIAN_WHY);
    hx_stateeqn_blocks_describe(jac, text, size);
}
