/* Binding of QBasic's screen (stdlib/draw/qbscreen.h): what QBasic programs do on a graphics
 * screen beyond the drawing statements (text in cells, GET/PUT, DRAW, pages, PMAP), for the
 * QBasic runtime and for scripts. */
#include "pcl_draw.h"

#define BLOCK_MT "pointcalc.Block"
static const char BLOCK_TAG = 'b';   /* its address tags the type (PCL_SELF_TAG) */

/* The integer argument k (value v) must lie in lo..hi, a range the screen sets. */
static int in_range(lua_State *L, int k, double v, int lo, int hi) {
    if (v < lo || v > hi) pcl_argfail(L, k, "must be an integer from %d to %d, got %s", lo, hi, pcl_pushnum(L, v));
    return (int)v;
}

#define ATTR(nm) {.name = nm, .kind = PCL_ANY, .flags = PCL_OPT, .read = pcl_read_attr, .dflt = -1}
#define INT(nm) {.name = nm, .kind = PCL_INTEGER}

static const pcl_arg print_at_args[] = {INT("row"), INT("column"), {.name = "text", .kind = PCL_STRING},
                                        ATTR("colour"), ATTR("background colour"),
                                        {.name = "cell height", .kind = PCL_INTEGER, .flags = PCL_OPT}, PCL_END};
PCL_BODY(l_print_at, a) {
    pc_canvas *c = pcl_active_canvas(L);
    /* the mode's cells, or those asked for: text mode's 43 and 50 lines use the 8x8 font */
    int h = a[5].present ? in_range(L, 6, a[5].x, 8, 16) : pc_cell_height(c);
    int row = in_range(L, 1, a[0].x, 1, c->height / h + 1), col = in_range(L, 2, a[1].x, 1, c->width / 8);
    return pcl_check_canvas(L, c, pc_text_cells(c, row, col, a[2].s, lua_rawlen(L, 3), h, (int)a[3].x, (int)a[4].x));
}

static const pcl_arg scroll_args[] = {INT("top row"), INT("bottom row"), ATTR("background colour"), PCL_END};
PCL_BODY(l_scroll_text, a) {
    pc_canvas *c = pcl_active_canvas(L);
    int h = pc_cell_height(c), rows = (c->height + h - 1) / h;
    int top = in_range(L, 1, a[0].x, 1, rows), bottom = in_range(L, 2, a[1].x, top, rows);
    return pcl_check_canvas(L, c, pc_text_scroll(c, top, bottom, h, (int)a[2].x));
}

/* ---- blocks ------------------------------------------------------------------------------ */

typedef struct { PCL_SELF; pc_block *b; long bytes; } block_box;   /* self: pcl.h */

/* The block at idx or NULL; one given the metatable by the debug library is refused. */
static block_box *toblock(lua_State *L, int idx) {
    block_box *bb = luaL_testudata(L, idx, BLOCK_MT);
    return pcl_genuine(L, idx, bb, !bb || pcl_tagged(L, idx, sizeof *bb, &BLOCK_TAG), "block");
}

static block_box *checkblock(lua_State *L, const char *fn) {
    block_box *bb = toblock(L, 1);
    if (!bb) pcl_argerror_full(L, fn, 1, 0, NULL, "a block from get_block");
    return bb;
}

static int block_gc(lua_State *L) {
    block_box *bb = pcl_tagged(L, 1, sizeof *bb, &BLOCK_TAG);
    if (!bb) return 0;   /* never a forged one */
    pc_block_free(bb->b);
    bb->b = NULL;
    return 0;
}

static int block_index(lua_State *L) {
    block_box *bb = checkblock(L, "block.field");
    if (!bb->b) return 0;
    pcl_push_results(L, 0, "w=i h=i bytes=i", bb->b->w, bb->b->h, (int)bb->bytes);
    lua_pushvalue(L, 2);
    lua_rawget(L, -2);
    return 1;
}

static int block_tostring(lua_State *L) {
    block_box *bb = checkblock(L, "tostring");
    lua_pushfstring(L, "block(%d x %d)", bb->b ? bb->b->w : 0, bb->b ? bb->b->h : 0);
    return 1;
}

