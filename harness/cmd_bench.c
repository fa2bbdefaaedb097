/* usrsub-harness bench: cost per call of every user entry. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>

#include "call_cost.h"
#include "commands.h"
#include "session.h"

static void usage(FILE *f)
{
    fprintf(f, "usage: usrsub-harness bench MODEL.xml [--repeats N]\n"
               "\n"
               "Cost per call of every user-subroutine entry of the model, through the\n"
               "dlopen'd function pointer: median over N (default 21) timed batches of\n"
               "about 2 ms after a warm-up, with the host calls per evaluation and in the\n"
               "dependency pass.\n");
}

int hx_command_bench(int argc, char **argv)
{
    static const struct option options[] = {{"repeats", required_argument, NULL, 'r'},
                                            {"help", no_argument, NULL, 'h'},
                                            {0, 0, 0, 0}};
    int repeats = 21, opt;
    optind = 1;
    while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
        switch (opt) {
        case 'r': repeats = atoi(optarg) > 0 ? atoi(optarg) : 21; break;
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
    hx_call_cost costs[256];
    const int n = hx_measure_call_costs(&s, repeats, costs, 256);
    printf("cost per call (median of %d batches):\n", repeats);
    hx_print_call_costs(stdout, costs, n);
    const int stopped = hx_host_stop_requested();
    hx_session_close(&s);
    return stopped ? 3 : 0;
}
