/* The print look as SVG (print.h): the same walk as cairo's surfaces (print.c), written as
 * SVG paths in pt, and labels as real <text> in the figure's font with one <tspan> a run
 * (italic letters, smaller and shifted scripts), each at the x Pango measured, so Inkscape
 * edits the text and it lands where the PDF and PNG have it.  cairo's own SVG surface would
 * turn the text into glyph outlines. */
#define _GNU_SOURCE   /* open_memstream */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "print_backend.h"

typedef struct {
    FILE *out;
    char *d; size_t dlen; FILE *path;   /* the path being built */
    int nclip, in_group;
    int failed;
} sbe;

static FILE *path(sbe *s) {
    if (!s->path) s->path = open_memstream(&s->d, &s->dlen);
    if (!s->path) s->failed = 1;
    return s->path;
}

static void s_clip(void *self, double x0, double y0, double x1, double y1) {
    sbe *s = self;
    if (s->in_group) fputs("</g>\n", s->out);
    s->nclip++;
    fprintf(s->out, "<clipPath id=\"c%d\"><rect x=\"%.3f\" y=\"%.3f\" width=\"%.3f\" "
            "height=\"%.3f\"/></clipPath>\n<g clip-path=\"url(#c%d)\">\n",
            s->nclip, x0, y0, x1 - x0, y1 - y0, s->nclip);
    s->in_group = 1;
}
static void s_move(void *self, double x, double y) {
    FILE *f = path(self);
    if (f) fprintf(f, "M%.3f %.3f", x, y);
}
static void s_line(void *self, double x, double y) {
    FILE *f = path(self);
    if (f) fprintf(f, "L%.3f %.3f", x, y);
}
static void s_curve(void *self, double x1, double y1, double x2, double y2, double x3, double y3) {
    FILE *f = path(self);
    if (f) fprintf(f, "C%.3f %.3f %.3f %.3f %.3f %.3f", x1, y1, x2, y2, x3, y3);
}
static void s_close(void *self) {
    FILE *f = path(self);
    if (f) fputc('Z', f);
}
static void s_rect(void *self, double x, double y, double w, double h) {
    FILE *f = path(self);
    if (f) fprintf(f, "M%.3f %.3fh%.3fv%.3fh%.3fZ", x, y, w, h, -w);
}

/* The path built so far, emptied; NULL when there is none. */
static const char *take(sbe *s) {
    if (!s->path) return NULL;
    if (fclose(s->path) != 0) s->failed = 1;
    s->path = NULL;
    return s->d && s->dlen ? s->d : NULL;
}
static void done(sbe *s) {
    free(s->d);
    s->d = NULL;
    s->dlen = 0;
}

static void s_stroke(void *self, pc_rgb c, const pc_pr_pen *p) {
    sbe *s = self;
    const char *d = take(s);
    if (d) {
        fprintf(s->out, "<path d=\"%s\" fill=\"none\" stroke=\"#%02x%02x%02x\" stroke-width=\"%.3f\"",
                d, c.r, c.g, c.b, p->width);
        fputs(p->round ? " stroke-linecap=\"round\" stroke-linejoin=\"round\"" : "", s->out);
        if (p->ndash) {
            fputs(" stroke-dasharray=\"", s->out);
            for (int i = 0; i < p->ndash; i++) fprintf(s->out, "%s%.3f", i ? " " : "", p->dash[i]);
            fputc('"', s->out);
        }
        fputs("/>\n", s->out);
    }
    done(s);
}

static void s_fill(void *self, pc_rgb c, int evenodd) {
    sbe *s = self;
    const char *d = take(s);
    if (d)
        fprintf(s->out, "<path d=\"%s\" fill=\"#%02x%02x%02x\"%s/>\n", d, c.r, c.g, c.b,
                evenodd ? " fill-rule=\"evenodd\"" : "");
    done(s);
}

static void xml_text(FILE *f, const char *s, size_t n) {
    for (size_t i = 0; i < n; i++) {
        char ch = s[i];
        if (ch == '<') fputs("&lt;", f);
        else if (ch == '>') fputs("&gt;", f);
        else if (ch == '&') fputs("&amp;", f);
        else if (ch == '"') fputs("&quot;", f);
        else fputc(ch, f);
    }
}

