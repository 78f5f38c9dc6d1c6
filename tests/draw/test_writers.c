/* The raster writers, the themes and atomic file writing: exact bytes and pixels. */
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>
#include "canvas.h"
#include "writers.h"

static pc_canvas *canvas(int w, int h, int ncolors) {
    pc_canvas *c = pc_canvas_new(w, h, ncolors);
    assert_non_null(c);
    return c;
}

static void assert_rgb(pc_rgb got, unsigned r, unsigned g, unsigned b) {
    if (got.r != r || got.g != g || got.b != b)
        fail_msg("colour #%02x%02x%02x, want #%02x%02x%02x", got.r, got.g, got.b, r, g, b);
}

/* ---- formats and themes ------------------------------------------------------------------ */

static void test_format_from_path(void **state) {
    (void)state;
    assert_int_equal(pc_format_from_path("a.png"), PC_FMT_PNG);
    assert_int_equal(pc_format_from_path("dir/A.PNG"), PC_FMT_PNG);
    assert_int_equal(pc_format_from_path("x.Svg"), PC_FMT_SVG);
    assert_int_equal(pc_format_from_path("/tmp/x.y.ppm"), PC_FMT_PPM);
    assert_int_equal(pc_format_from_path("pic.gif"), PC_FMT_UNKNOWN);
    assert_int_equal(pc_format_from_path("png"), PC_FMT_UNKNOWN);
    assert_int_equal(pc_format_from_path("a.png.txt"), PC_FMT_UNKNOWN);
    assert_int_equal(pc_format_from_path("out.png/picture"), PC_FMT_UNKNOWN);
    assert_int_equal(pc_format_from_path(""), PC_FMT_UNKNOWN);
}

static void test_screen_theme_is_the_palette(void **state) {
    (void)state;
    pc_canvas *c = canvas(4, 4, 16);
    pc_rgb pal[256];
    pc_theme_palette(c, PC_THEME_SCREEN, pal);
    assert_rgb(pal[0], 0, 0, 0);
    assert_rgb(pal[4], 0xaa, 0, 0);
    assert_rgb(pal[14], 0xff, 0xff, 0x55);
    assert_rgb(pal[15], 0xff, 0xff, 0xff);
    /* PALETTE after drawing: the writers use the colours of write time */
    assert_int_equal(pc_palette(c, 4, (pc_rgb){1, 2, 3}), PC_OK);
    pc_theme_palette(c, PC_THEME_SCREEN, pal);
    assert_rgb(pal[4], 1, 2, 3);
    pc_canvas_free(c);
}

static void test_paper_theme(void **state) {
    (void)state;
    pc_canvas *c = canvas(4, 4, 16);
    pc_rgb pal[256];
    pc_theme_palette(c, PC_THEME_PAPER, pal);
    assert_rgb(pal[0], 0xff, 0xff, 0xff);    /* the paper */
    assert_rgb(pal[15], 0, 0, 0);            /* white ink prints black */
    assert_rgb(pal[7], 0x55, 0x55, 0x55);    /* light grey -> dark grey */
    assert_rgb(pal[8], 0x99, 0x99, 0x99);    /* dark grey -> lighter grey, still faint */
    assert_rgb(pal[14], 0xa0, 0x78, 0x00);   /* yellow -> dark gold */
    assert_rgb(pal[1], 0x00, 0x00, 0xaa);    /* blue is dark already */
    assert_rgb(pal[4], 0xaa, 0x00, 0x00);
    /* every ink is darker than the paper: no colour but 0 is near white */
    for (int i = 1; i < 16; i++) assert_true(pal[i].r + pal[i].g + pal[i].b < 3 * 0xa0);

    /* the theme follows PALETTE: a colour is mapped by what it is, the background stays paper */
    pc_palette(c, 3, (pc_rgb){0xff, 0xff, 0x55});
    pc_palette(c, 0, (pc_rgb){0, 0, 0xaa});
    pc_theme_palette(c, PC_THEME_PAPER, pal);
    assert_rgb(pal[3], 0xa0, 0x78, 0x00);
    assert_rgb(pal[0], 0xff, 0xff, 0xff);
    /* a colour outside the table: a grey is inverted, a bright colour darkened, hue kept */
    pc_palette(c, 5, (pc_rgb){0x40, 0x40, 0x40});
    pc_palette(c, 6, (pc_rgb){0xff, 0x80, 0x00});
    pc_theme_palette(c, PC_THEME_PAPER, pal);
    assert_rgb(pal[5], 0xbf, 0xbf, 0xbf);
    assert_true(pal[6].r < 0xff && pal[6].r > pal[6].g && pal[6].g > pal[6].b);
    pc_canvas_free(c);
}

