/* The canvas: a QBasic-style raster of colour attributes plus the display list that produced it.
 *
 * Every drawing call does two things: it rasterises into `pixels` at once (so POINT and PAINT
 * see the picture exactly as QBasic would) and it appends one operation to the display list
 * (so the SVG writer can render the same picture as vectors).  Coordinates given to the
 * drawing functions are world coordinates: they pass through WINDOW (if set) and VIEW (if set)
 * to become screen pixels, y down, rounded to the nearest pixel only when rasterised.
 *
 * Colours are attributes: 0..255 are palette attributes (QBasic's colour numbers; a screen has
 * `ncolors` of them), 256.. are true colours ("#rrggbb") allocated on demand by pc_rgb_color,
 * one attribute per distinct colour.  PAINT's border test and POINT compare attributes.
 *
 * Beyond QBasic: paths (polylines and cubic segments), a pen (line width and dash pattern) for
 * lines, boxes, circles and paths, QBasic's 16-bit LINE style, and text in a built-in VGA font.
 *
 * This header is pure C: no Lua.  Errors are reported as status codes (status.h) with a
 * message in `pc_canvas.error`.
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
    PC_OP_FILL,      /* a PAINTed region: spans[first .. first+count) */
    PC_OP_PATH,      /* pts[first .. first+count) with their tags; flags: PC_PATH_CLOSED */
    PC_OP_TEXT,      /* text[first .. first+count) (UTF-8); x1, y1: top-left pixel of the
                        cell box; rx: scale; flags: the anchor it was placed by */
    PC_OP_FILLPATH,  /* a filled path: pts[first .. first+count) with their tags, every
                        subpath closed; flags: PC_FILL_EVENODD or PC_FILL_NONZERO */
    PC_OP_PIXELS     /* dots folded into whole pixels (see pc_canvas.dot_budget):
                        lpx[first .. first+count), by increasing pixel index */
} pc_op_kind;

enum { PC_ARC_FULL = 1, PC_ARC_RADIUS0 = 2, PC_ARC_RADIUS1 = 4 };

/* Path verbs: a MOVE starts a subpath at its point, a LINE goes to its point, a CUBIC takes
 * three points (two controls and the end).  In the display list each point carries the verb
 * it belongs to (all three points of a cubic are tagged CUBIC). */
enum { PC_PATH_MOVE, PC_PATH_LINE, PC_PATH_CUBIC };
enum { PC_PATH_CLOSED = 1 };
/* A PATH or FILLPATH op drawn at a size in pixels round an anchor (a marker, an arrow head,
 * an angle mark, equal-length ticks): x1, y1 hold the anchor, and framing (pc_fit) moves the
 * anchor and keeps the shape's size, mirroring it with the figure. */
enum { PC_OP_RIGID = 0x80 };
/* The fill rules of a filled path (as SVG's fill-rule), in the low bit of its flags; or-ed
 * with PC_FILL_TILE, the path is a tile of a tiling (a shaded surface's quads): the print look
 * strokes its outline in its own colour, a screen pixel wide, so that antialiased
 * neighbours show no seam of the paper between them (the pixels of the VGA look are exact). */
enum { PC_FILL_NONZERO = 0, PC_FILL_EVENODD = 1, PC_FILL_TILE = 2 };

/* Where text goes relative to its point: the side of the point (NE: above right). */
enum { PC_ANCHOR_C, PC_ANCHOR_N, PC_ANCHOR_NE, PC_ANCHOR_E, PC_ANCHOR_SE, PC_ANCHOR_S,
       PC_ANCHOR_SW, PC_ANCHOR_W, PC_ANCHOR_NW,
       PC_ANCHOR_AUTO   /* pc_text: placed when the picture is written (layout.h) */ };
/* A TEXT op's flags: the anchor (the low 4 bits), PC_TEXT_AUTO while an automatic label waits
 * to be placed, PC_TEXT_PLACED on one placed (in the copy the writers get, layout.h). */
enum { PC_TEXT_AUTO = 0x80, PC_TEXT_PLACED = 0x40, PC_TEXT_ANCHOR = 0x0f,
       PC_TEXT_DEVICE = 0x20   /* placed in device pixels (a caption): framing leaves it */ };

/* The largest attribute: true colours take 256 .. PC_MAX_ATTR. */
#define PC_MAX_ATTR 65535

