/* The code point of each byte of code page 437 as QBasic's screen shows it, for the build tools
 * cp437.c (the code page table) and psf2c.c (the BIOS's glyphs under these code points): the C
 * library's iconv, and for the control bytes PRINT does not act on the pictures the screen shows
 * (CHR$(1) a face, CHR$(3) a heart, CHR$(24) an arrow up, ...) as Unicode's characters for the
 * IBM PC's glyphs.  PRINT acts on the others (7 the bell, 9 a tab, 10..13 new lines, home and
 * CLS, 28..31 cursor moves), so they stay controls. */
#ifndef PC_CP437_CODE_H
#define PC_CP437_CODE_H
#include <iconv.h>
#include <stddef.h>
#include <stdint.h>

static const struct { uint8_t byte; uint16_t cp; } cp437_pictures[] = {
    {1, 0x263a}, {2, 0x263b}, {3, 0x2665}, {4, 0x2666}, {5, 0x2663}, {6, 0x2660}, {8, 0x25d8},
    {14, 0x266b}, {15, 0x263c}, {16, 0x25ba}, {17, 0x25c4}, {18, 0x2195}, {19, 0x203c},
    {20, 0x00b6}, {21, 0x00a7}, {22, 0x25ac}, {23, 0x21a8}, {24, 0x2191}, {25, 0x2193},
    {26, 0x2192}, {27, 0x2190}, {127, 0x2302},
};

/* The code point of byte b through cd (iconv_open("UTF-32LE", "CP437")) into *cp; 0 if the
 * converter gives no single character. */
static inline int cp437_code_point(iconv_t cd, int b, uint32_t *cp) {
    char in = (char)b, out[8];
    char *ip = &in, *op = out;
    size_t il = 1, ol = sizeof out;
    if (iconv(cd, &ip, &il, &op, &ol) == (size_t)-1 || ol != 4) return 0;
    const unsigned char *u = (const unsigned char *)out;
    *cp = u[0] | (uint32_t)u[1] << 8 | (uint32_t)u[2] << 16 | (uint32_t)u[3] << 24;
    for (size_t i = 0; i < sizeof cp437_pictures / sizeof cp437_pictures[0]; i++)
        if (cp437_pictures[i].byte == b) *cp = cp437_pictures[i].cp;
    return 1;
}

#endif
