/* A why-table made for one call (why.h): the explanation of a failed condition with the values
 * that broke it ("must hold 3 segment lengths (one per segment), got 2"), as the one row of a
 * table a binding raises as it raises any table's row (pcl_check). */
#ifndef PC_WHY_CALL_H
#define PC_WHY_CALL_H

#include <stddef.h>
#include "why.h"

typedef struct {
    pc_why row[2];      /* the row, then the end of the table */
    char text[240];     /* the row's text */
} pc_why_call;

/* Make w the table of one row {op, st, arg, key, the text of fmt (printf)} and return st;
 * with st PC_OK or op NULL the table is empty.  The text is a row's text as any table's: a
 * "%s" in it (written "%%s" in fmt) shows the argument's value, and it holds no other '%'. */
int pc_why_call_set(pc_why_call *w, const char *op, int st, int arg, const char *key, const char *fmt, ...);
/* Make w the table of the one row of table for op and st (empty when it has none) and return st:
 * a call explained partly by its values and partly by a fixed table. */
int pc_why_call_row(pc_why_call *w, const pc_why *table, const char *op, int st);

#endif