static void s_text(void *self, const pc_pr_label *lab) {
    sbe *s = self;
    const pc_mlayout *L = lab->layout;
    if (!L->nruns) return;
    pc_rgb c = lab->color, h = lab->halo_color;
    fprintf(s->out, "<text x=\"%.3f\" y=\"%.3f\" font-family=\"%s\" font-size=\"%.3f\" "
            "fill=\"#%02x%02x%02x\" xml:space=\"preserve\"", lab->x + L->runs[0].x,
            lab->y - L->runs[0].rise, lab->family, L->runs[0].size, c.r, c.g, c.b);
    if (lab->halo > 0)
        fprintf(s->out, " stroke=\"#%02x%02x%02x\" stroke-width=\"%.3f\" stroke-linejoin=\"round\" "
                "paint-order=\"stroke\"", h.r, h.g, h.b, lab->halo);
    if (L->math) {
        fputs(" data-label=\"", s->out);   /* the source, for an editor that knows the markup */
        xml_text(s->out, lab->source, strlen(lab->source));
        fputc('"', s->out);
    }
    fputc('>', s->out);
    for (size_t i = 0; i < L->nruns; i++) {
        const pc_mrun *r = &L->runs[i];
        fprintf(s->out, "<tspan x=\"%.3f\" y=\"%.3f\"", lab->x + r->x, lab->y - r->rise);
        if (r->italic) fputs(" font-style=\"italic\"", s->out);
        if (r->size != L->runs[0].size) fprintf(s->out, " font-size=\"%.3f\"", r->size);
        fputc('>', s->out);
        xml_text(s->out, L->text + r->first, r->len);
        fputs("</tspan>", s->out);
    }
    fputs("</text>\n", s->out);
    for (size_t i = 0; i < L->ndecos; i++) {
        const pc_mdeco *dc = &L->decos[i];
        double y = lab->y - dc->rise, x0 = lab->x + dc->x0, x1 = lab->x + dc->x1;
        double w = 0.05 * L->runs[0].size;
        if (dc->kind == PC_DECO_TILDE)   /* one period of a wave, up first: TeX's ~ accent */
            fprintf(s->out, "<path d=\"M%.3f %.3fC%.3f %.3f %.3f %.3f %.3f %.3f", x0, y + w,
                    x0 + (x1 - x0) / 3, y - 3 * w, x0 + 2 * (x1 - x0) / 3, y + 3 * w, x1, y - w);
        else
            fprintf(s->out, "<path d=\"M%.3f %.3fH%.3f", x0, y, x1);
        if (dc->kind == PC_DECO_VEC)
            fprintf(s->out, "M%.3f %.3fL%.3f %.3fL%.3f %.3f", x1 - 4 * w, y - 2 * w, x1, y,
                    x1 - 4 * w, y + 2 * w);
        fprintf(s->out, "\" fill=\"none\" stroke=\"#%02x%02x%02x\" stroke-width=\"%.3f\"/>\n",
                c.r, c.g, c.b, w);
    }
}

int pc_encode_print_svg(const pc_canvas *c, const pc_page *pg, FILE *out, char *err, size_t errlen);

int pc_encode_print_svg(const pc_canvas *c, const pc_page *pg, FILE *out, char *err, size_t errlen) {
    sbe s = {out, NULL, 0, NULL, 0, 0, 0};
    pc_rgb paper = pc_print_rgb(c, 0);
    fprintf(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%.3fpt\" "
            "height=\"%.3fpt\" viewBox=\"0 0 %.3f %.3f\">\n"
            "<rect width=\"%.3f\" height=\"%.3f\" fill=\"#%02x%02x%02x\"/>\n",
            pg->width, pg->height, pg->width, pg->height, pg->width, pg->height, paper.r, paper.g,
            paper.b);
    pc_pr_backend b = {&s, s_clip, s_move, s_line, s_curve, s_close, s_rect, s_stroke, s_fill,
                       s_text, NULL, 0};
    int st = pc_print_walk(c, pg, &b, err, errlen);
    take(&s);
    done(&s);
    if (s.in_group) fputs("</g>\n", out);
    fputs("</svg>\n", out);
    if (st == PC_OK && s.failed) st = PC_ENOMEM;
    if (st == PC_OK && (fflush(out) != 0 || ferror(out))) st = PC_EIO;
    return st;
}
