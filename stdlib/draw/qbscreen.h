/* QBasic's screen beyond SCREEN 12's drawing statements: the screen modes (size, colours,
 * pages, text cells, the pixel aspect CIRCLE corrects for), text printed into character cells
 * (PRINT, LOCATE on a graphics screen), graphics blocks (GET/PUT), the DRAW macro language and
 * copies between pages (PCOPY).
 *
 * Everything here changes the canvas the way the drawing statements do: the pixels at once,
 * and the display list so the SVG writer shows the same picture.  Pure C: no Lua. */
#ifndef PC_QBSCREEN_H
#define PC_QBSCREEN_H

#include <stddef.h>
#include "canvas.h"

/* A QBasic graphics mode as a VGA card shows it on a 4:3 monitor. */
typedef struct {
    int mode;
    int width, height;   /* pixels */
    int ncolors;         /* attributes: 2 (SCREEN 2), 4 (SCREEN 1), 16, 256 (SCREEN 13) */
    int pages;           /* screen pages for SCREEN m, apage, vpage and PCOPY */
    int cols, rows;      /* the text screen: 40 or 80 columns */
    int cell_h;          /* character cell height: 8, 14 or 16 (cells are 8 wide) */
    double aspect;       /* CIRCLE's default aspect: 4/3 * height / width (a pixel's height
                            over its width on a 4:3 monitor: 0.8333 in SCREEN 13) */
} pc_mode_info;

/* The facts of SCREEN mode (1, 2, 7, 8, 9, 12, 13); PC_EARG for a mode pointcalc does not have
 * (0, the text mode, has no canvas; 3..6, 8, 10, 11 are other adapters' modes). */
int pc_mode_info_of(int mode, pc_mode_info *out);
/* The mode whose size and colours canvas c has, with its facts into out; 0 for a canvas of
 * another size (screen{width =, height =}). */
int pc_mode_of_canvas(const pc_canvas *c, pc_mode_info *out);
/* The character cell height of c: its mode's (8, 14 or 16), or 16 for a canvas of another size. */
int pc_cell_height(const pc_canvas *c);

/* Reset the canvas to mode's size, colours and default palette (SCREEN mode).  The palettes:
 * SCREEN 1 black, light cyan, light magenta, white (QBasic's palette 1); SCREEN 2 black and
 * white; 7, 9, 12 the 16 EGA colours; 13 the VGA 256-colour palette. */
int pc_canvas_set_mode(pc_canvas *c, int mode);

/* ---- text in character cells ------------------------------------------------------------ */

/* Print n bytes (code page 437, QBasic's character set) into the cells of text row `row`,
 * from column `col` (both 1-based; cells 8 x cell_h pixels, the top-left cell at pixel 0,0), in
 * colour fg on an opaque background bg, as QBasic's PRINT does on a graphics screen: neither
 * WINDOW nor VIEW applies, cells beyond the screen's edge are not drawn.  Records a filled box
 * and a TEXT op (its ry holds cell_h) for the SVG writer. */
int pc_text_cells(pc_canvas *c, int row, int col, const char *bytes, size_t n, int cell_h,
                  int fg, int bg);

/* Scroll the text rows top..bottom (1-based) up by one row of cells, the bottom row cleared
 * to bg: what PRINT does past the last line of the text viewport (VIEW PRINT). */
int pc_text_scroll(pc_canvas *c, int top, int bottom, int cell_h, int bg);

/* Record the pixels of the screen rectangle x0..x1, y0..y1 (inclusive, clipped to the screen)
 * as they are now, one FILL op per colour: after an operation that moved pixels (PUT, a
 * scroll), the SVG writer shows what the raster has. */
int pc_record_pixels(pc_canvas *c, int x0, int y0, int x1, int y1);

/* ---- graphics blocks (GET and PUT) ------------------------------------------------------ */

typedef struct {
    int w, h;
    uint16_t *px;        /* w*h attributes, row-major */
} pc_block;

