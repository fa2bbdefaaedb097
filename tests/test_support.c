/* Shared helpers of the cmocka tests (test_support.h). */
#include "test_support.h"

#include <fcntl.h>
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

const char *test_temp_path(const char *name)
{
    static char paths[8][512];
    static int next;
    char *path = paths[next++ % 8];
    snprintf(path, 512, "%s/%s", test_temp_dir(), name);
    return path;
}

static void read_back(const char *path, char *text, size_t size)
{
    FILE *f = fopen(path, "r");
    size_t n = f != NULL ? fread(text, 1, size - 1, f) : 0;
    text[n] = '\0';
    if (f != NULL)
        fclose(f);
}

void test_capture(test_command_fn *command, const char *const *args, test_captured *c)
{
    char out_path[512], err_path[512];
    snprintf(out_path, sizeof out_path, "%s/captured_stdout.txt", test_temp_dir());
    snprintf(err_path, sizeof err_path, "%s/captured_stderr.txt", test_temp_dir());
    char *argv[32];
    int argc = 0;
    for (; args[argc] != NULL && argc < 31; ++argc)
        argv[argc] = (char *)args[argc];
    argv[argc] = NULL;
    fflush(stdout);
    fflush(stderr);
    const int out_fd = open(out_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = open(err_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int saved_out = dup(STDOUT_FILENO), saved_err = dup(STDERR_FILENO);
    assert_true(out_fd >= 0 && err_fd >= 0 && saved_out >= 0 && saved_err >= 0);
    dup2(out_fd, STDOUT_FILENO);
    dup2(err_fd, STDERR_FILENO);
    close(out_fd);
    close(err_fd);
    c->status = command(argc, argv);
    fflush(stdout);
    fflush(stderr);
    dup2(saved_out, STDOUT_FILENO);
    dup2(saved_err, STDERR_FILENO);
    close(saved_out);
    close(saved_err);
    read_back(out_path, c->out, sizeof c->out);
    read_back(err_path, c->err, sizeof c->err);
}