static const pcl_arg get_block_args[] = {A_X("first corner x"), A_NUM("first corner y"),
                                         A_X("second corner x"), A_NUM("second corner y"), PCL_END};
PCL_PAIRS_BODY(l_get_block, a) {
    pc_canvas *c = pcl_active_canvas(L);
    block_box *bb = pcl_tagged_new(L, sizeof *bb, &BLOCK_TAG, BLOCK_MT);
    bb->b = NULL;
    pcl_check_canvas(L, c, pc_get_block(c, a[0].x, a[1].x, a[2].x, a[3].x, &bb->b));
    bb->bytes = pc_block_bytes(c, bb->b->w, bb->b->h);
    return 1;
}

/* A block from get_block into out->obj. */
static int read_block(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    block_box *bb = toblock(L, idx);
    return bb && bb->b && (out->obj = bb->b);
}

static const char *const ACTIONS[] = {"pset", "preset", "and", "or", "xor", NULL};   /* PC_PUT_* */
static const pcl_arg put_block_args[] = {
    A_X("corner x"), A_NUM("corner y"), {.name = "block", .kind = PCL_ANY, .read = read_block, .expect = "a block from get_block"},
    {.name = "action", .kind = PCL_ENUM, .flags = PCL_OPT, .choices = ACTIONS, .dflt = PC_PUT_XOR}, PCL_END};
PCL_PAIRS_BODY(l_put_block, a) {
    return pcl_drawn(L, pc_put_block(pcl_active_canvas(L), a[0].x, a[1].x, a[2].obj, a[3].n));
}

/* ---- DRAW, pages, PMAP ------------------------------------------------------------------- */

static const pcl_arg draw_args[] = {{.name = "commands", .kind = PCL_ANY, .read = pcl_read_bytes, .expect = "a string"}, PCL_END};
PCL_BODY(l_draw, a) {
    pc_pages *p = pcl_pages(L);
    return pcl_check_canvas(L, p->c, pc_pages_draw(p, a[0].s));
}

/* paint_tile(x, y, tile [, border]): PAINT with a tile string (qbscreen.h) */
static const pcl_arg paint_tile_args[] = {
    A_X("x"), A_NUM("y"), {.name = "tile", .kind = PCL_ANY, .read = pcl_read_bytes, .lo = 1, .hi = 64, .expect = "a string of 1..64 bytes"},
    ATTR("border"), PCL_END};
PCL_PAIRS_BODY(l_paint_tile, a) {
    const unsigned char *tile = (const unsigned char *)a[2].s;
    return pcl_drawn(L, pc_paint_tile_bytes(pcl_active_canvas(L), a[0].x, a[1].x, tile, (size_t)a[2].n, (int)a[3].x));
}

static const pcl_arg pages_args[] = {INT("active page"), {.name = "visual page", .kind = PCL_INTEGER, .flags = PCL_OPT}, PCL_END};
PCL_BODY(l_pages, a) {
    pc_pages *p = pcl_pages(L);
    int active = in_range(L, 1, a[0].x, 0, p->npages - 1);
    int visual = a[1].present ? in_range(L, 2, a[1].x, 0, p->npages - 1) : active;
    return pc_pages_set(p, active, visual) == PC_OK ? 0 : pcl_fail(L, "out of memory for a page");
}

static const pcl_arg pcopy_args[] = {INT("source page"), INT("destination page"), PCL_END};
PCL_BODY(l_pcopy, a) {
    pc_pages *p = pcl_pages(L);
    int from = in_range(L, 1, a[0].x, 0, p->npages - 1), to = in_range(L, 2, a[1].x, 0, p->npages - 1);
    pc_canvas *src = pc_pages_page(p, from), *dst = pc_pages_page(p, to);
    if (!src || !dst) return pcl_fail(L, "out of memory for a page");
    return pcl_check_canvas(L, dst, pc_canvas_copy_picture(dst, src));
}

static const pcl_arg pmap_args[] = {A_NUM("value"), A_INT("function", 0, 3), PCL_END};
PCL_BODY(l_pmap, a) {
    double r = pc_pmap(pcl_active_canvas(L), a[0].x, (int)a[1].x);
    if (a[1].x < 2) lua_pushinteger(L, (lua_Integer)r);
    else lua_pushnumber(L, r);
    return 1;
}

