/* Choosing the format from a file name, and writing a file safely (docs/safety.md):
 *
 * - atomically: the picture goes to a temporary file in the target's directory, renamed over
 *   the target only when it is complete and closed without error, so readers never see half a
 *   picture and a failed save leaves nothing behind (an existing file untouched);
 * - only over regular files: a device, pipe, socket or folder at the path is never replaced
 *   (renaming over /dev/null would swap the device for a picture);
 * - through a symbolic link only to an existing regular file, which is replaced where it is;
 *   a dangling link is refused, since following it would create a file in a place the user
 *   did not name;
 * - respecting permissions: a read-only file stays as it is, even for root; a replaced file
 *   keeps its mode (and its owner, when we may set it);
 * - leaving nothing behind: the temporary file is created unnamed (O_TMPFILE) where the file
 *   system allows it and given a name only to be renamed into place, so even SIGKILL leaves
 *   no half-written file; elsewhere a named one (mkstemp) is used;
 * - cleaning up on signals: SIGINT, SIGTERM, SIGHUP and SIGQUIT that would end the process
 *   remove the temporary file first; SIGXFSZ (a file-size limit) is ignored while writing, so
 *   the write fails with "File too large" and is cleaned up like any other failure. */
#define _GNU_SOURCE   /* O_TMPFILE, linkat; realpath, mkstemp, fchmod, sigaction */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>
#include "print.h"
#include "writers.h"
#include "layout.h"

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
    if (strcasecmp(dot, ".pdf") == 0) return PC_FMT_PDF;
    if (strcasecmp(dot, ".eps") == 0) return PC_FMT_EPS;
    if (strcasecmp(dot, ".ps") == 0) return PC_FMT_PS;
    return PC_FMT_UNKNOWN;
}

static int fail(char *err, size_t errlen, const char *path, const char *reason, int code) {
    if (err && errlen) snprintf(err, errlen, "cannot write '%s': %s", path, reason);
    return code;
}

/* ---- the temporary file and signals ---------------------------------------------------------- */

/* The temporary file being written, for the signal handlers: a fixed buffer, since a handler
 * may not allocate. */
static char active_tmp[PATH_MAX + 64];
static volatile sig_atomic_t tmp_active;

void pc_write_file_abort(void) {
    if (tmp_active) {
        tmp_active = 0;
        unlink(active_tmp);   /* async-signal-safe */
    }
}

static const int fatal_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
#define NFATAL (sizeof fatal_signals / sizeof fatal_signals[0])

typedef struct {
    struct sigaction old[NFATAL], old_xfsz;
    int caught[NFATAL], xfsz;
} signal_guard;

/* A signal that would end the process: remove the temporary file, then die of it as before. */
static void on_fatal_signal(int sig) {
    pc_write_file_abort();
    struct sigaction dfl;
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, NULL);
    raise(sig);   /* delivered when the handler returns: the process ends as it would have */
}

/* Only signals left at their default (fatal) action are caught: a program's own handler, such
 * as the REPL's Ctrl-C, does not end the process and keeps working. */
static void guard_signals(signal_guard *g) {
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < NFATAL; i++) {
        g->caught[i] = 0;
        if (sigaction(fatal_signals[i], NULL, &g->old[i]) == 0 &&
            !(g->old[i].sa_flags & SA_SIGINFO) && g->old[i].sa_handler == SIG_DFL) {
            sa.sa_handler = on_fatal_signal;
            g->caught[i] = sigaction(fatal_signals[i], &sa, NULL) == 0;
        }
    }
    g->xfsz = 0;
    if (sigaction(SIGXFSZ, NULL, &g->old_xfsz) == 0 && !(g->old_xfsz.sa_flags & SA_SIGINFO) &&
        g->old_xfsz.sa_handler == SIG_DFL) {
        sa.sa_handler = SIG_IGN;   /* write() then fails with EFBIG */
        g->xfsz = sigaction(SIGXFSZ, &sa, NULL) == 0;
    }
}

static void release_signals(signal_guard *g) {
    for (size_t i = 0; i < NFATAL; i++)
        if (g->caught[i]) sigaction(fatal_signals[i], &g->old[i], NULL);
    if (g->xfsz) sigaction(SIGXFSZ, &g->old_xfsz, NULL);
}

/* ---- what may be replaced ------------------------------------------------------------------- */

static int may_write(const char *target, const struct stat *st) {
    if (geteuid() == 0) return (st->st_mode & 0222) != 0;   /* root: only the mode bits say no */
    return faccessat(AT_FDCWD, target, W_OK, AT_EACCESS) == 0;
}

