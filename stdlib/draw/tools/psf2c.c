/* psf2c: convert a PC Screen Font (PSF1 or PSF2, 8 pixels wide, with a Unicode table) into C
 * source for a built-in VGA font (font.h): the glyph bitmaps, a table from code point to glyph
 * sorted by code point, and the replacement glyph (U+FFFD if the font has it, else '?').  Run
 * at build time on the console fonts of the Debian package console-setup-linux and the VGA
 * BIOS image of the package vgabios, so no font data lives in the repository.
 *   psf2c FONT.psf OUT.c [HEIGHT PREFIX [ROM BYTES]]
 * HEIGHT (default 16) is the glyph height the font must have (8, 14 and 16: QBasic's cells);
 * PREFIX (default pc_font) names the generated arrays PREFIX_bits, PREFIX_map, ...
 * ROM, a VGA BIOS image (Debian's vgabios), gives code page 437's BYTES ("1-31,127-223") as
 * the BIOS draws them: QBasic's screen uses the BIOS font, and the console fonts differ (the
 * 8x8 and 8x14 Uni2 cells are other designs; Uni2-VGA16 draws the double lines of the box
 * drawings as single ones and lacks the half blocks).  The BIOS's table of HEIGHT-row glyphs
 * is found by the shapes of its blocks (CHR$(219) full, 221 and 222 the left and right
 * halves, 220 and 223 the lower and upper), and must be found once.  The control bytes that
 * PRINT shows (CHR$(1) a face, CHR$(3) a heart) get the BIOS's pictures under the code points
 * the code page table gives them (cp437_code.h). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cp437_code.h"

typedef struct { uint32_t cp; uint32_t glyph; } entry;

static entry *map;
static size_t nmap, capmap;

static void die(const char *msg, const char *arg) {
    fprintf(stderr, "psf2c: %s%s%s\n", msg, arg ? ": " : "", arg ? arg : "");
    exit(1);
}

static void add(uint32_t cp, uint32_t glyph) {
    if (cp > 0xffff) return;   /* the font module keeps the Basic Multilingual Plane */
    if (nmap == capmap) {
        capmap = capmap ? 2 * capmap : 1024;
        map = realloc(map, capmap * sizeof *map);
        if (!map) die("out of memory", NULL);
    }
    map[nmap++] = (entry){cp, glyph};
}

