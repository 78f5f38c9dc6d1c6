/* Framing given points before drawing (layout.h: pc_fit_around): the window round their box,
 * pad world units more on each side, at equal units on both axes at the view's aspect (or
 * each axis on its own).  Unlike pc_fit it moves nothing already drawn: it only sets the
 * window, so a script states its frame once, from the points of its figure. */
#include <math.h>
#include "canvas_internal.h"
#include "layout.h"

static long gcd(long a, long b) { return b ? gcd(b, a % b) : a; }

int pc_fit_around(pc_canvas *c, size_t n, const double *xy, double pad, int aspect) {
    if (n == 0) return pc_fail(c, "fit: around needs at least one point");
    if (!isfinite(pad) || pad < 0) return pc_fail(c, "fit: pad must be a finite number >= 0, got %g", pad);
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        if (!isfinite(x) || !isfinite(y)) return pc_fail(c, "fit: around point %zu is not finite", i + 1);
        x0 = fmin(x0, x); x1 = fmax(x1, x); y0 = fmin(y0, y); y1 = fmax(y1, y);
    }
    if (aspect == PC_FIT_FILL) {
        if ((x1 - x0 + 2 * pad) == 0 || (y1 - y0 + 2 * pad) == 0)
            return pc_fail(c, "fit: the points around span no %s and pad is 0: give a pad > 0", x0 == x1 ? "width" : "height");
        return pc_window(c, x0 - pad, y0 - pad, x1 + pad, y1 + pad, 0);
    }
    /* equal units: the window's sides in the ratio of the view's pixel spans (the window's
     * corners land on the view's corner pixels, pc_world_to_screen), reduced so that a
     * 4:3 span multiplies by 3 and divides by 4 exactly as a hand-written frame would */
    long W = c->view.x1 - c->view.x0, H = c->view.y1 - c->view.y0;
    if (W <= 0 || H <= 0) return pc_fail(c, "fit: the view is a single line of pixels: no aspect to frame at");
    long g = gcd(W, H);
    double a = (double)(W / g), b = (double)(H / g);
    double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, h = fmax((x1 - x0) * b / a, y1 - y0) / 2 + pad;
    if (h == 0) return pc_fail(c, "fit: the points around are one point and pad is 0: give a pad > 0");
    return pc_window(c, cx - h * a / b, cy - h, cx + h * a / b, cy + h, 0);
}