/* Decide where the picture goes.  Sets *target (path itself, or *resolved for a link) and
 * *existing (with *st) when a file is replaced.  0, or an error put into err. */
static int choose_target(const char *path, char **resolved, const char **target, int *existing,
                         struct stat *st, char *err, size_t errlen) {
    *target = path;
    *existing = 0;
    struct stat lst;
    if (lstat(path, &lst) != 0) return 0;   /* a new file: mkstemp reports a bad folder */
    if (S_ISLNK(lst.st_mode)) {
        *resolved = realpath(path, NULL);
        if (!*resolved) {
            int e = errno;
            if (e == ENOENT)
                return fail(err, errlen, path, "it is a symbolic link to a missing file "
                            "(pointcalc writes through a link only to an existing file)", PC_EIO);
            return fail(err, errlen, path, strerror(e), PC_EIO);
        }
        *target = *resolved;
        if (stat(*target, st) != 0) return fail(err, errlen, path, strerror(errno), PC_EIO);
    } else {
        *st = lst;
    }
    if (S_ISDIR(st->st_mode)) return fail(err, errlen, path, strerror(EISDIR), PC_EIO);
    if (!S_ISREG(st->st_mode))
        return fail(err, errlen, path, "it is not a regular file (a device, pipe or socket); "
                    "pointcalc replaces only regular files", PC_EIO);
    if (!may_write(*target, st))
        return fail(err, errlen, path, "Permission denied (the file is read-only)", PC_EIO);
    *existing = 1;
    return 0;
}

/* The permissions a newly created file gets: 0666 less the umask. */
static mode_t new_file_mode(void) {
    mode_t mask = umask(0);
    umask(mask);
    return 0666 & ~mask;
}

typedef struct { const pc_canvas *c; pc_format fmt; pc_theme theme; } picture;

/* The labels placed at write time (layout.h) on a resolved copy, then PDF, EPS and PS always in
 * the print look, PNG and SVG when the script asked for a figure. */
int pc_encode(const pc_canvas *c, pc_format fmt, pc_theme theme, FILE *f, char *why, size_t whylen) {
    int print = fmt == PC_FMT_PDF || fmt == PC_FMT_EPS || fmt == PC_FMT_PS ||
                (c->figure.on && (fmt == PC_FMT_PNG || fmt == PC_FMT_SVG));
    pc_canvas tmp;   /* the print look places labels by their Pango boxes (print_measure.c) */
    const pc_canvas *base = print ? &tmp : c;
    int st;
    const pc_canvas *r = print ? pc_print_resolve_why(c, &tmp, &st, why, whylen)
                               : pc_layout_resolve_why(c, &st, why, whylen);
    if (!r) return st;   /* why says what: memory, or a label's math drawn from a 3-D scene */
    if (print)
        st = pc_encode_print(r, fmt, f, why, whylen);
    else switch (fmt) {
    case PC_FMT_PNG: st = pc_encode_png(r, theme, f); break;
    case PC_FMT_SVG: st = pc_encode_svg(r, theme, f); break;
    case PC_FMT_PPM: st = pc_encode_ppm(r, theme, f); break;
    default: st = PC_EARG; snprintf(why, whylen, "unknown format"); break;
    }
    pc_layout_release(base, r);
    return st;
}

static int encode(void *ud, FILE *f, char *why, size_t whylen) {
    const picture *p = ud;
    return pc_encode(p->c, p->fmt, p->theme, f, why, whylen);
}

int pc_write_file(const pc_canvas *c, const char *path, pc_theme theme, char *err, size_t errlen) {
    pc_format fmt = pc_format_from_path(path);
    if (fmt == PC_FMT_UNKNOWN)
        return fail(err, errlen, path, "the extension must be .png, .svg, .ppm, .pdf, .eps or .ps",
                    PC_EARG);
    picture p = {c, fmt, theme};
    return pc_write_file_emit(path, encode, &p, err, errlen);
}

/* An unnamed file in the folder of tmp (a path ending in ".NAME.XXXXXX"), or -1 where the
 * file system cannot make one. */
static int open_unnamed(const char *tmp) {
#ifdef O_TMPFILE
    const char *slash = strrchr(tmp, '/');
    char dir[sizeof active_tmp];
    if (!slash) snprintf(dir, sizeof dir, ".");
    else if (slash == tmp) snprintf(dir, sizeof dir, "/");
    else snprintf(dir, sizeof dir, "%.*s", (int)(slash - tmp), tmp);
    return open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
#else
    (void)tmp;
    return -1;
#endif
}

