/* The harness's commands: usrsub-harness {check|rig|run|bench} MODEL.xml [options]. */
#ifndef HX_CMD_COMMANDS_H
#define HX_CMD_COMMANDS_H

/* Each returns the process exit status (0 success). argv[0] is the command. */
int hx_command_check(int argc, char **argv);
int hx_command_rig(int argc, char **argv);
int hx_command_run(int argc, char **argv);
int hx_command_bench(int argc, char **argv);

#endif