static void test_paper_theme_256(void **state) {
    (void)state;
    pc_canvas *c = canvas(4, 4, 256);
    pc_rgb pal[256];
    pc_theme_palette(c, PC_THEME_PAPER, pal);
    assert_rgb(pal[0], 0xff, 0xff, 0xff);
    assert_rgb(pal[15], 0, 0, 0);
    assert_rgb(pal[14], 0xa0, 0x78, 0x00);
    /* the grey ramp 16..31 (black to white on the screen) runs from paper to black ink */
    assert_rgb(pal[31], 0, 0, 0);
    for (int i = 17; i < 32; i++) assert_true(pal[i].r < pal[i - 1].r);
    /* the bright hues of the wheel (32..55) become darker, their brightness order kept */
    for (int i = 32; i < 56; i++) {
        pc_rgb s = c->palette[i], p = pal[i];
        assert_true(p.r <= s.r && p.g <= s.g && p.b <= s.b);
        assert_true(p.r + p.g + p.b < s.r + s.g + s.b);
    }
    pc_canvas_free(c);
}

/* ---- PPM --------------------------------------------------------------------------------- */

static unsigned char *encode(int (*enc)(const pc_canvas *, pc_theme, FILE *), const pc_canvas *c,
                             pc_theme theme, size_t *len) {
    char *buf = NULL;
    FILE *f = open_memstream(&buf, len);
    assert_non_null(f);
    assert_int_equal(enc(c, theme, f), PC_OK);
    assert_int_equal(fclose(f), 0);
    return (unsigned char *)buf;
}

static void test_ppm_bytes(void **state) {
    (void)state;
    pc_canvas *c = canvas(3, 2, 16);
    pc_pset(c, 0, 0, 15);
    pc_pset(c, 1, 0, 4);
    pc_pset(c, 2, 1, 14);
    pc_pset(c, 0, 1, 1);
    static const unsigned char screen[] = "P6\n3 2\n255\n"
                                          "\xff\xff\xff" "\xaa\x00\x00" "\x00\x00\x00"
                                          "\x00\x00\xaa" "\x00\x00\x00" "\xff\xff\x55";
    static const unsigned char paper[] = "P6\n3 2\n255\n"
                                         "\x00\x00\x00" "\xaa\x00\x00" "\xff\xff\xff"
                                         "\x00\x00\xaa" "\xff\xff\xff" "\xa0\x78\x00";
    size_t len;
    unsigned char *b = encode(pc_encode_ppm, c, PC_THEME_SCREEN, &len);
    assert_int_equal(len, sizeof screen - 1);
    assert_memory_equal(b, screen, len);
    free(b);
    b = encode(pc_encode_ppm, c, PC_THEME_PAPER, &len);
    assert_int_equal(len, sizeof paper - 1);
    assert_memory_equal(b, paper, len);
    free(b);
    pc_canvas_free(c);
}

/* ---- PNG --------------------------------------------------------------------------------- */

typedef struct {
    int width, height, bit_depth, color_type;
    unsigned char *rgb;     /* width*height*3 */
} png_pixels;

/* Read a PNG with libpng, expanded to 8-bit RGB. */
static png_pixels read_png(FILE *f) {
    png_pixels r = {0};
    unsigned char sig[8];
    assert_int_equal(fread(sig, 1, 8, f), 8);
    assert_int_equal(png_sig_cmp(sig, 0, 8), 0);
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    assert_non_null(info);
    if (setjmp(png_jmpbuf(png))) fail_msg("libpng could not read the file back");
    png_init_io(png, f);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    r.width = (int)png_get_image_width(png, info);
    r.height = (int)png_get_image_height(png, info);
    r.bit_depth = png_get_bit_depth(png, info);
    r.color_type = png_get_color_type(png, info);
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_gray_to_rgb(png);
    png_read_update_info(png, info);
    assert_int_equal(png_get_rowbytes(png, info), (size_t)r.width * 3);
    r.rgb = malloc((size_t)r.width * r.height * 3);
    for (int y = 0; y < r.height; y++) png_read_row(png, r.rgb + (size_t)y * r.width * 3, NULL);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    return r;
}

