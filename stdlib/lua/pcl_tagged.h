/* The userdata of equations, samples and surfaces (l_expr.c, l_surface.c): each block begins
 * with its own address tagged by its type (PCL_SELF, pcl.h), under the metatable of that name. */
#ifndef PCL_TAGGED_H
#define PCL_TAGGED_H

#include "pcl.h"

/* A new userdata of size bytes tagged by tag, with the metatable type (its other fields unset). */
static inline void *pcl_tagged_new(lua_State *L, size_t size, const char *tag, const char *type) {
    uintptr_t *self = lua_newuserdatauv(L, size, 0);
    *self = PCL_SELF_TAG(self, tag);
    luaL_setmetatable(L, type);
    return self;
}

/* The userdata of the metatable type at idx when its tag and size tell it genuine (PCL_TAG_ATLEAST:
 * a header of size bytes, the type checks the rest), NULL when idx holds none; a forged one raises
 * (pcl_genuine), or for a __gc (PCL_TAG_GC) gives NULL. */
enum { PCL_TAG_ATLEAST = 1, PCL_TAG_GC = 2 };
static inline void *pcl_tagged_udata(lua_State *L, int idx, const char *tag, const char *type, size_t size, int flags) {
    uintptr_t *self = luaL_testudata(L, idx, type);
    size_t len = lua_rawlen(L, idx);
    int ok = self && (flags & PCL_TAG_ATLEAST ? len >= size : len == size) && *self == PCL_SELF_TAG(self, tag);
    return flags & PCL_TAG_GC ? (ok ? self : NULL) : pcl_genuine(L, idx, self, !self || ok, type);
}

#endif
