/* DRAW: QBasic's graphics macro language (qbscreen.h).  A small reader of the command string:
 * each movement is a LINE between whole pixels of the screen, so the display list and the SVG
 * writer see ordinary lines. */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include "canvas_internal.h"
#include "qbscreen.h"

void pc_draw_state_reset(pc_draw_state *st) {
    st->color = -1;
    st->scale = 4;
    st->angle = 0;
    st->turn = 0;
    st->aspect = 1;
}

typedef struct {
    pc_canvas *c;
    pc_draw_state *st;
    const char *s;
    size_t i;
    double x, y;   /* the pen, in screen pixels (whole numbers, as QBasic's graphics cursor) */
} reader;

static void skip(reader *r) {
    while (r->s[r->i] == ' ' || r->s[r->i] == ';' || r->s[r->i] == '\t') r->i++;
}

/* An integer, optionally signed; *given 0 when there is none (the command's default). */
static int number(reader *r, int allow_sign, long *v, int *given, int *sign) {
    skip(r);
    const char *p = r->s + r->i;
    int neg = 0;
    *sign = 0;
    if (allow_sign && (*p == '+' || *p == '-')) {
        neg = *p == '-';
        *sign = 1;
        p++;
        while (*p == ' ') p++;
    }
    if (!isdigit((unsigned char)*p)) {
        *given = 0;
        if (*sign) return pc_fail(r->c, "draw: a number must follow the sign at character %zu", r->i + 1);
        return PC_OK;
    }
    long n = 0;
    while (isdigit((unsigned char)*p)) {
        n = n * 10 + (*p++ - '0');
        if (n > 1000000) return pc_fail(r->c, "draw: number too large at character %zu", r->i + 1);
    }
    r->i = (size_t)(p - r->s);
    *v = neg ? -n : n;
    *given = 1;
    return PC_OK;
}

static int required(reader *r, int allow_sign, long *v, char cmd) {
    int given, sign;
    size_t at = r->i;
    int ok = number(r, allow_sign, v, &given, &sign);
    if (ok == PC_OK && !given)
        return pc_fail(r->c, "draw: %c needs a number at character %zu", cmd, at + 1);
    return ok;
}

/* The screen pixel (x, y) as world coordinates, for the drawing statements. */
static void world(const reader *r, double x, double y, double *wx, double *wy) {
    pc_screen_to_world(r->c, x, y, wx, wy);
}

/* Move the pen by (dx, dy) pixels before scale and turn, or to (tx, ty) when absolute. */
static int move(reader *r, double dx, double dy, int absolute, int blank, int back) {
    double nx, ny;
    if (absolute) {
        nx = dx;
        ny = dy;
    } else {
        double k = r->st->scale / 4.0, t = r->st->turn * (3.14159265358979323846 / 180.0);
        /* counter-clockwise on the screen (y down): U turned by 90 degrees goes left.  The turn
         * is done on the monitor, where a pixel is 1/aspect times as high as wide: vertical
         * distances to monitor units and back (QBasic's DRAW in SCREEN 1 and 2, whose pixels
         * are not square: "A1 R10" there is 4 pixels up, not 10) */
        double a = r->st->aspect > 0 ? r->st->aspect : 1, my = dy / a;
        double rx = dx * cos(t) + my * sin(t), ry = (-dx * sin(t) + my * cos(t)) * a;
        nx = r->x + rx * k;
        ny = r->y + ry * k;
    }
    nx = (double)pc_px(nx);
    ny = (double)pc_px(ny);
    if (!blank) {
        double ax, ay, bx, by;
        world(r, r->x, r->y, &ax, &ay);
        world(r, nx, ny, &bx, &by);
        int ok = pc_line(r->c, ax, ay, bx, by, r->st->color);
        if (ok != PC_OK) return ok;
    }
    if (!back) {
        r->x = nx;
        r->y = ny;
    }
    return PC_OK;
}