static void assert_png_matches_as(const pc_canvas *c, pc_theme theme, int want_type, int want_depth) {
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(pc_encode_png(c, theme, f), PC_OK);
    rewind(f);
    png_pixels p = read_png(f);
    fclose(f);
    assert_int_equal(p.width, c->width);
    assert_int_equal(p.height, c->height);
    assert_int_equal(p.color_type, want_type);
    assert_int_equal(p.bit_depth, want_depth);
    pc_rgb pal[256];
    pc_theme_palette(c, theme, pal);
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) {
            pc_rgb want = pc_attr_rgb(c, pal, c->pixels[y * c->width + x]);
            const unsigned char *got = p.rgb + 3 * ((size_t)y * c->width + x);
            if (got[0] != want.r || got[1] != want.g || got[2] != want.b)
                fail_msg("pixel (%d, %d) is #%02x%02x%02x, want #%02x%02x%02x", x, y, got[0],
                         got[1], got[2], want.r, want.g, want.b);
        }
    free(p.rgb);
}

static void assert_png_matches(const pc_canvas *c, pc_theme theme, int want_depth) {
    assert_png_matches_as(c, theme, PNG_COLOR_TYPE_PALETTE, want_depth);
}

/* every colour at odd positions, an odd width (4-bit rows end in half a byte) */
static void draw_pattern(pc_canvas *c) {
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) pc_pset(c, x, y, (x * 7 + y * 3 + x * y) % c->ncolors);
    pc_circle(c, c->width / 2.0, c->height / 2.0, c->height / 3.0, c->ncolors - 1, NAN, NAN, NAN);
}

static void test_png_reads_back_16(void **state) {
    (void)state;
    pc_canvas *c = canvas(37, 23, 16);
    draw_pattern(c);
    assert_png_matches(c, PC_THEME_SCREEN, 4);
    assert_png_matches(c, PC_THEME_PAPER, 4);
    /* a palette change after drawing shows in the file */
    pc_palette(c, 9, (pc_rgb){0x12, 0x34, 0x56});
    assert_png_matches(c, PC_THEME_SCREEN, 4);
    pc_canvas_free(c);
}

static void test_png_reads_back_256_and_2(void **state) {
    (void)state;
    pc_canvas *c = canvas(300, 17, 256);
    draw_pattern(c);
    assert_png_matches(c, PC_THEME_SCREEN, 8);
    assert_png_matches(c, PC_THEME_PAPER, 8);
    pc_canvas_free(c);
    c = canvas(13, 5, 2);
    draw_pattern(c);
    assert_png_matches(c, PC_THEME_SCREEN, 1);
    pc_canvas_free(c);
}

static void test_png_screen_12(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new_mode(12);
    for (int i = 0; i <= 1000; i++) {
        double t = 6.283185307179586 * i / 1000;
        pc_pset(c, 320 + 200 * cos(t), 240 + 120 * sin(t), 14);
    }
    pc_circle(c, 320, 240, 50, 15, NAN, NAN, NAN);
    pc_paint(c, 320, 240, 1, 15);
    assert_png_matches(c, PC_THEME_SCREEN, 4);
    assert_png_matches(c, PC_THEME_PAPER, 4);
    pc_canvas_free(c);
}

/* ---- true colours ------------------------------------------------------------------------ */

static void test_true_colors_are_attributes(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new_mode(12);
    int orange = pc_rgb_color(c, (pc_rgb){0xff, 0x80, 0x00});
    assert_int_equal(orange, 256);
    /* two uses of one colour share its attribute; another colour gets the next */
    assert_int_equal(pc_rgb_color(c, (pc_rgb){0xff, 0x80, 0x00}), orange);
    int teal = pc_rgb_color(c, (pc_rgb){0x00, 0x80, 0x80});
    assert_int_equal(teal, 257);
    assert_int_equal(pc_pset(c, 10, 10, orange), PC_OK);
    assert_int_equal(pc_pset(c, 11, 10, pc_rgb_color(c, (pc_rgb){0xff, 0x80, 0x00})), PC_OK);
    assert_int_equal(pc_point(c, 10, 10), orange);
    assert_int_equal(pc_point(c, 11, 10), orange);
    assert_int_equal(c->palette[orange].g, 0x80);
    /* an attribute not allocated is refused */
    assert_int_equal(pc_pset(c, 1, 1, 258), PC_EARG);
    assert_int_equal(pc_pset(c, 1, 1, 16), PC_EARG);
    /* PAINT stops at a true-colour border; COLOR takes one */
    pc_circle(c, 100, 100, 20, teal, NAN, NAN, NAN);
    assert_int_equal(pc_paint(c, 100, 100, orange, teal), PC_OK);
    assert_int_equal(pc_point(c, 100, 100), orange);
    assert_int_equal(pc_point(c, 130, 100), 0);
    assert_int_equal(pc_color(c, teal, -1), PC_OK);
    pc_pset(c, 5, 5, -1);
    assert_int_equal(pc_point(c, 5, 5), teal);
    /* thousands of colours: each keeps its attribute */
    for (int i = 0; i < 5000; i++)
        assert_int_equal(pc_rgb_color(c, (pc_rgb){(uint8_t)i, (uint8_t)(i >> 8), 7}), 258 + i);
    for (int i = 0; i < 5000; i++)
        assert_int_equal(pc_rgb_color(c, (pc_rgb){(uint8_t)i, (uint8_t)(i >> 8), 7}), 258 + i);
    /* SCREEN forgets them */
    pc_canvas_reset(c, 640, 480, 16);
    assert_int_equal(c->ntrue, 0);
    assert_int_equal(pc_rgb_color(c, (pc_rgb){0x00, 0x80, 0x80}), 256);
    pc_canvas_free(c);
}

