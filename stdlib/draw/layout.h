/* The figure layout: what is decided when a picture is written, not when it is drawn.
 *
 * A label drawn without a direction (pc_text with PC_ANCHOR_AUTO) is recorded, not rasterised:
 * it is placed when the picture is written, with everything else already known, among candidate
 * positions round its point (label_place.c).  The writers get a resolved copy of the canvas
 * (pc_layout_resolve); the canvas itself keeps the labels pending, so every save places them
 * against everything drawn by then, and the same script always gives the same picture.
 *
 * Label boxes come from one text-measuring function per canvas (pc_canvas.measure): NULL is
 * the VGA look's 8 x 16 cells; the print look installs its own (sizes in screen pixels), so
 * placement works in both looks. */
#ifndef PC_LAYOUT_H
#define PC_LAYOUT_H

#include "canvas.h"

/* A box on the screen, in pixels: columns x0 .. x1-1, rows y0 .. y1-1 (half-open). */
typedef struct { double x0, y0, x1, y1; } pc_box2;

/* The size in screen pixels of the box of utf8 (n bytes) at scale, through c's measuring hook
 * (the VGA cells when none is set).  PC_EARG for invalid UTF-8. */
int pc_text_measure(const pc_canvas *c, const char *utf8, size_t n, int scale, double *w,
                    double *h);

/* The box in screen pixels that the TEXT op occupies, measured through c's hook: a placed
 * label's chosen box, text() from its corner, a label with a direction on that side of its
 * point at the gap it was given (read back from the VGA cell box pc_text recorded).  With the
 * VGA measure this is the cell box pc_text rasterised; with the print look's (print.h) it is
 * the box the print walk draws the label in. */
int pc_label_op_box(const pc_canvas *c, const pc_op *op, pc_box2 *box);
/* Is the TEXT op text() at a corner (no point labelled: the box starts at the point)? */
int pc_text_op_is_corner(const pc_op *op);

/* ---- placement, on its own (label_place.c) ------------------------------------------------ */

/* One label to place: its point (screen pixels), its box size, and either a fixed box
 * (fixed != 0: an obstacle that stays where it is) or the result of placement. */
typedef struct {
    double px, py;          /* the point it labels */
    double w, h;            /* its box */
    int fixed;
    pc_box2 box;            /* fixed: given; else: chosen */
    int anchor;             /* chosen side (PC_ANCHOR_*) */
    double gap;             /* chosen distance from the point, in pixels */
    int leader;             /* 1 when it sits so far out that a leader line joins it */
    pc_box2 bounds;         /* where it must stay (its VIEW); empty: the whole picture */
    int no_leader;          /* no leader line can be drawn: far places go without one */
} pc_label;

/* The ink the labels avoid: a summed-area table of a w x h mask of stroked pixels, so the ink
 * in any box is four look-ups.  mask[y * w + x] != 0 where there is ink. */
typedef struct {
    int w, h;
    uint32_t *sum;          /* (w+1) x (h+1) */
} pc_inkmap;

int pc_inkmap_init(pc_inkmap *m, const uint8_t *mask, int w, int h);
void pc_inkmap_free(pc_inkmap *m);
/* The number of ink pixels inside box b (clipped to the map). */
uint32_t pc_inkmap_count(const pc_inkmap *m, pc_box2 b);

/* Place the labels that are not fixed, in the picture (0, 0)-(width, height) (or each in its
 * bounds when they are not empty): each takes the
 * candidate (eight sides at growing distances, the far ones with a leader) that overlaps no
 * other label, stays inside, covers the least ink and no other label's point, in that order
 * of importance, nearer and in the order NE SE NW SW E W N S first among equals.  Greedy in
 * the given order, then the labels still in conflict placed again twice: deterministic.
 * ink may be NULL.
 * Returns PC_OK or PC_ENOMEM. */
int pc_place_labels(pc_label *lab, size_t n, const pc_inkmap *ink, double width, double height);

/* The box of a label of size w x h on side `anchor` of point (px, py), gap pixels off it, as
 * pc_text places its cell box for a pixel point (text.c's rule). */
pc_box2 pc_label_box(double px, double py, double w, double h, int anchor, double gap);

/* The room a label keeps clear round its box, for obstacles, the edge and other labels: the
 * box measured is the font's cell (or Pango's), but a reader's estimate of the glyphs may be
 * taller (an ascent of 0.92 em reaches 2.7 px over the VGA cell's 12 rows above the baseline,
 * and a stroke on pixel row Y is drawn at Y + 0.5) and wider (0.6 em a character against the
 * cell's 0.5), so a pixel of slack on every side, three above and a fifth more to the right. */
static inline pc_box2 pc_label_clear(pc_box2 b) {
    return (pc_box2){b.x0 - 1, b.y0 - 3, b.x1 + 1 + 0.2 * (b.x1 - b.x0), b.y1 + 1};
}

