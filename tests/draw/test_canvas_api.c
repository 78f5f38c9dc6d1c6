/* The canvas as a host sees it: the accessor functions the command line and the REPL use
 * instead of the fields (size, version, dirty/saved, paper, colours, error) and the REPL's
 * clear, which erases the picture and keeps the screen's settings and the graphics cursor. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"

static void test_size(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(16, 12, 16);
    int w = -1, h = -1;
    pc_canvas_size(c, &w, &h);
    assert_int_equal(w, 16);
    assert_int_equal(h, 12);
    assert_int_equal(pc_canvas_ncolors(c), 16);
    pc_canvas_size(c, NULL, &h);   /* either output may be left out */
    pc_canvas_size(c, &w, NULL);
    assert_int_equal(pc_canvas_reset(c, 320, 200, 256), PC_OK);   /* SCREEN 13 */
    pc_canvas_size(c, &w, &h);
    assert_int_equal(w, 320);
    assert_int_equal(h, 200);
    assert_int_equal(pc_canvas_ncolors(c), 256);
    pc_canvas_free(c);
}

/* dirty: something drawn since the last save; saving leaves the version alone. */
static void test_dirty_and_saved(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(16, 16, 16);
    assert_int_equal(pc_canvas_dirty(c), 0);             /* a new screen has nothing to save */
    uint64_t v0 = pc_canvas_version(c);
    assert_int_equal(pc_pset(c, 3, 4, 14), PC_OK);
    assert_int_equal(pc_canvas_dirty(c), 1);
    uint64_t v1 = pc_canvas_version(c);
    assert_true(v1 > v0);
    pc_canvas_mark_saved(c);
    assert_int_equal(pc_canvas_dirty(c), 0);
    assert_true(pc_canvas_version(c) == v1);
    assert_int_equal(pc_point(c, 3, 4), 14);             /* saving does not touch the picture */
    assert_int_equal(pc_cls(c), PC_OK);                  /* clearing draws nothing to save */
    assert_int_equal(pc_canvas_dirty(c), 0);
    assert_true(pc_canvas_version(c) > v1);
    assert_int_equal(pc_line(c, 0, 0, 5, 0, 2), PC_OK);
    assert_int_equal(pc_canvas_dirty(c), 1);
    assert_int_equal(pc_canvas_reset(c, 16, 16, 16), PC_OK);   /* SCREEN: a fresh picture */
    assert_int_equal(pc_canvas_dirty(c), 0);
    pc_canvas_free(c);
}

/* paper: the colour of the last full-screen clear; COLOR's background waits for CLS. */
static void test_paper(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(8, 8, 16);
    assert_int_equal(pc_canvas_paper(c), 0);
    assert_int_equal(pc_color(c, 15, 4), PC_OK);
    assert_int_equal(pc_canvas_paper(c), 0);
    assert_int_equal(pc_cls(c), PC_OK);
    assert_int_equal(pc_canvas_paper(c), 4);
    assert_int_equal(pc_point(c, 7, 7), 4);
    assert_int_equal(pc_canvas_reset(c, 8, 8, 16), PC_OK);
    assert_int_equal(pc_canvas_paper(c), 0);
    pc_canvas_free(c);
}

#define RGB_IS(p, R, G, B) do { assert_int_equal((p).r, R); assert_int_equal((p).g, G); \
                                assert_int_equal((p).b, B); } while (0)

/* The colour of an attribute: the VGA palette (6-bit DAC levels widened to 8 bits: 42 ->
 * 170, 63 -> 255, 21 -> 85), PALETTE changes, true colours; attributes not in use fail. */
static void test_rgb(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(8, 8, 16);
    pc_rgb k = {9, 9, 9};
    assert_int_equal(pc_canvas_rgb(c, 0, &k), PC_OK);  RGB_IS(k, 0, 0, 0);
    assert_int_equal(pc_canvas_rgb(c, 1, &k), PC_OK);  RGB_IS(k, 0, 0, 170);     /* blue */
    assert_int_equal(pc_canvas_rgb(c, 6, &k), PC_OK);  RGB_IS(k, 170, 85, 0);    /* brown */
    assert_int_equal(pc_canvas_rgb(c, 15, &k), PC_OK); RGB_IS(k, 255, 255, 255);
    assert_int_equal(pc_palette(c, 3, (pc_rgb){1, 2, 3}), PC_OK);
    assert_int_equal(pc_canvas_rgb(c, 3, &k), PC_OK);  RGB_IS(k, 1, 2, 3);
    int a = pc_rgb_color(c, (pc_rgb){0x12, 0x34, 0x56});
    int b = pc_rgb_color(c, (pc_rgb){0xfe, 0xdc, 0xba});
    assert_int_equal(a, 256);
    assert_int_equal(b, 257);
    assert_int_equal(pc_canvas_rgb(c, a, &k), PC_OK);  RGB_IS(k, 0x12, 0x34, 0x56);
    assert_int_equal(pc_canvas_rgb(c, b, &k), PC_OK);  RGB_IS(k, 0xfe, 0xdc, 0xba);
    /* the table a writer takes says the same */
    const pc_rgb *pal = pc_canvas_palette(c);
    RGB_IS(pal[1], 0, 0, 170);
    RGB_IS(pal[3], 1, 2, 3);
    RGB_IS(pal[256], 0x12, 0x34, 0x56);
    RGB_IS(pal[257], 0xfe, 0xdc, 0xba);
    /* not in use: 16..255 on a 16-colour screen, true colours not allocated, negatives */
    k = (pc_rgb){7, 7, 7};
    assert_int_equal(pc_canvas_rgb(c, 16, &k), PC_EARG);
    assert_int_equal(pc_canvas_rgb(c, 255, &k), PC_EARG);
    assert_int_equal(pc_canvas_rgb(c, 258, &k), PC_EARG);
    assert_int_equal(pc_canvas_rgb(c, -1, &k), PC_EARG);
    RGB_IS(k, 7, 7, 7);                                   /* untouched on failure */
    /* SCREEN 13: the 256-colour palette, greys from 16 (16 is black, 31 is white) */
    assert_int_equal(pc_canvas_reset(c, 8, 8, 256), PC_OK);
    assert_int_equal(pc_canvas_rgb(c, 31, &k), PC_OK); RGB_IS(k, 255, 255, 255);
    assert_int_equal(pc_canvas_rgb(c, 255, &k), PC_OK); RGB_IS(k, 0, 0, 0);
    pc_canvas_free(c);
}

