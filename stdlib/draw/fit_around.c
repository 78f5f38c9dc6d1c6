/* Framing given points before drawing (layout.h: pc_fit_around): the window round their box,
 * pad world units more on each side, at equal units on both axes at the view's aspect (or
 * each axis on its own).  Unlike pc_fit it moves nothing already drawn: it only sets the
 * window, so a script states its frame once, from the points of its figure. */
#include <math.h>
#include "canvas_internal.h"
#include "layout.h"

static long gcd(long a, long b) { return b ? gcd(b, a % b) : a; }

int pc_fit_around(pc_canvas *c, size_t n, const double *xy, double pad, int aspect) {
    return pc_fit_around_band(c, n, xy, pad, 0, aspect);
}

int pc_fit_around_band(pc_canvas *c, size_t n, const double *xy, double pad, double band, int aspect) {
    if (n == 0) return pc_fail(c, "fit: around needs at least one point");
    if (!isfinite(pad) || pad < 0) return pc_fail(c, "fit: pad must be a finite number >= 0, got %g", pad);
    /* the band: pixels kept free under the points' frame (a caption's line), so the frame is
     * the view less the band and the window reaches down over it at the same units */
    long W = c->view.x1 - c->view.x0, H = c->view.y1 - c->view.y0;
    if (!isfinite(band) || band < 0 || band >= H)
        return pc_fail(c, "fit: band must be a number of pixels >= 0 and below the view's %ld, got %g", H, band);
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        if (!isfinite(x) || !isfinite(y)) return pc_fail(c, "fit: around point %zu is not finite", i + 1);
        x0 = fmin(x0, x); x1 = fmax(x1, x); y0 = fmin(y0, y); y1 = fmax(y1, y);
    }
    double Hb = (double)H - band;
    if (aspect == PC_FIT_FILL) {
        if ((x1 - x0 + 2 * pad) == 0 || (y1 - y0 + 2 * pad) == 0)
            return pc_fail(c, "fit: the points around span no %s and pad is 0: give a pad > 0", x0 == x1 ? "width" : "height");
        double below = band * (y1 - y0 + 2 * pad) / Hb;
        return pc_window(c, x0 - pad, y0 - pad - below, x1 + pad, y1 + pad, 0);
    }
    /* equal units: the window's sides in the ratio of the view's pixel spans (the window's
     * corners land on the view's corner pixels, pc_world_to_screen), reduced so that a
     * 4:3 span multiplies by 3 and divides by 4 exactly as a hand-written frame would */
    if (W <= 0 || H <= 0) return pc_fail(c, "fit: the view is a single line of pixels: no aspect to frame at");
    double a, b;
    if (band == 0) {
        long g = gcd(W, H);
        a = (double)(W / g), b = (double)(H / g);
    } else a = (double)W, b = Hb;
    double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, h = fmax((x1 - x0) * b / a, y1 - y0) / 2 + pad;
    if (h == 0) return pc_fail(c, "fit: the points around are one point and pad is 0: give a pad > 0");
    return pc_window(c, cx - h * a / b, cy - h - band * 2 * h / Hb, cx + h * a / b, cy + h, 0);
}
