/*
 * usrsub-harness check: every user element in a child process of its own
 * (a crash or a hang in the user's code is reported with the element, the
 * entry, its arguments and the signal, and the other elements are still
 * checked): one evaluation at the model's initial state, then the checks of
 * tools/check/checks.h.
 */
#include <getopt.h>
#include <libgen.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "base/clock.h"
#include "base/finite.h"
#include "cmd/commands.h"
#include "cmd/options.h"
#include "host/element_call.h"
#include "session/session.h"
#include "host/state_inputs.h"
#include "frames/measures.h"
#include "tools/check/checks.h"

static void usage(FILE *f)
{
    fprintf(f, "usage: usrsub-harness check MODEL.xml [--timeout SECONDS]\n"
               "\n"
               "For every user-subroutine element, in a process of its own: its dependency pass\n"
               "(iflag = 1) and one evaluation at the initial state; analytic partials against\n"
               "finite differences (COUXX, COUXX2 at points varying each joint on its own; FIESUB's\n"
               "dfddis and dfdvel); the dependency audit of GFOSUB elements at states and times\n"
               "over the first second; the history audit (same inputs, same outputs, whatever was\n"
               "called before); every read outside the declared dependencies. An element that\n"
               "crashes, or a call that does not return within --timeout seconds (default 10),\n"
               "is reported with its entry and arguments. Exits 0 when every element passes, 1\n"
               "when one fails, 3 when one stops the run through c_errmes.\n");
}

/* One call of the element at its inputs at the model's initial state
 * (host/element_call.h): the number of outputs shown (a field's force, without
 * the partials it is not asked for). */
static int call_once(hx_session *s, hx_binding *b, double *in, double *out)
{
    hx_element_call_inputs(b, &s->frames, NULL, in);
    const int n = hx_element_call(b, &s->frames, in, 0, 0, out);
    return b->kind == HX_BIND_FIELD ? 6 : n;
}

/* One evaluation at the model's initial state: its outputs, finite or not
 * (-1: out of memory). A first call with the outputs filled with NaN finds
 * those the entry never writes: a solver zeroes them, as the harness does
 * in every other call, so they are noted, not failed. */
static int evaluate(hx_session *s, hx_binding *b, char *outputs, size_t size)
{
    const int nin = hx_element_call_input_count(b);
    double *in = calloc((size_t)(nin + hx_element_call_output_count(b)), sizeof(double));
    if (in == NULL)
        return -1;
    double *out = in + nin;
    b->output_fill = NAN;
    const int probed = call_once(s, b, in, out);
    b->output_fill = 0.0;
    /* numbered as the routine's own values (a VTOSUB's three, an SFOSUB's one) */
    char unwritten[256] = "";
    for (int k = 0, n = 0; k < probed && n < (int)sizeof unwritten - 8; ++k)
        if (isnan(out[k]))
            n += snprintf(unwritten + n, sizeof unwritten - (size_t)n, "%s%d", n ? ", " : "",
                          k + 1);
    if (unwritten[0] != '\0')
        printf("  note: %s never writes output%s %s of its call (a solver zeroes them before"
               " each call, as the harness does)\n", hx_binding_routine(b, 0),
               strchr(unwritten, ',') != NULL ? "s" : "", unwritten);
    const int nout = call_once(s, b, in, out);
    hx_format_values(outputs, size, out, nout, 6);
    const int finite = hx_all_finite(out, nout);
    free(in);
    return finite;
}

/* Everything check does to one element; the number of failures. */
static int check_element(hx_session *s, hx_binding *b)
{
    char deps[512], outputs[1024], lib[512], functions[160];
    snprintf(lib, sizeof lib, "%s", b->library);
    if (b->kind == HX_BIND_STATEEQN) {
        int n = snprintf(functions, sizeof functions, "%s", hx_binding_routine(b, 0));
        for (int k = 0; k < 4 && n > 0 && (size_t)n < sizeof functions; ++k)
            n += snprintf(functions + n, sizeof functions - (size_t)n, " %s%s",
                          hx_binding_routine(b, 1 + k),
                          b->fn.stateeqn.partial[k] != NULL ? "" : " (not exported)");
    } else {
        snprintf(functions, sizeof functions, b->kind == HX_BIND_COUPLER ? "%s %s %s" : "%s",
                 hx_binding_routine(b, 0), hx_binding_routine(b, 1), hx_binding_routine(b, 2));
    }
    printf("%s %d (%s in %s)\n  declared dependencies: %s\n", b->element, b->id, functions,
           basename(lib), hx_dependencies_text(&b->deps, deps, sizeof deps));
    if (b->setup_bytes >= 0) /* property data shared with earlier elements is theirs */
        printf("  set-up footprint: %ld bytes kept allocated by its first calls\n",
               b->setup_bytes);
    const int finite = evaluate(s, b, outputs, sizeof outputs);
    if (finite < 0) {
        printf("  %s %d: out of memory\n", b->element, b->id);
        return 1;
    }
    printf("  %s at t = 0: %s\n", b->kind == HX_BIND_STATEEQN   ? "state rates, then outputs"
                                   : b->kind == HX_BIND_MOTION ? "value, rate, acceleration"
                                                               : "outputs", outputs);
    if (hx_messages_stopped(&s->messages))
        return 1;
    if (!finite) {
        printf("  %s %d: FAIL: returned a non-finite value\n", b->element, b->id);
        return 1;
    }
    /* the history audit first: its times then lie past all the element has
     * seen and still in the model's first second */
    int failures = hx_audit_history(s, b, stdout);
    if (hx_messages_stopped(&s->messages))
        return failures + 1;
    if (b->kind == HX_BIND_COUPLER)
        failures += hx_check_coupler(s, b, stdout);
    else if (b->kind == HX_BIND_FIELD)
        failures += hx_check_field_partials(s, b, stdout);
    else if (b->kind == HX_BIND_STATEEQN)
        failures += hx_check_state_partials(s, b, stdout);
    else if (b->kind == HX_BIND_MOTION)
        failures += hx_check_motion(s, b, stdout);
    else
        failures += hx_audit_dependencies(s, b, stdout);
    failures += hx_check_queries(b, stdout);
    return failures;
}

