/* The safe mode's file functions (docs/safety.md): io.open, io.lines, io.input, io.output,
 * os.remove, os.rename, loadfile and dofile, opening what was checked and nothing else.
 *
 * A name is first converted as Lua converts it (a number is a name too), then opened without a
 * race: the folder part is opened as a directory descriptor and its real place compared with
 * the allowed folders, and the last part is opened relative to that descriptor without
 * following a link (O_NOFOLLOW); a link is followed only to check where the opened file really
 * is.  Swapping a link between the check and the open therefore reaches nothing outside.  A
 * regular file with other hard links is refused: one of them may be outside. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <lauxlib.h>
#include "pcl.h"
#include "sandbox.h"

/* The real place of an open descriptor (/proc/self/fd), into buf; 0 if unknown. */
static int real_place(int fd, char *buf, size_t len) {
    char link[64];
    snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    ssize_t n = readlink(link, buf, len - 1);
    if (n <= 0 || (size_t)n >= len - 1) return 0;
    buf[n] = 0;
    return buf[0] == '/';
}

static int fd_allowed(int fd) {
    char place[PATH_MAX + 16];
    return real_place(fd, place, sizeof place) && sandbox_under_allowed(place);
}

/* The name at arg, converted (a number becomes its string in place, as luaL_checklstring
 * does) and free of NUL bytes. */
static const char *name_arg(lua_State *L, const char *fname, int arg, int write) {
    sandbox_check_path(L, fname, arg, write);   /* NUL bytes and the resolved name */
    return lua_tostring(L, arg);
}

/* The folder part of path opened as a directory descriptor under an allowed folder, and the
 * last part in *base; raises the safe mode's error for fname's argument arg otherwise. */
static int open_parent(lua_State *L, const char *fname, int arg, int write, const char *path,
                       const char **base) {
    const char *slash = strrchr(path, '/');
    *base = slash ? slash + 1 : path;
    int dfd = -1;
    if (**base && strcmp(*base, ".") && strcmp(*base, "..")) {
        if (!slash) dfd = open(".", O_PATH | O_DIRECTORY | O_CLOEXEC);
        else {
            char *dir = slash == path ? strdup("/") : strndup(path, (size_t)(slash - path));
            if (dir) dfd = open(dir, O_PATH | O_DIRECTORY | O_CLOEXEC);
            free(dir);
        }
    }
    if (dfd >= 0 && fd_allowed(dfd)) return dfd;
    if (dfd >= 0) close(dfd);
    sandbox_refuse_path(L, fname, arg, write, NULL);
    return -1;
}

/* Open path for fname's argument arg with open(2) flags; -1 with errno for an ordinary
 * failure (a missing file), raising for a refused name. */
static int safe_open_fd(lua_State *L, const char *fname, int arg, const char *path, int flags) {
    int write = (flags & O_ACCMODE) != O_RDONLY;
    const char *base;
    int dfd = open_parent(L, fname, arg, write, path, &base);
    int common = O_CLOEXEC | O_NOCTTY;
    int fd = openat(dfd, base, (flags & ~O_TRUNC) | O_NOFOLLOW | common, 0666);
    if (fd < 0 && errno == ELOOP) {
        /* a symbolic link: followed, never creating, then checked where it led */
        fd = openat(dfd, base, (flags & ~(O_TRUNC | O_CREAT | O_EXCL)) | common);
        if (fd >= 0 && !fd_allowed(fd)) {
            close(fd);
            close(dfd);
            sandbox_refuse_path(L, fname, arg, write, NULL);
        }
    }
    int e = errno;
    close(dfd);
    if (fd < 0) {
        errno = e;
        return -1;
    }
    struct stat st;
    if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_nlink > 1 &&
        !sandbox_hardlinks_allowed()) {
        close(fd);
        sandbox_refuse_path(L, fname, arg, write, "a file without other hard links (a hard link "
                            "may be a file outside the allowed folders; --allow-hardlinks "
                            "permits them)");
    }
    if ((flags & O_TRUNC) && S_ISREG(st.st_mode) && ftruncate(fd, 0) != 0) {
        e = errno;
        close(fd);
        errno = e;
        return -1;
    }
    return fd;
}

