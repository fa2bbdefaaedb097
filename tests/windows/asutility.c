/* The stand-in utility library (asutility.h): the six utilities the library
 * calls (usrsub/entries/host_utilities.def), answered from recorded inputs. */
#include "asutility.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "usrsub/solver_abi.h"

static asutility_model model;
static asutility_motion motion;
static char log_text[1 << 16];
static size_t log_length;
static int errors;

static void note(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void note(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    const int n = vsnprintf(log_text + log_length, sizeof log_text - log_length, fmt, ap);
    va_end(ap);
    if (n > 0)
        log_length += (size_t)n < sizeof log_text - log_length ? (size_t)n : 0;
}

static void note_query(const char *fnc, const int *ipar, int nsize)
{
    note("q %s", fnc);
    for (int k = 0; k < nsize; ++k)
        note(" %d", ipar[k]);
    note("\n");
}

void asutility_set_model(const asutility_model *m)
{
    model = *m;
}

void asutility_set_motion(const asutility_motion *m)
{
    motion = *m;
}

const char *asutility_take_log(void)
{
    static char taken[sizeof log_text];
    memcpy(taken, log_text, log_length);
    taken[log_length] = '\0';
    log_length = 0;
    return taken;
}

int asutility_errors(void)
{
    return errors;
}

/* ---- the utilities -------------------------------------------------------- */

void c_sysary(const char *fnc, const int *ipar, int nsize, double *states, int *nstates,
              int *errflg)
{
    note_query(fnc, ipar, nsize);
    const double *from;
    int n;
    if (strcmp(fnc, "DISP") == 0)
        from = motion.disp, n = 6;
    else if (strcmp(fnc, "TDISP") == 0)
        from = motion.disp, n = 3;
    else if (strcmp(fnc, "RDISP") == 0)
        from = motion.disp + 3, n = 3;
    else if (strcmp(fnc, "VEL") == 0)
        from = motion.vel, n = 6;
    else if (strcmp(fnc, "TVEL") == 0)
        from = motion.vel, n = 3;
    else if (strcmp(fnc, "RVEL") == 0)
        from = motion.vel + 3, n = 3;
    else {
        *nstates = 0;
        *errflg = 1;
        return;
    }
    for (int k = 0; k < n; ++k)
        states[k] = motion.dependency_pass ? 0.0 : from[k];
    *nstates = n;
    *errflg = 0;
}

void c_sysfnc(const char *fnc, const int *ipar, int nsize, double *value, int *errflg)
{
    note_query(fnc, ipar, nsize);
    *value = 0.0;
    *errflg = strcmp(fnc, "AZ") != 0;
    if (!*errflg && !motion.dependency_pass)
        *value = motion.az;
}

void c_errmes(int errflg, const char *msg, int id, const char *endflg)
{
    if (!errflg)
        return;
    ++errors;
    note("errmes %s %d\n", endflg, id);
    fprintf(stderr, "c_errmes %d %s: %s\n", id, endflg, msg);
}

void c_usrmes(int msgflg, const char *msg, int id, const char *msgtyp)
{
    if (!msgflg)
        return;
    note("usrmes %s %d\n", msgtyp, id);
    fprintf(stderr, "c_usrmes %d %s: %s\n", id, msgtyp, msg);
}

void c_gtstrg(int id, char *string, int *nchars, int *istat)
{
    for (int k = 0; k < model.nstrings; ++k)
        if (model.string_ids[k] == id) {
            const int len = (int)strlen(model.strings[k]);
            const int n = len < *nchars ? len : *nchars;
            memcpy(string, model.strings[k], (size_t)n);
            *nchars = n;
            *istat = 0;
            return;
        }
    *nchars = 0;
    *istat = -1;
}

void c_gtunts(int *exists, double *scales, char *units)
{
    *exists = model.units_exist;
    if (!model.units_exist)
        return;
    memcpy(scales, model.scales, sizeof model.scales);
    memset(units, ' ', 12); /* four names; the library reads none */
}
