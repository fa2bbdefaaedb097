/*
 * The stand-in for the solver's utility library that entry_host provides to
 * the library: built as asutility.dll on Windows, where usrsub.dll imports
 * c_sysary & co. from it, and as a shared object loaded with RTLD_GLOBAL
 * before libusrsub.so on Linux. It answers the utilities from the recorded
 * inputs the host sets, and logs what the library asked and said.
 */
#ifndef ASUTILITY_H
#define ASUTILITY_H

#if defined(_WIN32)
#define ASUTILITY_EXPORT __declspec(dllexport)
#else
#define ASUTILITY_EXPORT __attribute__((visibility("default")))
#endif

#define ASUTILITY_STRINGS 64
#define ASUTILITY_STRING_MAX 256

/* A model's units (c_gtunts) and Reference_Strings (c_gtstrg). */
typedef struct asutility_model {
    int units_exist;
    double scales[4]; /* time, length, force, mass: sizes in SI */
    int nstrings;
    int string_ids[ASUTILITY_STRINGS];
    char strings[ASUTILITY_STRINGS][ASUTILITY_STRING_MAX];
} asutility_model;

/* The motion of I relative to J, as c_sysary and c_sysfnc report it. */
typedef struct asutility_motion {
    double disp[6]; /* DX DY DZ in J, then the Euler angles PSI THETA PHI (3-1-3) */
    double vel[6];  /* VX VY VZ, WX WY WZ in J */
    double az;      /* AZ(I, J) */
    int dependency_pass; /* answer zeros, as a solver does while iflag is set */
} asutility_motion;

typedef void asutility_set_model_fn(const asutility_model *model);
typedef void asutility_set_motion_fn(const asutility_motion *motion);
/* What the library asked and said since the last call, one item a line:
 * "q FNC IPAR..." per query, "usrmes TYPE ID", "errmes ENDFLG ID"; then
 * cleared. The messages' text goes to stderr (it names local paths). */
typedef const char *asutility_take_log_fn(void);
/* c_errmes calls with a non-zero errflg so far. */
typedef int asutility_errors_fn(void);

ASUTILITY_EXPORT asutility_set_model_fn asutility_set_model;
ASUTILITY_EXPORT asutility_set_motion_fn asutility_set_motion;
ASUTILITY_EXPORT asutility_take_log_fn asutility_take_log;
ASUTILITY_EXPORT asutility_errors_fn asutility_errors;

#endif
