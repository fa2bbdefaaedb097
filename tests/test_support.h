/* Shared helpers of the cmocka tests. */
#ifndef TEST_SUPPORT_H
#define TEST_SUPPORT_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

/* |actual - expected| <= abs_tol + rel_tol * |expected|, with a message. */
void assert_close_impl(double actual, double expected, double rel_tol, double abs_tol,
                       const char *what, const char *file, int line);
#define assert_close(actual, expected, rel_tol, abs_tol)                                  \
    assert_close_impl((actual), (expected), (rel_tol), (abs_tol), #actual, __FILE__, __LINE__)

/* Asserts that text contains every one of the NULL-terminated needles. */
void assert_contains_impl(const char *text, const char *const *needles, const char *file,
                          int line);
#define assert_contains(text, ...)                                                        \
    assert_contains_impl((text), (const char *const[]){__VA_ARGS__, NULL}, __FILE__, __LINE__)

/* A fresh temporary folder (removed at exit) and files in it. */
const char *test_temp_dir(void);
/* Writes content to NAME in the temporary folder; returns the full path. */
const char *test_write_file(const char *name, const char *content);
/* NAME in the temporary folder (the last 8 kept). */
const char *test_temp_path(const char *name);

/* A command run in-process (argv[0] first, NULL-terminated), its status and
 * what it wrote to stdout and stderr (through files, dup2), read back. */
typedef int test_command_fn(int argc, char **argv);
typedef struct test_captured {
    int status;
    char out[16384], err[16384];
} test_captured;
void test_capture(test_command_fn *command, const char *const *args, test_captured *c);

#endif