/* Lua's modes: [rwa]%+?b* */
static int mode_flags(const char *mode) {
    int flags;
    switch (mode[0]) {
    case 'r': flags = O_RDONLY; break;
    case 'w': flags = O_WRONLY | O_CREAT | O_TRUNC; break;
    case 'a': flags = O_WRONLY | O_CREAT | O_APPEND; break;
    default: return -1;
    }
    const char *m = mode + 1;
    if (*m == '+') {
        flags = (flags & ~O_ACCMODE) | O_RDWR;
        m++;
    }
    while (*m == 'b') m++;
    return *m ? -1 : flags;
}

static int close_stream(lua_State *L) {
    luaL_Stream *p = luaL_checkudata(L, 1, LUA_FILEHANDLE);
    int ok = fclose(p->f) == 0;
    return luaL_fileresult(L, ok, NULL);
}

/* A Lua file handle on top of the stack for path, or nil, message, errno (as io.open). */
static int push_stream(lua_State *L, const char *fname, int arg, const char *path,
                       const char *mode) {
    int flags = mode_flags(mode);
    if (flags < 0) return luaL_argerror(L, arg + 1, "invalid mode");
    luaL_Stream *p = lua_newuserdatauv(L, sizeof(luaL_Stream), 0);
    p->closef = NULL;   /* a closed file until it is open */
    luaL_setmetatable(L, LUA_FILEHANDLE);
    int fd = safe_open_fd(L, fname, arg, path, flags);
    if (fd < 0) return luaL_fileresult(L, 0, path);
    char fmode[4] = {mode[0], 0, 0, 0};
    if (flags & O_RDWR) fmode[1] = '+';
    p->f = fdopen(fd, fmode);
    if (!p->f) {
        int e = errno;
        close(fd);
        errno = e;
        return luaL_fileresult(L, 0, path);
    }
    p->closef = close_stream;
    return 1;
}

static int safe_io_open(lua_State *L) {
    const char *mode = luaL_optstring(L, 2, "r");
    const char *path = name_arg(L, "io.open", 1, mode_flags(mode) > 0 &&
                                (mode_flags(mode) & O_ACCMODE) != O_RDONLY);
    return push_stream(L, "io.open", 1, path, mode);
}

/* io.input(name) and io.output(name): the checked file handed to Lua's own (upvalue 1). */
static int safe_io_inout(lua_State *L) {
    int output = (int)lua_tointeger(L, lua_upvalueindex(2));
    const char *fname = output ? "io.output" : "io.input";
    if (lua_type(L, 1) == LUA_TSTRING || lua_type(L, 1) == LUA_TNUMBER) {
        const char *path = name_arg(L, fname, 1, output);
        if (push_stream(L, fname, 1, path, output ? "w" : "r") != 1)
            return luaL_error(L, "%s", lua_tostring(L, -2));
        lua_replace(L, 1);
    }
    lua_settop(L, 1);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, lua_gettop(L) - 1, 1);
    return 1;
}

/* The iterator of io.lines(name): the file's own lines iterator (upvalue 1), closing the file
 * (upvalue 2) at the end, as Lua's io.lines does. */
static int lines_step(lua_State *L) {
    int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_call(L, 0, LUA_MULTRET);
    if (lua_gettop(L) > n && lua_toboolean(L, n + 1)) return lua_gettop(L) - n;
    lua_getfield(L, lua_upvalueindex(2), "close");
    lua_pushvalue(L, lua_upvalueindex(2));
    lua_call(L, 1, 0);
    return 0;
}

static int safe_io_lines(lua_State *L) {
    if (lua_isnoneornil(L, 1)) {   /* the default input: Lua's own */
        lua_pushvalue(L, lua_upvalueindex(1));
        lua_insert(L, 1);
        lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
        return lua_gettop(L);
    }
    const char *path = name_arg(L, "io.lines", 1, 0);
    if (push_stream(L, "io.lines", 1, path, "r") != 1)
        return luaL_error(L, "%s", lua_tostring(L, -2));
    int file = lua_gettop(L);
    int nfmt = file - 2;   /* the formats after the name */
    lua_getfield(L, file, "lines");
    lua_pushvalue(L, file);
    for (int i = 0; i < nfmt; i++) lua_pushvalue(L, 2 + i);
    lua_call(L, 1 + nfmt, 1);
    lua_pushvalue(L, file);
    lua_pushcclosure(L, lines_step, 2);
    lua_pushnil(L);
    lua_pushnil(L);
    lua_pushvalue(L, file);   /* the to-be-closed value of a generic for */
    return 4;
}

