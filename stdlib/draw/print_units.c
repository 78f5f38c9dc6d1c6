/* Lengths with units and the figure's size (print.h).  One parser for every length a user
 * writes: figure{width =}, --size, pen{width = "0.5mm"}. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "print.h"

static const struct { const char *unit; double pt; } units[] = {
    {"cm", 72 / 2.54}, {"mm", 72 / 25.4}, {"in", 72}, {"pt", 1}, {"px", 0.75},
};

int pc_parse_length(const char *s, const char *what, double *pt, char *err, size_t errlen) {
    if (!s || !*s) {
        snprintf(err, errlen, "%s: expected a length such as \"12cm\", got an empty string", what);
        return PC_EARG;
    }
    char *end;
    double v = strtod(s, &end);
    /* a plain decimal number: strtod would also take "inf", "nan" and hexadecimal */
    size_t digits = strspn(s, "0123456789.+-eE");
    if (end == s || !isfinite(v) || s + digits < end) {
        snprintf(err, errlen, "%s: expected a length such as \"12cm\" or \"0.5mm\", got '%.40s'",
                 what, s);
        return PC_EARG;
    }
    if (!*end) {
        snprintf(err, errlen, "%s: the length '%.40s' needs a unit (cm, mm, in, pt or px)", what, s);
        return PC_EARG;
    }
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
        if (!strcmp(end, units[i].unit)) {
            if (!(v > 0)) {
                snprintf(err, errlen, "%s: a length must be positive, got '%.40s'", what, s);
                return PC_EARG;
            }
            *pt = v * units[i].pt;
            return PC_OK;
        }
    snprintf(err, errlen, "%s: unknown unit '%.20s' in '%.40s' (cm, mm, in, pt or px)", what, end, s);
    return PC_EARG;
}

int pc_parse_size(const char *s, double *w, double *h, char *err, size_t errlen) {
    const char *x = s ? strchr(s, 'x') : NULL;
    *h = 0;
    if (!x) return pc_parse_length(s, "--size", w, err, errlen);
    char first[64];
    size_t n = (size_t)(x - s);
    if (n >= sizeof first) n = sizeof first - 1;
    memcpy(first, s, n);
    first[n] = 0;
    int st = pc_parse_length(first, "--size (width)", w, err, errlen);
    return st != PC_OK ? st : pc_parse_length(x + 1, "--size (height)", h, err, errlen);
}

int pc_figure_set(pc_canvas *c, const pc_figure *f) {
    const double big = 5000 * 72 / 25.4;   /* 5 m */
    if ((f->width && !(f->width >= 1 && f->width <= big)) ||
        (f->height && !(f->height >= 1 && f->height <= big))) {
        snprintf(c->error, sizeof c->error, "figure: width and height must be 1 pt .. 5 m");
        return PC_EARG;
    }
    if (f->dpi && !(f->dpi >= 10 && f->dpi <= 2400)) {
        snprintf(c->error, sizeof c->error, "figure: dpi must be 10..2400, got %g", f->dpi);
        return PC_EARG;
    }
    if (f->size && !(f->size >= 1 && f->size <= 200)) {
        snprintf(c->error, sizeof c->error, "figure: size must be 1..200 pt, got %g", f->size);
        return PC_EARG;
    }
    const char *family;
    if (pc_font_family(f->font, &family, c->error, sizeof c->error) != PC_OK) return PC_EARG;
    pc_figure old = c->figure;
    c->figure = *f;
    c->figure.on = 1;
    pc_page pg;
    pc_print_page(c, &pg);
    if (pg.width * pg.dpi / 72 > 20000 || pg.height * pg.dpi / 72 > 20000) {
        c->figure = old;
        snprintf(c->error, sizeof c->error, "figure: at %g dpi the picture would be %.0fx%.0f "
                 "pixels (at most 20000 a side)", pg.dpi, pg.width * pg.dpi / 72,
                 pg.height * pg.dpi / 72);
        return PC_EARG;
    }
    return PC_OK;
}

void pc_print_page(const pc_canvas *c, pc_page *pg) {
    const pc_figure *f = &c->figure;
    double W = c->width, H = c->height;
    pg->dpi = f->dpi > 0 ? f->dpi : 96;
    pg->width = f->width > 0 ? f->width : f->height > 0 ? f->height * W / H : W * 0.75;
    pg->height = f->height > 0 ? f->height : pg->width * H / W;
    double sx = pg->width / W, sy = pg->height / H;
    pg->s = sx < sy ? sx : sy;   /* one scale: circles stay round */
    pg->ox = (pg->width - W * pg->s) / 2;
    pg->oy = (pg->height - H * pg->s) / 2;
}

/* The engineering pens (ISO 128-20 line types, in the widths of a 0.5 mm drawing): a main
 * (continuous thick) line, thin construction lines, dashed hidden lines, chain centre lines. */
static const struct { const char *name; double width_mm; int ndash; double dash_mm[4]; } pens[] = {
    {"main", 0.5, 0, {0}},
    {"thin", 0.25, 0, {0}},
    {"hidden", 0.35, 2, {3, 1.5}},
    {"centre", 0.25, 4, {12, 1.5, 1, 1.5}},
    {"center", 0.25, 4, {12, 1.5, 1, 1.5}},
};

int pc_pen_named(pc_canvas *c, const char *name) {
    for (size_t i = 0; i < sizeof pens / sizeof pens[0]; i++)
        if (!strcmp(name, pens[i].name)) {
            double dash[4];
            for (int k = 0; k < pens[i].ndash; k++) dash[k] = pens[i].dash_mm[k] * 72 / 25.4;
            return pc_pen_physical(c, pens[i].width_mm * 72 / 25.4, dash, pens[i].ndash);
        }
    snprintf(c->error, sizeof c->error, "pen: unknown pen \"%.40s\" (the named pens are \"main\", "
             "\"thin\", \"hidden\" and \"centre\")", name);
    return PC_EARG;
}
