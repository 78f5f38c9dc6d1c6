/* Looking up glyphs of the built-in font, and decoding UTF-8. */
#include "font.h"

static int lookup(const pc_font_entry *map, size_t nmap, int replacement, uint32_t cp) {
    size_t lo = 0, hi = nmap;
    while (lo < hi) {   /* binary search of the sorted table */
        size_t mid = (lo + hi) / 2;
        if (map[mid].cp < cp) lo = mid + 1;
        else hi = mid;
    }
    if (lo < nmap && map[lo].cp == cp) return map[lo].glyph;
    return replacement;
}

int pc_font_glyph(uint32_t cp) {
    return lookup(pc_font_map, pc_font_nmap, pc_font_replacement, cp);
}

const pc_font *pc_font_of_height(int h) {
    switch (h) {
    case 8: return &pc_font8_desc;
    case 14: return &pc_font14_desc;
    case 16: return &pc_font_desc;
    default: return NULL;
    }
}

int pc_font_glyph_in(const pc_font *f, uint32_t cp) {
    return lookup(f->map, f->nmap, f->replacement, cp);
}

int pc_utf8_next(const char *s, size_t n, size_t *i, uint32_t *cp) {
    const unsigned char *p = (const unsigned char *)s + *i;
    size_t left = n - *i;
    if (left == 0) return 0;
    unsigned c0 = p[0];
    int len;
    uint32_t v, min;
    if (c0 < 0x80) { *cp = c0; *i += 1; return 1; }
    if (c0 >= 0xc2 && c0 <= 0xdf) { len = 2; v = c0 & 0x1f; min = 0x80; }
    else if (c0 >= 0xe0 && c0 <= 0xef) { len = 3; v = c0 & 0x0f; min = 0x800; }
    else if (c0 >= 0xf0 && c0 <= 0xf4) { len = 4; v = c0 & 0x07; min = 0x10000; }
    else return 0;
    if (left < (size_t)len) return 0;
    for (int k = 1; k < len; k++) {
        if ((p[k] & 0xc0) != 0x80) return 0;
        v = v << 6 | (p[k] & 0x3f);
    }
    if (v < min || v > 0x10ffff || (v >= 0xd800 && v <= 0xdfff)) return 0;
    *cp = v;
    *i += (size_t)len;
    return 1;
}

long pc_utf8_count(const char *s, size_t n, size_t *bad) {
    size_t i = 0;
    long count = 0;
    uint32_t cp;
    while (i < n) {
        if (!pc_utf8_next(s, n, &i, &cp)) {
            if (bad) *bad = i;
            return -1;
        }
        count++;
    }
    return count;
}
