/* QBasic's screen pages (qbscreen.h: pc_pages): SCREEN 7's eight pages made on first use with
 * page 0's palette, drawing on the active page while another is shown, PALETTE on every page,
 * SCREEN dropping the other pages and keeping the page drawn on as page 0. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include "canvas.h"
#include "qbscreen.h"

static int px(const pc_canvas *c, int x, int y) { return c->pixels[(size_t)y * c->width + x]; }

static void test_pages(void **state) {
    (void)state;
    pc_pages p;
    assert_int_equal(pc_pages_init(&p), PC_OK);
    assert_int_equal(p.npages, 1);
    assert_int_equal(p.c->width, 640);
    assert_ptr_equal(pc_pages_shown(&p), p.c);
    assert_null(pc_pages_page(&p, 1));   /* SCREEN 12 has one page */
    assert_int_equal(pc_pages_set(&p, 1, 0), PC_EARG);
    pc_mode_info m;
    assert_int_equal(pc_mode_info_of(7, &m), PC_OK);
    assert_int_equal(pc_pages_screen(&p, &m), PC_OK);
    assert_int_equal(p.npages, 8);
    assert_int_equal(p.c->width, 320);
    assert_int_equal(p.c->screen_pixels, 1);
    pc_rgb red = {255, 0, 0};
    assert_int_equal(pc_palette(p.c, 3, red), PC_OK);
    /* draw on page 2, show page 0: page 2 is made blank with page 0's palette */
    assert_int_equal(pc_pages_set(&p, 2, 0), PC_OK);
    assert_int_equal(p.active, 2);
    assert_ptr_equal(p.c, p.pages[2]);
    assert_int_equal(p.c->palette[3].r, 255);
    assert_int_equal(pc_pset(p.c, 10, 20, 5), PC_OK);
    assert_int_equal(px(p.pages[2], 10, 20), 5);
    assert_int_equal(px(pc_pages_shown(&p), 10, 20), 0);
    assert_ptr_equal(pc_pages_shown(&p), p.pages[0]);
    /* PALETTE reaches every page made, and refuses an attribute beyond the screen's */
    pc_rgb green = {0, 255, 0};
    assert_int_equal(pc_pages_palette(&p, 4, green), PC_OK);
    assert_int_equal(p.pages[0]->palette[4].g, 255);
    assert_int_equal(p.pages[2]->palette[4].g, 255);
    assert_int_equal(pc_pages_palette(&p, 16, green), PC_EARG);
    /* SCREEN again: one page, the page drawn on (page 2) becomes page 0 */
    pc_canvas *drawn = p.c;
    assert_int_equal(pc_mode_info_of(12, &m), PC_OK);
    assert_int_equal(pc_pages_screen(&p, &m), PC_OK);
    assert_int_equal(p.npages, 1);
    assert_ptr_equal(p.pages[0], drawn);
    assert_null(p.pages[2]);
    assert_int_equal(p.c->width, 640);
    assert_int_equal(px(p.c, 10, 20), 0);   /* cleared */
    pc_pages_free(&p);
    assert_null(p.c);
}

/* DRAW through the pages: turns at the mode's aspect (SCREEN 2: 0.4167), square pixels else */
static void test_pages_draw(void **state) {
    (void)state;
    pc_pages p;
    assert_int_equal(pc_pages_init(&p), PC_OK);
    assert_int_equal(pc_pages_draw(&p, "BM100,100 R10"), PC_OK);
    assert_true(fabs(p.draw.aspect - 1) < 1e-12);
    assert_true(fabs(p.c->last_x - 110) < 1e-9 && fabs(p.c->last_y - 100) < 1e-9);
    pc_mode_info m;
    assert_int_equal(pc_mode_info_of(2, &m), PC_OK);
    assert_int_equal(pc_pages_screen(&p, &m), PC_OK);
    assert_int_equal(pc_pages_draw(&p, "BM100,100 A1 R12"), PC_OK);
    assert_true(fabs(p.draw.aspect - 4.0 / 3.0 * 200 / 640) < 1e-12);
    assert_true(fabs(p.c->last_x - 100) < 1e-9 && fabs(p.c->last_y - 95) < 1e-9);   /* up 12 * 0.4167 */
    assert_int_equal(pc_pages_draw(&p, "Q"), PC_EARG);
    pc_pages_free(&p);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_pages), cmocka_unit_test(test_pages_draw)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