/* A pen: what lines, boxes, circles and paths are stroked with. */
#define PC_PEN_MAXDASH 16
#define PC_PEN_MAXWIDTH 256
typedef struct {
    double width;                 /* pixels, 1..PC_PEN_MAXWIDTH; round caps and joins above 1 */
    int ndash;                    /* 0: solid; else even, the on/off lengths in dash[] */
    double dash[PC_PEN_MAXDASH];  /* on, off, on, off, ... in pixels along the stroke */
    double period;                /* sum of dash[] */
    unsigned style;               /* QBasic LINE style (16 bits, bit 15 first); 0: none */
    double print_width;           /* the print look: width in pt (a physical pen, print.h);
                                     0: width times the default print pen's */
    int print_dash;               /* 1: dash[] is in pt (a physical pen) */
} pc_stroke;

/* The style of one label in the print look (print.h): font family ("" for the figure's), size
 * in pt (0 for the figure's), halo (-1 for the default: on). */
typedef struct { char font[64]; double size; int halo; } pc_textstyle;

/* The print look's figure (print.h): on when a script or the command line asked for it. */
typedef struct {
    int on;
    double width, height;   /* pt; 0: from the canvas (96 px to the inch) or the aspect */
    double dpi;             /* raster outputs; 0: 96 */
    double size;            /* label size in pt; 0: 10 */
    char font[64];          /* "": serif */
    int frame;              /* 1: the script's figure{} (not the command line's --print):
                               without a window its coordinates are world units, y up, and
                               the picture is framed to what is drawn when it is written */
} pc_figure;

/* A drawing operation in screen coordinates (fractional, before rounding).  The header is
 * packed into 8 bytes, as before pens and true colours: scripts record millions of ops.  Its
 * clip rectangle is not in it: the clips are runs of ops (pc_clip), so a script may change
 * VIEW any number of times (a 16-bit index here once lost the drawing after 65,535). */
typedef struct {
    uint8_t kind;         /* pc_op_kind */
    uint8_t flags;
    uint16_t color;       /* attribute */
    uint16_t pen;         /* index into pc_canvas.pens (LINE, BOX, ARC, PATH; else 0) */
    double x1, y1, x2, y2;   /* double: a float would move some dots across a pixel edge */
    double rx, ry, a0, a1;
    uint32_t first, count;   /* DOTS: into dots[]; FILL: into spans[]; PATH: into pts[];
                                TEXT: into text[] */
} pc_op;

/* A dot of a DOTS run, in screen coordinates (16 bytes a dot: scripts plot millions). */
typedef struct { double x, y; } pc_xy;

/* One horizontal run of a painted region: pixels x0..x1 inclusive on row y. */
typedef struct { int16_t y, x0, x1; } pc_span;

/* A pixel of a PIXELS op: index y * width + x, and its attribute (the last dot's). */
typedef struct { uint32_t idx; uint16_t color; } pc_lpx;

/* A clip rectangle in screen pixels, inclusive. */
typedef struct { int x0, y0, x1, y1; } pc_rect;

/* A VIEW in force for a run of ops: ops[first ..] up to the next clip's first.  Recorded in
 * the order of the ops, so the firsts increase strictly (a clip no op used is replaced). */
typedef struct { pc_rect r; size_t first; } pc_clip;

/* A point of a picture's extent and the box round it in pixels (layout.h: pc_fit). */
typedef void (*pc_extent_fn)(void *ctx, double x, double y, double dx0, double dy0, double dx1,
                             double dy1);

