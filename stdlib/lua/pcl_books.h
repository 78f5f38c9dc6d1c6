/* Argument checks with the full name ("konopatsky.polar", "conic.elements") for the bindings
 * of the books' new functions (l_konopatsky_ch1.c, l_conic_elements.c), until they move onto
 * the declared argument layer. */
#ifndef PCL_BOOKS_H
#define PCL_BOOKS_H
#include "pcl.h"

/* The point at arg (weight 1, finite) into out; its dimension.  dim > 0 demands that dimension,
 * the message naming argument dim_arg (called dim_name). */
int pclb_point(lua_State *L, const char *fn, int arg, const char *what, int dim, int dim_arg,
               const char *dim_name, double *out);
/* count points at first.. named names[i], all of the first one's dimension; returns it. */
int pclb_points(lua_State *L, const char *fn, int first, int count, const char *const *names,
                double *out);

/* Push the table of a conic's elements (l_conic_elements.c): kind, circle, discriminant, coef,
 * center | vertex, axes, semi, a, b, foci, e, p, asymptotes, mu, w, k, k_ceva. */
struct pc_conic_info;
void pcl_push_conic_info(lua_State *L, const struct pc_conic_info *o);

#endif
