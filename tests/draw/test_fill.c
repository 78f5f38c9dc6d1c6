/* Filled paths (pc_fill_path): exact pixels by the pixel-centre rule of canvas.h, shared edges
 * covered once, the two fill rules, VIEW clipping, WINDOW, cubics, far points, errors, the
 * display-list operation, and the SVG writer's <path> read back and filled again. */
#define _GNU_SOURCE
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "writers.h"

static pc_canvas *small(int w, int h) {
    pc_canvas *c = pc_canvas_new(w, h, 16);
    assert_non_null(c);
    return c;
}

static int at(const pc_canvas *c, int x, int y) { return c->pixels[y * c->width + x]; }

static int count(const pc_canvas *c, int color) {
    int n = 0;
    for (int i = 0; i < c->width * c->height; i++) n += c->pixels[i] == color;
    return n;
}

static void assert_shape(const pc_canvas *c, const char *const rows[]) {
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) {
            int want = rows[y][x] == '#';
            if ((at(c, x, y) != 0) != want)
                fail_msg("pixel (%d, %d): want %s", x, y, want ? "ink" : "none");
        }
}

static int fill(pc_canvas *c, int n, const double *xy, int rule, int color) {
    return pc_fill_path(c, (size_t)n, xy, NULL, 0, rule, color);
}

/* The right triangle (0,0), (6,0), (0,6): row j holds the centres 0 <= i < 6 - j; the
 * hypotenuse's centres (i + j = 6) are on a right edge, so outside; row 6 is the bottom
 * edge, outside. */
static void test_triangle_pixels(void **state) {
    (void)state;
    pc_canvas *c = small(8, 8);
    const double t[] = {0, 0, 6, 0, 0, 6};
    assert_int_equal(fill(c, 3, t, PC_FILL_EVENODD, 4), PC_OK);
    static const char *const rows[] = {"######..", "#####...", "####....", "###.....",
                                       "##......", "#.......", "........", "........"};
    assert_shape(c, rows);
    assert_int_equal(count(c, 4), 21);
    /* the same triangle the other way round, and with the nonzero rule: the same pixels */
    pc_canvas *d = small(8, 8);
    const double r[] = {0, 6, 6, 0, 0, 0};
    assert_int_equal(fill(d, 3, r, PC_FILL_NONZERO, 4), PC_OK);
    assert_memory_equal(c->pixels, d->pixels, 64 * sizeof *c->pixels);
    pc_canvas_free(c);
    pc_canvas_free(d);
}

/* A triangle with fractional vertices: the pixels whose centres are strictly inside, by a
 * direct test of each centre against the three edges. */
static void test_fractional_triangle(void **state) {
    (void)state;
    pc_canvas *c = small(20, 20);
    const double t[] = {1.3, 2.7, 17.6, 5.2, 6.1, 18.4};
    assert_int_equal(fill(c, 3, t, PC_FILL_EVENODD, 2), PC_OK);
    int n = 0;
    for (int y = 0; y < 20; y++)
        for (int x = 0; x < 20; x++) {
            int in = 1;
            for (int k = 0; k < 3; k++) {
                double ax = t[2 * k], ay = t[2 * k + 1], bx = t[(2 * k + 2) % 6], by = t[(2 * k + 3) % 6];
                /* clockwise on the y-down screen: inside is on the right of each edge */
                double s = (bx - ax) * (y - ay) - (by - ay) * (x - ax);
                if (!(s > 0)) in = 0;
            }
            assert_int_equal(at(c, x, y) == 2, in);
            n += in;
        }
    assert_true(n > 100);   /* area 123.6 px */
    pc_canvas_free(c);
}

/* A mesh of quads with jittered fractional vertices, each split into two triangles, each
 * triangle drawn alone: every pixel is covered at most once, and the union is exactly the
 * fill of the mesh's outline. */