/* Give the unnamed file fd a name from the template tmp (its XXXXXX filled in place). */
static int name_unnamed(int fd, char *tmp) {
    char self[64];
    snprintf(self, sizeof self, "/proc/self/fd/%d", fd);
    size_t n = strlen(tmp);
    static const char digits[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    unsigned long seed = (unsigned long)getpid() * 2654435761u ^ (unsigned long)(size_t)tmp;
    for (int attempt = 0; attempt < 100; attempt++) {
        for (size_t i = n - 6; i < n; i++) {
            seed = seed * 6364136223846793005u + 1442695040888963407u;
            tmp[i] = digits[(seed >> 33) % 36];
        }
        if (linkat(AT_FDCWD, self, AT_FDCWD, tmp, AT_SYMLINK_FOLLOW) == 0) return 0;
        if (errno != EEXIST) return -1;
    }
    return -1;
}

int pc_write_file_emit(const char *path, pc_emit_fn emit, void *ud, char *err, size_t errlen) {
    char *resolved = NULL;
    const char *target;
    int existing;
    struct stat st;
    int code = choose_target(path, &resolved, &target, &existing, &st, err, errlen);
    if (code != 0) {
        free(resolved);
        return code;
    }

    /* the temporary file: ".NAME.XXXXXX" beside the target (hidden, same file system) */
    const char *base = basename_of(target);
    size_t dirlen = (size_t)(base - target), baselen = strlen(base);
    if (baselen > 200) baselen = 200;
    if (dirlen + baselen + 16 > sizeof active_tmp) {
        free(resolved);
        return fail(err, errlen, path, strerror(ENAMETOOLONG), PC_EIO);
    }
    char tmp[sizeof active_tmp];
    memcpy(tmp, target, dirlen);
    snprintf(tmp + dirlen, baselen + 16, ".%.*s.XXXXXX", (int)baselen, base);

    /* an unnamed file when possible; else mkstemp fills in the name the handlers read, with
     * the handlers already in place: there is no moment when the file exists and a signal
     * would miss it */
    signal_guard guard;
    memcpy(active_tmp, tmp, strlen(tmp) + 1);
    guard_signals(&guard);
    int fd = open_unnamed(tmp), unnamed = fd >= 0;
    tmp_active = !unnamed;
    if (!unnamed) fd = mkstemp(active_tmp);
    if (fd < 0) {
        int e = errno;
        tmp_active = 0;
        release_signals(&guard);
        free(resolved);
        return fail(err, errlen, path, strerror(e), PC_EIO);
    }
    memcpy(tmp, active_tmp, strlen(active_tmp) + 1);

    int e = 0;
    char why[200] = "";   /* a print-look message (a font, a label's math) */
    code = PC_OK;
    FILE *f = fdopen(fd, "wb");
    if (!f) {
        e = errno;
        close(fd);
    } else {
        errno = 0;
        code = emit(ud, f, why, sizeof why);
        if (code != PC_OK) e = errno ? errno : (code == PC_ENOMEM ? ENOMEM : EIO);
        if (code == PC_EARG || (code == PC_ENOMEM && why[0])) e = EINVAL;   /* why says it */
        if (!e && fflush(f) != 0) e = errno;
        if (!e && existing && geteuid() == 0)   /* root replacing a user's file: keep its owner */
            (void)!fchown(fileno(f), st.st_uid, st.st_gid);
        if (!e && fchmod(fileno(f), existing ? st.st_mode & 0777 : new_file_mode()) != 0)
            e = errno;
        if (!unnamed) {
            if (fclose(f) != 0 && !e) e = errno;
        } else if (fflush(f) != 0 && !e) e = errno;
    }
    if (unnamed && !e) {
        /* named only now, for the rename: the handlers remove it if a signal comes between */
        sigset_t all, old;
        sigfillset(&all);
        sigprocmask(SIG_BLOCK, &all, &old);
        if (name_unnamed(fileno(f), active_tmp) != 0) e = errno ? errno : EIO;
        else tmp_active = 1;
        sigprocmask(SIG_SETMASK, &old, NULL);
        memcpy(tmp, active_tmp, strlen(active_tmp) + 1);
    }
    if (unnamed && f && fclose(f) != 0 && !e) e = errno;
    if (!e && rename(tmp, target) != 0) e = errno;
    if (e && tmp_active) unlink(tmp);
    tmp_active = 0;
    release_signals(&guard);
    if (e) {
        code = code == PC_ENOMEM || code == PC_EARG ? code : PC_EIO;
        fail(err, errlen, path, why[0] ? why : strerror(e), code);
    } else {
        code = PC_OK;
        if (err && errlen) err[0] = 0;
    }
    free(resolved);
    return code;
}
