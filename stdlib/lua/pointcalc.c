/* luaopen_pointcalc: builds the module table from the binding files, then runs the Lua-side
 * helpers embedded from the .lua files of stdlib/lua (each receives the table as its argument). */
#include "pcl_args.h"
#include "pcl_embed.h"

#define PCL_CALL_OPEN(name) pcl_open_##name(L);

int luaopen_pointcalc(lua_State *L) {
    lua_newtable(L);
    PCL_MODULES(PCL_CALL_OPEN)
    luaL_getsubtable(L, LUA_REGISTRYINDEX, PCL_DECL_KEY);   /* the declarations, for interp/help.lua */
    lua_setfield(L, -2, "_decl");
    pcl_guard_upvalues(L);        /* debug.setupvalue cannot swap a declaration */
    for (const pc_chunk *ch = pcl_stdlib_chunks; ch->name; ch++) {   /* the Lua helpers */
        char chunkname[96];
        snprintf(chunkname, sizeof chunkname, "=[pointcalc/%s.lua]", ch->name);
        if (luaL_loadbuffer(L, ch->text, ch->len, chunkname) != LUA_OK)
            lua_error(L);
        lua_pushvalue(L, -2);
        lua_call(L, 1, 0);
    }
    lua_pushliteral(L, "pointcalc " PCL_VERSION);
    lua_setfield(L, -2, "_VERSION");
    return 1;
}
