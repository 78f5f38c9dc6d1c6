/* The SVG writer: the document parses as XML and its elements match the display list.
 * A small XML reader (enough for what the writer produces, strict about nesting and quoting)
 * and a path-data reader let the tests check element counts, attributes and geometry; when
 * xmllint is installed every document is also checked by it. */
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
#include <unistd.h>
#include <cmocka.h>
#include "canvas.h"
#include "writers.h"

#define PI 3.14159265358979

/* ---- a minimal XML reader ---------------------------------------------------------------- */

typedef struct {
    char name[32];
    char *attrs;     /* the attribute text, starting with a space */
    char *content;   /* character data directly inside (as written, entities unresolved) */
    int parent;      /* index of the enclosing element, -1 for the root */
} elem;

typedef struct {
    char *text;
    elem *e;
    int n;
} doc;

static void parse_fail(const char *text, const char *p, const char *why) {
    fail_msg("SVG does not parse at offset %ld (%s): %.60s", (long)(p - text), why, p);
}

static doc parse_xml(char *text) {
    doc d = {text, calloc(1, sizeof(elem)), 0};
    int stack[64], depth = 0, roots = 0;
    const char *p = text;
    while (*p) {
        if (*p != '<') {
            if (depth > 0 && !strcmp(d.e[stack[depth - 1]].name, "text")) {
                const char *q = strchr(p, '<');
                if (!q) parse_fail(text, p, "unclosed text");
                d.e[stack[depth - 1]].content = strndup(p, (size_t)(q - p));
                p = q;
                continue;
            }
            if (!isspace((unsigned char)*p)) parse_fail(text, p, "text outside an element");
            p++;
            continue;
        }
        if (strncmp(p, "<?", 2) == 0) {
            const char *q = strstr(p, "?>");
            if (!q || p != text) parse_fail(text, p, "declaration");
            p = q + 2;
        } else if (strncmp(p, "<!--", 4) == 0) {
            const char *q = strstr(p + 4, "-->");
            if (!q) parse_fail(text, p, "comment");
            p = q + 3;
        } else if (p[1] == '/') {
            const char *q = p + 2;
            while (isalnum((unsigned char)*q) || *q == '-' || *q == ':') q++;
            if (*q != '>' || depth == 0) parse_fail(text, p, "end tag");
            const char *open = d.e[stack[depth - 1]].name;
            if (strlen(open) != (size_t)(q - p - 2) || strncmp(open, p + 2, (size_t)(q - p - 2)))
                parse_fail(text, p, "end tag does not match");
            depth--;
            p = q + 1;
        } else {
            const char *q = p + 1;
            while (isalnum((unsigned char)*q) || *q == '-' || *q == ':') q++;
            if (q == p + 1 || q - p - 1 >= 32) parse_fail(text, p, "element name");
            if (depth == 0 && roots++) parse_fail(text, p, "second root element");
            d.e = realloc(d.e, (size_t)(d.n + 1) * sizeof(elem));
            elem *e = &d.e[d.n];
            memcpy(e->name, p + 1, (size_t)(q - p - 1));
            e->name[q - p - 1] = 0;
            e->parent = depth ? stack[depth - 1] : -1;
            e->content = NULL;
            const char *a = q;
            for (;;) {   /* attributes: name="value" */
                const char *s = q;
                while (isspace((unsigned char)*q)) q++;
                if (*q == '/' || *q == '>') break;
                if (q == s) parse_fail(text, q, "no space before an attribute");
                while (isalnum((unsigned char)*q) || *q == '-' || *q == ':') q++;
                if (q[0] != '=' || q[1] != '"') parse_fail(text, q, "attribute");
                q += 2;
                while (*q && *q != '"' && *q != '<' && *q != '&') q++;
                if (*q != '"') parse_fail(text, q, "attribute value");
                q++;
            }
            e->attrs = strndup(a, (size_t)(q - a));
            if (*q == '/') {
                if (q[1] != '>') parse_fail(text, q, "empty element");
                p = q + 2;
            } else {
                if (depth == 64) parse_fail(text, q, "too deep");
                stack[depth++] = d.n;
                p = q + 1;
            }
            d.n++;
        }
    }
    if (depth) parse_fail(text, p, "unclosed element");
    if (d.n == 0 || strcmp(d.e[0].name, "svg")) parse_fail(text, text, "the root is not svg");
    return d;
}

static void doc_free(doc *d) {
    for (int i = 0; i < d->n; i++) {
        free(d->e[i].attrs);
        free(d->e[i].content);
    }
    free(d->e);
    free(d->text);
}

/* the value of an attribute (a static buffer), NULL if absent */
static const char *attr(const elem *e, const char *name) {
    static char buf[4][1 << 16];
    static int k;
    char key[64];
    snprintf(key, sizeof key, "%s=\"", name);
    const char *p = e->attrs;
    while ((p = strstr(p, key)) != NULL) {
        if (isspace((unsigned char)p[-1])) break;
        p++;
    }
    if (!p) return NULL;
    p += strlen(key);
    const char *q = strchr(p, '"');
    k = (k + 1) % 4;
    size_t n = (size_t)(q - p) < sizeof buf[k] - 1 ? (size_t)(q - p) : sizeof buf[k] - 1;
    memcpy(buf[k], p, n);
    buf[k][n] = 0;
    return buf[k];
}

