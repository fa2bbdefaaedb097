/*
 * The bushing as a state equation (docs/interface.md §3.8), for a
 * Force_StateEqn: YFOSUB gives the state rates and the force on I from the
 * states and the inputs; YFOXX, YFOXU, YFOYX and YFOYU its partials
 * (column-major, rows first: pxxmat[i + nstate j] = d stated_i / d states_j).
 * USER(1, .gbs id [, .gbi id]); inputs: the 12 values DX DY DZ AX AY AZ (I,J)
 * and VX VY VZ WX WY WZ (I,J,J,J) in J axes; outputs: Fx Fy Fz Tx Ty Tz on I in
 * J axes. Like FIESUB, the routines get their state in their arguments and ask
 * the host nothing.
 */
#include <math.h>
#include <string.h>

#include "entry_report.h"
#include "entry_alias.h"
#include "finite.h"
#include "force_model.h"
#include "usrsub/solver_abi.h"

enum { INPUTS = 12, OUTPUTS = 6 };

/* What the host handed over, as one record. */
typedef struct state_call {
    const char *routine;
    int *id;
    double *par;
    int *npar;
    int *nstate;
    double *states;
    int *ninput;
    double *input;
    int *noutpt;
} state_call;

static void zero(double *v, long n)
{
    if (v != NULL && n > 0)
        memset(v, 0, sizeof(double) * (size_t)n);
}

/* The element's model when the call is sound (sizes as the model needs them,
 * finite states and inputs); NULL after reporting what is not. */
static const usrsub_force_model *checked_model(const state_call *c)
{
    if (!usrsub_entry_report_arguments_ok(c->routine, c->id, c->par, c->npar))
        return NULL;
    const usrsub_force_model *m =
        usrsub_force_model_of(c->routine, USRSUB_ELEMENT_YFOSUB, 0, *c->id, c->par, *c->npar);
    if (m == NULL)
        return NULL;
    const usrsub_state_layout *l = &m->states;
    const int nstate = c->nstate != NULL ? *c->nstate : -1;
    const int ninput = c->ninput != NULL ? *c->ninput : -1;
    const int noutpt = c->noutpt != NULL ? *c->noutpt : -1;
    if (nstate != l->n || ninput != INPUTS || noutpt != OUTPUTS ||
        (l->n > 0 && c->states == NULL) || c->input == NULL) {
        usrsub_entry_report_error(c->routine, *c->id, "sizes", "the bushing has %d states (friction %d,"
                           " balanced mounts %d, inertial mounts 2 x %d, rubber filters %d), 12"
                           " inputs (DX DY DZ AX AY AZ"
                           " of I relative to J, then VX VY VZ WX WY WZ) and 6 outputs; the host"
                           " passed nstate %d, ninput %d, noutpt %d%s: set num_state and the U"
                           " array to match; the outputs are zero", l->n, l->friction,
                           l->nmount, l->ninertial, l->nrubber, nstate, ninput, noutpt,
                           c->input == NULL || (l->n > 0 && c->states == NULL)
                               ? " and no states or inputs" : "");
        return NULL;
    }
    if (!usrsub_finite_all(c->input, INPUTS) || (l->n > 0 && !usrsub_finite_all(c->states, l->n))) {
        usrsub_entry_report_error(c->routine, *c->id, "state", "the inputs (%g %g %g %g %g %g | %g %g %g"
                           " %g %g %g) or the states are not finite; the outputs are zero",
                           c->input[0], c->input[1], c->input[2], c->input[3], c->input[4],
                           c->input[5], c->input[6], c->input[7], c->input[8], c->input[9],
                           c->input[10], c->input[11]);
        return NULL;
    }
    return m;
}

