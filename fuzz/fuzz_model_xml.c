/*
 * Fuzz target: the harness's XML model reader (expat and the resolution of
 * ids, markers, joints, couplers and forces) on arbitrary text. A model or an
 * error, never a crash.
 */
#include <stdint.h>
#include <stdio.h>

#include "model/model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    hx_message msg;
    hx_model *m = hx_model_parse((const char *)data, size, "/tmp/fuzz.xml", NULL, &msg);
    if (m != NULL)
        hx_model_free(m);
    return 0;
}