/* elements named `name` (NULL: any) that have attribute `with` (NULL: any) */
static int count(const doc *d, const char *name, const char *with) {
    int n = 0;
    for (int i = 0; i < d->n; i++)
        if ((!name || strcmp(d->e[i].name, name) == 0) && (!with || attr(&d->e[i], with))) n++;
    return n;
}

static const elem *nth(const doc *d, const char *name, const char *with, int k) {
    for (int i = 0; i < d->n; i++)
        if (strcmp(d->e[i].name, name) == 0 && (!with || attr(&d->e[i], with)) && k-- == 0)
            return &d->e[i];
    fail_msg("no element %s number %d", name, k);
    return NULL;
}

static int xmllint_present(void) {
    static int known = -1;
    if (known < 0) known = system("command -v xmllint >/dev/null 2>&1") == 0;
    return known;
}

/* Render to SVG, check it with xmllint when present, and parse it. */
static doc svg_of(const pc_canvas *c, pc_theme theme) {
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    assert_non_null(f);
    assert_int_equal(pc_encode_svg(c, theme, f), PC_OK);
    fclose(f);
    if (xmllint_present()) {
        char name[] = "/tmp/pc_svg_XXXXXX";
        int fd = mkstemp(name);
        assert_true(fd >= 0);
        assert_int_equal(write(fd, buf, len), (ssize_t)len);
        close(fd);
        char cmd[128];
        snprintf(cmd, sizeof cmd, "xmllint --noout %s", name);
        int rc = system(cmd);
        unlink(name);
        if (rc != 0) fail_msg("xmllint rejects the SVG:\n%s", buf);
    }
    return parse_xml(buf);
}

/* ---- a path-data reader ------------------------------------------------------------------ */

typedef struct { double x, y; int move; } vtx;   /* move: starts a subpath */

typedef struct {
    vtx *v;
    int n;
    int moves, arcs, closes, lines, curves;
} path;

static int is_num_start(char ch) { return isdigit((unsigned char)ch) || ch == '-' || ch == '.'; }

static double num(const char **p) {
    while (isspace((unsigned char)**p) || **p == ',') (*p)++;
    if (!is_num_start(**p)) fail_msg("path data: number expected at '%.20s'", *p);
    char *end;
    double v = strtod(*p, &end);
    const char *dot = memchr(*p, '.', (size_t)(end - *p));
    if (dot && end - dot - 1 > 2) fail_msg("path data: more than two decimals in '%.12s'", *p);
    *p = end;
    return v;
}

static void add_vtx(path *pa, double x, double y, int move) {
    pa->v = realloc(pa->v, (size_t)(pa->n + 1) * sizeof(vtx));
    pa->v[pa->n++] = (vtx){x, y, move};
}

static path parse_path(const char *d) {
    path pa = {0};
    double x = 0, y = 0, sx = 0, sy = 0;
    char cmd = 0;
    const char *p = d;
    for (;;) {
        while (isspace((unsigned char)*p) || *p == ',') p++;
        if (!*p) break;
        if (isalpha((unsigned char)*p)) cmd = *p++;
        else if (!cmd) fail_msg("path data starts with a number: %.20s", d);
        switch (cmd) {
        case 'M': case 'm': {
            double a = num(&p), b = num(&p);
            if (cmd == 'm' && pa.n) { a += x; b += y; }
            x = sx = a; y = sy = b;
            add_vtx(&pa, x, y, 1);
            pa.moves++;
            cmd = cmd == 'm' ? 'l' : 'L';
            break;
        }
        case 'L': x = num(&p); y = num(&p); add_vtx(&pa, x, y, 0); pa.lines++; break;
        case 'l': x += num(&p); y += num(&p); add_vtx(&pa, x, y, 0); pa.lines++; break;
        case 'H': x = num(&p); add_vtx(&pa, x, y, 0); break;
        case 'h': x += num(&p); add_vtx(&pa, x, y, 0); break;
        case 'V': y = num(&p); add_vtx(&pa, x, y, 0); break;
        case 'v': y += num(&p); add_vtx(&pa, x, y, 0); break;
        case 'C':
            for (int i = 0; i < 4; i++) num(&p);
            x = num(&p); y = num(&p);
            add_vtx(&pa, x, y, 0);
            pa.curves++;
            break;
        case 'A':
            for (int i = 0; i < 5; i++) num(&p);
            x = num(&p); y = num(&p);
            add_vtx(&pa, x, y, 0);
            pa.arcs++;
            break;
        case 'Z': case 'z':
            x = sx; y = sy;
            pa.closes++;
            cmd = 0;
            break;
        default: fail_msg("path data: unexpected command '%c'", cmd);
        }
    }
    return pa;
}

