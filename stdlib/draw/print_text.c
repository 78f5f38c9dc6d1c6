/* Fonts and text for the print look: families through fontconfig, advances through Pango.
 *
 * One PangoContext at 72 units to the inch (so a Pango size is a size in pt on the page) with
 * hinting off: the advances do not depend on the surface or the resolution, so the PDF, the
 * PNG at any dpi and the SVG put every run of a label at the same place. */
#include <fontconfig/fontconfig.h>
#include <pango/pangocairo.h>
#include <stdio.h>
#include <string.h>
#include "print_backend.h"

static const struct { const char *alias, *family, *package; } families[] = {
    {"serif", "CMU Serif", "fonts-cmu"},
    {"sans", "DejaVu Sans", "fonts-dejavu-core"},
    {"mono", "DejaVu Sans Mono", "fonts-dejavu-core"},
};

/* Is a family installed?  fontconfig substitutes a fallback for any name, so the match's
 * family is compared with the one asked for.  The answers are kept: a figure asks often. */
static int installed(const char *family) {
    static char known[16][64];
    static int nknown;
    for (int i = 0; i < nknown; i++)
        if (!strcmp(known[i], family)) return 1;
    FcPattern *pat = FcNameParse((const FcChar8 *)"");
    if (!pat) return 0;
    FcPatternAddString(pat, FC_FAMILY, (const FcChar8 *)family);
    FcConfigSubstitute(NULL, pat, FcMatchPattern);
    FcDefaultSubstitute(pat);
    FcResult res;
    FcPattern *m = FcFontMatch(NULL, pat, &res);
    int ok = 0;
    FcChar8 *got;
    if (m && FcPatternGetString(m, FC_FAMILY, 0, &got) == FcResultMatch)
        ok = !strcasecmp((const char *)got, family);
    if (m) FcPatternDestroy(m);
    FcPatternDestroy(pat);
    if (ok && nknown < 16 && strlen(family) < 64) strcpy(known[nknown++], family);
    return ok;
}

int pc_font_family(const char *font, const char **family, char *err, size_t errlen) {
    if (!font || !*font) font = "serif";
    const char *package = NULL;
    *family = font;
    for (size_t i = 0; i < sizeof families / sizeof families[0]; i++)
        if (!strcasecmp(font, families[i].alias) || !strcasecmp(font, families[i].family)) {
            *family = families[i].family;
            package = families[i].package;
        }
    if (installed(*family)) return PC_OK;
    if (package)
        snprintf(err, errlen, "font '%s' (%s) is not installed: install the Debian package %s "
                 "(./setup.sh does)", font, *family, package);
    else
        snprintf(err, errlen, "font '%.60s' is not installed (fc-list lists the fonts; the "
                 "defaults are serif, sans and mono)", font);
    return PC_EARG;
}

void *pc_pr_context(void) {
    static PangoContext *ctx;
    if (!ctx) {
        PangoFontMap *map = pango_cairo_font_map_new();
        pango_cairo_font_map_set_resolution(PANGO_CAIRO_FONT_MAP(map), 72);
        ctx = pango_font_map_create_context(map);
        cairo_font_options_t *o = cairo_font_options_create();
        cairo_font_options_set_hint_metrics(o, CAIRO_HINT_METRICS_OFF);
        cairo_font_options_set_hint_style(o, CAIRO_HINT_STYLE_NONE);
        pango_cairo_context_set_font_options(ctx, o);
        cairo_font_options_destroy(o);
        pango_context_set_round_glyph_positions(ctx, FALSE);
    }
    return ctx;
}

void *pc_pr_font(const char *family, int italic, double size) {
    PangoFontDescription *d = pango_font_description_new();
    pango_font_description_set_family(d, family);
    pango_font_description_set_style(d, italic ? PANGO_STYLE_ITALIC : PANGO_STYLE_NORMAL);
    pango_font_description_set_absolute_size(d, size * PANGO_SCALE);
    return d;
}

typedef struct { const char *family; PangoLayout *layout; } measurer;

static double measure(void *ctx, const char *s, size_t n, int italic, double size) {
    measurer *m = ctx;
    PangoFontDescription *d = pc_pr_font(m->family, italic, size);
    pango_layout_set_font_description(m->layout, d);
    pango_font_description_free(d);
    pango_layout_set_text(m->layout, s, (int)n);
    PangoRectangle logical;
    pango_layout_get_extents(m->layout, NULL, &logical);
    return (double)logical.width / PANGO_SCALE;
}

int pc_pr_layout(const char *label, int math, const char *family, double size, pc_mlayout *out,
                 char *err, size_t errlen) {
    PangoContext *ctx = pc_pr_context();
    static char known[64];   /* the last family's metrics: a figure asks for them per label */
    static double asc, desc;
    if (strcmp(known, family)) {
        PangoFontDescription *d = pc_pr_font(family, 0, 100);
        PangoFontMetrics *fm = pango_context_get_metrics(ctx, d, NULL);
        pango_font_description_free(d);
        asc = pango_font_metrics_get_ascent(fm) / (100.0 * PANGO_SCALE);
        desc = pango_font_metrics_get_descent(fm) / (100.0 * PANGO_SCALE);
        pango_font_metrics_unref(fm);
        snprintf(known, sizeof known, "%s", family);
    }
    measurer m = {family, pango_layout_new(ctx)};
    int st = math ? pc_math_layout(label, size, asc, desc, measure, &m, out, err, errlen)
                  : pc_plain_layout(label, size, asc, desc, measure, &m, out);
    g_object_unref(m.layout);
    return st;
}
