/* Shared helpers of the cmocka tests (test_support.h). */
#include "test_support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifdef USRSUB_LIBRARY
/* The example models name libusrsub.so, found through MS_USERDLL_DIR: ctest
 * sets it; a test run by hand finds the library it was built with. */
__attribute__((constructor)) static void default_library_folder(void)
{
    if (getenv("MS_USERDLL_DIR") != NULL)
        return;
    char folder[4096];
    snprintf(folder, sizeof folder, "%s", USRSUB_LIBRARY);
    char *slash = strrchr(folder, '/');
    if (slash != NULL) {
        *slash = '\0';
        setenv("MS_USERDLL_DIR", folder, 1);
    }
}
#endif

void assert_close_impl(double actual, double expected, double rel_tol, double abs_tol,
                       const char *what, const char *file, int line)
{
    const double err = fabs(actual - expected);
    if (!(err <= abs_tol + rel_tol * fabs(expected))) {
        print_error("%s = %.17g, expected %.17g (error %.3g > %.3g + %.3g * |expected|)\n",
                    what, actual, expected, err, abs_tol, rel_tol);
        _fail(file, line);
    }
}

void assert_contains_impl(const char *text, const char *const *needles, const char *file,
                          int line)
{
    for (const char *const *n = needles; *n != NULL; ++n)
        if (text == NULL || strstr(text, *n) == NULL) {
            print_error("text \"%s\" does not contain \"%s\"\n", text ? text : "(null)", *n);
            _fail(file, line);
        }
}

static char temp_dir[256];

static void remove_temp_dir(void)
{
    char command[300];
    snprintf(command, sizeof command, "rm -rf '%s'", temp_dir);
    if (system(command) != 0)
        fprintf(stderr, "could not remove %s\n", temp_dir);
}

const char *test_temp_dir(void)
{
    if (temp_dir[0] == '\0') {
        snprintf(temp_dir, sizeof temp_dir, "/tmp/usrsub-test-XXXXXX");
        if (mkdtemp(temp_dir) == NULL) {
            perror("mkdtemp");
            exit(1);
        }
        atexit(remove_temp_dir);
    }
    return temp_dir;
}

const char *test_write_file(const char *name, const char *content)
{
    static char paths[64][512];
    static int next;
    char *path = paths[next++ % 64];
    snprintf(path, 512, "%s/%s", test_temp_dir(), name);
    FILE *f = fopen(path, "w");
    if (f == NULL || fputs(content, f) < 0 || fclose(f) != 0) {
        perror(path);
        exit(1);
    }
    return path;
}
