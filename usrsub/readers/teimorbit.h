/*
 * TeimOrbit property files (.gbs, .gbi, .gfj): $ comments, [BLOCK]s,
 * (SUB_BLOCK)s, KEY = value entries and { column ... } tables of rows.
 * Block, sub-block, key and column names are upper-cased on reading (the
 * format is case-insensitive), and the misspellings seen in the vendor's
 * documentation are mended (SIFFNESS -> STIFFNESS, RUBER_ and RUBBER_BUSHING
 * -> RUBBER_DAMPING). Every entry and row keeps its line number for messages.
 */
#ifndef USRSUB_TEIMORBIT_H
#define USRSUB_TEIMORBIT_H

#include <stddef.h>

#include "usrsub/core/message.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct usrsub_teim_row {
    int line;
    int ncells;
    char **cell; /* quotes removed */
} usrsub_teim_row;

typedef struct usrsub_teim_table {
    char sub[64]; /* sub-block it belongs to ("" when none) */
    int line;
    int ncolumns;
    char **column;
    int nrows;
    usrsub_teim_row *row;
} usrsub_teim_table;

typedef struct usrsub_teim_entry {
    char sub[64];
    char key[64];
    char *value; /* as written, surrounding quotes removed */
    int line;
} usrsub_teim_entry;

typedef struct usrsub_teim_block {
    char name[96];
    int line;
    int nentries;
    usrsub_teim_entry *entry;
    int ntables;
    usrsub_teim_table *table;
} usrsub_teim_block;

typedef struct usrsub_teim_file {
    char *path;
    int nblocks;
    usrsub_teim_block *block;
} usrsub_teim_file;

/* Reads a file; on error writes "'path' line N: what" and returns -1. */
int usrsub_teim_read(const char *path, usrsub_teim_file **file, usrsub_message *msg);
/* Parses text already in memory (name is used in messages). */
int usrsub_teim_parse(const char *text, size_t length, const char *name,
                      usrsub_teim_file **file, usrsub_message *msg);
void usrsub_teim_free(usrsub_teim_file *file);

/* Look-ups by upper-case name; NULL when absent. */
const usrsub_teim_block *usrsub_teim_find_block(const usrsub_teim_file *f, const char *name);
const usrsub_teim_entry *usrsub_teim_find_entry(const usrsub_teim_block *b, const char *key);
/* The first table of a sub-block (sub NULL: the first table of the block). */
const usrsub_teim_table *usrsub_teim_find_table(const usrsub_teim_block *b, const char *sub);
/* Column index by upper-case name, or -1. */
int usrsub_teim_column(const usrsub_teim_table *t, const char *name);

/* A whole finite number (surrounding blanks allowed); 0 or -1. */
int usrsub_teim_number(const char *text, double *value);
/* Numbers separated by spaces, tabs or commas; returns how many were read, or
 * -1 when something is not a finite number or there are more than max. */
int usrsub_teim_numbers(const char *text, double *values, int max);

#ifdef __cplusplus
}
#endif

#endif
