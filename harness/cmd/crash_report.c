/* Crash reports of run, bench and rig (crash_report.h). */
#include "cmd/crash_report.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "host/call.h"

static const int signals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
#define NSIGNALS ((int)(sizeof signals / sizeof signals[0]))

static void on_crash(int sig)
{
    /* the call bound when the signal came: the element in whose code it died */
    const hx_call *c = hx_host_bound();
    char text[512];
    int n;
    if (c != NULL)
        n = snprintf(text, sizeof text, "usrsub-harness: %s %d crashed in %s with signal %d"
                     " (%s) at t = %g\n", c->element, c->id,
                     c->routine != NULL ? c->routine : "?", sig, strsignal(sig),
                     c->state != NULL ? c->state->time : 0.0);
    else
        n = snprintf(text, sizeof text, "usrsub-harness: crashed with signal %d (%s) outside any"
                     " user call\n", sig, strsignal(sig));
    fflush(stdout);
    if (n > 0 && write(STDERR_FILENO, text, (size_t)n) < 0)
        n = 0;
    _exit(128 + sig);
}

void hx_crash_report_begin(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_crash;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    for (int k = 0; k < NSIGNALS; ++k)
        sigaction(signals[k], &sa, NULL);
}

void hx_crash_report_end(void)
{
    for (int k = 0; k < NSIGNALS; ++k)
        signal(signals[k], SIG_DFL);
}