static void test_true_colors_in_png_and_ppm(void **state) {
    (void)state;
    pc_canvas *c = canvas(40, 30, 16);
    draw_pattern(c);
    int orange = pc_rgb_color(c, (pc_rgb){0xff, 0x80, 0x00});
    pc_line(c, 0, 5, 39, 5, orange);
    /* few colours: still an indexed PNG, of the colours used */
    assert_png_matches_as(c, PC_THEME_SCREEN, PNG_COLOR_TYPE_PALETTE, 8);
    FILE *f = tmpfile();
    assert_int_equal(pc_encode_png(c, PC_THEME_SCREEN, f), PC_OK);
    rewind(f);
    png_pixels p = read_png(f);
    fclose(f);
    const unsigned char *px = p.rgb + 3 * (5 * 40 + 7);
    assert_true(px[0] == 0xff && px[1] == 0x80 && px[2] == 0x00);
    free(p.rgb);
    /* the paper theme changes the palette colours, not the true ones */
    assert_png_matches_as(c, PC_THEME_PAPER, PNG_COLOR_TYPE_PALETTE, 8);
    pc_rgb pal[256];
    pc_theme_palette(c, PC_THEME_PAPER, pal);
    assert_int_equal(pc_attr_rgb(c, pal, orange).g, 0x80);
    assert_int_equal(pc_attr_rgb(c, pal, 15).r, 0);
    /* PPM has the rgb */
    f = tmpfile();
    assert_int_equal(pc_encode_ppm(c, PC_THEME_SCREEN, f), PC_OK);
    rewind(f);
    char head[16];
    assert_non_null(fgets(head, sizeof head, f));
    assert_non_null(fgets(head, sizeof head, f));
    assert_non_null(fgets(head, sizeof head, f));
    unsigned char rgb[3];
    fseek(f, 3 * (5 * 40 + 7), SEEK_CUR);
    assert_int_equal(fread(rgb, 1, 3, f), 3);
    assert_true(rgb[0] == 0xff && rgb[1] == 0x80 && rgb[2] == 0x00);
    fclose(f);
    /* two true colours and two palette colours: a 2-bit palette */
    pc_canvas *s = canvas(9, 3, 16);
    pc_pset(s, 0, 0, pc_rgb_color(s, (pc_rgb){1, 2, 3}));
    pc_pset(s, 1, 0, pc_rgb_color(s, (pc_rgb){4, 5, 6}));
    pc_pset(s, 2, 0, 9);
    assert_png_matches_as(s, PC_THEME_SCREEN, PNG_COLOR_TYPE_PALETTE, 2);
    /* more than 256 colours: RGB */
    for (int i = 0; i < 300; i++)
        pc_pset(c, i % 40, 10 + i / 40, pc_rgb_color(c, (pc_rgb){(uint8_t)i, (uint8_t)(i / 2), 200}));
    assert_png_matches_as(c, PC_THEME_SCREEN, PNG_COLOR_TYPE_RGB, 8);
    pc_canvas_free(c);
    pc_canvas_free(s);
}

