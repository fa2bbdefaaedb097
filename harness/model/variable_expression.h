/*
 * The expressions of Reference_Variable elements the harness evaluates
 * itself (docs/interface.md §7.10): one measure call such as DX(20,10,10),
 * AZ(20,10) or VX(20,10,10,10), optionally negated, or a plain number.
 */
#ifndef HX_MODEL_VARIABLE_EXPRESSION_H
#define HX_MODEL_VARIABLE_EXPRESSION_H

#include "base/message.h"
#include "model/model.h"

/* Reads text into v's function, marker ids, sign and number; 0, or -1 with
 * msg saying what the harness reads instead. */
int hx_parse_variable_expression(const char *text, hx_variable *v, hx_message *msg);

#endif
