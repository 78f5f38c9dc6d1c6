/* The canvas: a QBasic-style indexed-colour raster plus the display list that produced it.
 *
 * Every drawing call does two things: it rasterises into `pixels` at once (so POINT and PAINT
 * see the picture exactly as QBasic would) and it appends one operation to the display list
 * (so the SVG writer can render the same picture as vectors).  Coordinates given to the
 * drawing functions are world coordinates: they pass through WINDOW (if set) and VIEW (if set)
 * to become screen pixels, y down, rounded to the nearest pixel only when rasterised.
 *
 * This header is pure C: no Lua.  Errors are reported as PC_DRAW_* codes with a message in
 * `pc_canvas.error`.
 */
#ifndef PC_CANVAS_H
#define PC_CANVAS_H

#include <stddef.h>
#include <stdint.h>

#include "status.h"   /* PC_OK, PC_EARG (the message in pc_canvas.error says which), PC_ENOMEM, PC_EIO */

typedef struct { uint8_t r, g, b; } pc_rgb;

typedef enum {
    PC_OP_CLEAR,     /* fill the clip rectangle with colour (CLS, VIEW fill) */
    PC_OP_DOTS,      /* a run of PSET/PRESET dots of one colour: dots[first .. first+count) */
    PC_OP_LINE,      /* x1,y1 - x2,y2 */
    PC_OP_BOX,       /* outline of the box with corners x1,y1 and x2,y2 */
    PC_OP_FILLBOX,   /* filled box */
    PC_OP_ARC,       /* centre x1,y1, radii rx,ry; angles a0..a1 (radians, counter-clockwise
                        on screen); flags: PC_ARC_FULL, PC_ARC_RADIUS0, PC_ARC_RADIUS1 */
    PC_OP_FILL       /* a PAINTed region: spans[first .. first+count) */
} pc_op_kind;

enum { PC_ARC_FULL = 1, PC_ARC_RADIUS0 = 2, PC_ARC_RADIUS1 = 4 };

/* A drawing operation in screen coordinates (fractional, before rounding). */
typedef struct {
    pc_op_kind kind;
    uint8_t color;        /* palette attribute */
    uint8_t flags;
    uint16_t clip;        /* index into pc_canvas.clips */
    double x1, y1, x2, y2;   /* double: a float would move some dots across a pixel edge */
    double rx, ry, a0, a1;
    uint32_t first, count;   /* DOTS: into dots[]; FILL: into spans[] */
} pc_op;

/* A dot of a DOTS run, in screen coordinates (16 bytes a dot: scripts plot millions). */
typedef struct { double x, y; } pc_xy;

/* One horizontal run of a painted region: pixels x0..x1 inclusive on row y. */
typedef struct { int16_t y, x0, x1; } pc_span;

/* A clip rectangle in screen pixels, inclusive. */
typedef struct { int x0, y0, x1, y1; } pc_rect;

typedef struct pc_canvas {
    int width, height;
    int ncolors;            /* 16 for SCREEN 12, 256 for SCREEN 13 */
    uint8_t *pixels;        /* width*height attributes, row-major, y down */
    pc_rgb palette[256];    /* attribute -> colour */
    int fg, bg;             /* current foreground, background (CLS) attributes */
    int paper;              /* the attribute the whole screen was last cleared to (SCREEN, a
                               full-screen CLS): what a preview counts as empty.  COLOR's
                               background only takes effect at the next CLS */

    /* the graphics cursor: last point referenced (QBasic LINE -(x,y), STEP), in world units */
    double last_x, last_y;

    /* WINDOW: world -> view mapping; active when has_window */
    int has_window;
    int window_screen;      /* WINDOW SCREEN: y down instead of up */
    double wx1, wy1, wx2, wy2;

    /* VIEW: viewport in screen pixels; view_screen: coordinates stay absolute (VIEW SCREEN) */
    pc_rect view;
    int view_screen;

    /* display list */
    pc_op *ops; size_t nops, capops;
    pc_span *spans; size_t nspans, capspans;
    pc_xy *dots; size_t ndots, capdots;
    pc_rect *clips; size_t nclips, capclips;

    int dirty;              /* something drawn since the last save */
    uint64_t version;       /* bumped by every change of the picture (drawing, CLS, PALETTE,
                               SCREEN); never reset, so a watcher can tell "changed since I
                               last looked" without disturbing dirty */
    char error[160];
} pc_canvas;

/* QBasic screen modes: 12 (640x480, 16 colours) and 13 (320x200, 256 colours). */
pc_canvas *pc_canvas_new(int width, int height, int ncolors);
pc_canvas *pc_canvas_new_mode(int mode);          /* NULL for an unknown mode */
void pc_canvas_free(pc_canvas *c);
/* Re-initialise in place (SCREEN statement): size, palette, colours, window, view, list. */
int pc_canvas_reset(pc_canvas *c, int width, int height, int ncolors);

/* The default palettes: the 16 VGA colours; for 256 colours the VGA mode-13 palette. */
void pc_palette_default(pc_rgb *pal, int ncolors);

/* Coordinate mapping: world -> screen (fractional) and back; length along x. */
void pc_world_to_screen(const pc_canvas *c, double wx, double wy, double *sx, double *sy);
void pc_screen_to_world(const pc_canvas *c, double sx, double sy, double *wx, double *wy);
double pc_world_xscale(const pc_canvas *c);       /* screen pixels per world x unit */

/* The drawing statements.  color < 0 means "the default" (foreground, or background for
 * preset).  All return PC_OK or PC_EARG (with c->error set). */
int pc_cls(pc_canvas *c);
int pc_color(pc_canvas *c, int fg, int bg);       /* bg < 0: unchanged */
int pc_palette(pc_canvas *c, int attr, pc_rgb rgb);
int pc_palette_reset(pc_canvas *c);
int pc_pset(pc_canvas *c, double x, double y, int color);
int pc_preset(pc_canvas *c, double x, double y, int color);
int pc_line(pc_canvas *c, double x1, double y1, double x2, double y2, int color);
int pc_box(pc_canvas *c, double x1, double y1, double x2, double y2, int color, int filled);
/* CIRCLE: r in world x units; start/end in radians, NAN for "not given"; negative angles draw
 * a radius to the centre; aspect NAN for the default (square pixels: 1). */
int pc_circle(pc_canvas *c, double x, double y, double r, int color,
              double start, double end, double aspect);
/* PAINT: fill from (x,y) up to pixels of colour `border` (border < 0: same as paint colour). */
int pc_paint(pc_canvas *c, double x, double y, int color, int border);
/* POINT: the attribute at (x,y), or -1 outside the view. */
int pc_point(const pc_canvas *c, double x, double y);
/* WINDOW: maps world (x1,y1)-(x2,y2) onto the view; screen != 0 keeps y down. */
int pc_window(pc_canvas *c, double x1, double y1, double x2, double y2, int screen);
void pc_window_reset(pc_canvas *c);
/* VIEW: viewport (x1,y1)-(x2,y2) in screen pixels; fill/border < 0 for none; screen != 0
 * keeps coordinates absolute. */
int pc_view(pc_canvas *c, int x1, int y1, int x2, int y2, int fill, int border, int screen);
int pc_view_reset(pc_canvas *c);
/* The display list holds at most 65535 clip rectangles (VIEW changes, deduplicated against
 * the previous one); beyond, VIEW fails with PC_ENOMEM and the view stays as it was. */

/* Raw pixel access in screen pixels, clipped to the view: used by the rasteriser. */
void pc_plot(pc_canvas *c, int x, int y, int color);

#endif
