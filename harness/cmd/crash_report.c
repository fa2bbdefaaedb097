/* Crash reports of run, bench and rig (crash_report.h). */
#include "cmd/crash_report.h"

#include <signal.h>
#include <string.h>
#include <unistd.h>

#include "host/call.h"

static const int signals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
static const char *const signal_names[] = {"segmentation fault", "bus error",
                                           "floating-point exception", "illegal instruction",
                                           "aborted"};
#define NSIGNALS ((int)(sizeof signals / sizeof signals[0]))

/* The report is put together with these alone: a signal handler may call
 * write(2) and read memory, not snprintf, strsignal or stdio. */
typedef struct text {
    char buf[512];
    size_t n;
} text;

static void put(text *t, const char *s)
{
    for (; s != NULL && *s != '\0' && t->n < sizeof t->buf; ++s)
        t->buf[t->n++] = *s;
}

static void put_unsigned(text *t, unsigned long v)
{
    char digits[24];
    int k = 0;
    do {
        digits[k++] = (char)('0' + v % 10);
        v /= 10;
    } while (v != 0 && k < (int)sizeof digits);
    while (k > 0 && t->n < sizeof t->buf)
        t->buf[t->n++] = digits[--k];
}

static void put_int(text *t, int v)
{
    if (v < 0) {
        put(t, "-");
        put_unsigned(t, -(unsigned long)v);
    } else {
        put_unsigned(t, (unsigned long)v);
    }
}

/* A time with nine decimals (times are seconds or milliseconds: enough). */
static void put_time(text *t, double v)
{
    if (!(v == v) || v > 1e15 || v < -1e15) {
        put(t, "?");
        return;
    }
    if (v < 0) {
        put(t, "-");
        v = -v;
    }
    const unsigned long whole = (unsigned long)v;
    unsigned long fraction = (unsigned long)((v - (double)whole) * 1e9 + 0.5);
    unsigned long carry = 0;
    if (fraction >= 1000000000ul)
        fraction -= 1000000000ul, carry = 1;
    put_unsigned(t, whole + carry);
    put(t, ".");
    for (unsigned long scale = 100000000ul; scale > 0; scale /= 10)
        put_unsigned(t, fraction / scale % 10);
}

static void on_crash(int sig)
{
    const char *name = "unknown signal";
    for (int k = 0; k < NSIGNALS; ++k)
        if (signals[k] == sig)
            name = signal_names[k];
    /* the call bound when the signal came: the element in whose code it died */
    const hx_call *c = hx_host_bound();
    text t = {.n = 0};
    put(&t, "usrsub-harness: ");
    if (c != NULL) {
        put(&t, c->element);
        put(&t, " ");
        put_int(&t, c->id);
        put(&t, " crashed in ");
        put(&t, c->routine != NULL ? c->routine : "?");
        put(&t, " with signal ");
    } else {
        put(&t, "crashed with signal ");
    }
    put_int(&t, sig);
    put(&t, " (");
    put(&t, name);
    put(&t, ")");
    if (c != NULL) {
        put(&t, " at t = ");
        put_time(&t, c->frames != NULL ? c->frames->time : 0.0);
    } else {
        put(&t, " outside any user call");
    }
    put(&t, "\n");
    if (write(STDERR_FILENO, t.buf, t.n) < 0)
        t.n = 0;
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
