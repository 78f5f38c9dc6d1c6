/* Math in labels: the parse (styles, Greek, primes, scripts, accents), the layout (a subscript
 * lower and smaller than its base, both scripts at one x, a bar over its group), every error
 * with the label and the position, and the VGA look's pixels of a subscript. */
#include <math.h>
#include <stdio.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "font.h"
#include "math_label.h"

#define CHECK_NEAR(a, b) assert_true(fabs((a) - (b)) < 1e-9)

/* A monospace measure: 0.5 em a character, so the positions are easy to state. */
static double mono(void *ctx, const char *s, size_t n, int italic, double size) {
    (void)ctx; (void)italic;
    double k = 0;
    for (size_t i = 0; i < n; i++) k += ((unsigned char)s[i] & 0xc0) != 0x80;
    return k * 0.5 * size;
}

static pc_mlayout lay(const char *s) {
    pc_mlayout L;
    char err[200];
    int st = pc_math_layout(s, 10, 0.8, 0.2, mono, NULL, &L, err, sizeof err);
    if (st != PC_OK) fail_msg("%s: %s", s, err);
    return L;
}

static void run_is(const pc_mlayout *L, size_t i, const char *text, int italic) {
    assert_true(i < L->nruns);
    const pc_mrun *r = &L->runs[i];
    assert_int_equal(r->len, strlen(text));
    assert_memory_equal(L->text + r->first, text, r->len);
    assert_int_equal(r->italic, italic);
}

static void test_subscript_lower_and_smaller(void **state) {
    (void)state;
    pc_mlayout L = lay("$A_1$");
    assert_int_equal(L.nruns, 2);
    run_is(&L, 0, "A", 1);   /* letters italic */
    run_is(&L, 1, "1", 0);   /* digits upright */
    assert_true(L.runs[1].size < L.runs[0].size);
    CHECK_NEAR(L.runs[1].size, 7);
    assert_true(L.runs[1].rise < L.runs[0].rise);   /* below the base's baseline */
    CHECK_NEAR(L.runs[1].rise, -2.2);
    CHECK_NEAR(L.runs[1].x, 5);     /* right after the A */
    CHECK_NEAR(L.width, 5 + 3.5);
    assert_true(L.math);
    pc_mlayout_free(&L);
}

static void test_scripts_nest_and_share_x(void **state) {
    (void)state;
    pc_mlayout L = lay("$P_{0,3}^2$");
    assert_int_equal(L.nruns, 3);
    run_is(&L, 1, "0,3", 0);
    run_is(&L, 2, "2", 0);
    CHECK_NEAR(L.runs[1].x, L.runs[2].x);   /* both scripts start at one x */
    assert_true(L.runs[2].rise > 0 && L.runs[1].rise < 0);
    pc_mlayout_free(&L);
    L = lay("$x_{i_k}$");   /* a script of a script: smaller and lower again */
    assert_int_equal(L.nruns, 3);
    assert_true(L.runs[2].size < L.runs[1].size && L.runs[2].rise < L.runs[1].rise);
    CHECK_NEAR(L.runs[2].size, 5);
    pc_mlayout_free(&L);
}

static void test_greek_symbols_primes(void **state) {
    (void)state;
    pc_mlayout L = lay("$\\varphi \\le \\Gamma$");
    assert_string_equal(L.text, "\u03c6\u2264\u0393");
    assert_int_equal(L.nruns, 3);
    run_is(&L, 0, "\u03c6", 1);              /* a lower-case Greek letter is italic */
    run_is(&L, 1, "\u2264", 0);              /* a relation upright, */
    CHECK_NEAR(L.runs[1].x, 5 + 2.8);        /* with TeX's thick space (0.28 em) each side */
    run_is(&L, 2, "\u0393", 0);              /* a capital upright, as TeX */
    CHECK_NEAR(L.runs[2].x, 5 + 2.8 + 5 + 2.8);
    pc_mlayout_free(&L);
    L = lay("$-a-b$");   /* a sign at the start, a binary minus after: U+2212, spaced */
    assert_string_equal(L.text, "\u2212a\u2212b");
    CHECK_NEAR(L.runs[2].x, 5 + 5 + 2.2);
    pc_mlayout_free(&L);
    L = lay("$M''_1$");
    assert_string_equal(L.text, "M\u20331");
    pc_mlayout_free(&L);
    L = lay("$\\mathrm{max} x$");
    run_is(&L, 0, "max", 0);
    run_is(&L, 1, "x", 1);
    pc_mlayout_free(&L);
    /* every command of the table gives its text */
    for (size_t i = 0; i < pc_math_ncommands; i++) {
        char src[40];
        snprintf(src, sizeof src, "$\\%s$", pc_math_commands[i].name);
        pc_mlayout M = lay(src);
        assert_string_equal(M.text, pc_math_commands[i].utf8);
        pc_mlayout_free(&M);
    }
}