static int safe_os_remove(lua_State *L) {
    const char *path = name_arg(L, "os.remove", 1, 1);
    const char *base;
    int dfd = open_parent(L, "os.remove", 1, 1, path, &base);
    int rc = unlinkat(dfd, base, 0);
    if (rc != 0 && errno == EISDIR) rc = unlinkat(dfd, base, AT_REMOVEDIR);
    int e = errno;
    close(dfd);
    errno = e;
    return luaL_fileresult(L, rc == 0, path);
}

static int safe_os_rename(lua_State *L) {
    const char *from = name_arg(L, "os.rename", 1, 1);
    const char *to = name_arg(L, "os.rename", 2, 1);
    const char *b1, *b2;
    int d1 = open_parent(L, "os.rename", 1, 1, from, &b1);
    int d2 = open_parent(L, "os.rename", 2, 1, to, &b2);
    int rc = renameat(d1, b1, d2, b2);
    int e = errno;
    close(d1);
    close(d2);
    errno = e;
    return luaL_fileresult(L, rc == 0, NULL);
}

/* A checked file's text on the stack as a chunk (source only), or nil and the message. */
static int load_checked(lua_State *L, const char *fname, int arg) {
    const char *path = name_arg(L, fname, arg, 0);
    int fd = safe_open_fd(L, fname, arg, path, O_RDONLY);
    if (fd < 0) {
        lua_pushfstring(L, "cannot open %s: %s", path, strerror(errno));
        return 0;
    }
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    char chunk[8192];
    ssize_t n;
    while ((n = read(fd, chunk, sizeof chunk)) > 0) luaL_addlstring(&b, chunk, (size_t)n);
    int e = errno;
    close(fd);
    luaL_pushresult(&b);
    if (n < 0) {
        lua_pop(L, 1);
        lua_pushfstring(L, "cannot read %s: %s", path, strerror(e));
        return 0;
    }
    size_t len;
    const char *text = lua_tolstring(L, -1, &len);
    if (len && text[0] == '#') {   /* a #! line, kept as an empty line */
        while (len && *text != '\n') text++, len--;
    }
    lua_pushfstring(L, "@%s", path);
    int status = luaL_loadbufferx(L, text, len, lua_tostring(L, -1), "t");
    lua_replace(L, -3);   /* the chunk (or message) over the text */
    lua_pop(L, 1);
    return status == LUA_OK;
}

int sandbox_safe_loadfile(lua_State *L) {
    int env = !lua_isnone(L, 3);
    if (lua_isnoneornil(L, 1)) {   /* standard input, as Lua's own */
        if (luaL_loadfilex(L, NULL, "t") != LUA_OK) {
            luaL_pushfail(L);
            lua_insert(L, -2);
            return 2;
        }
    } else if (!load_checked(L, "loadfile", 1)) {
        luaL_pushfail(L);
        lua_insert(L, -2);
        return 2;
    }
    if (env) {
        lua_pushvalue(L, 3);
        if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
    }
    return 1;
}

int sandbox_safe_dofile(lua_State *L) {
    lua_settop(L, 1);
    if (lua_isnil(L, 1) ? luaL_loadfilex(L, NULL, "t") != LUA_OK : !load_checked(L, "dofile", 1))
        return lua_error(L);
    lua_call(L, 0, LUA_MULTRET);
    return lua_gettop(L) - 1;
}

/* Put the safe functions in place of io's and os's (tables at io and os). */
void sandbox_safe_files(lua_State *L, int io, int os) {
    lua_pushcfunction(L, safe_io_open);
    lua_setfield(L, io, "open");
    lua_getfield(L, io, "lines");
    lua_pushcclosure(L, safe_io_lines, 1);
    lua_setfield(L, io, "lines");
    for (int out = 0; out < 2; out++) {
        lua_getfield(L, io, out ? "output" : "input");
        lua_pushinteger(L, out);
        lua_pushcclosure(L, safe_io_inout, 2);
        lua_setfield(L, io, out ? "output" : "input");
    }
    lua_pushcfunction(L, safe_os_remove);
    lua_setfield(L, os, "remove");
    lua_pushcfunction(L, safe_os_rename);
    lua_setfield(L, os, "rename");
}
