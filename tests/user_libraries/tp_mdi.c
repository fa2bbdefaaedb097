/*
 * tp_mdi.c -- test user library written as Adams-style C code ported
 * to Linux: its entries are named through tp_mdi_names.h, so the library
 * exports sfosub_ and reqsub_ only. Its line spring reads its stiffness and
 * free length from "tp_mdi_spring.txt", a relative path, on its first call:
 * the file sits in the model's folder, the solver's working folder.
 *   SFOSUB: -k (DM(I, J) - L0), USER(i, j);
 *   REQSUB: DM(i, j), k, L0, USER(i, j).
 * Expected verdict: PASS, bound as sfosub_ and reqsub_; the body oscillates
 * as tp_scalar's first one does.
 */
#include "tp_mdi_names.h"
#include "usrsub/solver_abi.h"

#include <stdio.h>

USRSUB_EXPORT void STDCALL SFOSUB(int *id, double *time, double *par, int *npar, int *dflag,
                                  int *iflag, double *value);
USRSUB_EXPORT void STDCALL REQSUB(int *id, double *time, double *par, int *npar, int *iflag,
                                  double *result);

static double stiffness = -1.0, free_length;

/* The spring's numbers, read once; 0, or -1 when the file is missing. */
static int read_spring(int id)
{
    if (stiffness >= 0.0)
        return 0;
    FILE *f = fopen("tp_mdi_spring.txt", "r");
    if (f == NULL || fscanf(f, "%lf %lf", &stiffness, &free_length) != 2) {
        if (f != NULL)
            fclose(f);
        stiffness = -1.0;
        c_errmes(1, "tp_mdi: cannot read tp_mdi_spring.txt in the working folder", id, "STOP");
        return -1;
    }
    fclose(f);
    return 0;
}

static double length(const double *par)
{
    const int ipar[2] = {(int)par[0], (int)par[1]};
    double value = 0.0;
    int err = 0;
    c_sysfnc("DM", ipar, 2, &value, &err);
    return value;
}

USRSUB_EXPORT void STDCALL SFOSUB(int *id, double *time, double *par, int *npar, int *dflag,
                                  int *iflag, double *value)
{
    (void)time, (void)dflag, (void)iflag;
    if (*npar < 2 || read_spring(*id) != 0)
        return;
    *value = -stiffness * (length(par) - free_length);
}

USRSUB_EXPORT void STDCALL REQSUB(int *id, double *time, double *par, int *npar, int *iflag,
                                  double *result)
{
    (void)time, (void)iflag;
    if (*npar < 2 || read_spring(*id) != 0)
        return;
    result[0] = length(par);
    result[1] = stiffness;
    result[2] = free_length;
}