/* A full device: the encoders report the failure (libpng's through its error handler). */
static void test_encoders_report_write_errors(void **state) {
    (void)state;
    FILE *f = fopen("/dev/full", "wb");
    if (!f) skip();
    pc_canvas *c = pc_canvas_new_mode(12);
    draw_pattern(c);
    assert_int_equal(pc_encode_ppm(c, PC_THEME_SCREEN, f), PC_EIO);
    fclose(f);
    f = fopen("/dev/full", "wb");
    assert_int_equal(pc_encode_png(c, PC_THEME_SCREEN, f), PC_EIO);
    fclose(f);
    f = fopen("/dev/full", "wb");
    assert_int_equal(pc_encode_svg(c, PC_THEME_SCREEN, f), PC_EIO);
    fclose(f);
    pc_canvas_free(c);
}

/* ---- atomic writing ---------------------------------------------------------------------- */

typedef struct { char dir[64]; } tmpdir;

static void make_dir(tmpdir *t) {
    strcpy(t->dir, "/tmp/pc_writers_XXXXXX");
    assert_non_null(mkdtemp(t->dir));
}

static char *in_dir(const tmpdir *t, const char *name) {
    static char buf[4][256];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", t->dir, name);
    return buf[k];
}

/* the names in the directory, sorted, space-separated */
static void list_dir(const char *dir, char *out, size_t n) {
    struct dirent **names;
    int k = scandir(dir, &names, NULL, alphasort);
    assert_true(k >= 0);
    out[0] = 0;
    for (int i = 0; i < k; i++) {
        if (strcmp(names[i]->d_name, ".") && strcmp(names[i]->d_name, "..")) {
            if (out[0]) strncat(out, " ", n - strlen(out) - 1);
            strncat(out, names[i]->d_name, n - strlen(out) - 1);
        }
        free(names[i]);
    }
    free(names);
}

static void remove_tree(const char *dir) {
    char cmd[300];
    snprintf(cmd, sizeof cmd, "chmod -R u+w '%s' && rm -rf '%s'", dir, dir);
    assert_int_equal(system(cmd), 0);
}

static long file_size(const char *path) {
    struct stat st;
    if (stat(path, &st) != 0) return -1;
    return (long)st.st_size;
}

static void test_write_file_formats(void **state) {
    (void)state;
    tmpdir t;
    make_dir(&t);
    pc_canvas *c = canvas(3, 2, 16);
    pc_pset(c, 1, 0, 4);
    char err[512] = "untouched";
    mode_t old = umask(022);
    assert_int_equal(pc_write_file(c, in_dir(&t, "a.ppm"), PC_THEME_SCREEN, err, sizeof err), PC_OK);
    assert_string_equal(err, "");
    assert_int_equal(pc_write_file(c, in_dir(&t, "b.PNG"), PC_THEME_PAPER, err, sizeof err), PC_OK);
    assert_int_equal(pc_write_file(c, in_dir(&t, "c.svg"), PC_THEME_SCREEN, err, sizeof err), PC_OK);
    char names[512];
    list_dir(t.dir, names, sizeof names);
    assert_string_equal(names, "a.ppm b.PNG c.svg");   /* no temporary file is left */
    assert_int_equal(file_size(in_dir(&t, "a.ppm")), 11 + 18);

    /* the format follows the extension: check each file's first bytes */
    char head[8];
    FILE *f = fopen(in_dir(&t, "b.PNG"), "rb");
    assert_int_equal(fread(head, 1, 8, f), 8);
    fclose(f);
    assert_memory_equal(head, "\x89PNG\r\n\x1a\n", 8);
    f = fopen(in_dir(&t, "c.svg"), "rb");
    assert_int_equal(fread(head, 1, 5, f), 5);
    fclose(f);
    assert_memory_equal(head, "<?xml", 5);

    /* a new file gets 0666 less the umask, not mkstemp's 0600 */
    struct stat st;
    assert_int_equal(stat(in_dir(&t, "a.ppm"), &st), 0);
    assert_int_equal(st.st_mode & 0777, 0644);
    /* an existing file is replaced, keeping its permissions */
    assert_int_equal(chmod(in_dir(&t, "a.ppm"), 0600), 0);
    pc_pset(c, 0, 0, 15);
    assert_int_equal(pc_write_file(c, in_dir(&t, "a.ppm"), PC_THEME_SCREEN, err, sizeof err), PC_OK);
    assert_int_equal(stat(in_dir(&t, "a.ppm"), &st), 0);
    assert_int_equal(st.st_mode & 0777, 0600);
    f = fopen(in_dir(&t, "a.ppm"), "rb");
    unsigned char px[3];
    fseek(f, 11, SEEK_SET);
    assert_int_equal(fread(px, 1, 3, f), 3);
    fclose(f);
    assert_memory_equal(px, "\xff\xff\xff", 3);
    umask(old);
    pc_canvas_free(c);
    remove_tree(t.dir);
}