static void test_shared_edges(void **state) {
    (void)state;
    enum { N = 6, W = 48 };
    double vx[N + 1][N + 1], vy[N + 1][N + 1];
    unsigned seed = 12345;
    for (int i = 0; i <= N; i++)
        for (int j = 0; j <= N; j++) {
            seed = seed * 1103515245u + 12345u;
            double jx = (double)((seed >> 8) % 1000) / 1000 - 0.5;
            seed = seed * 1103515245u + 12345u;
            double jy = (double)((seed >> 8) % 1000) / 1000 - 0.5;
            int edge_i = i == 0 || i == N, edge_j = j == 0 || j == N;
            vx[i][j] = 4 + 6.5 * i + (edge_i ? 0 : 2.5 * jx);
            vy[i][j] = 3 + 6.5 * j + (edge_j ? 0 : 2.5 * jy);
        }
    int cover[W * W] = {0};
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            const double tri[2][6] = {
                {vx[i][j], vy[i][j], vx[i + 1][j], vy[i + 1][j], vx[i + 1][j + 1], vy[i + 1][j + 1]},
                {vx[i][j], vy[i][j], vx[i + 1][j + 1], vy[i + 1][j + 1], vx[i][j + 1], vy[i][j + 1]}};
            for (int k = 0; k < 2; k++) {
                pc_canvas *c = small(W, W);
                assert_int_equal(fill(c, 3, tri[k], (i + j + k) % 2, 1), PC_OK);
                for (int p = 0; p < W * W; p++) cover[p] += c->pixels[p] == 1;
                pc_canvas_free(c);
            }
        }
    pc_canvas *all = small(W, W);
    const double box[] = {4, 3, 4 + 6.5 * N, 3, 4 + 6.5 * N, 3 + 6.5 * N, 4, 3 + 6.5 * N};
    assert_int_equal(fill(all, 4, box, PC_FILL_EVENODD, 1), PC_OK);
    int covered = 0;
    for (int p = 0; p < W * W; p++) {
        if (cover[p] > 1) fail_msg("pixel (%d, %d) covered %d times", p % W, p / W, cover[p]);
        assert_int_equal(cover[p], all->pixels[p] == 1);
        covered += cover[p];
    }
    assert_int_equal(covered, 39 * 39);   /* centres 4..42 by 3..41 */
    pc_canvas_free(all);
}

/* A square with a square hole: two subpaths.  Even-odd leaves the hole whatever the
 * orientations; nonzero leaves it only when the inner square runs the other way. */
static void test_hole(void **state) {
    (void)state;
    const uint8_t verbs[] = {PC_PATH_MOVE, PC_PATH_LINE, PC_PATH_LINE, PC_PATH_LINE,
                             PC_PATH_MOVE, PC_PATH_LINE, PC_PATH_LINE, PC_PATH_LINE};
    const double same[] = {1, 1, 9, 1, 9, 9, 1, 9, 3, 3, 7, 3, 7, 7, 3, 7};
    const double opposite[] = {1, 1, 9, 1, 9, 9, 1, 9, 3, 3, 3, 7, 7, 7, 7, 3};
    static const char *const ring[] = {"..........", ".########.", ".########.", ".##....##.",
                                       ".##....##.", ".##....##.", ".##....##.", ".########.",
                                       ".########.", ".........."};
    struct { const double *xy; int rule, ink; } cases[] = {
        {same, PC_FILL_EVENODD, 48}, {opposite, PC_FILL_EVENODD, 48},
        {same, PC_FILL_NONZERO, 64}, {opposite, PC_FILL_NONZERO, 48}};
    for (int k = 0; k < 4; k++) {
        pc_canvas *c = small(10, 10);
        assert_int_equal(pc_fill_path(c, 8, cases[k].xy, verbs, 8, cases[k].rule, 3), PC_OK);
        assert_int_equal(count(c, 3), cases[k].ink);
        if (cases[k].ink == 48) assert_shape(c, ring);
        pc_canvas_free(c);
    }
}

/* VIEW clips the fill (VIEW SCREEN: absolute coordinates); what lies outside stays. */
static void test_view_clip(void **state) {
    (void)state;
    pc_canvas *c = small(10, 10);
    assert_int_equal(pc_view(c, 2, 3, 6, 5, -1, -1, 1), PC_OK);
    const double big[] = {-100, -100, 100, -100, 0, 100};
    assert_int_equal(fill(c, 3, big, PC_FILL_EVENODD, 5), PC_OK);
    for (int y = 0; y < 10; y++)
        for (int x = 0; x < 10; x++)
            assert_int_equal(at(c, x, y), (x >= 2 && x <= 6 && y >= 3 && y <= 5) ? 5 : 0);
    pc_canvas_free(c);
}

