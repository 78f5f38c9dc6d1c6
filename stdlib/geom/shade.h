/* Shaded surfaces: a 3-D surface cut into an nu x nv grid of quads, each quad seen through a
 * map to a y-down screen and given one flat (Lambert) shade, in painter's order.
 *
 * The normal of the quad with corners P00, P10, P11, P01 (in (u, v)) is the cross product of
 * its diagonals (P11 - P00) x (P01 - P10): for a plane quad it is twice the cross product of
 * its sides, and it stays defined for the slightly twisted quads of a curved surface.  It is
 * turned to the side the viewer sees (pc_viewer_toward at the quad's centre, the mean of its
 * corners; hidden.h), so a surface is lit on whichever side shows.  With L the unit direction
 * towards the light, the shade is
 *     k = ambient + (1 - ambient) * max(0, n . L)          (Lambert's cosine law)
 * so a quad facing the light gets the full colour and one at 60 degrees to it half (with
 * ambient 0).  Without a light the light is at the viewer (a headlight: L = the direction
 * towards the viewer at each quad).
 *
 * The order is the painter's: farthest first by pc_viewer_depth of the quad's centre (the
 * depth hidden lines use), ties by grid position, so drawing the quads in turn leaves the
 * nearer ones on top; drawing each quad's outline with its fill shows exactly the visible
 * parts of the mesh.
 *
 * Pure C, no canvas: the screen corners, shades and order; stdlib/draw/shaded.h draws them. */
#ifndef PC_SHADE_H
#define PC_SHADE_H
#include <stddef.h>
#include <stdint.h>
#include "hidden.h"

typedef struct {
    double xy[8];    /* the corners on the screen: (u_i, v_j), (u_i+1, v_j), (u_i+1, v_j+1),
                        (u_i, v_j+1), x and y each */
    double shade;    /* k in [0, 1] */
    double depth;    /* of the centre: larger is nearer */
    int i, j;        /* the grid cell: u from u0 + i (u1 - u0)/nu, v likewise */
} pc_shade_quad;

typedef struct {
    int nu, nv;           /* the grid, 1..1024 each */
    int has_light;        /* 0: the headlight */
    double light[3];      /* the direction towards the light (any length but zero) */
    double ambient;       /* 0..1 */
} pc_shade_opts;

/* The shaded quads of the 3-D surface s seen through `screen` (a map from 3-D to 2-D screen
 * pixels, y down), in painter's order, into *out (malloc'd, freed by the caller; NULL when
 * *n is 0).  A quad is left out when a corner has no finite image (a point at infinity, NaN
 * coordinates, the vanishing plane) or when its corners lie on both sides of the camera's
 * vanishing plane.  A quad without a normal (its diagonals parallel: collapsed) takes the
 * surface's normal at its centre, or the ambient shade when there is none.
 * PC_EDIM unless s is 3-D and the map 3 -> 2, PC_EDOMAIN for a grid outside 1..1024 or
 * ambient outside 0..1, PC_EZERO for a zero light, PC_ENONFINITE for a light with NaN or
 * infinite components, PC_ESINGULAR for a map of rank < 3, PC_ENOMEM; a failing evaluation
 * (a callback's error) is passed on. */
int pc_shade_quads(const pc_surface *s, const pc_map *screen, const pc_shade_opts *opts,
                   pc_shade_quad **out, size_t *n);

/* The base colour scaled by k (0..1): each channel round(c * k). */
void pc_shade_rgb(const uint8_t base[3], double k, uint8_t out[3]);

#endif
