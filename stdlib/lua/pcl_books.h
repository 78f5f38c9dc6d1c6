/* Shared by the bindings of the books' conics (l_conic_elements.c, l_korotky_shells.c). */
#ifndef PCL_BOOKS_H
#define PCL_BOOKS_H
#include "pcl.h"

/* Push the table of a conic's elements (l_conic_elements.c): kind, circle, discriminant, coef,
 * center | vertex, axes, semi, a, b, foci, e, p, asymptotes, mu, w, k, k_ceva. */
struct pc_conic_info;
void pcl_push_conic_info(lua_State *L, const struct pc_conic_info *o);

#endif
