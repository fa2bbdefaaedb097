/*
 * The numbers written between an element's tags (Reference_Array's IC data,
 * Reference_Spline's points): blanks, line breaks or commas between them.
 */
#ifndef HX_MODEL_NUMBER_LIST_H
#define HX_MODEL_NUMBER_LIST_H

/* The numbers of text into a new array (*out, to be freed); their count, or
 * -1 (out of memory), or -2 - k when the k-th token (from 0) is not a finite
 * number. */
int hx_read_numbers(const char *text, double **out);

#endif
