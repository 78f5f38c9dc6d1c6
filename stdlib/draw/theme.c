/* The colours the writers use.  The screen theme is the canvas palette as it is at write time
 * (PALETTE may have changed it after drawing, as in QBasic).  The paper theme is for print:
 * white paper, dark ink.
 *
 * Paper theme, 16 colours (by colour, so it follows PALETTE): the screen's background
 * (attribute 0, whatever its colour) is the paper, white.  Ink colours that are bright on the
 * black screen are darkened until they read on white; a colour keeps its hue, and a bright
 * variant stays lighter than its dark variant so the two remain distinguishable.  The greys
 * are inverted so that emphasis is kept: white ink (the QBasic default, 15) prints black,
 * light grey (7) dark grey, and dark grey (8), faint on the screen, a lighter grey that is
 * still faint on paper.  Contrast against white (WCAG ratio) is given for each.
 *
 *   attr  screen      paper       contrast
 *    0    black       #ffffff     (paper)
 *    1    #0000aa     #0000aa     13.3   blue is already dark
 *    2    #00aa00     #007a00      5.6
 *    3    #00aaaa     #007070      5.9
 *    4    #aa0000     #aa0000      7.8
 *    5    #aa00aa     #8c008c      8.4
 *    6    #aa5500     #8a4500      7.2   brown
 *    7    #aaaaaa     #555555      7.5   light grey -> dark grey
 *    8    #555555     #999999      2.9   dark grey -> light grey (grids, helper lines)
 *    9    #5555ff     #3434e0      7.7
 *   10    #55ff55     #1e8c1e      4.4
 *   11    #55ffff     #008c8c      4.1
 *   12    #ff5555     #d02020      5.4
 *   13    #ff55ff     #b020b0      5.7
 *   14    #ffff55     #a07800      4.1   yellow -> dark gold
 *   15    #ffffff     #000000     21.0
 *
 * Any other colour (256-colour screens, or a colour set with PALETTE) follows the same idea by
 * formula: attribute 0 is white; a grey (channels within 12 of each other) is inverted,
 * 255 - v; a coloured ink keeps its hue and has its luminance compressed into 0..0.2 (dark
 * colours stay as they are, bright ones darken, the order of brightness is kept).
 */
#include <math.h>
#include <string.h>
#include "writers.h"

static const pc_rgb ega_screen[16] = {
    {0x00, 0x00, 0x00}, {0x00, 0x00, 0xaa}, {0x00, 0xaa, 0x00}, {0x00, 0xaa, 0xaa},
    {0xaa, 0x00, 0x00}, {0xaa, 0x00, 0xaa}, {0xaa, 0x55, 0x00}, {0xaa, 0xaa, 0xaa},
    {0x55, 0x55, 0x55}, {0x55, 0x55, 0xff}, {0x55, 0xff, 0x55}, {0x55, 0xff, 0xff},
    {0xff, 0x55, 0x55}, {0xff, 0x55, 0xff}, {0xff, 0xff, 0x55}, {0xff, 0xff, 0xff}};

static const pc_rgb ega_paper[16] = {
    {0xff, 0xff, 0xff}, {0x00, 0x00, 0xaa}, {0x00, 0x7a, 0x00}, {0x00, 0x70, 0x70},
    {0xaa, 0x00, 0x00}, {0x8c, 0x00, 0x8c}, {0x8a, 0x45, 0x00}, {0x55, 0x55, 0x55},
    {0x99, 0x99, 0x99}, {0x34, 0x34, 0xe0}, {0x1e, 0x8c, 0x1e}, {0x00, 0x8c, 0x8c},
    {0xd0, 0x20, 0x20}, {0xb0, 0x20, 0xb0}, {0xa0, 0x78, 0x00}, {0x00, 0x00, 0x00}};

static double to_linear(int v) {
    double s = v / 255.0;
    return s <= 0.04045 ? s / 12.92 : pow((s + 0.055) / 1.055, 2.4);
}

static int to_srgb(double l) {
    if (l <= 0) return 0;
    if (l >= 1) return 255;
    double s = l <= 0.0031308 ? l * 12.92 : 1.055 * pow(l, 1 / 2.4) - 0.055;
    return (int)lrint(s * 255);
}

static int same(pc_rgb a, pc_rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

/* The print version of one ink colour (not the background). */
static pc_rgb paper_ink(pc_rgb c) {
    for (int i = 0; i < 16; i++)
        if (same(c, ega_screen[i])) return ega_paper[i];
    int mx = c.r > c.g ? (c.r > c.b ? c.r : c.b) : (c.g > c.b ? c.g : c.b);
    int mn = c.r < c.g ? (c.r < c.b ? c.r : c.b) : (c.g < c.b ? c.g : c.b);
    if (mx - mn <= 12) return (pc_rgb){(uint8_t)(255 - c.r), (uint8_t)(255 - c.g), (uint8_t)(255 - c.b)};
    double r = to_linear(c.r), g = to_linear(c.g), b = to_linear(c.b);
    double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    double target = fmin(y, 0.06 + 0.14 * y);   /* 0..1 -> 0..0.2, identity below 0.07 */
    double k = y > 0 ? target / y : 1;
    return (pc_rgb){(uint8_t)to_srgb(r * k), (uint8_t)to_srgb(g * k), (uint8_t)to_srgb(b * k)};
}

void pc_theme_palette(const pc_canvas *c, pc_theme theme, pc_rgb out[256]) {
    memcpy(out, c->palette, 256 * sizeof *out);
    if (theme != PC_THEME_PAPER) return;
    out[0] = (pc_rgb){255, 255, 255};
    for (int i = 1; i < 256; i++) out[i] = paper_ink(c->palette[i]);
}
