/* Choosing the format from a file name, and writing a file atomically: the picture goes to a
 * temporary file in the target's directory, which is renamed over the target only when it is
 * complete and closed without error.  Readers of the target never see a half-written file and
 * a failed save leaves nothing behind (and an existing file untouched). */
#define _XOPEN_SOURCE 700   /* realpath, mkstemp, fchmod */
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>
#include "writers.h"

static const char *basename_of(const char *path) {
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

pc_format pc_format_from_path(const char *path) {
    const char *dot = strrchr(basename_of(path), '.');
    if (!dot) return PC_FMT_UNKNOWN;
    if (strcasecmp(dot, ".png") == 0) return PC_FMT_PNG;
    if (strcasecmp(dot, ".svg") == 0) return PC_FMT_SVG;
    if (strcasecmp(dot, ".ppm") == 0) return PC_FMT_PPM;
    return PC_FMT_UNKNOWN;
}

static int fail(char *err, size_t errlen, const char *path, const char *reason, int code) {
    if (err && errlen) snprintf(err, errlen, "cannot write '%s': %s", path, reason);
    return code;
}

/* The permissions a newly created file gets: 0666 less the umask.  An existing target keeps
 * its own permission bits, as it would when overwritten in place. */
static mode_t new_file_mode(const char *target) {
    struct stat st;
    if (stat(target, &st) == 0 && S_ISREG(st.st_mode)) return st.st_mode & 07777;
    mode_t mask = umask(0);
    umask(mask);
    return 0666 & ~mask;
}

int pc_write_file(const pc_canvas *c, const char *path, pc_theme theme, char *err, size_t errlen) {
    pc_format fmt = pc_format_from_path(path);
    if (fmt == PC_FMT_UNKNOWN)
        return fail(err, errlen, path, "the extension must be .png, .svg or .ppm", PC_EARG);

    /* Write through a symbolic link to the file it names, as an in-place write would. */
    const char *target = path;
    char *resolved = NULL;
    struct stat lst;
    if (lstat(path, &lst) == 0 && S_ISLNK(lst.st_mode) && (resolved = realpath(path, NULL)))
        target = resolved;

    /* the temporary file: ".NAME.XXXXXX" beside the target (hidden, same file system) */
    const char *base = basename_of(target);
    size_t dirlen = (size_t)(base - target), baselen = strlen(base);
    if (baselen > 200) baselen = 200;
    char *tmp = malloc(dirlen + baselen + 16);
    if (!tmp) {
        free(resolved);
        return fail(err, errlen, path, strerror(ENOMEM), PC_ENOMEM);
    }
    memcpy(tmp, target, dirlen);
    snprintf(tmp + dirlen, baselen + 16, ".%.*s.XXXXXX", (int)baselen, base);

    int fd = mkstemp(tmp);
    if (fd < 0) {
        int e = errno;
        free(tmp);
        free(resolved);
        return fail(err, errlen, path, strerror(e), PC_EIO);
    }
    int e = 0, code = PC_OK;
    FILE *f = fdopen(fd, "wb");
    if (!f) {
        e = errno;
        close(fd);
    } else {
        errno = 0;
        switch (fmt) {
        case PC_FMT_PNG: code = pc_encode_png(c, theme, f); break;
        case PC_FMT_SVG: code = pc_encode_svg(c, theme, f); break;
        default: code = pc_encode_ppm(c, theme, f); break;
        }
        if (code != PC_OK) e = errno ? errno : (code == PC_ENOMEM ? ENOMEM : EIO);
        if (!e && fflush(f) != 0) e = errno;
        if (!e && fchmod(fileno(f), new_file_mode(target)) != 0) e = errno;
        if (fclose(f) != 0 && !e) e = errno;
    }
    if (!e && rename(tmp, target) != 0) e = errno;
    if (e) {
        unlink(tmp);
        code = code == PC_ENOMEM ? code : PC_EIO;
        fail(err, errlen, path, strerror(e), code);
    } else {
        code = PC_OK;
        if (err && errlen) err[0] = 0;
    }
    free(tmp);
    free(resolved);
    return code;
}