static uint32_t le32(const uint8_t *p) {
    return p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* PSF1: 16-bit code points per glyph, 0xFFFE starts a sequence (skipped), 0xFFFF ends. */
static void psf1_table(const uint8_t *p, const uint8_t *end, uint32_t nglyphs) {
    for (uint32_t g = 0; g < nglyphs && p + 1 < end; g++) {
        int in_seq = 0;
        for (; p + 1 < end; p += 2) {
            uint32_t v = p[0] | (uint32_t)p[1] << 8;
            if (v == 0xffff) { p += 2; break; }
            if (v == 0xfffe) in_seq = 1;
            else if (!in_seq) add(v, g);
        }
    }
}

/* One UTF-8 code point of a PSF2 table; 0 if malformed. */
static int utf8(const uint8_t **pp, const uint8_t *end, uint32_t *cp) {
    const uint8_t *p = *pp;
    int n = p[0] < 0x80 ? 0 : p[0] >= 0xf0 ? 3 : p[0] >= 0xe0 ? 2 : p[0] >= 0xc0 ? 1 : -1;
    if (n < 0 || p + n >= end) return 0;
    uint32_t v = n ? p[0] & (0x3f >> n) : p[0];
    for (int i = 1; i <= n; i++) v = v << 6 | (p[i] & 0x3f);
    *cp = v;
    *pp = p + n + 1;
    return 1;
}

/* PSF2: UTF-8 code points per glyph, 0xFE starts a sequence (skipped), 0xFF ends. */
static void psf2_table(const uint8_t *p, const uint8_t *end, uint32_t nglyphs) {
    for (uint32_t g = 0; g < nglyphs && p < end; g++) {
        int in_seq = 0;
        while (p < end) {
            if (*p == 0xff) { p++; break; }
            if (*p == 0xfe) { in_seq = 1; p++; continue; }
            uint32_t cp;
            if (!utf8(&p, end, &cp)) die("malformed Unicode table", NULL);
            if (!in_seq) add(cp, g);
        }
    }
}

static int by_cp(const void *a, const void *b) {
    const entry *x = a, *y = b;
    if (x->cp != y->cp) return x->cp < y->cp ? -1 : 1;
    return x->glyph < y->glyph ? -1 : x->glyph > y->glyph;
}

static uint8_t *read_all(const char *path, size_t *n) {
    FILE *f = fopen(path, "rb");
    if (!f) die("cannot open", path);
    size_t cap = 1 << 16;
    uint8_t *buf = malloc(cap);
    *n = 0;
    for (size_t got; buf && (got = fread(buf + *n, 1, cap - *n, f)) > 0;) {
        *n += got;
        if (*n == cap) buf = realloc(buf, cap *= 2);
    }
    fclose(f);
    if (!buf) die("out of memory", NULL);
    return buf;
}

typedef struct {
    uint8_t *data;
    const uint8_t *glyphs;
    uint32_t nglyphs, charsize;
} font;

/* Read the PSF font at path (cells 8 wide, want_h high), its Unicode table into map. */
static font load(const char *path, uint32_t want_h) {
    size_t n;
    uint8_t *d = read_all(path, &n);
    const uint8_t *glyphs, *end = d + n;
    uint32_t nglyphs, height, width = 8, charsize;
    int v2 = n >= 32 && le32(d) == 0x864ab572;
    if (v2) {
        uint32_t hdr = le32(d + 8), flags = le32(d + 12);
        nglyphs = le32(d + 16);
        charsize = le32(d + 20);
        height = le32(d + 24);
        width = le32(d + 28);
        if (!(flags & 1)) die("the font has no Unicode table", path);
        glyphs = d + hdr;
    } else if (n >= 4 && d[0] == 0x36 && d[1] == 0x04) {
        if (!(d[2] & 0x02)) die("the font has no Unicode table", path);
        nglyphs = d[2] & 0x01 ? 512 : 256;
        charsize = height = d[3];
        glyphs = d + 4;
    } else {
        die("not a PSF font", path);
    }
    if (width != 8 || height != want_h || charsize != want_h)
        die("the font does not have the asked 8-pixel-wide cells of HEIGHT rows", path);
    if (glyphs + (size_t)nglyphs * charsize > end) die("the font is truncated", path);
    if (v2) psf2_table(glyphs + nglyphs * charsize, end, nglyphs);
    else psf1_table(glyphs + nglyphs * charsize, end, nglyphs);
    return (font){d, glyphs, nglyphs, charsize};
}

/* The rows of output glyph g: f's own, then the ROM's extra[] in order. */
static const uint8_t *extra[256];
static const uint8_t *bits_of(const font *f, uint32_t g) {
    return g < f->nglyphs ? f->glyphs + (size_t)g * f->charsize : extra[g - f->nglyphs];
}

static int all(const uint8_t *rows, uint32_t n, uint8_t v) {
    for (uint32_t r = 0; r < n; r++)
        if (rows[r] != v) return 0;
    return 1;
}

/* The offset of the BIOS's font of h-row glyphs in rom (n bytes): the one place where the
 * blocks have their shapes and NUL and the space are blank. */
static size_t find_rom_font(const uint8_t *rom, size_t n, uint32_t h, const char *path) {
    size_t found = 0, count = 0;
    for (size_t o = 0; o + 256 * (size_t)h <= n; o++) {
        const uint8_t *g = rom + o;
        if (all(g, h, 0) && all(g + 32 * h, h, 0) && all(g + 219 * h, h, 0xff) &&
            all(g + 221 * h, h, 0xf0) && all(g + 222 * h, h, 0x0f) && g[220 * h] == 0 &&
            g[221 * h - 1] == 0xff && g[223 * h] == 0xff && g[224 * h - 1] == 0) {
            found = o;
            count++;
        }
    }
    if (count != 1) die("no single font of HEIGHT rows in the VGA BIOS image", path);
    return found;
}

int main(int argc, char **argv) {
    if (argc != 3 && argc != 5 && argc != 7)
        die("usage: psf2c FONT.psf OUT.c [HEIGHT PREFIX [ROM BYTES]]", NULL);
    uint32_t want_h = argc >= 5 ? (uint32_t)atoi(argv[3]) : 16;
    const char *prefix = argc >= 5 ? argv[4] : "pc_font";
    if (want_h < 1 || want_h > 32) die("bad HEIGHT", argv[3]);
    font f = load(argv[1], want_h);
    uint32_t charsize = f.charsize, nglyphs = f.nglyphs, nextra = 0;
    uint8_t *rom = NULL;
    if (argc == 7) {
        size_t n;
        rom = read_all(argv[5], &n);
        int take[256] = {0};
        for (const char *r = argv[6]; *r;) {   /* "LO-HI,LO-HI,..." */
            char *end;
            long lo = strtol(r, &end, 10), hi = *end == '-' ? strtol(end + 1, &end, 10) : lo;
            if (end == r || lo < 1 || hi > 255 || lo > hi || (*end && *end != ','))
                die("bad BYTES", argv[6]);
            for (long b = lo; b <= hi; b++) take[b] = 1;
            r = *end ? end + 1 : end;
        }
        const uint8_t *table = rom + find_rom_font(rom, n, want_h, argv[5]);
        iconv_t cd = iconv_open("UTF-32LE", "CP437");
        if (cd == (iconv_t)-1) die("iconv has no CP437", NULL);
        for (int b = 1; b < 256; b++) {
            if (!take[b]) continue;
            uint32_t cp;
            if (!cp437_code_point(cd, b, &cp)) die("iconv: no CP437", NULL);
            if (cp < 0x20 || cp == 0x7f) continue;   /* a control PRINT acts on */
            for (size_t i = 0; i < nmap; i++)   /* the ROM's glyph replaces FONT's */
                if (map[i].cp == cp) map[i].cp = UINT32_MAX;
            extra[nextra] = table + (size_t)b * want_h;
            add(cp, nglyphs + nextra++);
        }
        iconv_close(cd);
    }

    /* sorted, one glyph per code point (the first the table names) */
    qsort(map, nmap, sizeof *map, by_cp);
    size_t k = 0;
    for (size_t i = 0; i < nmap; i++)
        if (map[i].cp != UINT32_MAX && (k == 0 || map[k - 1].cp != map[i].cp)) map[k++] = map[i];
    nmap = k;
    long replacement = -1, question = -1;
    for (size_t i = 0; i < nmap; i++) {
        if (map[i].cp == 0xfffd) replacement = map[i].glyph;
        if (map[i].cp == '?') question = map[i].glyph;
    }
    if (replacement < 0) replacement = question;
    if (replacement < 0) die("the font has neither U+FFFD nor '?'", argv[1]);

    FILE *out = fopen(argv[2], "w");
    if (!out) die("cannot write", argv[2]);
    fprintf(out, "/* Generated by psf2c from a PSF console font and a VGA BIOS at build time: "
                 "do not edit. */\n"
                 "#include \"font.h\"\n\n"
                 "const size_t %s_nglyphs = %u;\n"
                 "const uint8_t %s_bits[%u][%u] = {\n", prefix, nglyphs + nextra, prefix,
            nglyphs + nextra, charsize);
    for (uint32_t g = 0; g < nglyphs + nextra; g++) {
        const uint8_t *bits = bits_of(&f, g);
        fputs("    {", out);
        for (uint32_t r = 0; r < charsize; r++)
            fprintf(out, "0x%02x%s", bits[r], r + 1 < charsize ? ", " : "");
        fputs("},\n", out);
    }
    fprintf(out, "};\n\nconst size_t %s_nmap = %zu;\n"
                 "const pc_font_entry %s_map[%zu] = {\n", prefix, nmap, prefix, nmap);
    for (size_t i = 0; i < nmap; i++)
        fprintf(out, "    {0x%04x, %u},\n", (unsigned)map[i].cp, (unsigned)map[i].glyph);
    fprintf(out, "};\n\nconst int %s_replacement = %ld;\n", prefix, replacement);
    /* the baseline: the row below the lowest ink of 'H' (capitals stand on it) */
    uint32_t base = charsize;
    for (size_t i = 0; i < nmap; i++)
        if (map[i].cp == 'H')
            for (base = charsize; base > 0 && !bits_of(&f, map[i].glyph)[base - 1];) base--;
    fprintf(out, "const pc_font %s_desc = {%u, %u, &%s_bits[0][0], %s_map, %zu, %ld};\n", prefix,
            charsize, base, prefix, prefix, nmap, replacement);
    int bad = ferror(out);
    if (fclose(out) != 0 || bad) die("cannot write", argv[2]);
    free(map);
    free(f.data);
    free(rom);
    return 0;
}