/* Winding number of the closed path around (px, py), counting vertical edges to the right. */
static int winding(const path *pa, double px, double py) {
    int w = 0;
    for (int i = 0; i < pa->n; i++) {
        if (pa->v[i].move) continue;
        vtx a = pa->v[i - 1], b = pa->v[i];
        if (a.x == b.x && a.x > px && fmin(a.y, b.y) < py && py < fmax(a.y, b.y)) w += b.y > a.y ? 1 : -1;
        /* the closing side of a subpath back to its start */
        if (i + 1 == pa->n || pa->v[i + 1].move) {
            int s = i;
            while (!pa->v[s].move) s--;
            vtx e = pa->v[s];
            if (b.x == e.x && b.x > px && fmin(b.y, e.y) < py && py < fmax(b.y, e.y))
                w += e.y > b.y ? 1 : -1;
        }
    }
    return w;
}

/* ---- the tests --------------------------------------------------------------------------- */

static pc_canvas *screen12(void) {
    pc_canvas *c = pc_canvas_new_mode(12);
    assert_non_null(c);
    return c;
}

static void test_document(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    doc d = svg_of(c, PC_THEME_SCREEN);
    const elem *root = &d.e[0];
    assert_string_equal(attr(root, "xmlns"), "http://www.w3.org/2000/svg");
    assert_string_equal(attr(root, "width"), "640");
    assert_string_equal(attr(root, "height"), "480");
    assert_string_equal(attr(root, "viewBox"), "0 0 640 480");
    /* the background in colour 0, then the group that sets 1-pixel square-capped strokes */
    assert_string_equal(d.e[1].name, "rect");
    assert_string_equal(attr(&d.e[1], "width"), "640");
    assert_string_equal(attr(&d.e[1], "fill"), "#000000");
    assert_string_equal(d.e[2].name, "g");
    assert_string_equal(attr(&d.e[2], "stroke-width"), "1");
    assert_string_equal(attr(&d.e[2], "stroke-linecap"), "square");
    assert_int_equal(d.n, 3);
    doc_free(&d);
    d = svg_of(c, PC_THEME_PAPER);
    assert_string_equal(attr(&d.e[1], "fill"), "#ffffff");
    doc_free(&d);
    pc_canvas_free(c);
}

/* The drawn elements: all but the root, the background rect, the group of stroke settings,
 * clip paths (and their rects) and clip groups. */
static int drawn(const doc *d) { return d->n - 3 - count(d, "clipPath", NULL) * 2 - (count(d, "g", NULL) - 1); }

