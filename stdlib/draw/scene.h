/* A 3-D scene: strokes and surfaces gathered while a script draws, resolved when the picture is
 * written, so every stroke is hidden where any surface of the figure lies in front of it,
 * whatever the order of the drawing calls.  A surface takes part as an occluder (hidden.h: a
 * depth test against its triangulated mesh); strokes are 3-D polylines and point markers.
 * pc_scene_draw draws the strokes onto a canvas: the seen parts solid, the hidden parts
 * dashed, left out, or shown as they are. */
#ifndef PC_SCENE_H
#define PC_SCENE_H

#include "canvas.h"
#include "hidden.h"

typedef enum { PC_HIDDEN_SHOW, PC_HIDDEN_DASHED, PC_HIDDEN_HIDE } pc_hidden_mode;

typedef struct pc_scene pc_scene;

/* An empty scene seen through `screen`, a map from 3-D to screen pixels (y down) that every
 * later addition is projected with.  NULL with *status: PC_EDIM unless 3 -> 2, PC_ESINGULAR
 * for a map of rank < 3, PC_ENOMEM. */
pc_scene *pc_scene_new(const pc_map *screen, int *status);
void pc_scene_free(pc_scene *sc);

/* A surface as an occluder, on a mesh x mesh grid (1..1024; 48 is plenty for a picture). */
int pc_scene_add_surface(pc_scene *sc, const pc_surface *s, int mesh);
/* A polyline of n 3-D points (xyz[3i..3i+2]); brk (may be NULL): brk[i] != 0 starts a new
 * piece at point i.  In colour `color` (an attribute; < 0: the canvas's foreground at draw
 * time) with the pen `pen` (an index into the canvas's pens, 0 the default). */
int pc_scene_add_polyline(pc_scene *sc, size_t n, const double *xyz, const uint8_t *brk,
                          int color, int pen);
/* A marker (furniture.h's styles) of size pixels at a 3-D point. */
int pc_scene_add_mark(pc_scene *sc, const double xyz[3], int style, double size, int color);

/* A dot (PSET's pixel) at a 3-D point: left out where it is hidden (unless PC_HIDDEN_SHOW),
 * since a pixel has no dashes. */
int pc_scene_add_dot(pc_scene *sc, const double xyz[3], int color);

/* An arrow head (furniture.h, len pixels long) at the 3-D point tip, pointing from `from`:
 * drawn where its tip is seen (always with PC_HIDDEN_SHOW). */
int pc_scene_add_arrow_head(pc_scene *sc, const double from[3], const double tip[3], double len,
                            int color);

/* A label of a 3-D point: written when the scene is drawn if its point is seen (always with
 * PC_HIDDEN_SHOW), on side `anchor` (PC_ANCHOR_AUTO: placed with the other labels). */
int pc_scene_add_label(pc_scene *sc, const double xyz[3], const char *utf8, int anchor, int scale,
                       int color);
/* The last label added drawn in the print look's {font =, size =, halo =} (canvas.h's
 * pc_text_style: "" or NULL, 0, -1 keep the figure's); PC_EARG if the last stroke is no label. */
int pc_scene_style_label(pc_scene *sc, const char *font, double size_pt, int halo);

/* Is the 3-D point x seen (no surface of the scene in front of it)? */
int pc_scene_visible(const pc_scene *sc, const double x[3]);
/* The number of surfaces and strokes gathered. */
size_t pc_scene_nsurfaces(const pc_scene *sc);
size_t pc_scene_nstrokes(const pc_scene *sc);

/* Every point the scene draws, on the screen (canvas.h's pc_extent_fn): the vertices of its
 * strokes (a straight segment in space is one on the screen), its markers with their size,
 * its labels with room for their box (measured through c) on any side.  For framing. */
int pc_scene_extent(const pc_scene *sc, const pc_canvas *c, pc_extent_fn put, void *ctx);
/* Draw the scene through a framing from now on: its screen x -> sx x + tx, y -> sy y + ty
 * (sx, sy > 0; the depth order does not change). */
void pc_scene_reframe(pc_scene *sc, double sx, double sy, double tx, double ty);

/* Draw every stroke onto c, its visibility sampled 3 px apart on the screen and each change
 * found by bisection (to 1/1024 of the step): seen runs as paths in
 * their pen, hidden runs by `mode` (dashed: the pen with dashes 4 on, 3 off).  Markers that
 * are hidden are left out unless mode is SHOW.  Returns PC_OK or the canvas's status. */
int pc_scene_draw(const pc_scene *sc, pc_canvas *c, pc_hidden_mode mode);

/* The scene the 3-D strokes seen through `screen` go into on canvas c, drawn in `mode`
 * (scene_set.c): the last one attached to c when its map and mode are these, else a new one
 * attached after it (the writers draw them all, in order, and fit{} reframes them).  NULL with
 * *status PC_OK when c has another attachment (draw as usual), else with the failure status. */
pc_scene *pc_canvas_scene(pc_canvas *c, const pc_map *screen, int mode, int *status);
/* Curve c (3-D) sampled at n + 1 equally spaced parameters as a polyline of the scene, broken
 * where it passes through a point at infinity. */
struct pc_curve;
int pc_scene_add_curve(pc_scene *sc, const struct pc_curve *c, int n, int color, int pen);

/* A path of n 3-D points (closed: back to the first), with arrow heads (furniture.h's
 * PC_ARROW_* bits) on its last and first segments, 9 px long, each drawn where its tip is seen. */
int pc_scene_add_path(pc_scene *sc, size_t n, const double *xyz, int closed, int heads, int color, int pen);

#endif