static void test_plain_text_unchanged(void **state) {
    (void)state;
    pc_mlayout L = lay("угол A_1 \\$5");
    assert_false(L.math);
    assert_int_equal(L.nruns, 1);
    run_is(&L, 0, "угол A_1 $5", 0);
    pc_mlayout_free(&L);
    assert_false(pc_has_math("P0 \\$"));
    assert_true(pc_has_math("a $b$"));
    char plain[64];
    assert_int_equal(pc_math_plain("$\\bar{t}$ и $A_1$", plain, sizeof plain), PC_OK);
    assert_string_equal(plain, "t и A1");
}

static void test_accents(void **state) {
    (void)state;
    pc_mlayout L = lay("$\\overline{AB}$");
    assert_int_equal(L.ndecos, 1);
    assert_int_equal(L.decos[0].kind, PC_DECO_BAR);
    CHECK_NEAR(L.decos[0].x0, 0);     /* over the whole group */
    CHECK_NEAR(L.decos[0].x1, 10);
    assert_true(L.decos[0].rise > 7);                  /* above the capitals */
    assert_true(L.ascent >= L.decos[0].rise);
    pc_mlayout_free(&L);
    L = lay("$\\bar{t}$ $\\vec v$");
    assert_int_equal(L.ndecos, 2);
    assert_true(L.decos[0].x0 > 0 && L.decos[0].x1 < 5);   /* \bar: narrower than its letter */
    assert_int_equal(L.decos[1].kind, PC_DECO_VEC);
    pc_mlayout_free(&L);
}

/* \tilde: a wave over its group, a little higher than a bar; \underline: a line under the
 * descenders (0.22 em) 0.08 em lower; an accent's group in runs of its own, so a bar over the
 * second t of "t\bar{t}" sits over that t, above its top. */
static void test_tilde_underline(void **state) {
    (void)state;
    pc_mlayout L = lay("$\\tilde A$");
    assert_int_equal(L.ndecos, 1);
    assert_int_equal(L.decos[0].kind, PC_DECO_TILDE);
    CHECK_NEAR(L.decos[0].x0, 0.6);    /* inset 0.12 of the letter's 5 */
    CHECK_NEAR(L.decos[0].x1, 4.4);
    CHECK_NEAR(L.decos[0].rise, 8.8);  /* the capital's 7 and 0.18 em */
    CHECK_NEAR(L.ascent, 10);          /* its wave's 1.2 above that */
    pc_mlayout_free(&L);
    L = lay("$\\underline{xy}$");
    assert_int_equal(L.ndecos, 1);
    assert_int_equal(L.decos[0].kind, PC_DECO_UNDER);
    CHECK_NEAR(L.decos[0].x0, 0);      /* the whole group */
    CHECK_NEAR(L.decos[0].x1, 10);
    CHECK_NEAR(L.decos[0].rise, -3);   /* 2.2 + 0.8 below the baseline */
    CHECK_NEAR(L.descent, 3.4);        /* its thickness below it */
    run_is(&L, 0, "xy", 1);
    pc_mlayout_free(&L);
    L = lay("$t\\bar{t}$");
    assert_int_equal(L.nruns, 2);
    CHECK_NEAR(L.decos[0].x0, 5.6);
    CHECK_NEAR(L.decos[0].x1, 9.4);
    CHECK_NEAR(L.decos[0].rise, 8.2);  /* over the second t's top, not on its baseline */
    pc_mlayout_free(&L);
    char plain[32];
    assert_int_equal(pc_math_plain("$\\tilde{A}\\underline B$", plain, sizeof plain), PC_OK);
    assert_string_equal(plain, "AB");
    assert_int_equal(pc_math_check("$\\tilde{A}$", NULL, 0), PC_OK);
    assert_int_equal(pc_math_check("no math \\tilde", NULL, 0), PC_OK);
    char err[200];
    assert_int_equal(pc_math_check("$\\tidle A$", err, sizeof err), PC_EARG);
    assert_string_equal(err, "label '$\\tidle A$': unknown command '\\tidle' at character 2");
}

/* The VGA look: the wave is one row of pixels a sine's period long, up first; the underline the
 * 8x16 cell's last row. */
