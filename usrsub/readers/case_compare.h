/*
 * Case-insensitive comparison of the readers' keywords and unit names:
 * strcasecmp (POSIX, <strings.h>), or _stricmp on Windows, where the C
 * runtime has it and no <strings.h> (mingw-w64's strcasecmp is the same call).
 */
#ifndef USRSUB_CASE_COMPARE_H
#define USRSUB_CASE_COMPARE_H

#ifdef _WIN32
#include <string.h>
#define usrsub_strcasecmp _stricmp
#else
#include <strings.h>
#define usrsub_strcasecmp strcasecmp
#endif

#endif
