/* Host adapter: the one file that calls the host's utilities (host.h). */
#include "host.h"

#include <math.h>
#include <string.h>

#include "usrsub/readers/units.h"

void usrsub_host_report_error(int id, const char *text)
{
    c_errmes(1, text, id, "STOP");
}

void usrsub_host_report_notice(int id, const char *text)
{
    c_usrmes(1, text, id, "INFO");
}

int usrsub_host_read_string(int string_id, char *text, int capacity)
{
    if (capacity < 2)
        return -1;
    memset(text, 0, (size_t)capacity);
    /* nchars carries the capacity in; a host that honours it never writes past. */
    int nchars = capacity - 1, istat = 0;
    c_gtstrg(string_id, text, &nchars, &istat);
    if (istat != 0)
        return -1;
    if (nchars < 0 || nchars > capacity - 1)
        nchars = capacity - 1;
    text[nchars] = '\0';
    size_t len = strlen(text);
    while (len > 0 && (text[len - 1] == ' ' || text[len - 1] == '\t'))
        text[--len] = '\0';
    return len > 0 ? 0 : -1;
}

int usrsub_host_model_units(double scales[USRSUB_UNIT_COUNT])
{
    /* The Adams-compatible layout: time, length, force, mass (docs/interface.md
     * §1). Room to spare for a host that writes more than it should. */
    double reply[4 * USRSUB_GTUNTS_COUNT];
    char names[4 * USRSUB_GTUNTS_NAMES_LENGTH];
    int exists = 0;
    for (int k = 0; k < (int)(sizeof reply / sizeof reply[0]); ++k)
        reply[k] = 1.0;
    c_gtunts(&exists, reply, names);
    scales[USRSUB_UNIT_TIME] = reply[USRSUB_GTUNTS_TIME];
    scales[USRSUB_UNIT_LENGTH] = reply[USRSUB_GTUNTS_LENGTH];
    scales[USRSUB_UNIT_FORCE] = reply[USRSUB_GTUNTS_FORCE];
    scales[USRSUB_UNIT_MASS] = reply[USRSUB_GTUNTS_MASS];
    scales[USRSUB_UNIT_ANGLE] = 1.0;
    if (exists == 0)
        return 0;
    for (int k = 0; k < USRSUB_UNIT_COUNT; ++k)
        if (!(isfinite(scales[k]) && scales[k] > 0.0))
            return -1;
    return 1;
}

int usrsub_host_query_array(const char *fnc, const int *ipar, int nsize, double *states,
                     int expected)
{
    int nstates = 0, errflg = 0;
    c_sysary(fnc, ipar, nsize, states, &nstates, &errflg);
    return (errflg == 0 && nstates == expected) ? 0 : -1;
}

int usrsub_host_query_value(const char *fnc, const int *ipar, int nsize, double *value)
{
    int errflg = 0;
    c_sysfnc(fnc, ipar, nsize, value, &errflg);
    return errflg == 0 ? 0 : -1;
}
