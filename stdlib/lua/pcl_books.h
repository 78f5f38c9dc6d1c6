/* Shared by the bindings of the books and the maps. */
#ifndef PCL_BOOKS_H
#define PCL_BOOKS_H
#include "pcl.h"

/* Push the table of a conic's elements, c:conic()'s (l_conic_elements.c); 1. */
struct pc_conic_info;
int pcl_push_conic_info(lua_State *L, const struct pc_conic_info *o);
/* Push a table of nr rows, each a list of nc numbers, from m row by row (l_conic_elements.c). */
void pcl_push_rows(lua_State *L, int nr, int nc, const double *m);

/* Declarations they share: an optional number > 0 (default d); an optional point of dimension
 * dm (absent: its cleared value, the origin); an optional location of the first's dimension. */
#define A_POSOPT(nm, d) {.name = nm, .kind = PCL_NUMBER, .flags = PCL_OPT | PCL_POS, .dflt = d}
#define A_POINTOPT(nm, dm) {.name = nm, .kind = PCL_POINT, .flags = PCL_OPT, .dim = dm}
#define A_SAMELOC(nm, fl) {.name = nm, .kind = PCL_LOC, .flags = PCL_SAMEDIM | (fl)}

#endif