/* WINDOW maps the points; the unit square over a 10 x 10 window on a 11 x 11 screen. */
static void test_window(void **state) {
    (void)state;
    pc_canvas *c = small(11, 11);
    assert_int_equal(pc_window(c, 0, 0, 10, 10, 0), PC_OK);   /* y up: world y 0 is row 10 */
    const double sq[] = {2, 2, 5, 2, 5, 4, 2, 4};
    assert_int_equal(fill(c, 4, sq, PC_FILL_EVENODD, 6), PC_OK);
    /* screen x 2..5, y 6..8: centres 2..4 by 6..7 */
    for (int y = 0; y < 11; y++)
        for (int x = 0; x < 11; x++)
            assert_int_equal(at(c, x, y), (x >= 2 && x <= 4 && y >= 6 && y <= 7) ? 6 : 0);
    assert_true(c->last_x == 2 && c->last_y == 4);
    pc_canvas_free(c);
}

/* A disc of radius 20 from four cubic quarters (k = 0.5523): its area within 1% of pi r^2
 * and every pixel whose centre is 1 px inside the circle filled, none 1 px outside. */
static void test_cubic_disc(void **state) {
    (void)state;
    pc_canvas *c = small(50, 50);
    const double k = 0.55228475 * 20, cx = 25, cy = 25, r = 20;
    const double xy[] = {cx + r, cy,
                         cx + r, cy + k, cx + k, cy + r, cx, cy + r,
                         cx - k, cy + r, cx - r, cy + k, cx - r, cy,
                         cx - r, cy - k, cx - k, cy - r, cx, cy - r,
                         cx + k, cy - r, cx + r, cy - k, cx + r, cy};
    const uint8_t verbs[] = {PC_PATH_MOVE, PC_PATH_CUBIC, PC_PATH_CUBIC, PC_PATH_CUBIC, PC_PATH_CUBIC};
    assert_int_equal(pc_fill_path(c, 13, xy, verbs, 5, PC_FILL_NONZERO, 9), PC_OK);
    assert_true(fabs(count(c, 9) - M_PI * r * r) < 0.01 * M_PI * r * r);
    for (int y = 0; y < 50; y++)
        for (int x = 0; x < 50; x++) {
            double d = hypot(x - cx, y - cy);
            if (d < r - 1) assert_int_equal(at(c, x, y), 9);
            if (d > r + 1) assert_int_equal(at(c, x, y), 0);
        }
    pc_canvas_free(c);
}

/* A vertex far off screen still places the fill exactly: the half-plane left of the line
 * x = 3 (a thin triangle reaching 1e12 px up and down). */
static void test_far_points(void **state) {
    (void)state;
    pc_canvas *c = small(8, 4);
    const double t[] = {3, -1e12, 3, 1e12, -1e12, 0};
    assert_int_equal(fill(c, 3, t, PC_FILL_EVENODD, 7), PC_OK);
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 8; x++) assert_int_equal(at(c, x, y), x < 3 ? 7 : 0);
    const double too_far[] = {0, 0, 2e15, 0, 0, 5};
    assert_int_equal(fill(c, 3, too_far, PC_FILL_EVENODD, 7), PC_EARG);
    assert_non_null(strstr(pc_canvas_error(c), "point 2 lies too far outside the screen"));
    pc_canvas_free(c);
}

static void test_degenerate_and_errors(void **state) {
    (void)state;
    pc_canvas *c = small(8, 8);
    const double line2[] = {1, 1, 6, 6}, one[] = {3, 3}, flat[] = {1, 1, 4, 4, 7, 7};
    assert_int_equal(fill(c, 2, line2, PC_FILL_EVENODD, 1), PC_OK);   /* no area: nothing */
    assert_int_equal(fill(c, 1, one, PC_FILL_EVENODD, 1), PC_OK);
    assert_int_equal(fill(c, 3, flat, PC_FILL_EVENODD, 1), PC_OK);
    assert_int_equal(count(c, 1), 0);
    size_t nops = c->nops, npts = c->npts;
    const double nan_pt[] = {0, 0, NAN, 1, 2, 2};
    assert_int_equal(fill(c, 3, nan_pt, PC_FILL_EVENODD, 1), PC_EARG);
    assert_non_null(strstr(pc_canvas_error(c), "fill: coordinates must be finite numbers"));
    assert_int_equal(fill(c, 0, one, PC_FILL_EVENODD, 1), PC_EARG);
    assert_string_equal(pc_canvas_error(c), "fill: no points");
    assert_int_equal(fill(c, 1, one, 7, 1), PC_EARG);
    assert_non_null(strstr(pc_canvas_error(c), "fill rule"));
    assert_int_equal(fill(c, 1, one, PC_FILL_EVENODD, 16), PC_EARG);
    assert_non_null(strstr(pc_canvas_error(c), "colour 16 out of range"));
    const uint8_t bad[] = {PC_PATH_LINE};
    assert_int_equal(pc_fill_path(c, 1, one, bad, 1, PC_FILL_EVENODD, 1), PC_EARG);
    assert_int_equal(c->nops, nops);   /* a refused fill records nothing */
    assert_int_equal(c->npts, npts);
    assert_int_equal(count(c, 1), 0);
    pc_canvas_free(c);
}