/* Evaluates at the call's point; 0, or -1 after reporting. */
static int evaluate(const state_call *c, const usrsub_force_model *m, double *stated, double *output,
                    usrsub_state_partials *p)
{
    usrsub_message msg;
    double xdot[USRSUB_MAX_STATES], y[OUTPUTS];
    if (usrsub_bushing_states_eval(m->bushing, m->limits, &m->states, c->input, c->states, xdot,
                                   y, p, &msg) != 0) {
        usrsub_entry_report_error(c->routine, *c->id, "balance", "%s; the outputs are zero", msg.text);
        return -1;
    }
    const int n = m->states.n;
    if (!usrsub_finite_all(xdot, n) || !usrsub_finite_all(y, OUTPUTS) ||
        (p != NULL && (!usrsub_finite_all(p->dxdot_dx, n * n) || !usrsub_finite_all(p->dxdot_du, n * INPUTS) ||
                       !usrsub_finite_all(p->dy_dx, OUTPUTS * n) || !usrsub_finite_all(p->dy_du, OUTPUTS * INPUTS)))) {
        usrsub_entry_report_error(c->routine, *c->id, "result", "the outputs at inputs (%g %g %g %g %g %g)"
                           " are not finite (a state out of any sensible range); they are zero",
                           c->input[0], c->input[1], c->input[2], c->input[3], c->input[4],
                           c->input[5]);
        return -1;
    }
    if (stated != NULL)
        memcpy(stated, xdot, sizeof(double) * (size_t)n);
    if (output != NULL)
        memcpy(output, y, sizeof y);
    return 0;
}

void STDCALL YFOSUB(int *id, double *time, double *par, int *npar, int *dflag, int *iflag,
                    int *nstate, double *states, int *ninput, double *input, int *noutpt,
                    double *stated, double *output)
{
    (void)time, (void)dflag, (void)iflag; /* no history: the dependency pass computes the same */
    const state_call c = {"YFOSUB", id, par, npar, nstate, states, ninput, input, noutpt};
    zero(stated, nstate != NULL ? *nstate : 0);
    zero(output, noutpt != NULL ? *noutpt : 0);
    const usrsub_force_model *m = checked_model(&c);
    if (m != NULL && evaluate(&c, m, stated, output, NULL) != 0) {
        zero(stated, *nstate);
        zero(output, *noutpt);
    }
}

/* The four partial routines: which block of the partials each copies. */
enum partial_block { BLOCK_XX, BLOCK_XU, BLOCK_YX, BLOCK_YU };

static void partial_entry(const char *routine, enum partial_block block, int *id, double *par,
                          int *npar, int *nstate, double *states, int *ninput, double *input,
                          int *noutpt, double *matrix)
{
    const long rows = block <= BLOCK_XU ? (nstate != NULL ? *nstate : 0) : (noutpt != NULL ? *noutpt : 0);
    const long cols = block == BLOCK_XX || block == BLOCK_YX ? (nstate != NULL ? *nstate : 0)
                                                             : (ninput != NULL ? *ninput : 0);
    zero(matrix, rows > 0 && cols > 0 ? rows * cols : 0);
    const state_call c = {routine, id, par, npar, nstate, states, ninput, input, noutpt};
    const usrsub_force_model *m = checked_model(&c);
    usrsub_state_partials p;
    if (m == NULL || matrix == NULL || evaluate(&c, m, NULL, NULL, &p) != 0)
        return;
    const double *from[4] = {p.dxdot_dx, p.dxdot_du, p.dy_dx, p.dy_du};
    memcpy(matrix, from[block], sizeof(double) * (size_t)(rows * cols));
}

#define PARTIAL_ENTRY(NAME, BLOCK)                                                              \
    void STDCALL NAME(int *id, double *time, double *par, int *npar, int *iflag, int *nstate,    \
                      double *states, int *ninput, double *input, int *noutpt, double *matrix)   \
    {                                                                                            \
        (void)time, (void)iflag;                                                                 \
        partial_entry(#NAME, BLOCK, id, par, npar, nstate, states, ninput, input, noutpt,        \
                      matrix);                                                                   \
    }

PARTIAL_ENTRY(YFOXX, BLOCK_XX)
PARTIAL_ENTRY(YFOXU, BLOCK_XU)
PARTIAL_ENTRY(YFOYX, BLOCK_YX)
PARTIAL_ENTRY(YFOYU, BLOCK_YU)

USRSUB_ENTRY_ALIAS(usrsub_yfosub_fn, yfosub_, YFOSUB)
USRSUB_ENTRY_ALIAS(usrsub_state_partial_fn, yfoxx_, YFOXX)
USRSUB_ENTRY_ALIAS(usrsub_state_partial_fn, yfoxu_, YFOXU)
USRSUB_ENTRY_ALIAS(usrsub_state_partial_fn, yfoyx_, YFOYX)
USRSUB_ENTRY_ALIAS(usrsub_state_partial_fn, yfoyu_, YFOYU)
