/*
 * tp_records.c -- test user library in Adams' C-style form: entries
 * named Gfosub, Vfosub, Fiesub, Sfosub, Cousub, Couxx, Couxx2, Motsub, Difsub, Varsub,
 * Reqsub (the default names in
 * mixed case), each given a constant record of its element, then the time
 * and flags by value. The records are laid out here from Adams' published
 * description: the id, the USER list's length and the list, then the
 * element's ids (docs/interface.md §5.3). Each routine checks its record
 * against what the model says and returns NaN when a field is wrong.
 *   Gfosub: a spring from I to the point (x0, 0, 0) of J, USER(k, x0, i, j);
 *   Vfosub (a Force_Vector_OneBody, whose JFLOAT is 0): the same spring
 *       from I to the point (x0, 0, 0) of RM, USER(k, x0);
 *   Fiesub (a Force_Field): -k (x - x0) along J's x from the deformation it
 *       is handed, with -k its one partial, USER(k, x0);
 *   Sfosub: -k (DM(I, J) - L0) along the line, USER(k, L0);
 *   Cousub, Couxx, Couxx2: the coupler a1 q1 + a2 q2 = 0, its gradient and
 *       its (zero) second derivatives, USER(a1, a2);
 *   Motsub: a sin(w t) and its derivatives, USER(a, w);
 *   Difsub: (AZ(i, j) - DIF(self)) / tau, USER(i, j, tau);
 *   Varsub: VX(i, j), USER(i, j);
 *   Reqsub: DIF(d), AZ(i, j), DX(k, l), USER(d, i, j, k, l).
 * Expected verdict: PASS; and the run follows tp_records.xml's closed forms.
 */
#include "usrsub/solver_abi.h"

#include <math.h>
#include <string.h>

struct sGforce { int ID; int NPAR; const double *PAR; int I; int RM; int JFLOAT; };
struct sVforce { int ID; int NPAR; const double *PAR; int I; int JFLOAT; int RM; };
struct sField { int ID; int NPAR; const double *PAR; int I; int J; };
struct sCoupler { int ID; int NPAR; const double *PAR; int NJOINT; int JOINTS[3]; char TYPE[3]; };
struct sSforce { int ID; int NPAR; const double *PAR; int I; int J; int ACTION_ONLY; const char *Type; };
struct sMotion {
    int ID; int NPAR; const double *PAR; int JOINT; const char *Type; int I; int J;
    char Which[2]; const char *DVA;
};
struct sDiff { int ID; int NPAR; const double *PAR; int STATIC_HOLD; int IMPLICIT; double IC_R1; double IC_R2; };
struct sVariable { int ID; int NPAR; const double *PAR; double IC; };
struct sRequest { int ID; int NPAR; const double *PAR; const char *COMMENT; const char *TITLE[8]; };

USRSUB_EXPORT void Gfosub(const struct sGforce *g, double time, int dflag, int iflag, double *result);
USRSUB_EXPORT void Vfosub(const struct sVforce *v, double time, int dflag, int iflag, double *result);
USRSUB_EXPORT void Fiesub(const struct sField *f, double time, double *disp, double *velo,
                          int dflag, int iflag, double *field, double *dfddis, double *dfdvel);
USRSUB_EXPORT void Sfosub(const struct sSforce *s, double time, int dflag, int iflag, double *result);
USRSUB_EXPORT void Cousub(const struct sCoupler *c, double time, double *disp, int iflag, double *out);
USRSUB_EXPORT void Couxx(const struct sCoupler *c, double time, double *disp, int iflag, double *out);
USRSUB_EXPORT void Couxx2(const struct sCoupler *c, double time, double *disp, int iflag, double *out);
USRSUB_EXPORT void Motsub(const struct sMotion *m, double time, int iord, int iflag, double *result);
USRSUB_EXPORT void Difsub(const struct sDiff *d, double time, int dflag, int iflag, double *result);
USRSUB_EXPORT void Varsub(const struct sVariable *v, double time, int dflag, int iflag, double *result);
USRSUB_EXPORT void Reqsub(const struct sRequest *r, double time, int iflag, double *result);

static double measure(const char *name, int i, int j)
{
    const int ipar[2] = {i, j};
    double value = 0.0;
    int err = 0;
    c_sysfnc(name, ipar, 2, &value, &err);
    return value;
}

USRSUB_EXPORT void Gfosub(const struct sGforce *g, double time, int dflag, int iflag, double *result)
{
    (void)time, (void)dflag, (void)iflag;
    if (g->ID != 1 || g->NPAR != 4 || g->I != (int)g->PAR[2] || g->JFLOAT != (int)g->PAR[3] ||
        g->RM != 12) {
        result[0] = NAN;
        return;
    }
    const double k = g->PAR[0];
    result[0] = -k * (measure("DX", g->I, g->JFLOAT) - g->PAR[1]);
    result[1] = -k * measure("DY", g->I, g->JFLOAT);
    result[2] = -k * measure("DZ", g->I, g->JFLOAT);
    result[3] = result[4] = result[5] = 0.0;
}