static void test_error(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(8, 8, 16);
    assert_string_equal(pc_canvas_error(c), "");
    assert_int_equal(pc_pset(c, 1, 1, 99), PC_EARG);
    assert_string_equal(pc_canvas_error(c), "colour 99 out of range 0..15");
    pc_canvas_free(c);
}

/* The REPL's clear with a full-screen view: the picture goes, the settings and the cursor
 * stay, and there is nothing left to save. */
static void test_clear_full(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(16, 16, 16);
    assert_int_equal(pc_window(c, 0, 0, 15, 15, 0), PC_OK);   /* world y up */
    assert_int_equal(pc_pen(c, 3, NULL, 0), PC_OK);
    assert_int_equal(pc_color(c, 14, 1), PC_OK);
    assert_int_equal(pc_line(c, 2, 2, 12, 9, -1), PC_OK);    /* the cursor goes to (12, 9) */
    assert_true(c->nops > 0);
    uint64_t v = pc_canvas_version(c);
    assert_int_equal(pc_canvas_clear(c), PC_OK);
    assert_true(pc_canvas_version(c) > v);
    assert_int_equal(pc_canvas_dirty(c), 0);
    assert_int_equal(pc_canvas_paper(c), 1);                 /* cleared to the background */
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) assert_int_equal(c->pixels[y * 16 + x], 1);
    assert_int_equal(c->nops, 1);                            /* one CLEAR to blue, nothing else */
    assert_int_equal(c->ops[0].kind, PC_OP_CLEAR);
    assert_true(c->last_x == 12 && c->last_y == 9);          /* a plain CLS would recentre it */
    assert_int_equal(c->has_window, 1);
    assert_true(c->wx2 == 15 && c->wy2 == 15);
    assert_true(c->pens[c->pen].width == 3);
    assert_int_equal(c->fg, 14);
    /* drawing goes on with the kept window: world (0, 15) is the top-left pixel */
    assert_int_equal(pc_pset(c, 0, 15, -1), PC_OK);
    assert_int_equal(c->pixels[0], 14);
    assert_int_equal(pc_canvas_dirty(c), 1);
    pc_canvas_free(c);
}

/* With a smaller view (VIEW SCREEN), clear erases the whole screen, border included, and
 * puts the same view back. */
static void test_clear_view(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(16, 16, 16);
    assert_int_equal(pc_view(c, 4, 3, 11, 12, 2, 5, 1), PC_OK);   /* fill 2, border 5 */
    assert_int_equal(c->pixels[2 * 16 + 3], 5);                   /* the border at (3, 2) */
    assert_int_equal(pc_pset(c, 6, 7, 12), PC_OK);                 /* absolute: VIEW SCREEN */
    assert_int_equal(c->pixels[7 * 16 + 6], 12);
    assert_int_equal(pc_line(c, 5, 5, 9, 10, 12), PC_OK);
    assert_int_equal(pc_canvas_clear(c), PC_OK);
    for (int i = 0; i < 16 * 16; i++) assert_int_equal(c->pixels[i], 0);
    assert_int_equal(c->nops, 0);                                  /* black: nothing recorded */
    assert_int_equal(c->view.x0, 4);
    assert_int_equal(c->view.y0, 3);
    assert_int_equal(c->view.x1, 11);
    assert_int_equal(c->view.y1, 12);
    assert_int_equal(c->view_screen, 1);
    assert_true(c->last_x == 9 && c->last_y == 10);
    assert_int_equal(pc_canvas_dirty(c), 0);
    /* the view clips again: (2, 2) is outside it, (6, 7) inside */
    assert_int_equal(pc_pset(c, 2, 2, 12), PC_OK);
    assert_int_equal(c->pixels[2 * 16 + 2], 0);
    assert_int_equal(pc_pset(c, 6, 7, 12), PC_OK);
    assert_int_equal(c->pixels[7 * 16 + 6], 12);
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_size),
        cmocka_unit_test(test_dirty_and_saved),
        cmocka_unit_test(test_paper),
        cmocka_unit_test(test_rgb),
        cmocka_unit_test(test_error),
        cmocka_unit_test(test_clear_full),
        cmocka_unit_test(test_clear_view),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
