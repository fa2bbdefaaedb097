/* Commands still to come (placeholders while the foundation is built). */
#include <stdio.h>

#include "commands.h"

int hx_command_rig(int argc, char **argv)
{
    (void)argc, (void)argv;
    fprintf(stderr, "usrsub-harness rig: not available in this build\n");
    return 2;
}