static void test_dense_dots_are_one_path(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    /* 100 dots on a quarter circle of radius 50: 0.79 px apart */
    for (int i = 0; i < 100; i++) {
        double t = PI / 2 * i / 99;
        pc_pset(c, 300 + 50 * cos(t), 200 - 50 * sin(t), 14);
    }
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 1);
    assert_int_equal(count(&d, "path", NULL), 1);
    const elem *e = nth(&d, "path", NULL, 0);
    assert_string_equal(attr(e, "stroke"), "#ffff55");
    assert_null(attr(e, "fill"));
    path pa = parse_path(attr(e, "d"));
    assert_int_equal(pa.moves, 1);        /* one polyline */
    assert_int_equal(pa.closes, 0);
    /* it starts and ends at the first and last dot (pixel centres: +0.5) ... */
    assert_float_equal(pa.v[0].x, 350.5, 1e-9);
    assert_float_equal(pa.v[0].y, 200.5, 1e-9);
    assert_float_equal(pa.v[pa.n - 1].x, 300.5, 0.006);
    assert_float_equal(pa.v[pa.n - 1].y, 150.5, 0.006);
    /* ... its vertices are dots of the curve, and there are fewer of them than dots */
    assert_true(pa.n >= 4 && pa.n < 60);
    for (int i = 0; i < pa.n; i++)
        assert_float_equal(hypot(pa.v[i].x - 300.5, pa.v[i].y - 200.5), 50, 0.01);
    free(pa.v);
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_polyline_stays_within_tolerance(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    /* 20000 dots on a circle of radius 100 and a sharp zigzag: the corners survive */
    for (int i = 0; i <= 20000; i++) {
        double t = 2 * PI * i / 20000;
        pc_pset(c, 320 + 100 * cos(t), 240 + 100 * sin(t), 15);
    }
    for (int i = 0; i <= 40; i++) pc_pset(c, 10 + i, 400 + (i % 20 < 10 ? i % 20 : 20 - i % 20), 12);
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(count(&d, "path", "stroke"), 2);
    path pa = parse_path(attr(nth(&d, "path", "stroke", 0), "d"));
    assert_int_equal(pa.moves, 1);
    assert_true(pa.n > 50 && pa.n < 400);
    /* every chord stays within 0.06 px of the circle: its middle is no further inside */
    for (int i = 1; i < pa.n; i++) {
        double mx = (pa.v[i].x + pa.v[i - 1].x) / 2, my = (pa.v[i].y + pa.v[i - 1].y) / 2;
        assert_true(hypot(mx - 320.5, my - 240.5) > 100 - 0.06);
    }
    free(pa.v);
    pa = parse_path(attr(nth(&d, "path", "stroke", 1), "d"));
    /* the zigzag: start, the four turns, end */
    assert_int_equal(pa.n, 5);
    double want[5][2] = {{10.5, 400.5}, {20.5, 410.5}, {30.5, 400.5}, {40.5, 410.5}, {50.5, 400.5}};
    for (int i = 0; i < 5; i++) {
        assert_float_equal(pa.v[i].x, want[i][0], 1e-9);
        assert_float_equal(pa.v[i].y, want[i][1], 1e-9);
    }
    free(pa.v);
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_isolated_dots_are_pixels(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    /* three dots far apart: three unit squares on exactly the raster's pixels */
    pc_pset(c, 10, 10, 15);
    pc_pset(c, 100.4, 50.6, 15);
    pc_pset(c, 300, 400, 15);
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 1);
    const elem *e = nth(&d, "path", NULL, 0);
    assert_string_equal(attr(e, "fill"), "#ffffff");
    assert_string_equal(attr(e, "shape-rendering"), "crispEdges");
    path pa = parse_path(attr(e, "d"));
    assert_int_equal(pa.moves, 3);
    assert_int_equal(pa.closes, 3);
    double want[3][2] = {{10, 10}, {100, 51}, {300, 400}};
    for (int k = 0, i = 0; i < pa.n; i++) {
        if (!pa.v[i].move) continue;
        assert_float_equal(pa.v[i].x, want[k][0], 1e-9);
        assert_float_equal(pa.v[i].y, want[k][1], 1e-9);
        /* a 1x1 square */
        assert_float_equal(pa.v[i + 1].x, want[k][0] + 1, 1e-9);
        assert_float_equal(pa.v[i + 2].y, want[k][1] + 1, 1e-9);
        assert_float_equal(pa.v[i + 3].x, want[k][0], 1e-9);
        k++;
    }
    free(pa.v);
    doc_free(&d);

    /* a later dot on the same pixel wins; other colours get their own path */
    pc_pset(c, 10, 10, 4);
    pc_pset(c, 200, 200, 2);
    d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 3);
    int red = 0, white = 0, green = 0;
    for (int i = 0; i < 3; i++) {
        e = nth(&d, "path", NULL, i);
        pa = parse_path(attr(e, "d"));
        if (!strcmp(attr(e, "fill"), "#aa0000")) red = pa.moves;
        if (!strcmp(attr(e, "fill"), "#ffffff")) white = pa.moves;
        if (!strcmp(attr(e, "fill"), "#00aa00")) green = pa.moves;
        free(pa.v);
    }
    assert_int_equal(red, 1);
    assert_int_equal(white, 2);
    assert_int_equal(green, 1);
    doc_free(&d);

    /* what is drawn after the dots covers them: the order of the display list is kept */
    pc_box(c, 0, 0, 639, 479, 1, 1);
    pc_pset(c, 5, 5, 14);
    d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 5);
    assert_string_equal(d.e[6].name, "rect");
    assert_string_equal(attr(&d.e[6], "fill"), "#0000aa");
    assert_string_equal(attr(&d.e[7], "fill"), "#ffff55");
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_lines(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    /* a triangle drawn with LINE -(x, y): one path, one subpath */
    pc_line(c, 10, 10, 50, 10, 15);
    pc_line(c, 50, 10, 30, 40, 15);
    pc_line(c, 30, 40, 10, 10, 15);
    /* a separate segment in the same colour joins the path as a second subpath */
    pc_line(c, 100, 100, 200, 150, 15);
    /* another colour: another path */
    pc_line(c, 0, 479, 639, 0, 4);
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 2);
    const elem *e = nth(&d, "path", NULL, 0);
    assert_string_equal(attr(e, "stroke"), "#ffffff");
    assert_string_equal(attr(e, "d"), "M10.5 10.5l40 0-20 30-20-30m90 90 100 50");
    e = nth(&d, "path", NULL, 1);
    assert_string_equal(attr(e, "stroke"), "#aa0000");
    assert_string_equal(attr(e, "d"), "M.5 479.5l639-479");
    doc_free(&d);

    /* far off-screen ends are cut near the screen: numbers stay small */
    pc_cls(c);
    pc_line(c, -1e7, 240, 1e7, 240, 15);
    pc_line(c, -1e7, -1e7, -2e7, 5e6, 15);   /* entirely outside: left out */
    d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 1);
    path pa = parse_path(attr(nth(&d, "path", NULL, 0), "d"));
    assert_int_equal(pa.n, 2);
    assert_float_equal(pa.v[0].x, -3, 1e-9);
    assert_float_equal(pa.v[1].x, 643, 1e-9);
    assert_float_equal(pa.v[1].y, 240.5, 1e-9);
    free(pa.v);
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_boxes(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    pc_box(c, 40, 60, 10, 20, 15, 0);     /* corners in any order */
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 1);
    const elem *e = nth(&d, "rect", "stroke", 0);
    assert_string_equal(attr(e, "x"), "10.5");
    assert_string_equal(attr(e, "y"), "20.5");
    assert_string_equal(attr(e, "width"), "30");
    assert_string_equal(attr(e, "height"), "40");
    assert_string_equal(attr(e, "stroke"), "#ffffff");
    assert_null(attr(e, "fill"));
    doc_free(&d);

    /* a filled box covers whole pixels: 10..40 is 31 pixels wide */
    pc_cls(c);
    pc_box(c, 10, 20, 40, 60, 4, 1);
    d = svg_of(c, PC_THEME_PAPER);
    assert_int_equal(drawn(&d), 1);
    e = &d.e[3];
    assert_string_equal(e->name, "rect");
    assert_string_equal(attr(e, "x"), "10");
    assert_string_equal(attr(e, "y"), "20");
    assert_string_equal(attr(e, "width"), "31");
    assert_string_equal(attr(e, "height"), "41");
    assert_string_equal(attr(e, "fill"), "#aa0000");
    assert_string_equal(attr(e, "shape-rendering"), "crispEdges");
    doc_free(&d);

    /* CLS in a background colour: a filled rect after the background */
    pc_color(c, 15, 1);
    pc_cls(c);
    d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 1);
    assert_string_equal(attr(&d.e[3], "fill"), "#0000aa");
    assert_string_equal(attr(&d.e[3], "width"), "640");
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_circles_and_ellipses(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    pc_circle(c, 50, 40, 10, 12, NAN, NAN, NAN);
    pc_circle(c, 200, 100, 20, 10, NAN, NAN, 0.5);
    pc_circle(c, 300, 100, 20, 11, NAN, NAN, 2.0);
    pc_circle(c, 400, 300, 0, 15, NAN, NAN, NAN);   /* radius 0: the centre pixel */
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 4);
    assert_int_equal(count(&d, "circle", NULL), 1);
    assert_int_equal(count(&d, "ellipse", NULL), 2);
    const elem *e = nth(&d, "circle", NULL, 0);
    assert_string_equal(attr(e, "cx"), "50.5");
    assert_string_equal(attr(e, "cy"), "40.5");
    assert_string_equal(attr(e, "r"), "10");
    assert_string_equal(attr(e, "stroke"), "#ff5555");
    e = nth(&d, "ellipse", NULL, 0);    /* aspect < 1 shrinks y */
    assert_string_equal(attr(e, "rx"), "20");
    assert_string_equal(attr(e, "ry"), "10");
    e = nth(&d, "ellipse", NULL, 1);    /* aspect > 1 shrinks x */
    assert_string_equal(attr(e, "rx"), "10");
    assert_string_equal(attr(e, "ry"), "20");
    e = nth(&d, "path", NULL, 0);
    assert_string_equal(attr(e, "fill"), "#ffffff");
    assert_string_equal(attr(e, "d"), "M400 300h1v1h-1z");
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_arcs(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    /* a quarter counter-clockwise from 0 (right) to pi/2 (up): sweep flag 0 */
    pc_circle(c, 50, 50, 20, 15, 0, PI / 2, NAN);
    /* three quarters: the large-arc flag */
    pc_circle(c, 150, 50, 20, 15, PI / 2, 2 * PI, NAN);
    /* negative angles: radii from the centre to both ends, a closed pie */
    pc_circle(c, 250, 50, 20, 15, -PI / 2, -PI, NAN);
    /* one negative angle: one radius, to the end */
    pc_circle(c, 350, 50, 20, 15, 0, -PI / 2, NAN);
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 4);
    assert_int_equal(count(&d, "path", NULL), 4);
    assert_string_equal(attr(nth(&d, "path", NULL, 0), "d"), "M70.5 50.5A20 20 0 0 0 50.5 30.5");
    assert_string_equal(attr(nth(&d, "path", NULL, 1), "d"), "M150.5 30.5A20 20 0 1 0 170.5 50.5");
    assert_string_equal(attr(nth(&d, "path", NULL, 2), "d"),
                        "M250.5 50.5L250.5 30.5A20 20 0 0 0 230.5 50.5Z");
    assert_string_equal(attr(nth(&d, "path", NULL, 3), "d"), "M370.5 50.5A20 20 0 0 0 350.5 30.5L350.5 50.5");
    doc_free(&d);

    /* an arc of a whole turn (start 0, end 2*pi) needs two A commands */
    pc_cls(c);
    pc_circle(c, 100, 100, 30, 15, 0, 2 * PI, 0.5);
    d = svg_of(c, PC_THEME_SCREEN);
    path pa = parse_path(attr(nth(&d, "path", NULL, 0), "d"));
    assert_int_equal(pa.arcs, 2);
    assert_float_equal(pa.v[1].x, 70.5, 1e-9);    /* half way: the left end */
    assert_float_equal(pa.v[2].x, 130.5, 1e-9);
    free(pa.v);
    doc_free(&d);
    pc_canvas_free(c);
}