typedef struct pc_canvas {
    int width, height;
    int ncolors;            /* palette attributes: 16 for SCREEN 12, 256 for SCREEN 13 */
    uint16_t *pixels;       /* width*height attributes, row-major, y down */
    pc_rgb *palette;        /* attribute -> colour: 256 palette entries, then the ntrue true
                               colours (attributes 256 .. 255 + ntrue) */
    int ntrue;
    uint16_t *rgb_index;    /* hash of the true colours (rgb -> attribute; 0: empty slot) */
    size_t rgb_slots;
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
    pc_clip *clips; size_t nclips, capclips;         /* runs of ops drawn in one VIEW */
    pc_xy *pts; uint8_t *tags; size_t npts, cappts;   /* path points and their verbs */
    char *text; size_t ntext, captext;                /* the strings of TEXT ops */
    pc_lpx *lpx; size_t nlpx, caplpx;                 /* the pixels of PIXELS ops */

    /* Memory bounded by the picture, not by the number of calls: when the dots drawn one
     * after another (no other op between, one VIEW) pass dot_budget, they are folded into one
     * PIXELS op, the last colour of each pixel they hit, which later dots join in turn.  The
     * raster is unchanged; the SVG writes the pixels as its layer of exact pixels (isolated
     * dots already are).  pc_canvas_reset sets max(width * height, 65536): a dot costs 16
     * bytes, a dot of a new colour 96, a folded pixel 8. */
    size_t dot_budget;
    size_t fold_mark;       /* c->ndots where the run of dots being counted starts */

    /* pens: pens[0] is the default (width 1, solid); `pen` is the one in force */
    pc_stroke *pens; size_t npens, cappens;
    int pen;

    /* the print look: label styles (a TEXT op's pen indexes them; 0: the default) and the
     * figure's settings, which SCREEN keeps */
    pc_textstyle *tstyles; size_t ntstyles, captstyles;
    pc_figure figure;
    int screen_pixels;      /* the script chose its screen (SCREEN): its coordinates are that
                               screen's pixels, so a figure{} is not framed to its content */

    int dirty;              /* something drawn since the last save */
    uint64_t version;       /* bumped by every change of the picture (drawing, CLS, PALETTE,
                               SCREEN); never reset, so a watcher can tell "changed since I
                               last looked" without disturbing dirty */
    char error[160];

    /* The text-measuring hook of the figure layout (layout.h): the size in screen pixels of a
     * label's box.  NULL: the VGA look's 8 x 16 cells.  Kept by SCREEN and CLS. */
    int (*measure)(void *ctx, const char *utf8, size_t n, int scale, double *w, double *h);
    void *measure_ctx;

    /* What is resolved when the picture is written (layout.h): a 3-D scene.  resolve draws it
     * onto the writer's copy of the canvas before the labels are placed; drop frees it, and
     * is called when the display list starts afresh (SCREEN, a full CLS) and by
     * pc_canvas_free.  NULL: nothing attached. */
    int (*attach_resolve)(void *attach, struct pc_canvas *copy);
    void (*attach_drop)(void *attach);
    /* What framing (layout.h: pc_fit) needs of it: every point it will draw, in screen
     * pixels, with the box round it that does not scale (a marker, room for a label); and the
     * framing itself, x -> sx x + tx, y -> sy y + ty, to draw it through.  NULL: none. */
    int (*attach_extent)(void *attach, const struct pc_canvas *c, pc_extent_fn put, void *ctx);
    void (*attach_frame)(void *attach, double sx, double sy, double tx, double ty);
    void *attach;
    /* Furniture measured in pixels between world points (furniture.c: dimension, angle_mark,
     * centre_line, hatch) drawn in a figure framed when written: kept here with the points'
     * pixels of the call and expanded when the frame is known (fit.c).  Dropped with the
     * attachment; a writer's copy borrows them (deferred_borrowed: never frees them). */
    struct pc_deferred *deferred; size_t ndeferred, capdeferred;
    int deferred_borrowed;
} pc_canvas;

/* Drop what is attached (see pc_canvas.attach). */
void pc_canvas_detach(pc_canvas *c);

/* QBasic screen modes: 12 (640x480, 16 colours), 13 (320x200, 256 colours) and the others of
 * qbscreen.h (1, 2, 7, 9). */
pc_canvas *pc_canvas_new(int width, int height, int ncolors);
pc_canvas *pc_canvas_new_mode(int mode);          /* NULL for an unknown mode */
void pc_canvas_free(pc_canvas *c);
/* Re-initialise in place (SCREEN statement): size, palette, colours, window, view, list. */
int pc_canvas_reset(pc_canvas *c, int width, int height, int ncolors);

/* The default palettes: the 16 VGA colours; for 256 colours the VGA mode-13 palette. */
void pc_palette_default(pc_rgb *pal, int ncolors);

/* Coordinate mapping: world -> screen (fractional) and back; length along x. */
void pc_world_to_screen(const pc_canvas *c, double wx, double wy, double *sx, double *sy);
/* Is c a figure{} framed to its content when written (the script's figure{}, no window, no
 * SCREEN)?  Its world is then the screen mirrored, y up (layout.h: pc_fit_figure). */
int pc_figure_frames(const pc_canvas *c);
void pc_screen_to_world(const pc_canvas *c, double sx, double sy, double *wx, double *wy);
double pc_world_xscale(const pc_canvas *c);       /* screen pixels per world x unit */

/* True colours: the attribute of rgb, allocated on first use (deduplicated: the same rgb
 * always gives the same attribute).  Returns the attribute (>= 256), or -1 with c->error set
 * when PC_MAX_ATTR - 255 colours are already in use or memory runs out. */
