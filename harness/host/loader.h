/*
 * Finding and loading user-subroutine libraries the way the solver does
 * (docs/interface.md §5):
 *   usrsub_dll_name: absolute, or relative to the model file's folder, then to
 *   each folder of MS_USERDLL_DIR (';' or ':' separated); when the attribute is
 *   missing or "NULL", the library named by MS_USERSUBDLL (same search).
 * A library is opened once per resolved path and stays open until closed.
 */
#ifndef HX_HOST_LOADER_H
#define HX_HOST_LOADER_H

#include <stddef.h>

#include "base/message.h"

typedef struct hx_library {
    char *path;
    void *handle;
} hx_library;

typedef struct hx_loader {
    hx_library *libraries;
    int count, capacity;
} hx_loader;

/* Resolves a library name to an existing file's real path. */
int hx_loader_resolve(const char *dll_name, const char *model_dir, char *path, size_t size,
                      hx_message *msg);

/* Opens (once) the library at a resolved path. */
void *hx_loader_open(hx_loader *loader, const char *path, hx_message *msg);

/* The longest entry name looked up, with its terminator. */
#define HX_ENTRY_NAME_MAX 64

/* An entry of an opened library by the names a solver looks it up by
 * (docs/interface.md §5): NAME as given, then in lower case with a trailing
 * underscore (Adams' C port header on Linux, gfortran), then in lower case.
 * bound receives the name found; NULL with a message naming all three. */
void *hx_loader_entry(void *handle, const char *path, const char *name, char *bound,
                      size_t size, hx_message *msg);
/* An entry by its exact name alone (Adams' C-style names, e.g. Gfosub). */
void *hx_loader_entry_exact(void *handle, const char *path, const char *name, char *bound,
                            size_t size, hx_message *msg);

/* dlclose every library. */
void hx_loader_close_all(hx_loader *loader);

#endif
