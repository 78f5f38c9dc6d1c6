/* Lua source files compiled into the binary (see cmake/embed.cmake). */
#ifndef PCL_EMBED_H
#define PCL_EMBED_H
#include <stddef.h>
typedef struct { const char *name; const char *text; size_t len; } pc_chunk;
extern const pc_chunk pcl_stdlib_chunks[];   /* the .lua files of stdlib/lua, loaded by luaopen_pointcalc */
extern const pc_chunk pc_interp_chunks[];    /* the .lua files of interp, used by the host only */
#endif