int pc_rgb_color(pc_canvas *c, pc_rgb rgb);
/* The one parser of colour strings: exactly "#rrggbb" ('#' and six hexadecimal digits, either
 * case; len bytes, so an embedded NUL is refused) into *out.  PC_EARG for anything else
 * ("#12345g", "#-1-1-1", "# 1 2 3", "#fff"), *out untouched. */
int pc_rgb_parse(const char *s, size_t len, pc_rgb *out);

/* The drawing statements.  color < 0 means "the default" (foreground, or background for
 * preset).  All return PC_OK or PC_EARG (with c->error set).  A colour is any attribute:
 * 0..ncolors-1 or a true colour from pc_rgb_color. */
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
/* LINE with QBasic's 16-bit style: box 0 for a line, 1 for B (the outline).  As QBasic (and
 * GW-BASIC) do, bit 15 comes first and each pixel step along the line uses the next bit; the
 * pattern restarts at each statement and runs on round the four sides of a box.  A line is
 * walked from its upper end (from its second point when both ends are level); a box's sides in
 * the order bottom, top (both from the second corner's x), then right and left from the top.
 * The style is one pixel wide: the pen's width and dashes do not apply. */
int pc_line_styled(pc_canvas *c, double x1, double y1, double x2, double y2, int color, int box,
                   unsigned pattern);

/* A path of n points xy[2i], xy[2i+1] (world coordinates).  verbs NULL: move to the first
 * point, line to each other one; else nverbs verbs, the first a MOVE, consuming exactly n
 * points.  closed: each subpath ends with a line back to its start.  Rasterised exactly as the
 * chain of LINEs through its vertices (cubics flattened to within 0.1 px on the screen); the
 * dash phase runs on across vertices and restarts at each subpath.  A subpath of one point
 * draws nothing.  The graphics cursor moves to the last point. */
int pc_path(pc_canvas *c, size_t n, const double *xy, const uint8_t *verbs, size_t nverbs,
            int closed, int color);

/* pc_path with the points already in screen coordinates (fractional pixels, y down, before
 * VIEW's clip), as a curve flattened through WINDOW and VIEW gives them: its vertices are
 * converted from world to screen once, where they were flattened, not again here.  The
 * graphics cursor moves to the world point of the last one. */
int pc_path_screen(pc_canvas *c, size_t n, const double *sxy, const uint8_t *verbs,
                   size_t nverbs, int closed, int color);

/* A filled path: the points and verbs as for pc_path (world coordinates; cubics flattened to
 * within 0.1 px on the screen), every subpath closed, filled with `color` by `rule`
 * (PC_FILL_EVENODD: inside where a ray crosses the outline an odd number of times, so a
 * subpath inside another makes a hole; PC_FILL_NONZERO: where the outline winds round a
 * non-zero number of times), or-ed with PC_FILL_TILE for a tile.  No outline is drawn and
 * the pen does not apply.
 * Pixels: pixel (i, j) is filled when its centre, the screen point (i, j), is inside; a centre
 * exactly on the outline counts as inside on a left or top edge and outside on a right or
 * bottom edge (each scanline's run is the half-open x0 <= i < x1, each edge the half-open
 * y0 <= j < y1).  So polygons that share an edge (the same two vertices) neither overlap
 * nor leave a gap between them, and a tiling of the plane covers every pixel exactly once.
 * Clipped to VIEW.  A point farther than 1e15 pixels from the screen is an error (it could
 * not be placed to the pixel).  The graphics cursor moves to the last point. */
int pc_fill_path(pc_canvas *c, size_t n, const double *xy, const uint8_t *verbs, size_t nverbs,
                 int rule, int color);

/* The pen for the lines, boxes, circles and paths drawn from now on: width in pixels
 * (1..PC_PEN_MAXWIDTH; above 1 every pixel of the 1-pixel stroke becomes a disc of that
 * diameter), dash: ndash on/off lengths in pixels (ndash even, at most PC_PEN_MAXDASH, each
 * > 0; 0 for solid) measured along the stroke from its start.  SCREEN restores the default. */
int pc_pen(pc_canvas *c, double width, const double *dash, int ndash);
void pc_pen_reset(pc_canvas *c);
/* A physical pen for the print look: width in pt (0.1..100), dash on/off lengths in pt.  The
 * VGA look draws it at 96 px to the inch (at least 1 pixel wide). */
int pc_pen_physical(pc_canvas *c, double width_pt, const double *dash_pt, int ndash);

