/* usrsub-harness bench: cost per call of every user entry, and added costs. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "call_cost.h"
#include "rhs_cost.h"
#include "commands.h"
#include "session.h"

#define MAX_COMPARISONS 16

static void usage(FILE *f)
{
    fprintf(f, "usage: usrsub-harness bench MODEL.xml [--repeats N] [--compare BASE,OTHER]...\n"
               "\n"
               "Cost per call of every user-subroutine entry of the model, through the\n"
               "dlopen'd function pointer: median over N (default 21) timed batches of\n"
               "about 2 ms after a warm-up, with the host calls per evaluation and in the\n"
               "dependency pass.\n"
               "\n"
               "  --compare BASE,OTHER  the added cost of force element OTHER over BASE (ids,\n"
               "                        or vector:ID / field:ID): the median of their\n"
               "                        per-round differences\n");
}

typedef struct comparison {
    char text[64];
    int base, other; /* force indices */
} comparison;

static const hx_call_cost *cost_of(const hx_call_cost *costs, int n, int force_index)
{
    for (int k = 0; k < n; ++k)
        if (costs[k].force_index == force_index)
            return &costs[k];
    return NULL;
}

/* Resolves "BASE,OTHER" against the model. */
static int parse_comparison(const hx_model *m, comparison *c, usrsub_message *msg)
{
    char base[64];
    const char *comma = strchr(c->text, ',');
    if (comma == NULL || comma - c->text >= (long)sizeof base)
        return usrsub_fail(msg, "--compare %s: expected BASE,OTHER (two force element ids)",
                           c->text);
    memcpy(base, c->text, (size_t)(comma - c->text));
    base[comma - c->text] = '\0';
    if (hx_model_find_force(m, base, &c->base, msg) != 0 ||
        hx_model_find_force(m, comma + 1, &c->other, msg) != 0) {
        usrsub_message_prefix(msg, "--compare %s", c->text);
        return -1;
    }
    return 0;
}

int hx_command_bench(int argc, char **argv)
{
    static const struct option options[] = {{"repeats", required_argument, NULL, 'r'},
                                            {"compare", required_argument, NULL, 'c'},
                                            {"help", no_argument, NULL, 'h'},
                                            {0, 0, 0, 0}};
    comparison comparisons[MAX_COMPARISONS];
    int repeats = 21, ncompare = 0, opt;
    optind = 1;
    while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
        switch (opt) {
        case 'r': repeats = atoi(optarg) > 0 ? atoi(optarg) : 21; break;
        case 'c':
            if (ncompare == MAX_COMPARISONS) {
                fprintf(stderr, "usrsub-harness bench: at most %d --compare\n", MAX_COMPARISONS);
                return 2;
            }
            snprintf(comparisons[ncompare++].text, sizeof comparisons[0].text, "%s", optarg);
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
    usrsub_message msg;
    if (hx_session_open(&s, argv[optind], &msg) != 0) {
        fprintf(stderr, "usrsub-harness bench: %s\n", msg.text);
        return 1;
    }
    for (int k = 0; k < ncompare; ++k)
        if (parse_comparison(s.model, &comparisons[k], &msg) != 0) {
            fprintf(stderr, "usrsub-harness bench: %s\n", msg.text);
            hx_session_close(&s);
            return 2;
        }
    hx_call_cost *costs = calloc(256, sizeof *costs);
    hx_rhs_cost rc;
    int n = 0;
    if (costs == NULL || hx_measure_rhs_cost(&s, repeats, costs, 256, &n, &rc, &msg) != 0) {
        fprintf(stderr, "usrsub-harness bench: %s\n", costs ? msg.text : "out of memory");
        free(costs);
        hx_session_close(&s);
        return 1;
    }
    printf("cost per call (median of %d batches):\n", repeats);
    hx_print_call_costs(stdout, costs, n);
    printf("right-hand side: %.1f ns per evaluation: the %d user entry calls in it %.1f ns, the"
           " harness's own share %.1f ns (%.0f %% of the user entries)\n", rc.rhs_ns,
           rc.user_calls, rc.user_ns, rc.harness_ns,
           rc.user_ns > 0.0 ? 100.0 * rc.harness_ns / rc.user_ns : 0.0);
    for (int k = 0; k < ncompare; ++k) {
        const hx_call_cost *base = cost_of(costs, n, comparisons[k].base);
        const hx_call_cost *other = cost_of(costs, n, comparisons[k].other);
        if (base == NULL || other == NULL) {
            printf("added cost %s: not a user element of the model\n", comparisons[k].text);
            continue;
        }
        printf("added cost of %s %s over %s %s: %.1f ns per call (median of per-round"
               " differences)\n", other->element, other->function, base->element,
               base->function, hx_added_cost(base, other, repeats));
    }
    hx_call_costs_free(costs, n);
    free(costs);
    const int stopped = hx_host_stop_requested();
    hx_session_close(&s);
    return stopped ? 3 : 0;
}