/* PUT's actions */
enum { PC_PUT_PSET, PC_PUT_PRESET, PC_PUT_AND, PC_PUT_OR, PC_PUT_XOR };

/* GET (x1,y1)-(x2,y2): the block of pixels between two corners given in world coordinates
 * (WINDOW applies), inclusive.  Both corners must lie inside the view (QBasic's Illegal
 * function call otherwise): PC_EARG with the reason.  The block is allocated into *out (free
 * it with pc_block_free). */
int pc_get_block(pc_canvas *c, double x1, double y1, double x2, double y2, pc_block **out);
void pc_block_free(pc_block *b);
/* The bytes QBasic's GET stores for a w x h block in this mode: 4 for the header plus the
 * rows, each (w * bits per pixel + 7) / 8 bytes per plane (planar EGA modes: 4 planes of 1
 * bit; SCREEN 13 one byte a pixel).  Programs size GET's array by it. */
long pc_block_bytes(const pc_canvas *c, int w, int h);

/* PUT (x,y), block, action: the block's top-left pixel at the world point (x,y).  The whole
 * block must fit in the view (PC_EARG otherwise).  PSET copies, PRESET copies the complement
 * (ncolors - 1 - attribute, QBasic's bitwise NOT within the colour bits), AND, OR and XOR
 * combine bit by bit with the screen; XOR twice restores the screen.  The graphics cursor
 * does not move. */
int pc_put_block(pc_canvas *c, double x, double y, const pc_block *b, int action);

/* ---- DRAW ------------------------------------------------------------------------------- */

/* The state DRAW keeps between statements (reset by SCREEN): colour (-1: the foreground),
 * scale S (units of 1/4 pixel, 4 by default), angle A (0..3, quarter turns) and turn TA
 * (degrees). */
typedef struct {
    int color;
    double scale;
    int angle;
    double turn;
    double aspect;   /* the pixel aspect of the screen (CIRCLE's, 1 by default): a turned
                        figure keeps its size on a 4:3 monitor, as QBasic's DRAW does */
} pc_draw_state;
void pc_draw_state_reset(pc_draw_state *st);

/* ---- pages: QBasic's video memory (qbpages.c) --------------------------------------------- */

#define PC_MAX_PAGES 8
/* The pages of a screen: c the page drawn on (the active one), pages[0..npages-1] the screen's
 * pages (pages[0] the first canvas, the others made on first use), `visual` the page shown
 * and saved, and DRAW's state kept between statements. */
typedef struct {
    pc_canvas *c;
    pc_canvas *pages[PC_MAX_PAGES];
    int npages, active, visual;
    pc_draw_state draw;
} pc_pages;
/* One page of SCREEN 12; PC_ENOMEM. */
int pc_pages_init(pc_pages *p);
void pc_pages_free(pc_pages *p);
/* The page shown: the visual page, or the page drawn on before any was made. */
pc_canvas *pc_pages_shown(const pc_pages *p);
/* Page n, made on first use as a blank screen like page 0 (its palette too); NULL when the
 * screen has no page n, or out of memory. */
pc_canvas *pc_pages_page(pc_pages *p, int n);
/* SCREEN: back to one page (the page drawn on becomes page 0, the others dropped), reset to
 * m's size and colours with m's number of pages, in pixel coordinates; DRAW's state reset. */
int pc_pages_screen(pc_pages *p, const pc_mode_info *m);
/* SCREEN , , active, visual: draw on one page, show another (both made); PC_EARG for a page
 * the screen does not have, PC_ENOMEM. */
int pc_pages_set(pc_pages *p, int active, int visual);
/* PALETTE: the palette is the video card's, so every page takes the change. */
int pc_pages_palette(pc_pages *p, int attr, pc_rgb rgb);