/* Text in the built-in VGA font (8x16 cells, see font.h), transparent background.  The cell
 * box (8*scale per character by 16*scale) goes on the `anchor` side of the point (x, y), `gap`
 * pixels off it: with the point in pixel (X, Y) and g = round(gap), NE puts the box's
 * bottom-left pixel at (X + g, Y - g); N centres it above (left X - w/2, bottom Y - g); C
 * centres it on the point (left X - w/2, top Y - h/2); the other sides likewise.  SE with gap
 * 0 puts the top-left pixel on the point.  scale 1..8; characters the font lacks show its
 * replacement glyph; invalid UTF-8 is an error.  anchor PC_ANCHOR_AUTO records the label
 * without drawing it: the writers place it (layout.h) and gap does not apply. */
int pc_text(pc_canvas *c, double x, double y, const char *utf8, int anchor, double gap,
            int scale, int color);
/* The print-look style of the last TEXT op (font "" or NULL: the figure's; size 0: the
 * figure's; halo -1: default).  PC_EARG when the last op is not text or a value is out of
 * range. */
int pc_text_style(pc_canvas *c, const char *font, double size_pt, int halo);
/* The size in pixels of the cell box of utf8 at scale; PC_EARG for invalid UTF-8 or scale. */
int pc_text_size(const char *utf8, int scale, int *w, int *h);

/* POINT: the attribute at (x,y), or -1 outside the view. */
int pc_point(const pc_canvas *c, double x, double y);
/* WINDOW: maps world (x1,y1)-(x2,y2) onto the view; screen != 0 keeps y down. */
int pc_window(pc_canvas *c, double x1, double y1, double x2, double y2, int screen);
void pc_window_reset(pc_canvas *c);
/* VIEW: viewport (x1,y1)-(x2,y2) in screen pixels; fill/border < 0 for none; screen != 0
 * keeps coordinates absolute. */
int pc_view(pc_canvas *c, int x1, int y1, int x2, int y2, int fill, int border, int screen);
int pc_view_reset(pc_canvas *c);
/* The display list records each VIEW change that is drawn in (no limit on their number); VIEW
 * fails with PC_ENOMEM only when memory runs out, and then the view stays as it was. */

/* ---- the canvas seen from a host (the command line, the REPL, a watcher) -----------------
 * A host reads and changes the canvas only through these functions and the drawing
 * statements above, never through its fields. */

/* The screen: width and height in pixels (either pointer may be NULL), palette colours. */
void pc_canvas_size(const pc_canvas *c, int *width, int *height);
int pc_canvas_ncolors(const pc_canvas *c);
/* The change counter: bumped by every change of the picture (drawing, CLS, PALETTE, SCREEN),
 * never by saving, and never going back, so "changed since I last looked" is a comparison. */
uint64_t pc_canvas_version(const pc_canvas *c);
/* Has something been drawn since the canvas was last saved (or cleared, or SCREEN)? */
int pc_canvas_dirty(const pc_canvas *c);
/* The picture was written out: pc_canvas_dirty is 0 until the next drawing.  The version
 * does not change. */
void pc_canvas_mark_saved(pc_canvas *c);
/* The attribute the whole screen was last cleared to (SCREEN, a full-screen CLS): the colour
 * a preview counts as empty paper. */
int pc_canvas_paper(const pc_canvas *c);
/* The colour of attribute attr, a palette attribute (0..ncolors-1) or a true colour (256..);
 * PC_EARG (c->error untouched, *out unchanged) for an attribute not in use. */
int pc_canvas_rgb(const pc_canvas *c, int attr, pc_rgb *out);
/* The colour table indexed by attribute (palette attributes, then the true colours), for
 * writers that take one.  Valid until the next call that may add a colour. */
const pc_rgb *pc_canvas_palette(const pc_canvas *c);
/* The message of the last call that failed ("" when none has). */
const char *pc_canvas_error(const pc_canvas *c);
/* Erase the picture, keeping the screen's settings: size, colours, palette, true colours,
 * pen, window, and the view with its VIEW SCREEN mode.  The whole screen (not just the view)
 * is cleared to the background colour, the display list starts afresh and the graphics
 * cursor stays where it was; the canvas counts as saved.  The REPL's `clear`. */
int pc_canvas_clear(pc_canvas *c);

/* Raw pixel access in screen pixels, clipped to the view: used by the rasteriser. */
void pc_plot(pc_canvas *c, int x, int y, int color);

#endif