static void test_write_file_unknown_extension(void **state) {
    (void)state;
    pc_canvas *c = canvas(3, 2, 16);
    char err[256];
    assert_int_equal(pc_write_file(c, "pic.gif", PC_THEME_SCREEN, err, sizeof err), PC_EARG);
    assert_string_equal(err, "cannot write 'pic.gif': the extension must be .png, .svg, .ppm, .pdf, .eps or .ps");
    assert_int_equal(pc_write_file(c, "picture", PC_THEME_SCREEN, err, sizeof err), PC_EARG);
    assert_string_equal(err, "cannot write 'picture': the extension must be .png, .svg, .ppm, .pdf, .eps or .ps");
    assert_int_equal(access("pic.gif", F_OK), -1);
    pc_canvas_free(c);
}

static void test_write_file_failures_leave_nothing(void **state) {
    (void)state;
    tmpdir t;
    make_dir(&t);
    pc_canvas *c = canvas(20, 10, 16);
    pc_line(c, 0, 0, 19, 9, 15);
    char err[512], want[512], names[512];

    /* a directory that does not exist */
    char *p = in_dir(&t, "missing/x.png");
    assert_int_equal(pc_write_file(c, p, PC_THEME_SCREEN, err, sizeof err), PC_EIO);
    snprintf(want, sizeof want, "cannot write '%s': No such file or directory", p);
    assert_string_equal(err, want);

    /* a path through a regular file */
    FILE *f = fopen(in_dir(&t, "plain"), "w");
    fclose(f);
    p = in_dir(&t, "plain/x.svg");
    assert_int_equal(pc_write_file(c, p, PC_THEME_SCREEN, err, sizeof err), PC_EIO);
    snprintf(want, sizeof want, "cannot write '%s': Not a directory", p);
    assert_string_equal(err, want);

    /* the target is a directory: the picture is written to the temporary file, the rename
     * fails, and the temporary file is removed again */
    assert_int_equal(mkdir(in_dir(&t, "d.ppm"), 0755), 0);
    p = in_dir(&t, "d.ppm");
    assert_int_equal(pc_write_file(c, p, PC_THEME_SCREEN, err, sizeof err), PC_EIO);
    snprintf(want, sizeof want, "cannot write '%s': Is a directory", p);
    assert_string_equal(err, want);
    list_dir(t.dir, names, sizeof names);
    assert_string_equal(names, "d.ppm plain");

    /* a directory without write permission (root may write anyway) */
    assert_int_equal(mkdir(in_dir(&t, "ro"), 0555), 0);
    p = in_dir(&t, "ro/x.png");
    int rc = pc_write_file(c, p, PC_THEME_SCREEN, err, sizeof err);
    if (geteuid() != 0) {
        assert_int_equal(rc, PC_EIO);
        snprintf(want, sizeof want, "cannot write '%s': Permission denied", p);
        assert_string_equal(err, want);
        list_dir(in_dir(&t, "ro"), names, sizeof names);
        assert_string_equal(names, "");
    }
    /* a short err buffer is truncated, never overrun */
    char tiny[8];
    assert_int_equal(pc_write_file(c, "x.gif", PC_THEME_SCREEN, tiny, sizeof tiny), PC_EARG);
    assert_string_equal(tiny, "cannot ");
    pc_canvas_free(c);
    remove_tree(t.dir);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_format_from_path),
        cmocka_unit_test(test_screen_theme_is_the_palette),
        cmocka_unit_test(test_paper_theme),
        cmocka_unit_test(test_paper_theme_256),
        cmocka_unit_test(test_ppm_bytes),
        cmocka_unit_test(test_png_reads_back_16),
        cmocka_unit_test(test_png_reads_back_256_and_2),
        cmocka_unit_test(test_png_screen_12),
        cmocka_unit_test(test_encoders_report_write_errors),
        cmocka_unit_test(test_write_file_formats),
        cmocka_unit_test(test_write_file_unknown_extension),
        cmocka_unit_test(test_write_file_failures_leave_nothing),
        cmocka_unit_test(test_true_colors_are_attributes),
        cmocka_unit_test(test_true_colors_in_png_and_ppm),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