enum outcome { PASSED, FAILED, STOPPED, CRASHED };

/* The user's call a child was in when it died or hung. */
static void report_call(const hx_binding *b, const hx_call_log *log, const char *what)
{
    char args[512] = "";
    if (log->nargs > 0) {
        char values[480];
        hx_format_values(values, sizeof values, log->args, log->nargs, 6);
        snprintf(args, sizeof args, ", %s (%s)",
                 b->kind == HX_BIND_COUPLER ? "disp" : b->kind == HX_BIND_STATEEQN ? "input"
                                                     : "disp and velo", values);
    }
    printf("  %s %d: FAIL: %s in %s (%s) called with iflag = %d, dflag = %d, time = %g%s\n",
           b->element, b->id, what, log->routine != NULL ? log->routine : b->names[0],
           b->library, log->iflag, log->dflag, log->time, args);
}

/* Runs check_element in a child and watches it. */
static enum outcome isolate(hx_session *s, hx_binding *b, hx_call_log *log, double timeout)
{
    memset((void *)log, 0, sizeof *log);
    b->log = log;
    fflush(stdout);
    fflush(stderr);
    const pid_t child = fork();
    if (child < 0) { /* no process to spare: check in this one */
        const int failures = check_element(s, b);
        b->log = NULL;
        return hx_messages_stopped(&s->messages) ? STOPPED : failures ? FAILED : PASSED;
    }
    if (child == 0) {
        /* line by line: what was printed before a crash is not lost with it */
        setvbuf(stdout, NULL, _IOLBF, 0);
        const int failures = check_element(s, b);
        fflush(stdout);
        fflush(stderr);
        _exit(hx_messages_stopped(&s->messages) ? 3 : failures ? 1 : 0);
    }
    unsigned long seen = 0;
    double since = hx_seconds();
    int status = 0;
    for (;;) {
        const pid_t done = waitpid(child, &status, WNOHANG);
        if (done == child)
            break;
        const unsigned long begun = log->begun;
        if (begun != seen || log->returned == begun) {
            seen = begun;
            since = hx_seconds();
        } else if (hx_seconds() - since > timeout) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            char what[96];
            snprintf(what, sizeof what, "did not return within %g s (a hang; killed)", timeout);
            report_call(b, log, what);
            b->log = NULL;
            return CRASHED;
        }
        const struct timespec pause = {0, 5000000};
        nanosleep(&pause, NULL);
    }
    b->log = NULL;
    if (WIFSIGNALED(status)) {
        char what[96];
        snprintf(what, sizeof what, "crashed with signal %d (%s)", WTERMSIG(status),
                 strsignal(WTERMSIG(status)));
        report_call(b, log, what);
        return CRASHED;
    }
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
    return code == 0 ? PASSED : code == 3 ? STOPPED : FAILED;
}

int hx_command_check(int argc, char **argv)
{
    static const struct option options[] = {{"timeout", required_argument, NULL, 't'},
                                            {"help", no_argument, NULL, 'h'},
                                            {0, 0, 0, 0}};
    double timeout = 10.0;
    int opt;
    optind = 1;
    while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
        switch (opt) {
        case 't':
            if (hx_option_positive("check", "timeout", optarg, &timeout) != 0)
                return 2;
            break;
        case 'h': usage(stdout); return 0;
        default: usage(stderr); return 2;
        }
    }
    if (optind != argc - 1) {
        usage(stderr);
        return 2;
    }
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, argv[optind], stderr, &msg) != 0) {
        fprintf(stderr, "usrsub-harness check: %s\n", msg.text);
        return 1;
    }
    hx_call_log *log = mmap(NULL, sizeof *log, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS,
                            -1, 0);
    if (log == MAP_FAILED) {
        fprintf(stderr, "usrsub-harness check: cannot share memory with the checking processes\n");
        hx_session_close(&s);
        return 1;
    }
    printf("derivative checks at relative tolerance %s\n", HX_DERIVATIVE_TOLERANCE_TEXT);
    int counts[4] = {0, 0, 0, 0};
    for (int k = 0; k < s.bindings.count; ++k) {
        const enum outcome o = isolate(&s, &s.bindings.items[k], log, timeout);
        counts[o]++;
        fflush(stdout);
    }
    munmap(log, sizeof *log);
    printf("check: %d element%s: %d passed, %d failed, %d crashed or hung, %d stopped the run\n",
           s.bindings.count, s.bindings.count == 1 ? "" : "s", counts[PASSED], counts[FAILED],
           counts[CRASHED], counts[STOPPED]);
    hx_session_close(&s);
    if (counts[STOPPED] > 0)
        return 3;
    return counts[FAILED] + counts[CRASHED] > 0 ? 1 : 0;
}
