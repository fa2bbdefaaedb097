/* usrsub-harness: load, check, rig, run and benchmark user subroutines. */
#include <stdio.h>
#include <string.h>

#include "cmd/commands.h"
#include "cmd/exact_heap.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: usrsub-harness COMMAND MODEL.xml [options]\n"
            "\n"
            "Loads a MotionSolve XML model, loads its user-subroutine libraries the way the\n"
            "solver does, and answers their utility calls.\n"
            "\n"
            "commands:\n"
            "  check   dependency pass and one evaluation of every user element; analytic\n"
            "          partials against finite differences; dependency audit\n"
            "  rig     drive one force element through a deformation or force history\n"
            "  run     integrate the model's dynamics\n"
            "  bench   cost per call, and run time against error\n"
            "\n"
            "usrsub-harness COMMAND --help shows the options of a command.\n");
}

int main(int argc, char **argv)
{
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    static const struct {
        const char *name;
        int (*run)(int, char **);
    } commands[] = {{"check", hx_command_check},
                    {"rig", hx_command_rig},
                    {"run", hx_command_run},
                    {"bench", hx_command_bench}};
    if (strcmp(argv[1], "check") == 0) /* its set-up footprints, byte-exact */
        hx_exact_heap_counts(argv);
    for (size_t k = 0; k < sizeof commands / sizeof commands[0]; ++k)
        if (strcmp(argv[1], commands[k].name) == 0)
            return commands[k].run(argc - 1, argv + 1);
    fprintf(stderr, "usrsub-harness: unknown command '%s'\n\n", argv[1]);
    usage(stderr);
    return 2;
}