/* The display list holds one FILLPATH op with the screen points, the rule and the colour;
 * a true colour works as any attribute. */
static void test_display_list(void **state) {
    (void)state;
    pc_canvas *c = small(10, 10);
    int red = pc_rgb_color(c, (pc_rgb){200, 10, 20});
    const double t[] = {1, 1, 8, 1, 1, 8};
    assert_int_equal(fill(c, 3, t, PC_FILL_NONZERO, red), PC_OK);
    assert_int_equal(c->nops, 1);
    const pc_op *op = &c->ops[0];
    assert_int_equal(op->kind, PC_OP_FILLPATH);
    assert_int_equal(op->flags, PC_FILL_NONZERO);
    assert_int_equal(op->color, red);
    assert_int_equal(op->count, 3);
    assert_true(c->pts[op->first + 1].x == 8 && c->pts[op->first + 1].y == 1);
    assert_int_equal(at(c, 1, 1), red);
    assert_int_equal(c->dirty, 1);
    pc_canvas_free(c);
}

/* ---- the SVG writer, read back ----------------------------------------------------------- */

static char *svg_of(const pc_canvas *c) {
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    assert_non_null(f);
    assert_int_equal(pc_encode_svg(c, PC_THEME_SCREEN, f), PC_OK);
    fclose(f);
    return buf;
}

/* The d of the n-th element <path ... containing `attr`, or NULL. */
static char *path_d(const char *svg, const char *attr, int nth) {
    const char *p = svg;
    while ((p = strstr(p, "<path"))) {
        const char *end = strstr(p, "/>");
        assert_non_null(end);
        const char *a = strstr(p, attr);
        if (a && a < end && nth-- == 0) {
            const char *d = strstr(p, " d=\"");
            assert_true(d && d < end);
            d += 4;
            return strndup(d, (size_t)(strchr(d, '"') - d));
        }
        p = end;
    }
    return NULL;
}

/* Path data of absolute M, L, C, Z back to points and verbs, 0.5 px taken off (the SVG puts
 * pixel (i, j)'s centre at (i + 0.5, j + 0.5)). */
static size_t parse_d(const char *d, double *xy, uint8_t *verbs, size_t *nverbs) {
    size_t n = 0, nv = 0;
    char cmd = 0;
    const char *p = d;
    while (*p) {
        if (isspace((unsigned char)*p)) { p++; continue; }
        if (isalpha((unsigned char)*p)) {
            cmd = *p++;
            if (cmd == 'Z') continue;
            assert_true(cmd == 'M' || cmd == 'L' || cmd == 'C');
            verbs[nv++] = cmd == 'M' ? PC_PATH_MOVE : cmd == 'L' ? PC_PATH_LINE : PC_PATH_CUBIC;
            for (int k = 0; k < (cmd == 'C' ? 6 : 2); k++) {
                char *e;
                while (isspace((unsigned char)*p)) p++;
                xy[2 * n + k] = strtod(p, &e) - 0.5;
                assert_true(e != p);
                p = e;
            }
            n += cmd == 'C' ? 3 : 1;
            continue;
        }
        fail_msg("unexpected path data at %.20s", p);
    }
    *nverbs = nv;
    return n;
}

