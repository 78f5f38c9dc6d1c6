/* Writing files safely (write_file.c, docs/safety.md): what a save may replace (regular files
 * only, through a link only to an existing regular file, never a read-only file) and that a
 * save stopped by a signal or a file-size limit leaves no temporary file. */
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <cmocka.h>
#include "canvas.h"
#include "writers.h"

typedef struct { char dir[64]; } tmpdir;

static void make_dir(tmpdir *t) {
    strcpy(t->dir, "/tmp/pc_write_file_XXXXXX");
    assert_non_null(mkdtemp(t->dir));
}

static char *in_dir(const tmpdir *t, const char *name) {
    static char buf[4][256];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", t->dir, name);
    return buf[k];
}

static void remove_tree(const char *dir) {
    char cmd[300];
    snprintf(cmd, sizeof cmd, "chmod -R u+w '%s' && rm -rf '%s'", dir, dir);
    assert_int_equal(system(cmd), 0);
}

/* The number of hidden temporary files (".NAME.XXXXXX") in dir. */
static int temporaries(const char *dir) {
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        if (e->d_name[0] == '.' && strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) n++;
    closedir(d);
    return n;
}

static void write_text(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void assert_text(const char *path, const char *want) {
    char buf[64] = {0};
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    assert_string_equal(buf, want);
}

static pc_canvas *small_canvas(void) {
    pc_canvas *c = pc_canvas_new(3, 2, 16);
    assert_non_null(c);
    pc_pset(c, 1, 0, 4);
    return c;
}

static void expect_error(const pc_canvas *c, const char *path, const char *reason) {
    char err[512], want[512];
    assert_int_equal(pc_write_file(c, path, PC_THEME_SCREEN, err, sizeof err), PC_EIO);
    snprintf(want, sizeof want, "cannot write '%s': %s", path, reason);
    assert_string_equal(err, want);
}

#define NOT_REGULAR "it is not a regular file (a device, pipe or socket); " \
                    "pointcalc replaces only regular files"

/* A pipe (standing in for a device such as /dev/null, which the old rename replaced) is never
 * replaced, whether named directly or through a link. */
static void test_non_regular_files_are_not_replaced(void **state) {
    (void)state;
    tmpdir t;
    make_dir(&t);
    pc_canvas *c = small_canvas();
    assert_int_equal(mkfifo(in_dir(&t, "pipe.png"), 0644), 0);
    expect_error(c, in_dir(&t, "pipe.png"), NOT_REGULAR);
    assert_int_equal(symlink(in_dir(&t, "pipe.png"), in_dir(&t, "link.png")), 0);
    expect_error(c, in_dir(&t, "link.png"), NOT_REGULAR);
    struct stat st;
    assert_int_equal(lstat(in_dir(&t, "pipe.png"), &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
    assert_int_equal(lstat(in_dir(&t, "link.png"), &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    /* a folder: refused before anything is written */
    assert_int_equal(mkdir(in_dir(&t, "d.svg"), 0755), 0);
    expect_error(c, in_dir(&t, "d.svg"), "Is a directory");
    assert_int_equal(temporaries(t.dir), 0);
    pc_canvas_free(c);
    remove_tree(t.dir);
}

/* Through a link to an existing regular file: that file is replaced where it is, keeping its
 * mode; the link stays a link.  A dangling link is refused and creates nothing. */
static void test_links(void **state) {
    (void)state;
    tmpdir t;
    make_dir(&t);
    pc_canvas *c = small_canvas();
    assert_int_equal(mkdir(in_dir(&t, "real"), 0755), 0);
    write_text(in_dir(&t, "real/pic.ppm"), "old");
    assert_int_equal(chmod(in_dir(&t, "real/pic.ppm"), 0640), 0);
    assert_int_equal(symlink("real/pic.ppm", in_dir(&t, "pic.ppm")), 0);
    char err[512];
    assert_int_equal(pc_write_file(c, in_dir(&t, "pic.ppm"), PC_THEME_SCREEN, err, sizeof err),
                     PC_OK);
    struct stat st;
    assert_int_equal(lstat(in_dir(&t, "pic.ppm"), &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_int_equal(stat(in_dir(&t, "real/pic.ppm"), &st), 0);
    assert_int_equal(st.st_mode & 0777, 0640);
    assert_int_equal(st.st_size, 11 + 18);   /* "P6\n3 2\n255\n" and 3x2 pixels */
    assert_int_equal(temporaries(t.dir) + temporaries(in_dir(&t, "real")), 0);

    assert_int_equal(symlink("real/elsewhere.png", in_dir(&t, "dangling.png")), 0);
    expect_error(c, in_dir(&t, "dangling.png"),
                 "it is a symbolic link to a missing file "
                 "(pointcalc writes through a link only to an existing file)");
    assert_int_equal(access(in_dir(&t, "real/elsewhere.png"), F_OK), -1);
    pc_canvas_free(c);
    remove_tree(t.dir);
}

/* A read-only file stays as it is, also for root (who could otherwise rename over it). */
static void test_read_only_file_is_kept(void **state) {
    (void)state;
    tmpdir t;
    make_dir(&t);
    pc_canvas *c = small_canvas();
    write_text(in_dir(&t, "ro.png"), "keep me");
    assert_int_equal(chmod(in_dir(&t, "ro.png"), 0444), 0);
    expect_error(c, in_dir(&t, "ro.png"), "Permission denied (the file is read-only)");
    assert_text(in_dir(&t, "ro.png"), "keep me");
    assert_int_equal(temporaries(t.dir), 0);
    pc_canvas_free(c);
    remove_tree(t.dir);
}

/* A file-size limit (ulimit -f): the save fails with a message instead of the process being
 * killed by SIGXFSZ with the temporary file left behind.  In a child, to keep the limit there. */
static void test_file_size_limit(void **state) {
    (void)state;
    tmpdir t;
    make_dir(&t);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        pc_canvas *c = pc_canvas_new(400, 300, 16);
        for (int i = 0; i < 300; i++) pc_line(c, 0, i, 399, 299 - i, i % 16);
        struct rlimit rl = {4096, 4096};
        setrlimit(RLIMIT_FSIZE, &rl);
        char err[512], want[512];
        int rc = pc_write_file(c, in_dir(&t, "big.ppm"), PC_THEME_SCREEN, err, sizeof err);
        snprintf(want, sizeof want, "cannot write '%s': File too large", in_dir(&t, "big.ppm"));
        _exit(rc == PC_EIO && !strcmp(err, want) ? 0 : 3);
    }
    int status;
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 0);
    assert_int_equal(temporaries(t.dir), 0);
    assert_int_equal(access(in_dir(&t, "big.ppm"), F_OK), -1);
    remove_tree(t.dir);
}

/* A child saving over and over is killed by sig while a temporary file exists: the process
 * dies of that signal, and no temporary file is left. */
static void kill_while_saving(int sig) {
    tmpdir t;
    make_dir(&t);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        pc_canvas *c = pc_canvas_new(1200, 900, 16);
        for (int i = 0; i < 900; i += 2) pc_line(c, 0, i, 1199, 899 - i, i % 16);
        char err[512];
        for (;;) pc_write_file(c, in_dir(&t, "x.png"), PC_THEME_SCREEN, err, sizeof err);
    }
    /* wait for a temporary file to appear (at most 20 s) */
    struct timespec pause = {0, 1000000};
    int waited = 0;
    while (temporaries(t.dir) == 0 && waited < 20000) {
        nanosleep(&pause, NULL);
        waited++;
    }
    assert_true(waited < 20000);
    kill(pid, sig);
    int status;
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(WIFSIGNALED(status));
    assert_int_equal(WTERMSIG(status), sig);
    assert_int_equal(temporaries(t.dir), 0);
    remove_tree(t.dir);
}

static void test_signals_remove_the_temporary_file(void **state) {
    (void)state;
    for (int round = 0; round < 3; round++) {
        kill_while_saving(SIGTERM);
        kill_while_saving(SIGINT);
    }
    kill_while_saving(SIGHUP);
    /* outside a save the dispositions are the program's own again */
    struct sigaction sa;
    assert_int_equal(sigaction(SIGTERM, NULL, &sa), 0);
    assert_true(sa.sa_handler == SIG_DFL);
    assert_int_equal(sigaction(SIGXFSZ, NULL, &sa), 0);
    assert_true(sa.sa_handler == SIG_DFL);
}

int main(void) {
    /* the tests are about the default dispositions, whatever the caller left ignored */
    signal(SIGXFSZ, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGINT, SIG_DFL);
    signal(SIGHUP, SIG_DFL);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_non_regular_files_are_not_replaced),
        cmocka_unit_test(test_links),
        cmocka_unit_test(test_read_only_file_is_kept),
        cmocka_unit_test(test_file_size_limit),
        cmocka_unit_test(test_signals_remove_the_temporary_file),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
