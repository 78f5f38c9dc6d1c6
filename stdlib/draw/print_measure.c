/* Label boxes in the print look: the measuring hook of the figure layout (layout.h) set from
 * Pango, so automatic placement in the print look works with the labels' real sizes.
 *
 * A box is the Pango layout of the label at the figure's font and size (times the label's
 * scale) with its halo on every side, in screen pixels of the canvas (the page's pt divided by
 * the page's scale), so the placement engine, which works in screen pixels, sees exactly the
 * box the print walk then draws the label in (print.c).  The resolution of the output (dpi)
 * does not enter: the page is in pt, so the PDF, the EPS, a PNG at any dpi and the SVG of one
 * run get the same boxes and so the same places. */
#include <stdlib.h>
#include <string.h>
#include "canvas_internal.h"
#include "layout.h"
#include "math_label.h"
#include "print.h"
#include "print_backend.h"

/* The halo's width on each side, as a fraction of the text size (print.c draws 0.16 em). */
#define HALO_EM 0.16

int pc_print_measure(void *ctx, const char *utf8, size_t n, int scale, double *w, double *h) {
    const pc_canvas *c = ctx;
    pc_page pg;
    pc_print_page(c, &pg);
    double size = (c->figure.size > 0 ? c->figure.size : PC_PRINT_SIZE_PT) * (scale >= 1 ? scale : 1);
    const char *family;
    char err[200];
    if (pc_font_family(c->figure.font, &family, err, sizeof err) != PC_OK) return PC_EARG;
    char *s = malloc(n + 1);
    if (!s) return PC_ENOMEM;
    memcpy(s, utf8, n);
    s[n] = 0;
    pc_mlayout L = {0};
    int st = pc_pr_layout(s, pc_has_math(s), family, size, &L, err, sizeof err);
    if (st != PC_OK) {   /* bad math: the walk reports it; measure it as plain text meanwhile */
        pc_mlayout_free(&L);
        st = pc_pr_layout(s, 0, family, size, &L, err, sizeof err);
    }
    free(s);
    if (st != PC_OK) return st;
    double halo = HALO_EM * size;
    *w = (L.width + 2 * halo) / pg.s;
    *h = (L.ascent + L.descent + 2 * halo) / pg.s;
    pc_mlayout_free(&L);
    return PC_OK;
}

const pc_canvas *pc_print_resolve(const pc_canvas *c, pc_canvas *tmp) {
    int st;
    return pc_print_resolve_why(c, tmp, &st, NULL, 0);
}

const pc_canvas *pc_print_resolve_why(const pc_canvas *c, pc_canvas *tmp, int *status, char *why,
                                      size_t whylen) {
    *tmp = *c;   /* shares everything: pc_layout_resolve copies what it changes */
    tmp->measure = pc_print_measure;
    tmp->measure_ctx = tmp;
    tmp->attach_drop = NULL;
    return pc_layout_resolve_why(tmp, status, why, whylen);
}