static void test_svg_read_back(void **state) {
    (void)state;
    pc_canvas *c = small(40, 30);
    int teal = pc_rgb_color(c, (pc_rgb){0x12, 0x80, 0x7f});
    const uint8_t verbs[] = {PC_PATH_MOVE, PC_PATH_LINE, PC_PATH_LINE, PC_PATH_LINE,
                             PC_PATH_MOVE, PC_PATH_LINE, PC_PATH_CUBIC};
    const double xy[] = {2, 2, 37.25, 2, 37.25, 27.5, 2, 27.5,
                         10, 10, 20, 10, 24, 14, 18, 22, 10, 20};
    assert_int_equal(pc_fill_path(c, 9, xy, verbs, 7, PC_FILL_EVENODD, teal), PC_OK);
    const double tri[] = {5, 25, 9, 15, 12, 26};
    assert_int_equal(fill(c, 3, tri, PC_FILL_NONZERO, 14), PC_OK);
    char *svg = svg_of(c);
    assert_non_null(strstr(svg, "<path fill=\"#12807f\" fill-rule=\"evenodd\" shape-rendering=\"crispEdges\" d=\"M2.5 2.5L37.75 2.5L37.75 28L2.5 28ZM10.5 10.5L20.5 10.5C24.5 14.5 18.5 22.5 10.5 20.5Z\"/>"));
    char *d2 = path_d(svg, "fill=\"#ffff55\"", 0);   /* colour 14, nonzero: no fill-rule */
    assert_non_null(d2);
    assert_string_equal(d2, "M5.5 25.5L9.5 15.5L12.5 26.5Z");
    assert_null(strstr(strstr(svg, "#ffff55"), "evenodd"));
    /* each path filled again from its data gives the raster's pixels */
    pc_canvas *again = small(40, 30);
    assert_int_equal(pc_rgb_color(again, (pc_rgb){0x12, 0x80, 0x7f}), teal);
    const char *attrs[2] = {"fill=\"#12807f\"", "fill=\"#ffff55\""};
    const int colors[2] = {teal, 14}, rules[2] = {PC_FILL_EVENODD, PC_FILL_NONZERO};
    for (int k = 0; k < 2; k++) {
        char *d = path_d(svg, attrs[k], 0);
        double pts[64];
        uint8_t vb[32];
        size_t nv, n = parse_d(d, pts, vb, &nv);
        assert_int_equal(pc_fill_path(again, n, pts, vb, nv, rules[k], colors[k]), PC_OK);
        free(d);
    }
    assert_memory_equal(c->pixels, again->pixels, 40 * 30 * sizeof *c->pixels);
    free(d2);
    free(svg);
    pc_canvas_free(again);
    pc_canvas_free(c);
}

/* A fill reaching far off the screen is cut to the clip in the SVG (no clamped garbage):
 * every number written is within the screen and its margin. */
static void test_svg_far(void **state) {
    (void)state;
    pc_canvas *c = small(20, 20);
    const double t[] = {10, -1e9, 10, 1e9, -1e9, 0};
    assert_int_equal(fill(c, 3, t, PC_FILL_EVENODD, 2), PC_OK);
    char *svg = svg_of(c);
    char *d = path_d(svg, "fill=\"#00aa00\"", 0);
    assert_non_null(d);
    double pts[64];
    uint8_t vb[32];
    size_t nv, n = parse_d(d, pts, vb, &nv);
    assert_true(n >= 3 && n < 32);
    for (size_t i = 0; i < 2 * n; i++) assert_true(pts[i] >= -4 && pts[i] <= 24);
    pc_canvas *again = small(20, 20);
    assert_int_equal(pc_fill_path(again, n, pts, vb, nv, PC_FILL_EVENODD, 2), PC_OK);
    assert_memory_equal(c->pixels, again->pixels, 400 * sizeof *c->pixels);
    free(d);
    free(svg);
    pc_canvas_free(again);
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_triangle_pixels),   cmocka_unit_test(test_fractional_triangle),
        cmocka_unit_test(test_shared_edges),      cmocka_unit_test(test_hole),
        cmocka_unit_test(test_view_clip),         cmocka_unit_test(test_window),
        cmocka_unit_test(test_cubic_disc),        cmocka_unit_test(test_far_points),
        cmocka_unit_test(test_degenerate_and_errors), cmocka_unit_test(test_display_list),
        cmocka_unit_test(test_svg_read_back),     cmocka_unit_test(test_svg_far),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
