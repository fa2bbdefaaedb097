/* Commands still to come (placeholders while the foundation is built). */
#include <stdio.h>

#include "commands.h"

int hx_command_rig(int argc, char **argv)
{
    (void)argc, (void)argv;
    fprintf(stderr, "usrsub-harness rig: not available in this build\n");
    return 2;
}

int hx_command_run(int argc, char **argv)
{
    (void)argc, (void)argv;
    fprintf(stderr, "usrsub-harness run: not available in this build\n");
    return 2;
}

int hx_command_bench(int argc, char **argv)
{
    (void)argc, (void)argv;
    fprintf(stderr, "usrsub-harness bench: not available in this build\n");
    return 2;
}
