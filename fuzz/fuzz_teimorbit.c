/*
 * Fuzz target: the TeimOrbit parser and the three property-file readers
 * (.gbs bushing, .gbi mount limits, .gfj flexible joint) on arbitrary bytes.
 * They must return a model or an error, never crash, leak or hang.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "usrsub/readers/bushing_reader.h"
#include "usrsub/readers/flex_joint_reader.h"
#include "usrsub/readers/mount_limits_reader.h"
#include "usrsub/readers/teimorbit.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char path[64];

static void remove_scratch(void)
{
    unlink(path);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    usrsub_message msg;
    usrsub_read_report report = {0};
    usrsub_teim_file *f;
    if (usrsub_teim_parse((const char *)data, size, "fuzz", &f, &msg) == 0)
        usrsub_teim_free(f);
    /* the readers take a path: the same bytes through a file */
    if (path[0] == '\0') {
        snprintf(path, sizeof path, "/tmp/usrsub-fuzz-%d.txt", (int)getpid());
        atexit(remove_scratch);
    }
    FILE *out = fopen(path, "wb");
    if (out == NULL)
        return 0;
    fwrite(data, 1, size, out);
    fclose(out);
    static const double mm_n_kg_s_rad[5] = {1e-3, 1.0, 1.0, 1.0, 1.0};
    usrsub_bushing *b;
    if (usrsub_bushing_read(path, mm_n_kg_s_rad, &b, &report, &msg) == 0)
        usrsub_bushing_free(b);
    usrsub_mount_limits *l;
    if (usrsub_mount_limits_read(path, NULL, &l, &report, &msg) == 0)
        usrsub_mount_limits_free(l);
    usrsub_flex_joint *j;
    if (usrsub_flex_joint_read(path, mm_n_kg_s_rad, &j, &report, &msg) == 0)
        usrsub_flex_joint_free(j);
    return 0;
}
