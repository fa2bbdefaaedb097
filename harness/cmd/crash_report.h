/*
 * run, bench and rig call the user's code in the harness's own process: if
 * it crashes there, the harness names the element, the entry and the time of
 * the call it died in, and the signal, before it exits (128 + the signal).
 * check isolates each element in a child process instead (check.c).
 */
#ifndef HX_CMD_CRASH_REPORT_H
#define HX_CMD_CRASH_REPORT_H

void hx_crash_report_begin(void);
void hx_crash_report_end(void);

#endif
