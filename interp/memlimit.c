/* The accounting allocator (memlimit.h).  glibc lets a program replace malloc by defining it
 * (the manual's "Replacing malloc"): these forward to glibc's own allocator and count the
 * usable size of every block, so a limit is checked before a block is taken, wherever the
 * request comes from (Lua, the core, libpng, the C library itself). */
#define _GNU_SOURCE
#include "memlimit.h"
#include <errno.h>
#include <stdint.h>
#include <string.h>
#include <unistd.h>

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(PC_NO_MEMLIMIT)
#include <malloc.h>

extern void *__libc_malloc(size_t);
extern void *__libc_calloc(size_t, size_t);
extern void *__libc_realloc(void *, size_t);
extern void *__libc_memalign(size_t, size_t);
extern void __libc_free(void *);

static size_t in_use;                     /* updated atomically: the server has threads */
static size_t limit_bytes;
static void (*refused_hook)(size_t);

int pc_mem_counting(void) { return 1; }
size_t pc_mem_in_use(void) { return __atomic_load_n(&in_use, __ATOMIC_RELAXED); }

void pc_mem_set_limit(size_t limit, void (*on_refuse)(size_t)) {
    refused_hook = on_refuse;
    __atomic_store_n(&limit_bytes, limit, __ATOMIC_RELAXED);
}

/* May `more` bytes be taken?  (A request the size of the whole address space is refused too.) */
static int allowed(size_t more) {
    size_t lim = __atomic_load_n(&limit_bytes, __ATOMIC_RELAXED);
    if (!lim || more == 0) return 1;
    if (more <= lim && pc_mem_in_use() <= lim - more) return 1;
    if (refused_hook) refused_hook(more);
    errno = ENOMEM;
    return 0;
}

static void *counted(void *p) {
    if (p) __atomic_add_fetch(&in_use, malloc_usable_size(p), __ATOMIC_RELAXED);
    return p;
}

static void uncount(void *p) {
    if (p) __atomic_sub_fetch(&in_use, malloc_usable_size(p), __ATOMIC_RELAXED);
}

void *malloc(size_t n) { return allowed(n) ? counted(__libc_malloc(n)) : NULL; }

void free(void *p) {
    uncount(p);
    __libc_free(p);
}

void *calloc(size_t n, size_t size) {
    if (size && n > SIZE_MAX / size) {
        errno = ENOMEM;
        return NULL;
    }
    return allowed(n * size) ? counted(__libc_calloc(n, size)) : NULL;
}

void *realloc(void *p, size_t n) {
    if (!p) return malloc(n);
    if (n == 0) {
        free(p);
        return NULL;
    }
    size_t old = malloc_usable_size(p);
    if (n > old && !allowed(n - old)) return NULL;   /* p stays valid, as realloc promises */
    void *q = __libc_realloc(p, n);
    if (!q) return NULL;
    __atomic_sub_fetch(&in_use, old, __ATOMIC_RELAXED);
    return counted(q);
}

void *memalign(size_t align, size_t n) {
    return allowed(n) ? counted(__libc_memalign(align, n)) : NULL;
}

void *aligned_alloc(size_t align, size_t n) { return memalign(align, n); }

int posix_memalign(void **out, size_t align, size_t n) {
    if (align < sizeof(void *) || (align & (align - 1))) return EINVAL;
    void *p = memalign(align, n);
    if (!p && n) return ENOMEM;
    *out = p;
    return 0;
}

void *valloc(size_t n) { return memalign((size_t)sysconf(_SC_PAGESIZE), n); }

void *pvalloc(size_t n) {
    size_t page = (size_t)sysconf(_SC_PAGESIZE);
    return memalign(page, (n + page - 1) / page * page);
}

#elif defined(__SANITIZE_ADDRESS__)
/* AddressSanitizer brings its own allocator, which cannot refuse for us: its allocation hooks
 * count, and a block that takes the heap past the limit is reported at once (the script then
 * stops at its next instruction, one block past the limit). */
int __sanitizer_install_malloc_and_free_hooks(void (*)(const volatile void *, size_t),
                                              void (*)(const volatile void *));
size_t __sanitizer_get_current_allocated_bytes(void);

static size_t limit_bytes;
static void (*refused_hook)(size_t);

int pc_mem_counting(void) { return 1; }
size_t pc_mem_in_use(void) { return __sanitizer_get_current_allocated_bytes(); }

static void on_malloc(const volatile void *p, size_t n) {
    (void)p;
    size_t lim = __atomic_load_n(&limit_bytes, __ATOMIC_RELAXED);
    if (lim && refused_hook && pc_mem_in_use() > lim) refused_hook(n);
}

static void on_free(const volatile void *p) { (void)p; }   /* the hooks come in pairs */

void pc_mem_set_limit(size_t limit, void (*on_refuse)(size_t)) {
    static int installed;
    if (!installed) installed = __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free);
    refused_hook = on_refuse;
    __atomic_store_n(&limit_bytes, limit, __ATOMIC_RELAXED);
}

#else   /* no glibc: the Lua heap's counting allocator is the only one */

int pc_mem_counting(void) { return 0; }
size_t pc_mem_in_use(void) { return 0; }
void pc_mem_set_limit(size_t limit, void (*on_refuse)(size_t)) { (void)limit; (void)on_refuse; }

#endif
