/* The tables of status explanations (why.h). */
#include <string.h>
#include "why.h"

const pc_why *pc_why_find(const pc_why *table, const char *op, int status) {
    for (const pc_why *w = table; w && w->op; w++)
        if (w->status == status && !strcmp(w->op, op)) return w;
    return NULL;
}
