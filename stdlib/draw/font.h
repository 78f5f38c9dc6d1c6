/* The built-in bitmap font: VGA 8x16 character cells, so raster output needs no font files.
 * The glyphs and the Unicode table are generated at build time (tools/psf2c.c) from the
 * console font Uni2-VGA16 of the Debian package console-setup-linux (Latin, Greek, Cyrillic),
 * code page 437's accented letters, box drawings and blocks (128..223) from the VGA BIOS image
 * of the Debian package vgabios (the font QBasic's screen shows; Uni2 draws the double lines as
 * single ones, lacks the half blocks and places the accents otherwise); nothing of the font is kept in the repository.  The 8x8 and 8x14 cells of
 * QBasic's other screen modes (13, 1, 2, 7: 8x8; 9: 8x14) take all of code page 437 from the
 * BIOS (IBM's 8x8 and 8x14 designs; Uni2-VGA8 and Uni2-VGA14, other designs, give the rest),
 * and the code page 437 table of QBasic's strings comes from iconv (tools/cp437.c).
 *
 * Pure C: no Lua. */
#ifndef PC_FONT_H_INCLUDED
#define PC_FONT_H_INCLUDED

#include <stddef.h>
#include <stdint.h>

#define PC_FONT_W 8
#define PC_FONT_H 16
/* The row whose top edge is the baseline: capitals and digits end on row 11, descenders reach
 * below.  SVG's <text> is placed by its baseline, so this puts it where the raster has it. */
#define PC_FONT_BASELINE 12

typedef struct { uint16_t cp, glyph; } pc_font_entry;

/* generated: the glyphs (row 0 at the top, bit 7 the leftmost pixel), code point -> glyph
 * sorted by code point, and the glyph drawn for characters the font lacks */
extern const size_t pc_font_nglyphs;
extern const uint8_t pc_font_bits[][16];
extern const size_t pc_font_nmap;
extern const pc_font_entry pc_font_map[];
extern const int pc_font_replacement;

/* The glyph index of a code point: the font's replacement glyph if it has none. */
int pc_font_glyph(uint32_t cp);

/* A font of 8-pixel-wide cells h rows high: the rows of glyph g start at bits + g * h;
 * capitals stand on row `baseline` (the row below their lowest ink). */
typedef struct {
    int h, baseline;
    const uint8_t *bits;
    const pc_font_entry *map;
    size_t nmap;
    int replacement;
} pc_font;
/* the generated fonts: 8x16 (the arrays above), 8x14 and 8x8 */
extern const pc_font pc_font_desc, pc_font14_desc, pc_font8_desc;
/* The font with cells of height h (8, 14 or 16); NULL for any other height. */
const pc_font *pc_font_of_height(int h);
/* The glyph index of a code point in font f (its replacement glyph if it has none). */
int pc_font_glyph_in(const pc_font *f, uint32_t cp);

/* Code page 437 (QBasic's character set): byte -> Unicode code point. */
extern const uint16_t pc_cp437[256];

/* Decode one code point of UTF-8 at s[*i] (s of n bytes), advancing *i.  Strict: overlong
 * forms, surrogates, values above U+10FFFF and truncated sequences are invalid (returns 0). */
int pc_utf8_next(const char *s, size_t n, size_t *i, uint32_t *cp);

/* The number of code points of a UTF-8 string, or -1 if it is not valid UTF-8 (*bad receives
 * the offset of the first invalid byte). */
long pc_utf8_count(const char *s, size_t n, size_t *bad);

#endif
