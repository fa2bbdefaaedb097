/* The calling conventions of the bound elements (invoke.h): each call bound
 * to the host with the frames its queries are answered from, its outputs
 * zeroed first as a solver zeroes them, and logged for check's crash reports. */
#include "host/invoke.h"

#include <string.h>

#include "host/records.h"

static void log_call(hx_binding *b, int which, double time, int iflag, int dflag,
                     const double *args, int nargs)
{
    hx_call_log *log = b->log;
    log->routine = hx_binding_routine(b, which);
    log->iflag = iflag, log->dflag = dflag;
    log->time = time;
    log->nargs = nargs;
    for (int k = 0; k < nargs && k < 12; ++k)
        log->args[k] = args[k];
    log->begun++;
}

/* What an entry's outputs hold before it is called. */
static void fill(double *out, int n, double value)
{
    for (int k = 0; k < n; ++k)
        out[k] = value;
}

/* The caller's record (set up with hx_binding_call_init) or a default one. */
static void begin(hx_binding *b, int which, const hx_frames *fr, int iflag, hx_call *call,
                  hx_call *local)
{
    if (call == NULL) {
        hx_binding_call_init(b, local, which, fr, iflag);
        call = local;
    }
    if (fr->time > b->latest_time)
        b->latest_time = fr->time;
    hx_host_bind(call);
}

void hx_invoke_coupler(hx_binding *b, int which, const hx_frames *fr, const double *disp,
                       int ndisp, int iflag, double *out, hx_call *call)
{
    hx_call local;
    begin(b, which, fr, iflag, call, &local);
    int id = b->id, npar = b->npar, n = ndisp, flag = iflag;
    double t = fr->time, d[3] = {0, 0, 0};
    for (int k = 0; k < ndisp && k < 3; ++k)
        d[k] = disp[k];
    /* a solver zeroes what an entry returns: outputs it never writes read 0 */
    fill(out, which == 0 ? 1 : which == 1 ? ndisp : ndisp * ndisp, b->output_fill);
    if (b->log != NULL)
        log_call(b, which, t, iflag, 0, d, ndisp);
    if (b->record != NULL)
        hx_record_coupler(b, which, t, d, iflag, out);
    else
        b->fn.coupler[which](&id, &t, b->par, &npar, d, &n, &flag, out);
    if (b->log != NULL)
        b->log->returned++;
    hx_host_unbind();
}

void hx_invoke_force(hx_binding *b, const hx_frames *fr, int dflag, int iflag, double *values,
                     hx_call *call)
{
    hx_call local;
    begin(b, 0, fr, iflag, call, &local);
    int id = b->id, npar = b->npar, df = dflag, flag = iflag;
    double t = fr->time;
    if (b->log != NULL)
        log_call(b, 0, t, iflag, dflag, NULL, 0);
    fill(values, hx_force_routine_values(b->part), b->output_fill);
    if (b->record != NULL)
        hx_record_values(b, t, dflag, iflag, values);
    else
        b->fn.force(&id, &t, b->par, &npar, &df, &flag, values);
    if (b->log != NULL)
        b->log->returned++;
    hx_host_unbind();
}

void hx_invoke_field(hx_binding *b, const hx_frames *fr, const double disp[6],
                     const double velo[6], int dflag, int iflag, double field[6], double dfddis[36],
                     double dfdvel[36], hx_call *call)
{
    hx_call local;
    begin(b, 0, fr, iflag, call, &local);
    int id = b->id, npar = b->npar, df = dflag, flag = iflag;
    double t = fr->time, d[6], v[6];
    memcpy(d, disp, sizeof d);
    memcpy(v, velo, sizeof v);
    if (b->log != NULL) {
        double args[12];
        memcpy(args, d, sizeof d);
        memcpy(args + 6, v, sizeof v);
        log_call(b, 0, t, iflag, dflag, args, 12);
    }
    fill(field, 6, b->output_fill);
    memset(dfddis, 0, 36 * sizeof(double));
    memset(dfdvel, 0, 36 * sizeof(double)); /* some FIESUBs never write it */
    if (b->record != NULL)
        hx_record_fiesub(b, t, d, v, dflag, iflag, field, dfddis, dfdvel);
    else
        b->fn.field(&id, &t, b->par, &npar, d, v, &df, &flag, field, dfddis, dfdvel);
    if (b->log != NULL)
        b->log->returned++;
    hx_host_unbind();
}