int pc_draw_macro(pc_canvas *c, pc_draw_state *st, const char *cmds) {
    if (!cmds) return pc_fail(c, "draw: no command string");
    reader r = {c, st, cmds, 0, 0, 0};
    double sx, sy;
    pc_world_to_screen(c, c->last_x, c->last_y, &sx, &sy);
    r.x = (double)pc_px(sx);
    r.y = (double)pc_px(sy);
    int blank = 0, back = 0, ok = PC_OK;
    static const struct { char cmd; int dx, dy; } moves[] = {
        {'U', 0, -1}, {'D', 0, 1}, {'L', -1, 0}, {'R', 1, 0},
        {'E', 1, -1}, {'F', 1, 1}, {'G', -1, 1}, {'H', -1, -1}};
    for (;;) {
        skip(&r);
        char ch = (char)toupper((unsigned char)cmds[r.i]);
        if (!ch) break;
        size_t at = r.i++;
        long n = 1, m;
        int given, sign, done = 0;
        for (size_t k = 0; k < sizeof moves / sizeof *moves; k++)
            if (moves[k].cmd == ch) {
                if ((ok = number(&r, 0, &n, &given, &sign)) != PC_OK) return ok;
                if (!given) n = 1;
                ok = move(&r, (double)moves[k].dx * n, (double)moves[k].dy * n, 0, blank, back);
                blank = back = 0;
                done = 1;
                break;
            }
        if (ok != PC_OK) return ok;
        if (done) continue;
        switch (ch) {
        case 'B': blank = 1; break;
        case 'N': back = 1; break;
        case 'M': {
            skip(&r);
            int relative = cmds[r.i] == '+' || cmds[r.i] == '-';
            if ((ok = required(&r, 1, &n, 'M')) != PC_OK) return ok;
            skip(&r);
            if (cmds[r.i] != ',') return pc_fail(c, "draw: M needs x,y at character %zu", at + 1);
            r.i++;
            if ((ok = required(&r, 1, &m, 'M')) != PC_OK) return ok;
            if (relative) ok = move(&r, (double)n, (double)m, 0, blank, back);
            else {
                /* absolute: pixels of the view (VIEW SCREEN: of the screen) */
                double ox = c->view_screen ? 0 : c->view.x0, oy = c->view_screen ? 0 : c->view.y0;
                ok = move(&r, ox + (double)n, oy + (double)m, 1, blank, back);
            }
            if (ok != PC_OK) return ok;
            blank = back = 0;
            break;
        }
        case 'C':
            if ((ok = required(&r, 0, &n, 'C')) != PC_OK) return ok;
            if (n >= c->ncolors) return pc_fail(c, "draw: colour %ld out of range 0..%d", n, c->ncolors - 1);
            st->color = (int)n;
            break;
        case 'S':
            if ((ok = required(&r, 0, &n, 'S')) != PC_OK) return ok;
            if (n < 1 || n > 255) return pc_fail(c, "draw: scale S must be 1..255, got %ld", n);
            st->scale = (double)n;
            break;
        case 'A':
            if ((ok = required(&r, 0, &n, 'A')) != PC_OK) return ok;
            if (n > 3) return pc_fail(c, "draw: angle A must be 0..3, got %ld", n);
            st->angle = (int)n;
            st->turn = 90.0 * (double)n;
            break;
        case 'T':
            if (toupper((unsigned char)cmds[r.i]) != 'A')
                return pc_fail(c, "draw: T must be TA at character %zu", at + 1);
            r.i++;
            if ((ok = required(&r, 1, &n, 'T')) != PC_OK) return ok;
            if (n < -360 || n > 360) return pc_fail(c, "draw: turn TA must be -360..360, got %ld", n);
            st->turn = (double)n;
            break;
        case 'P': {
            if ((ok = required(&r, 0, &n, 'P')) != PC_OK) return ok;
            skip(&r);
            if (cmds[r.i] != ',') return pc_fail(c, "draw: P needs paint,border at character %zu", at + 1);
            r.i++;
            if ((ok = required(&r, 0, &m, 'P')) != PC_OK) return ok;
            if (n >= c->ncolors || m >= c->ncolors)
                return pc_fail(c, "draw: P colours must be 0..%d, got %ld,%ld", c->ncolors - 1, n, m);
            double wx, wy;
            world(&r, r.x, r.y, &wx, &wy);
            if ((ok = pc_paint(c, wx, wy, (int)n, (int)m)) != PC_OK) return ok;
            break;
        }
        default:
            return pc_fail(c, "draw: unknown command '%c' at character %zu", cmds[at], at + 1);
        }
    }
    if (blank || back) return pc_fail(c, "draw: B or N at the end of the string moves nothing");
    world(&r, r.x, r.y, &c->last_x, &c->last_y);
    return PC_OK;
}
