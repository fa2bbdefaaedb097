/*
 * Fuzz target: the Adams dataset reader (the statement parse, the keyword
 * tables, the translation into the XML builders, the markers' frames, the
 * resolve passes) and the command-file reader, on arbitrary text. A model,
 * a command list or an error; never a crash or a leak.
 */
#include <stdint.h>
#include <stdio.h>

#include "model/adm/command_file.h"
#include "model/model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    hx_message msg;
    /* text beginning with '<' is XML, fuzz_model_xml's */
    if (size == 0 || data[0] != '<') {
        hx_model *m = hx_model_parse((const char *)data, size, "/tmp/fuzz.adm", NULL, &msg);
        hx_model_free(m);
    }
    hx_command_file *f = hx_command_file_parse((const char *)data, size, "/tmp/fuzz.acf", &msg);
    hx_command_file_free(f);
    return 0;
}