static const pcl_arg mode_info_args[] = {{.name = "mode", .kind = PCL_INTEGER, .expect = "a screen mode 1, 2, 7, 8, 9, 12 or 13"}, PCL_END};
PCL_BODY(l_mode_info, a) {
    pc_mode_info m;
    if (a[0].x < 0 || a[0].x > 13 || pc_mode_info_of((int)a[0].x, &m) != PC_OK)
        return pcl_argfail(L, 1, "must be a screen mode 1, 2, 7, 8, 9, 12 or 13, got %s", pcl_pushnum(L, a[0].x));
    return pcl_push_results(L, 0, "width=i height=i colors=i pages=i cols=i rows=i cell=i aspect=n", m.width, m.height,
                            m.ncolors, m.pages, m.cols, m.rows, m.cell_h, m.aspect);
}

static const pcl_fn fns[] = {
    {.name = "print_at", .fn = l_print_at, .args = print_at_args, .sig = "print_at(row, col, text [, fg [, bg [, cell]]])", .help = "Text in the character cells of a row and column (1-based; 8x8, 8x14 or 8x16 by the mode, or cell pixels high), code page 437, on an opaque background, as QBasic's PRINT."},
    {.name = "scroll_text", .fn = l_scroll_text, .args = scroll_args, .sig = "scroll_text(top, bottom [, bg])", .help = "Move the text rows top..bottom up by one row of cells; the bottom row is cleared."},
    {.name = "get_block", .fn = l_get_block, .args = get_block_args, .sig = "get_block(x1, y1, x2, y2) -> block", .help = "QBasic's GET: the pixels between two corners (inside the view); block.w, block.h and block.bytes (the size QBasic's array needs)."},
    {.name = "put_block", .fn = l_put_block, .args = put_block_args, .sig = "put_block(x, y, block [, \"xor\"|\"pset\"|\"preset\"|\"and\"|\"or\"])", .help = "QBasic's PUT: the block with its top-left corner at (x, y), combined with the screen (XOR by default: twice restores)."},
    {.name = "draw", .fn = l_draw, .args = draw_args, .sig = "draw(commands)", .help = "QBasic's DRAW: U D L R E F G H n, M x,y, B and N prefixes, C n, S n, A n, TA n, P paint,border, from the graphics cursor."},
    {.name = "pages", .fn = l_pages, .args = pages_args, .sig = "pages(active [, visual])", .help = "Draw on page `active` and show page `visual` (SCREEN 7 has 8 pages, SCREEN 9 two); the page shown is the one saved."},
    {.name = "pcopy", .fn = l_pcopy, .args = pcopy_args, .sig = "pcopy(from, to)", .help = "QBasic's PCOPY: page `to` becomes a copy of page `from`."},
    {.name = "pmap", .fn = l_pmap, .args = pmap_args, .sig = "pmap(value, fn) -> number", .help = "QBasic's PMAP: fn 0 and 1 map a world x or y to view pixels, 2 and 3 map pixels back."},
    {.name = "mode_info", .fn = l_mode_info, .args = mode_info_args, .sig = "mode_info(mode) -> {width, height, colors, pages, cols, rows, cell, aspect}", .help = "The facts of SCREEN mode 1, 2, 7, 8, 9, 12 or 13: aspect is CIRCLE's default (4/3 * height/width: 0.8333 in SCREEN 13)."},
    {.name = "paint_tile", .fn = l_paint_tile, .args = paint_tile_args, .sig = "paint_tile(x, y, tile [, border])", .help = "QBasic's PAINT with a tile string (1..64 bytes, read as the mode keeps pixels: a bit a pixel in SCREEN 2, two in SCREEN 1, 4 bit planes a row in the 16-colour modes, a byte a pixel in SCREEN 13), up to the border colour (default: the foreground)."},
    PCL_END};

void pcl_open_qbscreen(lua_State *L) {
    static const luaL_Reg meta[] = {{"__gc", block_gc}, {"__index", block_index}, {"__tostring", block_tostring},
                                    {NULL, NULL}};
    if (luaL_newmetatable(L, BLOCK_MT)) luaL_setfuncs(L, meta, 0);
    lua_pop(L, 1);
    pcl_register(L, -1, fns, 0);
}
