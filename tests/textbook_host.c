/* A textbook host for the tests (textbook_host.h). */
#include "textbook_host.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "usrsub/solver_abi.h"

static textbook_host *host; /* the one the utilities answer from */

void textbook_host_use(textbook_host *h)
{
    host = h;
}

void textbook_euler313(const textbook_host *h, const double R[9], double e[3])
{
    const double st = hypot(R[2], R[5]);
    e[1] = atan2(st, R[8]);
    if (h->guard && st < 1e-14) {
        e[0] = atan2(R[3], R[0]);
        e[2] = 0.0;
        return;
    }
    e[0] = atan2(R[2], -R[5]);
    e[2] = atan2(R[6], R[7]);
}

/* R_J^T R_I, and R_J^T (p_I - p_J), with the rounding a host has. */
static void relative(double R[9], double d[3])
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            R[3 * i + j] = host->RJ[i] * host->RI[j] + host->RJ[3 + i] * host->RI[3 + j] +
                           host->RJ[6 + i] * host->RI[6 + j];
        d[i] = host->RJ[i] * (host->pI[0] - host->pJ[0]) + host->RJ[3 + i] * (host->pI[1] - host->pJ[1]) +
               host->RJ[6 + i] * (host->pI[2] - host->pJ[2]);
    }
}

static void relative_rates(double v[6])
{
    /* bodies do not translate here; the angular velocity of I relative to J, in J */
    double dw[3];
    for (int k = 0; k < 3; ++k)
        dw[k] = host->wI[k] - host->wJ[k];
    for (int i = 0; i < 3; ++i) {
        v[i] = 0.0;
        v[3 + i] = host->RJ[i] * dw[0] + host->RJ[3 + i] * dw[1] + host->RJ[6 + i] * dw[2];
    }
}

void c_sysary(const char *fnc, const int *ipar, int nsize, double *states, int *nstates,
              int *errflg)
{
    (void)ipar, (void)nsize;
    double R[9], d[3], v[6];
    relative(R, d);
    relative_rates(v);
    *errflg = 0;
    if (strcmp(fnc, "DISP") == 0) {
        memcpy(states, d, sizeof d);
        textbook_euler313(host, R, states + 3);
        *nstates = 6;
    } else if (strcmp(fnc, "RDISP") == 0) {
        textbook_euler313(host, R, states);
        *nstates = 3;
    } else if (strcmp(fnc, "TDISP") == 0) {
        memcpy(states, d, sizeof d);
        *nstates = 3;
    } else if (strcmp(fnc, "VEL") == 0) {
        memcpy(states, v, sizeof v);
        *nstates = 6;
    } else if (strcmp(fnc, "RVEL") == 0 || strcmp(fnc, "TVEL") == 0) {
        memcpy(states, fnc[0] == 'R' ? v + 3 : v, 3 * sizeof(double));
        *nstates = 3;
    } else {
        *nstates = 0;
        *errflg = 1;
    }
}

void c_sysfnc(const char *fnc, const int *ipar, int nsize, double *value, int *errflg)
{
    (void)ipar, (void)nsize;
    double R[9], d[3];
    relative(R, d);
    *errflg = 0;
    if (strcmp(fnc, "AZ") == 0)
        *value = atan2(R[3], R[0]);
    else if (strcmp(fnc, "AX") == 0)
        *value = atan2(R[7], R[4]);
    else if (strcmp(fnc, "AY") == 0)
        *value = atan2(R[2], R[8]);
    else if (fnc[0] == 'D' && fnc[1] >= 'X' && fnc[1] <= 'Z' && fnc[2] == '\0')
        *value = d[fnc[1] - 'X'];
    else
        *errflg = 1, *value = 0.0;
}

void c_errmes(int errflg, const char *msg, int id, const char *endflg)
{
    (void)id, (void)endflg;
    if (!errflg)
        return;
    host->errors++;
    snprintf(host->last_error, sizeof host->last_error, "%s", msg);
}

void c_usrmes(int msgflg, const char *msg, int id, const char *msgtyp)
{
    (void)msgflg, (void)msg, (void)id, (void)msgtyp;
}

void c_gtstrg(int id, char *string, int *nchars, int *istat)
{
    if (id < 1 || id > 8 || host->strings[id - 1] == NULL) {
        *istat = -1;
        return;
    }
    const int len = (int)strlen(host->strings[id - 1]);
    const int capacity = *nchars;
    const int n = len < capacity ? len : capacity;
    memcpy(string, host->strings[id - 1], (size_t)n);
    if (n < capacity)
        string[n] = '\0';
    *nchars = n;
    *istat = 0;
}

void c_gtunts(int *exists, double *scales, char *units)
{
    /* the Adams-compatible layout: time, length, force, mass (s, mm, N, kg) */
    *exists = 1;
    const double s_mm_n_kg[4] = {1.0, 1e-3, 1.0, 1.0};
    memcpy(scales, s_mm_n_kg, sizeof s_mm_n_kg);
    memcpy(units, "S  MM N  KG ", 12);
}
