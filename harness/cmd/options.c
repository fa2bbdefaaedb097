/* Option values and output files of the commands (options.h). */
#include "cmd/options.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int hx_option_number(const char *command, const char *option, const char *text, double *out)
{
    char *end;
    errno = 0;
    const double v = strtod(text, &end);
    if (end == text || *end != '\0' || errno == ERANGE || !isfinite(v)) {
        fprintf(stderr, "usrsub-harness %s: --%s '%s' is not a number\n", command, option, text);
        return -1;
    }
    *out = v;
    return 0;
}

int hx_option_positive(const char *command, const char *option, const char *text, double *out)
{
    if (hx_option_number(command, option, text, out) != 0)
        return -1;
    if (!(*out > 0.0)) {
        fprintf(stderr, "usrsub-harness %s: --%s %s must be above zero\n", command, option, text);
        return -1;
    }
    return 0;
}

int hx_option_count(const char *command, const char *option, const char *text, long min,
                    long *out)
{
    char *end;
    errno = 0;
    const long v = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE || v < min) {
        fprintf(stderr, "usrsub-harness %s: --%s '%s' is not a whole number of at least %ld\n",
                command, option, text, min);
        return -1;
    }
    *out = v;
    return 0;
}

int hx_option_max_order(const char *command, const char *text, int *out)
{
    long order = 0;
    if (hx_option_count(command, "max-order", text, 1, &order) != 0)
        return -1;
    if (order > 5) {
        fprintf(stderr, "usrsub-harness %s: --max-order %ld: BDF's orders are 1 to 5\n", command,
                order);
        return -1;
    }
    *out = (int)order;
    return 0;
}

int hx_make_parent_folders(const char *path, hx_message *msg)
{
    char folder[4096];
    snprintf(folder, sizeof folder, "%s", path);
    char *slash = strrchr(folder, '/');
    if (slash == NULL || slash == folder)
        return 0;
    *slash = '\0';
    for (char *p = folder + 1; ; ++p) {
        const char c = *p;
        if (c != '/' && c != '\0')
            continue;
        *p = '\0';
        struct stat st;
        if (stat(folder, &st) != 0) {
            if (mkdir(folder, 0777) != 0 && errno != EEXIST)
                return hx_fail(msg, "cannot create the folder %s: %s", folder, strerror(errno));
        } else if (!S_ISDIR(st.st_mode)) {
            return hx_fail(msg, "cannot create the folder %s: a file of that name is in the way",
                           folder);
        }
        *p = c;
        if (c == '\0')
            break;
    }
    return 0;
}

FILE *hx_open_output(const char *path, hx_message *msg)
{
    if (hx_make_parent_folders(path, msg) != 0)
        return NULL;
    FILE *f = fopen(path, "w");
    if (f == NULL)
        hx_fail(msg, "cannot write %s: %s", path, strerror(errno));
    return f;
}
