/* What failed, by status: a table of explanations of an API's core statuses, one row per
 * operation and status, naming the condition that failed and the argument it concerns.  The
 * bindings raise the row's text (pcl_core.h), so a body only calls the core and pushes. */
#ifndef PC_WHY_H
#define PC_WHY_H

#include "status.h"

typedef struct {
    const char *op;    /* the operation as the API names it ("conic.ed_k") */
    int status;        /* the status it explains */
    int arg;           /* the argument it concerns (1, 2, ...), or 0 */
    const char *key;   /* or the option key it concerns, or NULL */
    const char *text;  /* what must hold; "%s" (at most one) shows the argument's value */
} pc_why;

/* The row of table (ended by a row with op NULL) for op and status, or NULL. */
const pc_why *pc_why_find(const pc_why *table, const char *op, int status);

#endif
