/* M:expanded(): a point equation's coordinates expanded in powers of its one parameter as the
 * book prints them (Fig. 2.17: x = 4t(9t + 0,8)/(70t^2 - 75t + 44,2)), with the printer of
 * konop_print.h; the equation from stdlib/geom/expr.h. */
#ifndef PC_KONOP_EXPANDED_H
#define PC_KONOP_EXPANDED_H
#include <stddef.h>
#include "expr.h"

/* The coordinates of e ("x = ...", "y = ..."; a scalar equation: its one expression) into
 * texts, each in `each` characters from texts + axis * each (dim, at most PC_MAXDIM, of them):
 * their count, or -1 with the reason in why (no or several parameters, a function that is not
 * rational, a weight identically 0). */
int pc_k_expanded(const pc_expr_pool *pool, int e, char *texts, size_t each, char *why, size_t size);

#endif