USRSUB_EXPORT void Vfosub(const struct sVforce *v, double time, int dflag, int iflag, double *result)
{
    (void)time, (void)dflag, (void)iflag;
    if (v->ID != 11 || v->NPAR != 2 || v->I != 50 || v->JFLOAT != 0 || v->RM != 12) {
        result[0] = NAN;
        return;
    }
    result[0] = -v->PAR[0] * (measure("DX", v->I, v->RM) - v->PAR[1]);
    result[1] = result[2] = 0.0;
}

USRSUB_EXPORT void Fiesub(const struct sField *f, double time, double *disp, double *velo,
                          int dflag, int iflag, double *field, double *dfddis, double *dfdvel)
{
    (void)time, (void)velo, (void)iflag;
    for (int k = 0; k < 6; ++k)
        field[k] = 0.0;
    if (f->ID != 12 || f->NPAR != 2 || f->I != 60 || f->J != 16) {
        field[0] = NAN;
        return;
    }
    field[0] = -f->PAR[0] * (disp[0] - f->PAR[1]);
    if (dflag) {
        for (int k = 0; k < 36; ++k)
            dfddis[k] = dfdvel[k] = 0.0;
        dfddis[0] = -f->PAR[0];
    }
}

USRSUB_EXPORT void Sfosub(const struct sSforce *s, double time, int dflag, int iflag, double *result)
{
    (void)time, (void)dflag, (void)iflag;
    if (s->ID != 2 || s->NPAR != 2 || s->I != 40 || s->J != 14 || s->ACTION_ONLY != 0 ||
        strcmp(s->Type, "TRANSLATION") != 0) {
        *result = NAN;
        return;
    }
    *result = -s->PAR[0] * (measure("DM", s->I, s->J) - s->PAR[1]);
}

/* Whether the coupler's record is the model's: Constraint_Coupler 1 on the
 * revolute joints 7 and 8. */
static int coupler_record_ok(const struct sCoupler *c)
{
    return c->ID == 1 && c->NPAR == 2 && c->NJOINT == 2 && c->JOINTS[0] == 7 &&
           c->JOINTS[1] == 8 && c->TYPE[0] == 'R' && c->TYPE[1] == 'R';
}

USRSUB_EXPORT void Cousub(const struct sCoupler *c, double time, double *disp, int iflag, double *out)
{
    (void)time, (void)iflag;
    out[0] = coupler_record_ok(c) ? c->PAR[0] * disp[0] + c->PAR[1] * disp[1] : NAN;
}

USRSUB_EXPORT void Couxx(const struct sCoupler *c, double time, double *disp, int iflag, double *out)
{
    (void)time, (void)disp, (void)iflag;
    const int ok = coupler_record_ok(c);
    for (int k = 0; k < c->NJOINT; ++k)
        out[k] = ok ? c->PAR[k] : NAN;
}

USRSUB_EXPORT void Couxx2(const struct sCoupler *c, double time, double *disp, int iflag, double *out)
{
    (void)time, (void)disp, (void)iflag;
    const int ok = coupler_record_ok(c);
    for (int k = 0; k < c->NJOINT * c->NJOINT; ++k)
        out[k] = ok ? 0.0 : NAN;
}

USRSUB_EXPORT void Motsub(const struct sMotion *m, double time, int iord, int iflag, double *result)
{
    (void)iflag;
    if (m->ID != 6 || m->JOINT != 6 || m->I != 30 || m->J != 12 ||
        strcmp(m->Type, "ROTATION") != 0 || strcmp(m->DVA, "DISP") != 0) {
        *result = NAN;
        return;
    }
    const double a = m->PAR[0], w = m->PAR[1];
    *result = iord == 0 ? a * sin(w * time) : iord == 1 ? a * w * cos(w * time)
                                                       : -a * w * w * sin(w * time);
}

USRSUB_EXPORT void Difsub(const struct sDiff *d, double time, int dflag, int iflag, double *result)
{
    (void)time, (void)dflag, (void)iflag;
    if (d->ID != 7 || d->NPAR != 3 || d->IMPLICIT != 0 || d->IC_R1 != 0.0 ||
        d->IC_R2 != 3.0) {
        *result = NAN;
        return;
    }
    int id = d->ID, err = 0;
    double z = 0.0;
    c_sysfnc("DIF", &id, 1, &z, &err);
    *result = (measure("AZ", (int)d->PAR[0], (int)d->PAR[1]) - z) / d->PAR[2];
}

USRSUB_EXPORT void Varsub(const struct sVariable *v, double time, int dflag, int iflag, double *result)
{
    (void)time, (void)dflag, (void)iflag;
    if (v->ID != 9 || v->NPAR != 2 || v->IC != 0.5) {
        *result = NAN;
        return;
    }
    *result = measure("VX", (int)v->PAR[0], (int)v->PAR[1]);
}

USRSUB_EXPORT void Reqsub(const struct sRequest *r, double time, int iflag, double *result)
{
    (void)time, (void)iflag;
    if (r->ID != 8 || r->NPAR != 5 || r->COMMENT == NULL || r->TITLE[7] == NULL) {
        result[0] = NAN;
        return;
    }
    int id = (int)r->PAR[0], err = 0;
    c_sysfnc("DIF", &id, 1, &result[0], &err);
    result[1] = measure("AZ", (int)r->PAR[1], (int)r->PAR[2]);
    result[2] = measure("DX", (int)r->PAR[3], (int)r->PAR[4]);
    for (int k = 3; k < 8; ++k)
        result[k] = 0.0;
}
