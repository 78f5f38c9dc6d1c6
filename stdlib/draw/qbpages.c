/* QBasic's screen pages (qbscreen.h: pc_pages): SCREEN 7 has 8, SCREEN 9 two, the others one;
 * drawing goes to the active page, the visual page is the one shown and saved. */
#include <string.h>
#include "qbscreen.h"

int pc_pages_init(pc_pages *p) {
    memset(p, 0, sizeof *p);
    if (!(p->c = pc_canvas_new_mode(12))) return PC_ENOMEM;
    p->pages[0] = p->c;
    p->npages = 1;
    pc_draw_state_reset(&p->draw);
    return PC_OK;
}

void pc_pages_free(pc_pages *p) {
    for (int i = 0; i < PC_MAX_PAGES; i++)
        if (p->pages[i] != p->c) pc_canvas_free(p->pages[i]);
    pc_canvas_free(p->c);
    memset(p, 0, sizeof *p);
}

pc_canvas *pc_pages_shown(const pc_pages *p) { return p->pages[p->visual] ? p->pages[p->visual] : p->c; }

pc_canvas *pc_pages_page(pc_pages *p, int n) {
    if (n < 0 || n >= p->npages) return NULL;
    if (!p->pages[n]) {   /* a page first used: a blank screen like page 0's */
        pc_canvas *p0 = p->pages[0], *q = pc_canvas_new(p0->width, p0->height, p0->ncolors);
        if (!q) return NULL;
        memcpy(q->palette, p0->palette, 256 * sizeof *q->palette);
        p->pages[n] = q;
    }
    return p->pages[n];
}

int pc_pages_screen(pc_pages *p, const pc_mode_info *m) {
    for (int i = 0; i < PC_MAX_PAGES; i++) {   /* the page drawn on becomes page 0 */
        if (p->pages[i] != p->c) pc_canvas_free(p->pages[i]);
        p->pages[i] = NULL;
    }
    p->pages[0] = p->c;
    p->npages = 1;
    p->active = p->visual = 0;
    pc_draw_state_reset(&p->draw);
    int rc = pc_canvas_reset(p->c, m->width, m->height, m->ncolors);
    if (rc != PC_OK) return rc;
    p->npages = m->pages;
    p->c->screen_pixels = 1;   /* pixel coordinates */
    return PC_OK;
}

int pc_pages_draw(pc_pages *p, const char *cmds) {
    pc_mode_info m;
    p->draw.aspect = pc_mode_of_canvas(p->c, &m) ? m.aspect : 1;
    return pc_draw_macro(p->c, &p->draw, cmds);
}

int pc_pages_set(pc_pages *p, int active, int visual) {
    if (active < 0 || active >= p->npages || visual < 0 || visual >= p->npages) return PC_EARG;
    pc_canvas *a = pc_pages_page(p, active);
    if (!a || !pc_pages_page(p, visual)) return PC_ENOMEM;
    p->c = a;
    p->active = active;
    p->visual = visual;
    return PC_OK;
}

int pc_pages_palette(pc_pages *p, int attr, pc_rgb rgb) {
    for (int i = 0; i < PC_MAX_PAGES; i++)   /* the pages share their colours: c refuses for all */
        if (p->pages[i] && p->pages[i] != p->c) pc_palette(p->pages[i], attr, rgb);
    return pc_palette(p->c, attr, rgb);
}
