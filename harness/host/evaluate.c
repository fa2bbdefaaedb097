/* One way to call a bound element (evaluate.h). */
#include "host/evaluate.h"

#include <string.h>

#include "host/state_inputs.h"
#include "frames/measures.h"

int hx_binding_input_count(const hx_binding *b)
{
    const hx_model *m = b->model;
    switch (b->kind) {
    case HX_BIND_COUPLER: return m->couplers[b->index].njoints;
    case HX_BIND_FIESUB: return 12;
    case HX_BIND_YFOSUB: return m->stateeqns[b->index].nstate + m->stateeqns[b->index].ninput;
    default: return 0; /* they ask the host for the state, or take the time alone */
    }
}

int hx_binding_output_count(const hx_binding *b)
{
    const hx_model *m = b->model;
    switch (b->kind) {
    case HX_BIND_COUPLER: {
        const int n = m->couplers[b->index].njoints;
        return 1 + n + n * n;
    }
    case HX_BIND_GFOSUB: return hx_force_routine_values(b->part);
    case HX_BIND_FIESUB: return 6 + 72;
    case HX_BIND_YFOSUB: return m->stateeqns[b->index].nstate + 6;
    case HX_BIND_REQSUB: return 8;
    case HX_BIND_MOTSUB: return 3;
    default: return 1;
    }
}

void hx_binding_inputs(const hx_binding *b, const hx_frames *s, const double *states, double *in)
{
    const hx_model *m = b->model;
    if (b->kind == HX_BIND_COUPLER) {
        const hx_coupler *c = &m->couplers[b->index];
        for (int i = 0; i < c->njoints; ++i)
            in[i] = hx_joint_coordinate(s, c->joint[i]);
    } else if (b->kind == HX_BIND_FIESUB) {
        hx_force_deformation(s, b->index, in, in + 6);
    } else if (b->kind == HX_BIND_YFOSUB) {
        const hx_stateeqn *f = &m->stateeqns[b->index];
        memcpy(in, states != NULL ? states : f->initial, sizeof(double) * (size_t)f->nstate);
        hx_stateeqn_inputs(s, b->index, in + f->nstate);
    }
}

int hx_binding_evaluate(hx_binding *b, const hx_frames *s, double *in, int iflag, int dflag,
                        double *out)
{
    switch (b->kind) {
    case HX_BIND_COUPLER: {
        const int n = b->model->couplers[b->index].njoints;
        hx_invoke_coupler(b, 0, s, in, n, iflag, out, NULL);
        hx_invoke_coupler(b, 1, s, in, n, iflag, out + 1, NULL);
        hx_invoke_coupler(b, 2, s, in, n, iflag, out + 1 + n, NULL);
        return 1 + n + n * n;
    }
    case HX_BIND_GFOSUB:
        hx_invoke_gfosub(b, s, dflag, iflag, out, NULL);
        return hx_force_routine_values(b->part);
    case HX_BIND_FIESUB:
        hx_invoke_fiesub(b, s, in, in + 6, dflag, iflag, out, out + 6, out + 42, NULL);
        return 6 + 72;
    case HX_BIND_YFOSUB: {
        const int ns = b->model->stateeqns[b->index].nstate;
        hx_invoke_yfosub(b, s, in, in + ns, dflag, iflag, out, out + ns, NULL);
        return ns + 6;
    }
    case HX_BIND_MOTSUB: /* the motion, its rate and its acceleration */
        for (int iord = 0; iord < 3; ++iord)
            hx_invoke_routine(b, s, iord, iflag, out + iord, NULL);
        return 3;
    default:
        hx_invoke_routine(b, s, dflag, iflag, out, NULL);
        return hx_binding_output_count(b);
    }
}
