/*
 * hx_model_read and hx_model_parse (model.h): the reader is chosen by the
 * text, not by the file's name. MotionSolve XML begins with '<' (after
 * blanks and a UTF-8 byte-order mark); anything else is an Adams dataset
 * (docs/interface.md §9). A file that is empty or blank goes to the XML
 * reader, whose message names it, as before datasets were read.
 */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "model/readers.h"

/* 1 when the text is a dataset: its first non-blank character is not '<'. */
static int is_dataset(const char *text, size_t length)
{
    size_t k = 0;
    if (length >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        k = 3;
    while (k < length && (text[k] == ' ' || text[k] == '\t' || text[k] == '\r' ||
                          text[k] == '\n' || text[k] == '\f' || text[k] == '\v'))
        ++k;
    return k < length && text[k] != '<';
}

/* The whole file into *text; 0, or -1 when it cannot be read (the XML reader
 * then gives its message). */
static int slurp(const char *path, char **text, size_t *length)
{
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return -1;
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return -1;
    size_t capacity = (size_t)st.st_size + 1, n = 0;
    char *buffer = malloc(capacity);
    while (buffer != NULL) {
        n += fread(buffer + n, 1, capacity - n, f);
        if (n < capacity || ferror(f))
            break;
        char *grown = realloc(buffer, 2 * capacity); /* the file grew since stat */
        if (grown == NULL) {
            free(buffer);
            buffer = NULL;
            break;
        }
        buffer = grown;
        capacity *= 2;
    }
    const int failed = buffer == NULL || ferror(f);
    fclose(f);
    if (failed) {
        free(buffer);
        return -1;
    }
    *text = buffer;
    *length = n;
    return 0;
}

hx_model *hx_model_read(const char *path, FILE *warnings, hx_message *msg)
{
    char *text = NULL;
    size_t length = 0;
    if (slurp(path, &text, &length) != 0 || !is_dataset(text, length)) {
        free(text);
        return hx_xml_read(path, NULL, 0, warnings, msg);
    }
    hx_model *m = hx_dataset_read(path, text, length, 1, warnings, msg);
    free(text);
    return m;
}

hx_model *hx_model_parse(const char *text, size_t length, const char *name, FILE *warnings,
                         hx_message *msg)
{
    if (text == NULL)
        text = "", length = 0;
    if (is_dataset(text, length))
        return hx_dataset_read(name, text, length, 0, warnings, msg);
    return hx_xml_read(name, text, length, warnings, msg);
}