static void test_vga_tilde_underline_pixels(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(32, 32, 16);
    assert_int_equal(pc_text(c, 0, 8, "$\\tilde A$", PC_ANCHOR_SE, 0, 1, 15), PC_OK);
    /* baseline row 20; rise 14.08 -> row 6; x 1..6 (inset 0.96 of 8) */
    static const int wave[][2] = {{1, 6}, {2, 5}, {3, 6}, {4, 6}, {5, 7}, {6, 6}};
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            int want = 0;
            for (size_t k = 0; k < 6; k++) want |= wave[k][0] == x && wave[k][1] == y;
            assert_int_equal(c->pixels[y * 32 + x], want ? 15 : 0);
        }
    pc_canvas_free(c);
    c = pc_canvas_new(32, 32, 16);
    assert_int_equal(pc_text(c, 0, 0, "$\\underline{A}$", PC_ANCHOR_SE, 0, 1, 15), PC_OK);
    for (int x = 0; x < 32; x++) assert_int_equal(c->pixels[15 * 32 + x], x < 8 ? 15 : 0);
    for (int y = 16; y < 32; y++)
        for (int x = 0; x < 32; x++) assert_int_equal(c->pixels[y * 32 + x], 0);
    pc_canvas_free(c);
}

static void expect_error(const char *label, const char *msg) {
    pc_mlayout L;
    char err[200];
    assert_int_equal(pc_math_layout(label, 10, 0.8, 0.2, mono, NULL, &L, err, sizeof err), PC_EARG);
    assert_string_equal(err, msg);
    assert_null(L.runs);
}

static void test_errors_name_label_and_position(void **state) {
    (void)state;
    expect_error("$A_{1$", "label '$A_{1$': unbalanced '{' at character 4");
    expect_error("$A}$", "label '$A}$': unbalanced '}' at character 3");
    expect_error("$\\foo x$", "label '$\\foo x$': unknown command '\\foo' at character 2");
    expect_error("угол $A_1", "label 'угол $A_1': unclosed '$' at character 6");
    expect_error("$A_$", "label '$A_$': '_' needs a character or a {group} after it at character 4");
    expect_error("$x^$", "label '$x^$': '^' needs a character or a {group} after it at character 4");
    expect_error("$\\bar$", "label '$\\bar$': \\bar needs a character or a {group} after it at character 6");
    expect_error("$a\\", "label '$a\\': '\\' at the end at character 3");
    expect_error("$\\tilde$", "label '$\\tilde$': \\tilde needs a character or a {group} after it at character 8");
    expect_error("$\\underline{$", "label '$\\underline{$': unbalanced '{' at character 12");
}

/* The VGA look: a subscript in the 8x8 cells, lower than the base's 8x16 cell. */
static void test_vga_subscript_pixels(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(64, 32, 16);
    assert_int_equal(pc_text(c, 0, 0, "$A_1$", PC_ANCHOR_SE, 0, 1, 15), PC_OK);
    int a_bottom = -1, one_top = 99, one_bottom = -1, one_w = 0;
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 64; x++) {
            if (!c->pixels[y * 64 + x]) continue;
            if (x < 8) a_bottom = y;
            else {
                if (y < one_top) one_top = y;
                one_bottom = y;
                one_w = x;
            }
        }
    assert_int_equal(a_bottom, 11);          /* the A ends on the 8x16 font's baseline row */
    assert_true(one_bottom > a_bottom);      /* the 1 goes below it */
    assert_true(one_bottom - one_top + 1 <= 8);   /* and is at most 8 rows: smaller */
    assert_true(one_w < 16);
    /* a label without '$' has the pixels it always had */
    pc_canvas *d = pc_canvas_new(64, 32, 16), *e = pc_canvas_new(64, 32, 16);
    assert_int_equal(pc_text(d, 0, 0, "A_1", PC_ANCHOR_SE, 0, 1, 15), PC_OK);
    for (int k = 0; k < 3; k++) {
        const uint8_t *rows = pc_font_bits[pc_font_glyph("A_1"[k])];
        for (int r = 0; r < 16; r++)
            for (int b = 0; b < 8; b++)
                if (rows[r] & (0x80 >> b)) e->pixels[r * 64 + k * 8 + b] = 15;
    }
    assert_memory_equal(d->pixels, e->pixels, 64 * 32 * sizeof *d->pixels);
    /* an error names the call and the label */
    assert_int_equal(pc_text(c, 0, 0, "$\\nope$", PC_ANCHOR_SE, 0, 1, 15), PC_EARG);
    assert_string_equal(c->error, "label '$\\nope$': unknown command '\\nope' at character 2");
    pc_canvas_free(c);
    pc_canvas_free(d);
    pc_canvas_free(e);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_subscript_lower_and_smaller),
        cmocka_unit_test(test_scripts_nest_and_share_x),
        cmocka_unit_test(test_greek_symbols_primes),
        cmocka_unit_test(test_plain_text_unchanged),
        cmocka_unit_test(test_accents),
        cmocka_unit_test(test_tilde_underline),
        cmocka_unit_test(test_vga_tilde_underline_pixels),
        cmocka_unit_test(test_errors_name_label_and_position),
        cmocka_unit_test(test_vga_subscript_pixels),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
