/* libpointcalc: the C core of pointcalc as one library (docs/c-api.md).
 *   #include <pointcalc.h>     with  cc prog.c $(pkg-config --cflags --libs pointcalc)
 * The kernel (points, ratios, meets, maps, the one curve and one surface type, point equations,
 * numerics), the books' constructions and the drawing layer (the canvas, its PNG, SVG and PPM
 * writers and the print look: PDF, EPS, PS, print-look PNG and SVG through cairo and Pango). Every function returns PC_OK or an error status of status.h unless its header
 * says otherwise; nothing here knows about Lua. */
#ifndef POINTCALC_H
#define POINTCALC_H

#define POINTCALC_VERSION_MAJOR 0
#define POINTCALC_VERSION_MINOR 1
#define POINTCALC_VERSION_PATCH 0

#ifdef __cplusplus
extern "C" {
#endif

/* the kernel */
#include "status.h"
#include "point.h"
#include "simplex.h"
#include "map.h"
#include "linalg.h"
#include "numeric.h"
#include "optimize.h"
#include "smooth.h"
#include "cnum.h"
#include "curve.h"
#include "surface.h"
#include "expr.h"
#include "hidden.h"
#include "shade.h"
/* drawing */
#include "canvas.h"
#include "writers.h"
#include "print.h"
#include "math_label.h"
#include "font.h"
#include "qbscreen.h"
#include "shaded.h"
#include "braille.h"
/* the books */
#include "curvilinear.h"
#include "fourier.h"
#include "spline.h"
#include "approx.h"
#include "conic.h"
#include "konop_curves.h"
#include "konop_interp.h"
#include "oneratio.h"
#include "buimov.h"
#include "plane_curves.h"
#include "reconstruct.h"
#include "conic_props.h"
#include "conic_shells.h"
#include "conic_surface.h"
#include "elastic.h"
#include "ferguson.h"
#include "graphdiff.h"
#include "pencils4.h"

#ifdef __cplusplus
}
#endif
#endif