/* Run a DRAW string from the graphics cursor: U D L R E F G H n (default 1), M x,y (absolute
 * in view pixels) and M +-x,+-y (relative), the prefixes B (move only) and N (return after),
 * C n, S n, A n, TA n, P paint,border.  Spaces and ';' separate commands.  Distances are in
 * pixels times scale/4, turned by A and TA (counter-clockwise on the screen, the turn done on
 * the monitor: in SCREEN 2 "A1 R10" goes up 10 * 0.4167 pixels, so the figure keeps its size
 * and shape; st->aspect is that ratio); lines are drawn
 * between the rounded end points as LINE draws them, and the cursor moves to the end.  X
 * (substrings) and '=' (numbers from variables) are the caller's to expand first.  A command
 * it cannot read is PC_EARG with the position named. */
int pc_draw_macro(pc_canvas *c, pc_draw_state *st, const char *cmds);
/* DRAW on the page drawn on with the pages' state, its turns at the aspect of the mode the
 * canvas is in (SCREEN 1, 2...: a figure keeps its size on a 4:3 monitor), else 1. */
int pc_pages_draw(pc_pages *p, const char *cmds);

/* ---- PAINT with a tile ------------------------------------------------------------------ */

/* A paint pattern: w x h attributes, row-major, repeated over the screen from pixel 0,0. */
typedef struct {
    int w, h;
    uint16_t attr[8 * 64];
} pc_tile;

/* QBasic's tile string (PAINT (x, y), tile$): n bytes (1..64) describing rows of the pattern
 * the way the mode keeps pixels in video memory: 1 bit a pixel in SCREEN 2 (a byte is a row
 * of 8 pixels, the high bit leftmost), 2 bits in SCREEN 1 (a byte is 4 pixels), 4 planes in
 * the 16-colour modes (4 bytes a row of 8 pixels: blue, green, red, intensity; a short last
 * row is completed with 0), one byte a pixel in SCREEN 13 (8 bytes a row).  PC_EARG for an
 * empty or too long string. */
int pc_tile_from_bytes(pc_canvas *c, const unsigned char *bytes, size_t n, pc_tile *out);

/* PAINT (x, y), tile, border: the region around (x, y) bounded by the border colour (border
 * < 0: the foreground colour) filled with the tile; the painted box is recorded as pixels
 * for the SVG writer (raster.c). */
int pc_paint_tile(pc_canvas *c, double x, double y, const pc_tile *tile, int border);
/* The two in one: PAINT (x, y), tile$, border with the tile string's n bytes (paint_tile). */
int pc_paint_tile_bytes(pc_canvas *c, double x, double y, const unsigned char *bytes, size_t n, int border);

/* ---- pages ------------------------------------------------------------------------------ */

/* PCOPY: make dst's picture a copy of src's (pixels and display list); dst keeps its WINDOW,
 * VIEW, colours and cursor.  Both must have the same size and colours. */
int pc_canvas_copy_picture(pc_canvas *dst, const pc_canvas *src);

/* ---- the statements' arguments (qbstatements.c) ------------------------------------------ */

/* VIEW with the corners as given: rounded to whole pixels; corners beyond any screen (over
 * 1e6 away) refused as not inside the screen. */
int pc_view_at(pc_canvas *c, double x1, double y1, double x2, double y2, int fill, int border, int screen);
/* PALETTE's colour number 65536*blue + 256*green + red, each 0..63, as 8-bit rgb; PC_EARG for
 * any other number. */
int pc_rgb_qbasic(long long q, pc_rgb *out);
/* PMAP(v, fn): fn 0 and 1 a world x or y to view pixels (rounded), 2 and 3 pixels back to the
 * world; the pixels count from the view's corner unless VIEW SCREEN. */
double pc_pmap(const pc_canvas *c, double v, int fn);

/* LINE: a segment, with box 1 a box's outline, box 2 a filled box; pattern 0..0xffff is the
 * 16-bit line style (QBasic's INTEGER -21846 is 0xAAAA), which a filled box ignores; -1 none. */
int pc_line_stmt(pc_canvas *c, double x1, double y1, double x2, double y2, int color, int box, long pattern);
/* The message of c's last failure without a leading statement name ("pset: "), for the
 * caller to put its own name first. */
const char *pc_canvas_message(const pc_canvas *c);

#endif
