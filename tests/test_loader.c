/* Library resolution as the solver does it, and the errors for a missing
 * library or function. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "host/binding.h"
#include "host/loader.h"
#include "test_support.h"

/* A folder in the temporary folder holding a copy (link) of hostprobe. */
static const char *folder_with_probe(const char *folder, const char *name)
{
    static char dir[512];
    snprintf(dir, sizeof dir, "%s/%s", test_temp_dir(), folder);
    mkdir(dir, 0755);
    char link_path[600];
    snprintf(link_path, sizeof link_path, "%s/%s", dir, name);
    unlink(link_path);
    if (symlink(HOSTPROBE_LIBRARY, link_path) != 0)
        fail_msg("symlink %s", link_path);
    return dir;
}

static int clear_environment(void **state)
{
    (void)state;
    unsetenv("MS_USERSUBDLL");
    unsetenv("MS_USERDLL_DIR");
    return 0;
}

static void absolute_path(void **state)
{
    (void)state;
    char path[PATH_MAX], real[PATH_MAX];
    hx_message msg;
    assert_int_equal(hx_loader_resolve(HOSTPROBE_LIBRARY, "/nonexistent", path, sizeof path, &msg), 0);
    assert_string_equal(path, realpath(HOSTPROBE_LIBRARY, real));
}

static void relative_to_the_model_folder(void **state)
{
    (void)state;
    const char *dir = folder_with_probe("models", "libmodelprobe.so");
    char path[PATH_MAX];
    hx_message msg;
    assert_int_equal(hx_loader_resolve("libmodelprobe.so", dir, path, sizeof path, &msg), 0);
    assert_contains(path, "hostprobe");
}

static void then_ms_userdll_dir(void **state)
{
    (void)state;
    const char *dir = folder_with_probe("dlls", "libdirprobe.so");
    char dirs[700];
    snprintf(dirs, sizeof dirs, "/nonexistent;%s", dir);
    setenv("MS_USERDLL_DIR", dirs, 1);
    char path[PATH_MAX];
    hx_message msg;
    assert_int_equal(hx_loader_resolve("libdirprobe.so", "/tmp", path, sizeof path, &msg), 0);
    assert_contains(path, "hostprobe");
}

static void ms_usersubdll_when_the_name_is_missing(void **state)
{
    (void)state;
    char path[PATH_MAX];
    hx_message msg;
    assert_int_equal(hx_loader_resolve(NULL, "/tmp", path, sizeof path, &msg), -1);
    assert_contains(msg.text, "MS_USERSUBDLL is not set");
    setenv("MS_USERSUBDLL", HOSTPROBE_LIBRARY, 1);
    assert_int_equal(hx_loader_resolve(NULL, "/tmp", path, sizeof path, &msg), 0);
    assert_contains(path, "hostprobe");
}

static void missing_library_is_named(void **state)
{
    (void)state;
    char path[PATH_MAX];
    hx_message msg;
    setenv("MS_USERDLL_DIR", "/opt/nowhere", 1);
    assert_int_equal(hx_loader_resolve("libnothere.so", "/tmp/models", path, sizeof path, &msg), -1);
    assert_contains(msg.text, "libnothere.so", "not found", "/tmp/models", "/opt/nowhere");
    assert_int_equal(hx_loader_resolve("/abs/libnothere.so", "/tmp", path, sizeof path, &msg), -1);
    assert_contains(msg.text, "/abs/libnothere.so", "does not exist");
}

static void missing_function_is_named_with_its_library(void **state)
{
    (void)state;
    /* hostprobe has GFOSUB but no FIESUB */
    char model[2048];
    snprintf(model, sizeof model,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "<Force_Field id=\"5\" i_marker_id=\"20\" j_marker_id=\"10\"\n"
             "  usrsub_param_string=\"USER(1)\" usrsub_dll_name=\"%s\"/>\n"
             "</Model></MotionSolve>\n", HOSTPROBE_LIBRARY);
    hx_message msg;
    hx_model *m = hx_model_read(test_write_file("nofiesub.xml", model), NULL, &msg);
    assert_non_null(m);
    hx_bindings b;
    hx_messages messages;
    hx_messages_init(&messages, NULL);
    assert_int_equal(hx_bind(m, &messages, &b, &msg), -1);
    assert_contains(msg.text, "Force_Field 5", "'FIESUB'", "hostprobe", "nofiesub.xml:6");
    hx_bindings_free(&b);
    hx_messages_destroy(&messages);
    hx_model_free(m);
}

static void a_library_is_opened_once(void **state)
{
    (void)state;
    hx_loader loader = {0};
    hx_message msg;
    char path[PATH_MAX];
    assert_int_equal(hx_loader_resolve(HOSTPROBE_LIBRARY, NULL, path, sizeof path, &msg), 0);
    void *a = hx_loader_open(&loader, path, &msg);
    void *b = hx_loader_open(&loader, path, &msg);
    assert_non_null(a);
    assert_ptr_equal(a, b);
    assert_int_equal(loader.count, 1);
    char bound[HX_ENTRY_NAME_MAX];
    assert_non_null(hx_loader_entry(a, path, "GFOSUB", bound, sizeof bound, &msg));
    assert_null(hx_loader_entry(a, path, "NOPE", bound, sizeof bound, &msg));
    assert_contains(msg.text, "'NOPE'", path, "looked up NOPE, nope_ and nope");
    hx_loader_close_all(&loader);
}

/* NAME, then name_ (Adams' C port header and gfortran on Linux), then name;
 * the library's lower-case names are the same functions as its upper-case ones. */
static void entries_by_the_names_linux_solvers_use(void **state)
{
    (void)state;
    hx_loader loader = {0};
    hx_message msg;
    char bound[HX_ENTRY_NAME_MAX];
    void *lib = hx_loader_open(&loader, USRSUB_LIBRARY, &msg);
    assert_non_null(lib);
    void *upper = hx_loader_entry(lib, USRSUB_LIBRARY, "GFOSUB", bound, sizeof bound, &msg);
    assert_string_equal(bound, "GFOSUB");
    void *lower = hx_loader_entry(lib, USRSUB_LIBRARY, "gfosub", bound, sizeof bound, &msg);
    assert_string_equal(bound, "gfosub_");
    assert_non_null(upper);
    assert_ptr_equal(upper, lower);
    assert_non_null(hx_loader_entry(lib, USRSUB_LIBRARY, "Abm_Bushing_Field", bound, sizeof bound,
                                    &msg));
    assert_string_equal(bound, "abm_bushing_field_");
    /* a name too long to look up is refused, not truncated */
    char longname[HX_ENTRY_NAME_MAX + 8];
    memset(longname, 'A', sizeof longname - 1);
    longname[sizeof longname - 1] = '\0';
    assert_null(hx_loader_entry(lib, USRSUB_LIBRARY, longname, bound, sizeof bound, &msg));
    assert_contains(msg.text, "longer than");
    hx_loader_close_all(&loader);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(absolute_path, clear_environment),
        cmocka_unit_test_setup(relative_to_the_model_folder, clear_environment),
        cmocka_unit_test_setup(then_ms_userdll_dir, clear_environment),
        cmocka_unit_test_setup(ms_usersubdll_when_the_name_is_missing, clear_environment),
        cmocka_unit_test_setup(missing_library_is_named, clear_environment),
        cmocka_unit_test_setup(missing_function_is_named_with_its_library, clear_environment),
        cmocka_unit_test_setup(a_library_is_opened_once, clear_environment),
        cmocka_unit_test_setup(entries_by_the_names_linux_solvers_use, clear_environment),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
