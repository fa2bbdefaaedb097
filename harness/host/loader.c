/* Library resolution and loading (loader.h). */
#include "host/loader.h"

#include <ctype.h>
#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int usable(const char *path, char *real, size_t size)
{
    char resolved[PATH_MAX];
    if (access(path, R_OK) != 0 || realpath(path, resolved) == NULL)
        return 0;
    snprintf(real, size, "%s", resolved);
    return 1;
}

int hx_loader_resolve(const char *dll_name, const char *model_dir, char *path, size_t size,
                      hx_message *msg)
{
    const char *name = dll_name;
    const char *source = "usrsub_dll_name";
    if (name == NULL || *name == '\0') {
        name = getenv("MS_USERSUBDLL");
        source = "MS_USERSUBDLL";
        if (name == NULL || *name == '\0')
            return hx_fail(msg, "no usrsub_dll_name (or \"NULL\") and MS_USERSUBDLL is not"
                               " set: no user-subroutine library to load");
    }
    if (name[0] == '/') {
        if (usable(name, path, size))
            return 0;
        return hx_fail(msg, "library '%s' (%s) does not exist or cannot be read", name,
                           source);
    }
    char candidate[PATH_MAX];
    char looked[1024];
    int n = snprintf(looked, sizeof looked, "%s", model_dir != NULL ? model_dir : ".");
    snprintf(candidate, sizeof candidate, "%s/%s", model_dir != NULL ? model_dir : ".", name);
    if (usable(candidate, path, size))
        return 0;
    const char *dirs = getenv("MS_USERDLL_DIR");
    if (dirs == NULL || *dirs == '\0')
        return hx_fail(msg, "library '%s' (%s) not found; looked in the model's folder (%s),"
                           " and MS_USERDLL_DIR is not set (set it to the library's folder)",
                       name, source, looked);
    char *copy = strdup(dirs);
    char *save = NULL;
    for (char *dir = copy ? strtok_r(copy, ";:", &save) : NULL; dir != NULL;
         dir = strtok_r(NULL, ";:", &save)) {
        if (n > 0 && (size_t)n < sizeof looked)
            n += snprintf(looked + n, sizeof looked - (size_t)n, ", %s", dir);
        snprintf(candidate, sizeof candidate, "%s/%s", dir, name);
        if (usable(candidate, path, size)) {
            free(copy);
            return 0;
        }
    }
    free(copy);
    return hx_fail(msg, "library '%s' (%s) not found; looked in the model's folder and"
                       " MS_USERDLL_DIR: %s", name, source, looked);
}

void *hx_loader_open(hx_loader *loader, const char *path, hx_message *msg)
{
    for (int k = 0; k < loader->count; ++k)
        if (strcmp(loader->libraries[k].path, path) == 0)
            return loader->libraries[k].handle;
    void *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (handle == NULL) {
        hx_fail(msg, "cannot load library '%s': %s", path, dlerror());
        return NULL;
    }
    if (loader->count == loader->capacity) {
        const int grown = loader->capacity ? 2 * loader->capacity : 4;
        hx_library *p = realloc(loader->libraries, sizeof *p * (size_t)grown);
        if (p == NULL) {
            dlclose(handle);
            hx_fail(msg, "out of memory");
            return NULL;
        }
        loader->libraries = p;
        loader->capacity = grown;
    }
    loader->libraries[loader->count].path = strdup(path);
    loader->libraries[loader->count].handle = handle;
    loader->count++;
    return handle;
}

void *hx_loader_entry(void *handle, const char *path, const char *name, char *bound,
                      size_t size, hx_message *msg)
{
    char forms[3][HX_ENTRY_NAME_MAX];
    const size_t n = strlen(name);
    if (n + 2 > sizeof forms[0]) {
        hx_fail(msg, "entry name '%.40s...' is longer than %d characters", name,
                HX_ENTRY_NAME_MAX - 2);
        return NULL;
    }
    for (size_t k = 0; k <= n; ++k) { /* the terminators too */
        forms[0][k] = name[k];
        forms[1][k] = forms[2][k] = (char)tolower((unsigned char)name[k]);
    }
    forms[1][n] = '_';
    forms[1][n + 1] = '\0';
    for (int k = 0; k < 3; ++k) {
        dlerror();
        void *symbol = dlsym(handle, forms[k]);
        if (symbol != NULL) {
            snprintf(bound, size, "%s", forms[k]);
            return symbol;
        }
    }
    hx_fail(msg, "function '%s' not found in library '%s' (looked up %s, %s and %s)", name, path,
            forms[0], forms[1], forms[2]);
    return NULL;
}

void *hx_loader_entry_exact(void *handle, const char *path, const char *name, char *bound,
                            size_t size, hx_message *msg)
{
    dlerror();
    void *symbol = dlsym(handle, name);
    if (symbol == NULL) {
        hx_fail(msg, "function '%s' not found in library '%s'", name, path);
        return NULL;
    }
    snprintf(bound, size, "%s", name);
    return symbol;
}

void hx_loader_close_all(hx_loader *loader)
{
    for (int k = 0; k < loader->count; ++k) {
        dlclose(loader->libraries[k].handle);
        free(loader->libraries[k].path);
    }
    free(loader->libraries);
    loader->libraries = NULL;
    loader->count = loader->capacity = 0;
}
