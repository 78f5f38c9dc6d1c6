/* The built-in bitmap font: VGA 8x16 character cells, so raster output needs no font files.
 * The glyphs and the Unicode table are generated at build time (tools/psf2c.c) from the
 * console font Uni2-VGA16 of the Debian package console-setup-linux (Latin, Greek, Cyrillic,
 * box drawing); nothing of the font is kept in the repository.
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

/* Decode one code point of UTF-8 at s[*i] (s of n bytes), advancing *i.  Strict: overlong
 * forms, surrogates, values above U+10FFFF and truncated sequences are invalid (returns 0). */
int pc_utf8_next(const char *s, size_t n, size_t *i, uint32_t *cp);

/* The number of code points of a UTF-8 string, or -1 if it is not valid UTF-8 (*bad receives
 * the offset of the first invalid byte). */
long pc_utf8_count(const char *s, size_t n, size_t *bad);

#endif
