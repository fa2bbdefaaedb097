/* The run's CSV: a header and one row per output time (simulation.h). */
#include <stdlib.h>

#include "sim/dynamics/accelerations.h"
#include "sim/dynamics/constraint_forces.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/reactions.h"
#include "sim/dynamics/routines.h"
#include "sim/dynamics/element_outputs.h"
#include "sim/simulation/requests.h"
#include "sim/simulation/simulation.h"
#include "sim/dynamics/stateeqns.h"
#include "frames/measures.h"

void hx_csv_header(FILE *f, const hx_dynamics *d)
{
    const hx_model *m = d->m;
    fprintf(f, "t");
    for (int k = 0; k < m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        const int id = m->bodies[k].id;
        if (dof->kind == HX_DOF_FREE)
            fprintf(f, ",body%d.x,body%d.y,body%d.z,body%d.q0,body%d.q1,body%d.q2,body%d.q3"
                       ",body%d.vx,body%d.vy,body%d.vz,body%d.wx,body%d.wy,body%d.wz",
                    id, id, id, id, id, id, id, id, id, id, id, id, id);
        else if (dof->kind != HX_DOF_GROUND) {
            const int jid = m->joints[m->bodies[k].joint].id;
            fprintf(f, ",joint%d.q,joint%d.u", jid, jid);
        }
    }
    for (int k = 0; k < m->ncouplers; ++k) {
        const hx_coupler *c = &m->couplers[k];
        fprintf(f, ",coupler%d.lambda", c->id);
        for (int j = 0; j < c->njoints; ++j)
            fprintf(f, ",coupler%d.force%d", c->id, j + 1);
    }
    for (int k = 0; k < m->nforces; ++k) {
        const int id = m->forces[k].id;
        static const char *const names[6] = {"x", "y", "z", "ax", "ay", "az"};
        for (int j = 0; j < 6; ++j)
            fprintf(f, ",force%d.d%s", id, names[j]);
        static const char *const loads[6] = {"fx", "fy", "fz", "tx", "ty", "tz"};
        for (int j = 0; j < 6; ++j)
            fprintf(f, ",force%d.%s", id, loads[j]);
    }
    hx_stateeqns_csv_header(f, d);
    hx_routines_csv_header(f, d);
    hx_requests_csv_header(f, m);
    fprintf(f, ",energy,dissipated,phi,phidot");
    /* the joints' reactions after every other column (docs/harness.md) */
    for (int k = 0; k < m->njoints; ++k) {
        const char *kind = hx_joint_type_is_primitive(m->joints[k].type) ? "jprim" : "joint";
        const int id = m->joints[k].id;
        fprintf(f, ",%s%d.fx,%s%d.fy,%s%d.fz,%s%d.tx,%s%d.ty,%s%d.tz", kind, id, kind, id, kind,
                id, kind, id, kind, id, kind, id);
    }
    fprintf(f, "\n");
}

/* The row's values after the evaluation at (t, y), the joints' reactions and
 * the bodies' accelerations given. */
static int row(FILE *f, const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
               const hx_energy *energy, const hx_energy *energy0, const hx_expr_outputs *s)
{
    const hx_model *m = d->m;
    double phi, phidot;
    if (hx_constraints_residuals(d, dd, t, y, &phi, &phidot) != 0)
        return -1;
    fprintf(f, "%.10g", t);
    for (int k = 0; k < m->nbodies; ++k) {
        const hx_body_dof *dof = &d->dof[k];
        const double *u = y + d->nq + dof->u;
        if (dof->kind == HX_DOF_FREE) {
            const hx_frame *fr = &dd->frames.bodies[k];
            for (int j = 0; j < 7; ++j)
                fprintf(f, ",%.12g", y[dof->q + j]);
            fprintf(f, ",%.12g,%.12g,%.12g,%.12g,%.12g,%.12g", u[0], u[1], u[2], fr->w[0],
                    fr->w[1], fr->w[2]);
        } else if (dof->kind != HX_DOF_GROUND) {
            fprintf(f, ",%.15g,%.15g", y[dof->q], u[0]);
        }
    }
    for (int k = 0; k < m->ncouplers; ++k) {
        const hx_coupler *c = &m->couplers[k];
        const double lambda = dd->lambda[k];
        fprintf(f, ",%.15g", lambda);
        for (int j = 0; j < c->njoints; ++j)
            fprintf(f, ",%.15g", hx_constraints_coupler_force(d, dd, t, y, k, j));
    }
    for (int k = 0; k < m->nforces; ++k) {
        double disp[6], velo[6];
        hx_force_deformation(&dd->frames, k, disp, velo);
        for (int j = 0; j < 6; ++j)
            fprintf(f, ",%.12g", disp[j]);
        for (int j = 0; j < 6; ++j)
            fprintf(f, ",%.12g", dd->element_load[6 * k + j]);
    }
    hx_stateeqns_csv_row(f, d, dd, y);
    if (hx_routines_csv_row(f, d, dd, y, s) != 0)
        return -1;
    hx_message msg;
    if (hx_requests_csv_row(f, &dd->frames, d->routine_binding, s, &msg) != 0)
        return hx_dynamics_fail(dd, "%s", msg.text);
    fprintf(f, ",%.15g,%.15g,%.3g,%.3g", energy->total, hx_dissipated(energy, energy0), phi,
            phidot);
    for (int k = 0; k < 6 * m->njoints; ++k)
        fprintf(f, ",%.15g", s->reactions[k]);
    fprintf(f, "\n");
    return 0;
}

int hx_csv_row(FILE *f, const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
               const hx_energy *energy, const hx_energy *energy0)
{
    const hx_model *m = d->m;
    double *ydot = malloc(sizeof(double) * ((size_t)d->n + 6 * (size_t)m->njoints +
                                            6 * (size_t)m->nbodies + 12 * (size_t)m->nloads +
                                            12 * (size_t)m->nforces +
                                            hx_constraint_forces_size(d)));
    if (ydot == NULL || hx_dynamics_rhs(d, dd, t, y, ydot) != 0) {
        free(ydot);
        return -1;
    }
    /* at this state, before anything else evaluates on dd */
    double *reactions = ydot + d->n, *accelerations = reactions + 6 * m->njoints;
    hx_reactions_all(d, dd, ydot, reactions);
    hx_accelerations_bodies(d, dd, ydot, accelerations);
    double *loads = accelerations + 6 * m->nbodies;
    hx_message msg;
    /* the loads' and constraints' forces, for the requests and the REQSUBs' queries */
    const int need_outputs = m->nrequests > 0 || m->noutput_queries > 0;
    if (need_outputs && hx_element_outputs_loads(d, dd, loads, &msg) != 0) {
        free(ydot);
        return hx_dynamics_fail(dd, "%s", msg.text);
    }
    double *forces = loads + 12 * m->nloads, *constraints = forces + 12 * m->nforces;
    hx_element_outputs_forces(d, dd, forces);
    if (need_outputs && hx_constraint_forces_all(d, dd, t, y, ydot, constraints) != 0) {
        free(ydot);
        return -1;
    }
    const hx_expr_outputs s = {reactions, accelerations, loads, forces, constraints};
    const int status = row(f, d, dd, t, y, energy, energy0, &s);
    free(ydot);
    return status;
}
