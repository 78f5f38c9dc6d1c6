/* luaopen_pointcalc: builds the module table from the binding files, then runs the Lua-side
 * helpers embedded from the .lua files of stdlib/lua (each receives the table as its argument). */
#include "pcl_args.h"
#include <stdio.h>
#include "pcl_embed.h"

static void run_lua_helpers(lua_State *L) {
    for (const pc_chunk *ch = pcl_stdlib_chunks; ch->name; ch++) {
        char chunkname[96];
        snprintf(chunkname, sizeof chunkname, "=[pointcalc/%s.lua]", ch->name);
        if (luaL_loadbuffer(L, ch->text, ch->len, chunkname) != LUA_OK)
            lua_error(L);
        lua_pushvalue(L, -2);
        lua_call(L, 1, 0);
    }
}

int luaopen_pointcalc(lua_State *L) {
    lua_newtable(L);
    pcl_open_errors(L);
    pcl_open_point(L);
    pcl_open_expr(L);
    pcl_open_simplex(L);
    pcl_open_map(L);
    pcl_open_map_more(L);
    pcl_open_draw(L);
    pcl_open_qb(L);
    pcl_open_qbscreen(L);
    pcl_open_smooth(L);
    pcl_open_curves(L);
    pcl_open_surface(L);
    pcl_open_camera(L);
    pcl_open_konopatsky(L);
    pcl_open_konopatsky_ch1(L);
    pcl_open_konopatsky_schemes(L);
    pcl_open_konopatsky_triples(L);
    pcl_open_params(L);
    pcl_open_korotky(L);
    pcl_open_korotky_meet(L);
    pcl_open_buimov(L);
    pcl_open_buimov_more(L);
    pcl_open_conic_elements(L);   /* after conic (konopatsky) and plane (buimov) */
    pcl_open_curvilinear(L);
    pcl_open_complex(L);
    pcl_open_figure(L);
    pcl_open_figure_layout(L);
    pcl_push_decls(L);            /* the declarations, for interp/help.lua */
    lua_setfield(L, -2, "_decl");
    pcl_guard_upvalues(L);        /* debug.setupvalue cannot swap a declaration */
    run_lua_helpers(L);
    lua_pushliteral(L, "pointcalc " PCL_VERSION);
    lua_setfield(L, -2, "_VERSION");
    return 1;
}
