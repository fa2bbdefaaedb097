/* One way to call a bound element (element_call.h). */
#include "host/element_call.h"

#include <string.h>

#include "host/invoke.h"
#include "host/state_inputs.h"
#include "frames/measures.h"

int hx_element_call_input_count(const hx_binding *b)
{
    const hx_model *m = b->model;
    switch (b->kind) {
    case HX_BIND_COUPLER: return m->couplers[b->index].njoints;
    case HX_BIND_FIELD: return 12;
    case HX_BIND_STATEEQN: return m->stateeqns[b->index].nstate + m->stateeqns[b->index].ninput;
    default: return 0; /* they ask the host for the state, or take the time alone */
    }
}

int hx_element_call_output_count(const hx_binding *b)
{
    const hx_model *m = b->model;
    switch (b->kind) {
    case HX_BIND_COUPLER: {
        const int n = m->couplers[b->index].njoints;
        return 1 + n + n * n;
    }
    case HX_BIND_FORCE: return hx_force_routine_values(b->part);
    case HX_BIND_FIELD: return 6 + 72;
    case HX_BIND_STATEEQN: return m->stateeqns[b->index].nstate + 6;
    case HX_BIND_REQUEST: return 8;
    case HX_BIND_MOTION: return 3;
    default: return 1;
    }
}

void hx_element_call_inputs(const hx_binding *b, const hx_frames *fr, const double *states,
                            double *in)
{
    const hx_model *m = b->model;
    if (b->kind == HX_BIND_COUPLER) {
        const hx_coupler *c = &m->couplers[b->index];
        for (int i = 0; i < c->njoints; ++i)
            in[i] = hx_joint_coordinate(fr, c->joint[i], c->freedom[i]);
    } else if (b->kind == HX_BIND_FIELD) {
        hx_force_deformation(fr, b->index, in, in + 6);
    } else if (b->kind == HX_BIND_STATEEQN) {
        const hx_stateeqn *f = &m->stateeqns[b->index];
        memcpy(in, states != NULL ? states : f->initial, sizeof(double) * (size_t)f->nstate);
        hx_stateeqn_inputs(fr, b->index, in + f->nstate);
    }
}

int hx_element_call(hx_binding *b, const hx_frames *fr, double *in, int iflag, int dflag,
                    double *out)
{
    switch (b->kind) {
    case HX_BIND_COUPLER: {
        const int n = b->model->couplers[b->index].njoints;
        hx_invoke_coupler(b, 0, fr, in, n, iflag, out, NULL);
        hx_invoke_coupler(b, 1, fr, in, n, iflag, out + 1, NULL);
        hx_invoke_coupler(b, 2, fr, in, n, iflag, out + 1 + n, NULL);
        return 1 + n + n * n;
    }
    case HX_BIND_FORCE:
        hx_invoke_force(b, fr, dflag, iflag, out, NULL);
        return hx_force_routine_values(b->part);
    case HX_BIND_FIELD:
        hx_invoke_field(b, fr, in, in + 6, dflag, iflag, out, out + 6, out + 42, NULL);
        return 6 + 72;
    case HX_BIND_STATEEQN: {
        const int ns = b->model->stateeqns[b->index].nstate;
        hx_invoke_stateeqn(b, fr, in, in + ns, dflag, iflag, out, out + ns, NULL);
        return ns + 6;
    }
    case HX_BIND_MOTION: /* the motion, its rate and its acceleration */
        for (int iord = 0; iord < 3; ++iord)
            hx_invoke_routine(b, fr, iord, iflag, out + iord, NULL);
        return 3;
    default:
        hx_invoke_routine(b, fr, dflag, iflag, out, NULL);
        return hx_element_call_output_count(b);
    }
}