void hx_invoke_routine(hx_binding *b, const hx_frames *fr, int flag, int iflag, double *values,
                       hx_call *call)
{
    hx_call local;
    begin(b, 0, fr, iflag, call, &local);
    int id = b->id, npar = b->npar, f = flag, fl = iflag;
    double t = fr->time;
    if (b->log != NULL)
        log_call(b, 0, t, iflag, flag, NULL, 0);
    fill(values, b->kind == HX_BIND_REQUEST ? 8 : 1, b->output_fill);
    if (b->record != NULL)
        hx_record_values(b, t, flag, iflag, values);
    else if (b->kind == HX_BIND_REQUEST)
        b->fn.request(&id, &t, b->par, &npar, &fl, values);
    else
        b->fn.value(&id, &t, b->par, &npar, &f, &fl, values);
    if (b->log != NULL)
        b->log->returned++;
    hx_host_unbind();
}

void hx_invoke_stateeqn(hx_binding *b, const hx_frames *fr, double *states, double *input,
                        int dflag, int iflag, double *stated, double output[6], hx_call *call)
{
    const hx_stateeqn *f = &b->model->stateeqns[b->index];
    hx_call local;
    begin(b, 0, fr, iflag, call, &local);
    int id = b->id, npar = b->npar, df = dflag, flag = iflag;
    int nstate = f->nstate, ninput = f->ninput, noutpt = 6;
    double t = fr->time;
    if (b->log != NULL)
        log_call(b, 0, t, iflag, dflag, input, ninput);
    fill(stated, nstate, b->output_fill);
    fill(output, 6, b->output_fill);
    b->fn.stateeqn.rates(&id, &t, b->par, &npar, &df, &flag, &nstate, states, &ninput, input, &noutpt,
              stated, output);
    if (b->log != NULL)
        b->log->returned++;
    hx_host_unbind();
}

void hx_invoke_stateeqn_partial(hx_binding *b, int which, const hx_frames *fr, double *states,
                                double *input, double *matrix, hx_call *call)
{
    const hx_stateeqn *f = &b->model->stateeqns[b->index];
    hx_call local;
    begin(b, 1 + which, fr, 0, call, &local);
    int id = b->id, npar = b->npar, flag = 0;
    int nstate = f->nstate, ninput = f->ninput, noutpt = 6;
    double t = fr->time;
    if (b->log != NULL)
        log_call(b, 1 + which, t, 0, 0, input, ninput);
    /* YFOXX n x n, YFOXU n x ninput, YFOYX 6 x n, YFOYU 6 x ninput */
    memset(matrix, 0, sizeof(double) * (size_t)((which < 2 ? nstate : 6) *
                                                 (which % 2 == 0 ? nstate : ninput)));
    b->fn.stateeqn.partial[which](&id, &t, b->par, &npar, &flag, &nstate, states, &ninput, input,
                            &noutpt, matrix);
    if (b->log != NULL)
        b->log->returned++;
    hx_host_unbind();
}

void hx_invoke_twin(hx_binding *b, const hx_frames *fr, const double disp[6],
                    const double velo[6], double field[6], double dfddis[36], double dfdvel[36],
                    hx_messages *messages)
{
    hx_call call;
    hx_call_init(&call, b->element, b->id, b->twin_name, b->model, fr, messages, 0, NULL);
    call.may_query = 0; /* a FIESUB entry (docs/interface.md §1) */
    hx_host_bind(&call);
    int id = b->id, npar = b->twin_npar, df = 1, flag = 0; /* dflag: its partials are wanted */
    double t = fr->time, d[6], v[6];
    memcpy(d, disp, sizeof d);
    memcpy(v, velo, sizeof v);
    memset(field, 0, 6 * sizeof(double));
    memset(dfddis, 0, 36 * sizeof(double));
    memset(dfdvel, 0, 36 * sizeof(double));
    b->twin(&id, &t, b->twin_par, &npar, d, v, &df, &flag, field, dfddis, dfdvel);
    hx_host_unbind();
}