/* The leader line of a far label l (its box placed): from 2 px off its point to a pixel short
 * of its clearance, in whole pixels; 0 when the box is too near to need one. */
int pc_label_leader(const pc_label *l, double seg[4]);

/* Do two boxes overlap (share any pixel)? */
static inline int pc_box2_overlap(pc_box2 a, pc_box2 b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

/* ---- resolving a canvas for a writer (layout.c) ------------------------------------------- */

/* Has c anything for the writer to resolve (a pending label)? */
int pc_layout_pending(const pc_canvas *c);
/* A copy of c with every pending label placed and rasterised (the display list and pixels
 * copied; the rest shared, read-only), or c itself when nothing is pending.  NULL when memory
 * runs out.  Release with pc_layout_release. */
const pc_canvas *pc_layout_resolve(const pc_canvas *c);
/* The same, saying why on NULL: *status PC_ENOMEM, or the status of what the resolution drew
 * (a 3-D scene's label with bad math: PC_EARG) with its message in why. */
const pc_canvas *pc_layout_resolve_why(const pc_canvas *c, int *status, char *why, size_t whylen);
void pc_layout_release(const pc_canvas *c, const pc_canvas *resolved);

/* The placed labels of c, in the order they were drawn: *out gets a malloc'd array of
 * *n boxes (screen pixels), the anchors in anchors (may be NULL).  For tests and for a script
 * that asks where its labels went. */
int pc_layout_labels(const pc_canvas *c, pc_box2 **out, int **anchors, size_t *n);

/* ---- framing (fit.c) ---------------------------------------------------------------------- */

/* The box in screen pixels of everything drawn (text cells included, a pending label in its
 * first place); PC_EARG when nothing is drawn. */
int pc_drawn_extent(const pc_canvas *c, pc_box2 *out);

/* Frame what is drawn in the view, margin pixels in from its edges: everything moved and
 * scaled (equal scales on both axes with PC_FIT_EQUAL, each axis filling the view with
 * PC_FIT_FILL) so that every point and every text cell is inside, as large as that allows and
 * centred.  Pixel sizes (pens, markers, text) stay.  The display list is drawn again through
 * the framing, and the window changes so that later drawing lands in the same frame (a
 * script without a window gets one in its old pixel coordinates, y down).  Nothing drawn:
 * nothing changes.  PC_EARG for a margin outside 0..half the view, or labels that cannot fit
 * whatever the scale. */
enum { PC_FIT_EQUAL, PC_FIT_FILL };
int pc_fit(pc_canvas *c, double margin, int aspect);

/* A pending automatic label reserves its box on every side of its point, this far off, so
 * that wherever placement puts it, it stays in the frame. */
#define PC_FIT_LABEL_GAP 3.0
/* The framing a figure{} gets by default (pc_figure_frames, canvas.h): what is drawn (in
 * world units, y up, the screen mirrored) framed at equal units PC_FIT_MARGIN pixels in from
 * the view's edges.  The writers' copy is framed (pc_layout_resolve), never the canvas. */
#define PC_FIT_MARGIN 12.0
int pc_fit_figure(pc_canvas *c);

/* Frame the given points (n pairs x, y in world units) before drawing: the window round their
 * box with pad world units more on each side, at equal units at the view's aspect, centred
 * (PC_FIT_EQUAL), or the box itself plus pad (PC_FIT_FILL); y up.  What is already drawn does
 * not move (that is pc_fit).  PC_EARG for no points, a non-finite one, a negative pad, or a
 * box of no size with pad 0. */
int pc_fit_around(pc_canvas *c, size_t n, const double *xy, double pad, int aspect);
/* The same with band pixels kept free at the bottom of the view (a caption's line): the points
 * are framed in the view less the band, and the window reaches down over it at the same units.
 * PC_EARG as above, or for a band < 0 or not below the view's height. */
int pc_fit_around_band(pc_canvas *c, size_t n, const double *xy, double pad, double band, int aspect);

/* A label as the writers place it (figure_items.c): its text (a copy, NUL-ended), its box in
 * screen pixels, its side ("c", "n", "ne", ...) and whether it was placed automatically. */
typedef struct {
    const char *text;
    size_t len;
    pc_box2 box;
    const char *side;
    int autoplaced;
} pc_placed;
/* Every label of c as a writer places it, *n of them, in one block (free() it); NULL when out
 * of memory. */
pc_placed *pc_placed_labels(const pc_canvas *c, size_t *n);

/* fit{}: with around, the frame of the n points xy (pc_fit_around_band, pad and band); else
 * the frame of what is drawn (pc_fit, margin).  Each framing's own option given to the other
 * is PC_EARG with the reason (figure_items.c). */
typedef struct {
    int has_margin, has_pad, has_band, around, aspect;
    double margin, pad, band;
    size_t n;
    const double *xy;
} pc_fit_opts;
int pc_fit_options(pc_canvas *c, const pc_fit_opts *o);

#endif
