/* A why-table made for one call (why_call.h). */
#include <stdarg.h>
#include <stdio.h>
#include "why_call.h"

int pc_why_call_set(pc_why_call *w, const char *op, int st, int arg, const char *key, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(w->text, sizeof w->text, fmt, ap);
    va_end(ap);
    w->row[0] = (pc_why){st == 0 ? NULL : op, st, arg, key, w->text};
    w->row[1] = (pc_why){NULL, 0, 0, NULL, NULL};
    return st;
}

int pc_why_call_row(pc_why_call *w, const pc_why *table, const char *op, int st) {
    const pc_why *r = pc_why_find(table, op, st);
    if (!r) return pc_why_call_set(w, NULL, st, 0, NULL, "");
    return pc_why_call_set(w, op, st, r->arg, r->key, "%s", r->text);
}
