/*
 * The two readers of a model, private to the model layer: MotionSolve XML
 * (xml_reader.c) and Adams datasets (adm/dataset.c). hx_model_read and
 * hx_model_parse (model_read.c) choose one by the text (docs/architecture.md,
 * "Two readers, one model").
 */
#ifndef HX_MODEL_READERS_H
#define HX_MODEL_READERS_H

#include <stddef.h>
#include <stdio.h>

#include "model/model.h"

/* The XML model at path, or in text (length bytes; path then only names it)
 * when text is not NULL. */
hx_model *hx_xml_read(const char *path, const char *text, size_t length, FILE *warnings,
                      hx_message *msg);
/* The Adams dataset in text (length bytes), read from path. */
hx_model *hx_dataset_read(const char *path, const char *text, size_t length, int from_file,
                          FILE *warnings, hx_message *msg);

#endif