/* The painted path covers exactly the painted pixels (nonzero rule at pixel centres). */
static void assert_fill_matches(const pc_canvas *c, const doc *d, int color, int k) {
    const elem *e = nth(d, "path", "fill", k);
    assert_string_equal(attr(e, "shape-rendering"), "crispEdges");
    path pa = parse_path(attr(e, "d"));
    int painted = 0;
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) {
            int in = winding(&pa, x + 0.5, y + 0.5) != 0;
            int want = c->pixels[y * c->width + x] == color;
            if (in != want) fail_msg("pixel (%d, %d): path %s, raster %s", x, y, in ? "in" : "out",
                                     want ? "painted" : "not");
            painted += want;
        }
    assert_true(painted > 0);
    free(pa.v);
}

static void test_paint(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(60, 50, 16);
    /* the inside of a box outline: one square */
    pc_box(c, 10, 10, 20, 20, 15, 0);
    pc_paint(c, 15, 15, 4, 15);
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 2);
    const elem *e = nth(&d, "path", NULL, 0);
    assert_string_equal(attr(e, "fill"), "#aa0000");
    assert_string_equal(attr(e, "d"), "M11 11h9v9h-9z");
    doc_free(&d);

    /* a ring between two circles: an outline with a hole, pixel for pixel */
    pc_cls(c);
    pc_circle(c, 30, 25, 20, 15, NAN, NAN, NAN);
    pc_circle(c, 30, 25, 8, 15, NAN, NAN, NAN);
    pc_paint(c, 30, 25 + 14, 2, 15);
    d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(count(&d, "path", "fill"), 1);
    path pa = parse_path(attr(nth(&d, "path", "fill", 0), "d"));
    assert_true(pa.moves >= 2);    /* the outside and the hole */
    free(pa.v);
    assert_fill_matches(c, &d, 2, 0);
    doc_free(&d);

    /* the outside of a shape touching the edges, with pixels meeting only at corners */
    pc_cls(c);
    for (int i = 0; i < 12; i++) pc_pset(c, 20 + i, 10 + i, 15);   /* a diagonal wall */
    pc_pset(c, 40, 30, 15);
    pc_pset(c, 41, 31, 15);
    pc_paint(c, 0, 0, 9, 15);
    d = svg_of(c, PC_THEME_SCREEN);
    assert_fill_matches(c, &d, 9, 0);
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_clip_groups(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    pc_view(c, 100, 50, 199, 149, -1, -1, 0);
    pc_circle(c, 50, 50, 80, 15, NAN, NAN, NAN);
    pc_line(c, 0, 0, 99, 99, 15);
    pc_view_reset(c);
    pc_circle(c, 320, 240, 10, 14, NAN, NAN, NAN);
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(count(&d, "clipPath", NULL), 1);
    const elem *cp = nth(&d, "clipPath", NULL, 0);
    const elem *r = cp + 1;
    assert_string_equal(r->name, "rect");
    assert_string_equal(attr(r, "x"), "100");
    assert_string_equal(attr(r, "y"), "50");
    assert_string_equal(attr(r, "width"), "100");
    assert_string_equal(attr(r, "height"), "100");
    char url[64];
    snprintf(url, sizeof url, "url(#%s)", attr(cp, "id"));
    const elem *g = nth(&d, "g", "clip-path", 0);
    assert_string_equal(attr(g, "clip-path"), url);
    /* the view's circle and line are in the group (view coordinates moved to the screen), the
     * later circle is not */
    const elem *c1 = nth(&d, "circle", NULL, 0), *c2 = nth(&d, "circle", NULL, 1);
    assert_ptr_equal(&d.e[c1->parent], g);
    assert_string_equal(attr(c1, "cx"), "150.5");
    assert_ptr_equal(&d.e[nth(&d, "path", NULL, 0)->parent], g);
    assert_ptr_not_equal(&d.e[c2->parent], g);
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_palette_at_write_time_and_paper(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    pc_circle(c, 100, 100, 10, 3, NAN, NAN, NAN);
    pc_circle(c, 200, 100, 10, 15, NAN, NAN, NAN);
    pc_palette(c, 3, (pc_rgb){0x01, 0x02, 0x03});
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_string_equal(attr(nth(&d, "circle", NULL, 0), "stroke"), "#010203");
    doc_free(&d);
    d = svg_of(c, PC_THEME_PAPER);
    assert_string_equal(attr(nth(&d, "circle", NULL, 1), "stroke"), "#000000");
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_far_away_dots_are_left_out(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    for (int i = 0; i < 1000; i++) pc_pset(c, 1e8 + i, 5e7, 15);   /* dense, far away */
    pc_pset(c, -1e9, 1e9, 15);
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 0);
    doc_free(&d);
    /* a dense run leaving the screen is cut a few pixels outside it */
    pc_cls(c);
    for (int i = 0; i < 100; i++) pc_pset(c, 600 + i, 100, 15);
    d = svg_of(c, PC_THEME_SCREEN);
    path pa = parse_path(attr(nth(&d, "path", NULL, 0), "d"));
    assert_int_equal(pa.n, 2);
    assert_float_equal(pa.v[0].x, 600.5, 1e-9);
    assert_true(pa.v[1].x >= 641 && pa.v[1].x <= 644);
    free(pa.v);
    doc_free(&d);
    pc_canvas_free(c);
}


/* The listings' thick dot, circle (x, y), 1: a dense run is one stroke 3 px wide, sparse dots
 * and bigger circles (markers) stay circles. */
static void test_brush_runs(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    for (int i = 0; i < 200; i++) {             /* dense: 0.8 px apart on a circle */
        double t = PI * i / 199;
        pc_circle(c, 300 + 50 * cos(t), 200 - 50 * sin(t), 1, 10, NAN, NAN, NAN);
    }
    for (int i = 0; i < 3; i++)                 /* sparse: 40 px apart */
        pc_circle(c, 100 + 40 * i, 400, 1, 10, NAN, NAN, NAN);
    pc_circle(c, 500, 400, 5, 10, NAN, NAN, NAN);   /* a marker */
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(count(&d, "path", NULL), 1);
    const elem *e = nth(&d, "path", NULL, 0);
    assert_string_equal(attr(e, "stroke"), "#55ff55");
    assert_string_equal(attr(e, "stroke-width"), "3");
    assert_string_equal(attr(e, "stroke-linecap"), "round");
    path pa = parse_path(attr(e, "d"));
    assert_int_equal(pa.moves, 1);
    assert_true(pa.n >= 4 && pa.n < 100);       /* simplified, yet on the curve */
    for (int i = 0; i < pa.n; i++)
        assert_float_equal(hypot(pa.v[i].x - 300.5, pa.v[i].y - 200.5), 50, 0.01);
    assert_float_equal(pa.v[0].x, 350.5, 1e-9);
    assert_float_equal(pa.v[pa.n - 1].x, 250.5, 0.006);
    free(pa.v);
    assert_int_equal(count(&d, "circle", NULL), 4);
    assert_string_equal(attr(nth(&d, "circle", NULL, 3), "r"), "5");
    doc_free(&d);
    pc_canvas_free(c);
}

/* ---- paths, pens, styles, text, true colours --------------------------------------------- */

static void test_paths(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    const double poly[] = {10, 20, 30, 40.25, 50, 20};
    pc_path(c, 3, poly, NULL, 0, 1, 14);
    const double xy[] = {5, 50, 15, 2, 60, 2, 74, 50, 100, 100, 120, 100};
    const uint8_t verbs[] = {PC_PATH_MOVE, PC_PATH_CUBIC, PC_PATH_MOVE, PC_PATH_LINE};
    pc_path(c, 6, xy, verbs, 4, 0, 14);
    doc d = svg_of(c, PC_THEME_SCREEN);
    /* one <path> per path op, not a trail of dots, aligned like LINE (+0.5) */
    assert_int_equal(drawn(&d), 2);
    const elem *e = nth(&d, "path", NULL, 0);
    assert_string_equal(attr(e, "stroke"), "#ffff55");
    assert_string_equal(attr(e, "d"), "M10.5 20.5L30.5 40.75L50.5 20.5Z");
    e = nth(&d, "path", NULL, 1);
    assert_string_equal(attr(e, "d"), "M5.5 50.5C15.5 2.5 60.5 2.5 74.5 50.5M100.5 100.5L120.5 100.5");
    path pa = parse_path(attr(e, "d"));
    assert_int_equal(pa.moves, 2);
    assert_int_equal(pa.curves, 1);
    free(pa.v);
    doc_free(&d);
    /* a segment to far away is cut near the clip */
    pc_cls(c);
    const double far[] = {100, 100, 1e9, 100};
    pc_path(c, 2, far, NULL, 0, 0, 14);
    d = svg_of(c, PC_THEME_SCREEN);
    assert_string_equal(attr(nth(&d, "path", NULL, 0), "d"), "M100.5 100.5L643 100.5");
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_pens(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    const double dash[] = {6, 3};
    pc_pen(c, 3, dash, 2);
    pc_line(c, 10, 10, 100, 10, 15);
    pc_line(c, 100, 10, 100, 50, 15);
    pc_box(c, 200, 200, 220, 230, 4, 0);
    pc_circle(c, 300, 300, 40, 2, NAN, NAN, NAN);
    pc_pen(c, 2, NULL, 0);
    pc_circle(c, 400, 300, 40, 2, NAN, NAN, NAN);
    const double poly[] = {10, 400, 50, 420};
    pc_path(c, 2, poly, NULL, 0, 0, 9);
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(drawn(&d), 5);
    const elem *e = nth(&d, "path", NULL, 0);
    assert_string_equal(attr(e, "stroke-width"), "3");
    assert_string_equal(attr(e, "stroke-linecap"), "round");
    /* each dash 1 px shorter, each gap 1 px longer: the caps make up the pixels */
    assert_string_equal(attr(e, "stroke-dasharray"), "5 4");
    /* the dashes restart at each LINE: each is its own subpath */
    assert_string_equal(attr(e, "d"), "M10.5 10.5l90 0m0 0 0 40");
    e = nth(&d, "path", NULL, 1);
    assert_string_equal(attr(e, "d"), "M200.5 200.5H220.5V230.5H200.5Z");
    assert_string_equal(attr(e, "stroke-dasharray"), "5 4");
    /* a dashed circle is a path from angle 0 counter-clockwise, two half arcs */
    e = nth(&d, "path", NULL, 2);
    path pa = parse_path(attr(e, "d"));
    assert_int_equal(pa.arcs, 2);
    assert_float_equal(pa.v[0].x, 340.5, 1e-9);
    assert_float_equal(pa.v[0].y, 300.5, 1e-9);
    free(pa.v);
    e = nth(&d, "circle", NULL, 0);
    assert_string_equal(attr(e, "stroke-width"), "2");
    assert_null(attr(e, "stroke-dasharray"));
    e = nth(&d, "path", NULL, 3);
    assert_string_equal(attr(e, "stroke-width"), "2");
    assert_string_equal(attr(e, "d"), "M10.5 400.5L50.5 420.5");
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_styled_lines_are_exact_pixels(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(60, 50, 16);
    pc_line_styled(c, 3, 5, 50, 30, 12, 0, 0xAAAA);
    pc_line_styled(c, 5, 40, 40, 45, 12, 1, 0xF0F0);
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(count(&d, "path", "fill"), 1);
    assert_fill_matches(c, &d, 12, 0);
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_text(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    pc_text(c, 100, 100, "a<b&\"c'", PC_ANCHOR_NE, 3, 1, 14);
    pc_text(c, 10, 20, "\xce\xb1\x01", PC_ANCHOR_SE, 0, 2, pc_rgb_color(c, (pc_rgb){0x12, 0x34, 0x56}));
    doc d = svg_of(c, PC_THEME_SCREEN);
    assert_int_equal(count(&d, "text", NULL), 2);
    const elem *e = nth(&d, "text", NULL, 0);
    /* the cell box: left 103, bottom row 97, so top 82; the baseline 12 rows down */
    assert_string_equal(attr(e, "x"), "103");
    assert_string_equal(attr(e, "y"), "94");
    assert_string_equal(attr(e, "font-family"), "monospace");
    assert_string_equal(attr(e, "font-size"), "16");
    assert_string_equal(attr(e, "textLength"), "56");   /* 7 characters */
    assert_string_equal(attr(e, "lengthAdjust"), "spacingAndGlyphs");
    assert_string_equal(attr(e, "fill"), "#ffff55");
    assert_string_equal(e->content, "a&lt;b&amp;&quot;c&apos;");
    e = nth(&d, "text", NULL, 1);
    assert_string_equal(attr(e, "x"), "10");
    assert_string_equal(attr(e, "y"), "44");
    assert_string_equal(attr(e, "font-size"), "32");
    assert_string_equal(attr(e, "textLength"), "32");
    assert_string_equal(attr(e, "fill"), "#123456");
    /* a control character, which XML cannot hold, is the replacement character */
    assert_string_equal(e->content, "\xce\xb1\xef\xbf\xbd");
    doc_free(&d);
    pc_canvas_free(c);
}

static void test_true_colors(void **state) {
    (void)state;
    pc_canvas *c = screen12();
    int orange = pc_rgb_color(c, (pc_rgb){0xff, 0x80, 0x00});
    pc_line(c, 10, 10, 100, 10, orange);
    pc_pset(c, 300, 300, orange);
    doc d = svg_of(c, PC_THEME_PAPER);
    assert_string_equal(attr(nth(&d, "path", "stroke", 0), "stroke"), "#ff8000");
    assert_string_equal(attr(nth(&d, "path", "fill", 0), "fill"), "#ff8000");
    doc_free(&d);
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_document),
        cmocka_unit_test(test_dense_dots_are_one_path),
        cmocka_unit_test(test_polyline_stays_within_tolerance),
        cmocka_unit_test(test_isolated_dots_are_pixels),
        cmocka_unit_test(test_lines),
        cmocka_unit_test(test_boxes),
        cmocka_unit_test(test_circles_and_ellipses),
        cmocka_unit_test(test_arcs),
        cmocka_unit_test(test_paint),
        cmocka_unit_test(test_clip_groups),
        cmocka_unit_test(test_palette_at_write_time_and_paper),
        cmocka_unit_test(test_far_away_dots_are_left_out),
        cmocka_unit_test(test_brush_runs),
        cmocka_unit_test(test_paths),
        cmocka_unit_test(test_pens),
        cmocka_unit_test(test_styled_lines_are_exact_pixels),
        cmocka_unit_test(test_text),
        cmocka_unit_test(test_true_colors),
    };
    if (!xmllint_present()) fprintf(stderr, "note: xmllint not found; SVG checked by the built-in reader only\n");
    return cmocka_run_group_tests(tests, NULL, NULL);
}
