/* The process's one accounting allocator (memlimit.c): malloc, calloc, realloc, free and the
 * aligned allocators of the C library, counted, so that --max-memory holds inside native calls
 * (a canvas, a display list, a flattening, a text) and not only for the Lua heap. */
#ifndef PC_MEMLIMIT_H
#define PC_MEMLIMIT_H

#include <stddef.h>

/* Whether the allocator is in place (not under AddressSanitizer, which has its own). */
int pc_mem_counting(void);

/* Bytes in use on the C heap now (0 when not counting). */
size_t pc_mem_in_use(void);

/* Refuse (return NULL, errno ENOMEM) any allocation that would take the heap past limit bytes
 * (0: no limit); on_refuse, if given, is told the size of each refused request.  It runs
 * inside malloc: it must not allocate. */
void pc_mem_set_limit(size_t limit, void (*on_refuse)(size_t request));

#endif
