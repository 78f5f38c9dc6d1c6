/* The canvas as Unicode braille text, for a terminal (the REPL's :show).
 *
 * A braille cell (U+2800..U+28FF) holds 2x4 dots.  A terminal cell is about twice as tall as it
 * is wide, so the dots come out square: the canvas is scaled by one factor, `scale` canvas
 * pixels per dot in both directions.  A dot is set when any pixel of its block is ink (not the
 * background attribute), so one-pixel lines survive the reduction.  Each cell gets one colour:
 * the ink attribute that covers most pixels of the cell.
 *
 * Pure C: no Lua. */
#ifndef PC_BRAILLE_H
#define PC_BRAILLE_H

#include <stdint.h>
#include <stdio.h>
#include "canvas.h"

/* One cell: the dot pattern (bit k is braille dot k+1, so the character is U+2800 + bits) and
 * the colour attribute (-1 for an empty cell).  Dots by position in the cell:
 *     bit 0  bit 3
 *     bit 1  bit 4
 *     bit 2  bit 5
 *     bit 6  bit 7 */
typedef struct {
    uint8_t bits;
    int32_t color;
} pc_braille_cell;

/* The bit of the dot in column dx (0..1) and row dy (0..3) of a cell. */
uint8_t pc_braille_bit(int dx, int dy);

/* The grid for a width x height canvas in at most max_cols x max_rows cells: returns the scale
 * (canvas pixels per dot, never below 1: small canvases are shown pixel for pixel) and the grid
 * size in *cols, *rows (each at least 1). */
double pc_braille_fit(int width, int height, int max_cols, int max_rows, int *cols, int *rows);

/* Render the canvas into cells[rows * cols] (row-major).  The dot in column dx, row dy of the
 * whole picture covers the pixels floor(dx*scale) .. floor((dx+1)*scale)-1 (likewise for y);
 * `background` is the attribute that counts as empty paper. */
void pc_braille_render(const pc_canvas *c, int background, double scale, int cols, int rows,
                       pc_braille_cell *cells);

/* How colours reach the terminal. */
typedef enum {
    PC_TERM_MONO,    /* no escape sequences */
    PC_TERM_16,      /* SGR 30-37 / 90-97 */
    PC_TERM_256,     /* SGR 38;5;N: the xterm 6x6x6 cube and grey ramp */
    PC_TERM_RGB      /* SGR 38;2;R;G;B */
} pc_term_colors;

/* The SGR parameters that select rgb as the foreground in the given mode ("" for MONO), into
 * buf (at least 20 bytes).  Returns buf. */
char *pc_term_color(pc_rgb rgb, pc_term_colors mode, char *buf);

/* Write the cells as UTF-8 text, one line per row, each line ending in "\n".  Empty cells are
 * spaces.  palette gives the colour of each attribute; a cell whose colour is pure white is
 * written in the terminal's default foreground, so white ink (QBasic's default colour 15)
 * shows on light and dark terminals alike.  With frame set, a box-drawing frame surrounds the
 * picture (dimmed when colours are on).  Returns 0, or -1 on a write error. */
int pc_braille_print(FILE *out, const pc_braille_cell *cells, int cols, int rows,
                     const pc_rgb *palette, pc_term_colors mode, int frame);

#endif
