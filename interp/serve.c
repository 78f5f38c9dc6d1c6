/* pointcalc serve SCRIPT [--port N]: the live page (docs/live.md).
 *
 * libmicrohttpd serves, on 127.0.0.1 only, one thread handling the requests in turn:
 *   /            the page (interp/live_page.lua: static HTML and a small script)
 *   /params      JSON: the script's name, its sliders ({name, min, max, default, step,
 *                animate}, from a run with the defaults) and that run's error, if any
 *   /render?k=v  the figure as SVG with those slider values (422 and the message on an error);
 *                &format=png or &format=pdf for PNG or PDF (the page's downloads; PDF is
 *                the print look, and a script's figure{} gives it to SVG and PNG as well)
 *   /script      the script's text (shown beside the figure)
 *   /version     the script file's modification time: the page polls it to reload on save
 * Every render (and /params, which runs the script too) happens in a child process forked for
 * it: in the script's folder (relative names resolve there, messages name the script by its
 * own name), with the safe mode and the time and memory limits inside it (and a CPU limit and
 * a wall-clock kill around it), the answer piped back.  A render that runs away, loops in a
 * native call or crashes ends its child; the server answers 422 and goes on.  The server's
 * own process never runs script code. */
#define _GNU_SOURCE   /* pipe2, strsignal */
#include "serve.h"
#include <arpa/inet.h>
#include <math.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <lauxlib.h>
#include <microhttpd.h>
#include "host.h"
#include "memlimit.h"
#include "pcl.h"
#include "render.h"

#define RENDER_SECONDS 2    /* a run longer than this is stopped: an edit cannot hang the page */
#define KILL_SECONDS 6      /* a child still running this long after its start is killed */
#define MAX_PARAMS 64
#define THREADS 4           /* requests served at once (each render in its own child) */
#define IDLE_SECONDS 15     /* an idle connection is closed after this */
#define MAX_CONNECTIONS 4096
#define MAX_PER_ADDRESS 2048   /* the page's clients are all 127.0.0.1: generous, yet a bound */
#define MAX_ANSWER (64u << 20) /* a child's answer larger than this is refused */

static const char *script;      /* as given */
static char folder[4096];       /* its folder: the child's working folder */
static const char *script_name; /* its name in that folder */
static sandbox_config cfg;   /* the safe mode: the page runs the script on the browser's behalf */
static char *page;              /* the page, made once */
static size_t page_len;

/* ---- small JSON and text helpers ------------------------------------------------------------ */

typedef struct { char *s; size_t n, cap; } buf;

static void put(buf *b, const char *s, size_t n) {
    if (b->n + n + 1 > b->cap) {
        size_t cap = (b->cap + n + 1) * 2;
        char *p = realloc(b->s, cap);
        if (!p) return;
        b->s = p;
        b->cap = cap;
    }
    memcpy(b->s + b->n, s, n);
    b->n += n;
    b->s[b->n] = 0;
}

static void puts_(buf *b, const char *s) { put(b, s, strlen(s)); }

static void put_json_string(buf *b, const char *s) {
    put(b, "\"", 1);
    for (; *s; s++) {
        char esc[8];
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') { esc[0] = '\\'; esc[1] = (char)c; put(b, esc, 2); }
        else if (c < 0x20) { snprintf(esc, sizeof esc, "\\u%04x", c); puts_(b, esc); }
        else put(b, (const char *)s, 1);
    }
    put(b, "\"", 1);
}

static void put_number(buf *b, double v) {   /* the shortest text that reads back as v */
    char t[32];
    snprintf(t, sizeof t, "%.15g", v);
    if (strtod(t, NULL) != v) snprintf(t, sizeof t, "%.17g", v);
    puts_(b, t);
}

/* ---- responses -------------------------------------------------------------------------------- */

static enum MHD_Result reply(struct MHD_Connection *con, unsigned code, const char *type,
                             char *body, size_t len) {
    struct MHD_Response *r = MHD_create_response_from_buffer(len, body, MHD_RESPMEM_MUST_FREE);
    if (!r) {
        free(body);
        return MHD_NO;
    }
    MHD_add_response_header(r, "Content-Type", type);
    MHD_add_response_header(r, "Cache-Control", "no-store");
    enum MHD_Result ok = MHD_queue_response(con, code, r);
    MHD_destroy_response(r);
    return ok;
}

static enum MHD_Result reply_text(struct MHD_Connection *con, unsigned code, const char *text) {
    char *body = strdup(text);
    return body ? reply(con, code, "text/plain; charset=utf-8", body, strlen(body)) : MHD_NO;
}

/* The page (the server's own chunk, no script code), made once before serving. */
static char *page_html(size_t *len) {
    lua_State *L = host_new_state(&sandbox_untrusted);
    if (!L) return NULL;
    char *html = NULL;
    lua_getglobal(L, "require");
    lua_pushliteral(L, "live_page");
    if (lua_pcall(L, 1, 1, 0) == LUA_OK && lua_isstring(L, -1)) {
        const char *s = lua_tolstring(L, -1, len);
        html = malloc(*len);
        if (html) memcpy(html, s, *len);
    }
    lua_close(L);
    pc_mem_set_limit(0, NULL);   /* the limits are the children's, not the server's */
    return html;
}

/* The slider values of the query string (only names the script could declare). */
typedef struct { render_param p[MAX_PARAMS]; int n; int bad; pc_format fmt; } query;

static enum MHD_Result each_arg(void *cls, enum MHD_ValueKind kind, const char *key,
                                const char *value) {
    (void)kind;
    query *q = cls;
    char text[128];
    if (!strcmp(key, "format")) {   /* not a slider: the download's format */
        q->fmt = !value ? PC_FMT_UNKNOWN : !strcmp(value, "svg") ? PC_FMT_SVG
                 : !strcmp(value, "png") ? PC_FMT_PNG : !strcmp(value, "pdf") ? PC_FMT_PDF
                                                                                : PC_FMT_UNKNOWN;
        q->bad |= q->fmt == PC_FMT_UNKNOWN;
        return MHD_YES;
    }
    if (!value || q->n == MAX_PARAMS || snprintf(text, sizeof text, "%s=%s", key, value) >= (int)sizeof text ||
        !render_parse_param(text, &q->p[q->n])) {
        q->bad = 1;
        return MHD_NO;
    }
    q->n++;
    return MHD_YES;
}

/* ---- in the child: one run, its answer as "CODE TYPE\n" and the body ---------------------- */

static void answer(buf *out, unsigned code, const char *type, const char *body, size_t len) {
    char head[128];
    snprintf(head, sizeof head, "%u %s\n", code, type);
    puts_(out, head);
    put(out, body, len);
}

static void child_render(const query *q, buf *out) {
    render_run r;
    if (!render_script(script_name, q->p, q->n, &cfg, &r)) {
        render_close(&r);
        answer(out, 422, "text/plain; charset=utf-8", r.error, strlen(r.error));
        return;
    }
    size_t len;
    char *body = render_encode(&r, q->fmt, &len);
    render_close(&r);
    const char *type = q->fmt == PC_FMT_PNG ? "image/png"
                       : q->fmt == PC_FMT_PDF ? "application/pdf" : "image/svg+xml";
    if (!body) answer(out, 500, "text/plain; charset=utf-8", r.error, strlen(r.error));
    else answer(out, 200, type, body, len);
    free(body);
}

static void child_params(buf *out) {
    render_run r;
    int ok = render_script(script_name, NULL, 0, &cfg, &r);
    buf b = {0};
    puts_(&b, "{\"script\": ");
    put_json_string(&b, script_name);
    puts_(&b, ", \"params\": [");
    pcl_push_params(r.L);
    lua_Integer n = luaL_len(r.L, -1);
    for (lua_Integer i = 1; i <= n; i++) {
        lua_geti(r.L, -1, i);
        puts_(&b, i > 1 ? ", {" : "{");
        static const char *const nums[] = {"min", "max", "default", "step"};
        lua_getfield(r.L, -1, "name");
        puts_(&b, "\"name\": ");
        put_json_string(&b, lua_tostring(r.L, -1));
        lua_pop(r.L, 1);
        for (int k = 0; k < 4; k++) {
            lua_getfield(r.L, -1, nums[k]);
            puts_(&b, ", \"");
            puts_(&b, nums[k]);
            puts_(&b, "\": ");
            put_number(&b, lua_tonumber(r.L, -1));
            lua_pop(r.L, 1);
        }
        lua_getfield(r.L, -1, "animate");
        puts_(&b, lua_toboolean(r.L, -1) ? ", \"animate\": true}" : ", \"animate\": false}");
        lua_pop(r.L, 2);
    }
    puts_(&b, "], \"error\": ");
    if (ok) puts_(&b, "null");
    else put_json_string(&b, r.error);
    puts_(&b, "}\n");
    render_close(&r);
    if (b.s) answer(out, 200, "application/json", b.s, b.n);
    free(b.s);
}

static int write_all(int fd, const char *p, size_t n) {
    while (n) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return 0;
        p += w;
        n -= (size_t)w;
    }
    return 1;
}

/* The child: limits, the script's folder, standard error to the server, one run. */
static void child_main(int out_fd, int err_fd, const query *q) {
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGPIPE, SIG_DFL);
    dup2(err_fd, STDERR_FILENO);
    close(err_fd);
    int nul = open("/dev/null", O_RDONLY);   /* a render that reads input reads nothing */
    if (nul >= 0 && nul != STDIN_FILENO) {
        dup2(nul, STDIN_FILENO);
        close(nul);
    }
    struct rlimit cpu = {RENDER_SECONDS + 3, RENDER_SECONDS + 4};   /* SIGXCPU, then SIGKILL */
    setrlimit(RLIMIT_CPU, &cpu);
    struct rlimit fsize = {256u << 20, 256u << 20};   /* save() in the folder: no disk filling */
    setrlimit(RLIMIT_FSIZE, &fsize);
    if (chdir(folder) != 0) {
        fprintf(stderr, "cannot enter the script's folder %s: %s\n", folder, strerror(errno));
        _exit(3);
    }
    buf out = {0};
    if (q) child_render(q, &out);
    else child_params(&out);
    int ok = out.s && write_all(out_fd, out.s, out.n);
    _exit(ok ? 0 : 3);
}

/* ---- in the server: a child per run --------------------------------------------------------- */

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

/* Read the child's answer and its standard error until both close or the kill time. */
static int collect(pid_t pid, int out_fd, int err_fd, buf *out, buf *err) {
    double end = now() + KILL_SECONDS;
    struct pollfd fds[2] = {{out_fd, POLLIN, 0}, {err_fd, POLLIN, 0}};
    int open_fds = 2, killed = 0;
    while (open_fds) {
        int ms = (int)((end - now()) * 1000);
        if (ms <= 0) {
            kill(pid, SIGKILL);
            killed = 1;
            break;
        }
        int n = poll(fds, 2, ms);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) break;
        for (int i = 0; i < 2; i++) {
            if (fds[i].fd < 0 || !fds[i].revents) continue;
            char chunk[65536];
            ssize_t r = read(fds[i].fd, chunk, sizeof chunk);
            if (r < 0 && errno == EINTR) continue;
            buf *b = i ? err : out;
            if (r > 0 && b->n + (size_t)r <= (i ? 8192u : MAX_ANSWER)) put(b, chunk, (size_t)r);
            if (r <= 0) {
                fds[i].fd = -1;
                open_fds--;
            }
        }
    }
    int status;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    return killed ? -1 : status;
}

/* Run one render (q) or the /params run (q NULL) in a child and answer with its result. */
static enum MHD_Result run_child(struct MHD_Connection *con, const query *q) {
    int outp[2], errp[2];
    if (pipe2(outp, O_CLOEXEC) != 0) return reply_text(con, 503, "cannot start a render: no pipe");
    if (pipe2(errp, O_CLOEXEC) != 0) {
        close(outp[0]);
        close(outp[1]);
        return reply_text(con, 503, "cannot start a render: no pipe");
    }
    pid_t pid = fork();
    if (pid == 0) {
        close(outp[0]);
        close(errp[0]);
        child_main(outp[1], errp[1], q);
    }
    close(outp[1]);
    close(errp[1]);
    if (pid < 0) {
        close(outp[0]);
        close(errp[0]);
        return reply_text(con, 503, "cannot start a render: no process");
    }
    buf out = {0}, err = {0};
    int status = collect(pid, outp[0], errp[0], &out, &err);
    close(outp[0]);
    close(errp[0]);
    char *nl = out.s ? memchr(out.s, '\n', out.n) : NULL;
    unsigned code;
    char type[64];
    if (status == 0 && nl && sscanf(out.s, "%u %63[^\n]", &code, type) == 2) {
        size_t head = (size_t)(nl + 1 - out.s), len = out.n - head;
        char *body = malloc(len + 1);
        if (body) memcpy(body, out.s + head, len);
        free(out.s);
        free(err.s);
        return body ? reply(con, code, type, body, len) : MHD_NO;
    }
    /* the child did not answer: stopped by a limit, killed, crashed */
    char msg[9000];
    const char *said = err.s ? err.s : "";
    size_t said_len = strcspn(said, "\n");   /* its first line ("fig.lua:3: time limit ...") */
    if (said_len) snprintf(msg, sizeof msg, "%.*s", (int)said_len, said);
    else if (status == -1 || (WIFSIGNALED(status) && (WTERMSIG(status) == SIGKILL ||
                                                      WTERMSIG(status) == SIGXCPU)))
        snprintf(msg, sizeof msg, "%s: the render was stopped: time limit of %d s exceeded",
                 script_name, RENDER_SECONDS);
    else if (WIFSIGNALED(status))
        snprintf(msg, sizeof msg, "%s: the render ended of signal %d (%s)", script_name,
                 WTERMSIG(status), strsignal(WTERMSIG(status)));
    else
        snprintf(msg, sizeof msg, "%s: the render ended without an answer (status %d)",
                 script_name, WEXITSTATUS(status));
    if (err.s && err.n) fprintf(stderr, "%s", err.s);   /* the whole story on the terminal */
    free(out.s);
    free(err.s);
    return reply_text(con, 422, msg);
}

static enum MHD_Result do_render(struct MHD_Connection *con) {
    query q = {.n = 0, .fmt = PC_FMT_SVG};
    MHD_get_connection_values(con, MHD_GET_ARGUMENT_KIND, each_arg, &q);
    if (q.bad) return reply_text(con, 400, "bad query: use name=number for sliders, format=svg|png|pdf");
    return run_child(con, &q);
}

static enum MHD_Result do_params(struct MHD_Connection *con) { return run_child(con, NULL); }

static enum MHD_Result do_version(struct MHD_Connection *con) {
    struct stat st;
    char t[64];
    if (stat(script, &st) != 0) snprintf(t, sizeof t, "missing");
    else snprintf(t, sizeof t, "%lld.%09ld %lld", (long long)st.st_mtim.tv_sec,
                  st.st_mtim.tv_nsec, (long long)st.st_size);
    return reply_text(con, 200, t);
}

static enum MHD_Result do_script(struct MHD_Connection *con) {
    FILE *f = fopen(script, "rb");
    buf b = {0};
    char chunk[4096];
    size_t n;
    if (!f) return reply_text(con, 404, "the script is missing");
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) put(&b, chunk, n);
    fclose(f);
    if (!b.s) put(&b, "", 0);
    if (!b.s) return MHD_NO;
    return reply(con, 200, "text/plain; charset=utf-8", b.s, b.n);
}

static enum MHD_Result handle(void *cls, struct MHD_Connection *con, const char *url,
                              const char *method, const char *version, const char *upload,
                              size_t *upload_size, void **state) {
    (void)cls; (void)version; (void)upload; (void)upload_size; (void)state;
    if (strcmp(method, "GET") != 0) return reply_text(con, 405, "only GET");
    if (!strcmp(url, "/")) {
        char *html = page ? malloc(page_len) : NULL;
        if (html) memcpy(html, page, page_len);
        return html ? reply(con, 200, "text/html; charset=utf-8", html, page_len)
                    : reply_text(con, 500, "the page is missing");
    }
    if (!strcmp(url, "/render")) return do_render(con);
    if (!strcmp(url, "/params")) return do_params(con);
    if (!strcmp(url, "/version")) return do_version(con);
    if (!strcmp(url, "/script")) return do_script(con);
    return reply_text(con, 404, "not found");
}

static volatile sig_atomic_t stop;
static void on_signal(int sig) { (void)sig; stop = 1; }

int serve_main(const char *path, int port) {
    script = path;
    /* the script may read files beside it (data, images), nothing else; the child works in
     * that folder, so relative names resolve there (docs/live.md) */
    char *real = realpath(path, NULL);
    if (!real) {
        fprintf(stderr, "%s: cannot open '%s': %s\n", host_progname, path, strerror(errno));
        return 1;
    }
    snprintf(folder, sizeof folder, "%s", real);
    free(real);
    char *slash = strrchr(folder, '/');
    static char name[1024];
    snprintf(name, sizeof name, "%s", slash + 1);
    script_name = name;
    if (slash == folder) folder[1] = 0;    /* a script in / */
    else *slash = 0;
    cfg = sandbox_untrusted;
    cfg.nallow = 1;
    cfg.allow[0] = ".";
    cfg.timeout = RENDER_SECONDS;
    page = page_html(&page_len);
    /* idle connections are closed and bounded; enough descriptors for them */
    struct rlimit nofile;
    if (getrlimit(RLIMIT_NOFILE, &nofile) == 0 && nofile.rlim_cur < MAX_CONNECTIONS + 256) {
        nofile.rlim_cur = nofile.rlim_max < MAX_CONNECTIONS + 256 ? nofile.rlim_max
                                                                  : MAX_CONNECTIONS + 256;
        setrlimit(RLIMIT_NOFILE, &nofile);
    }
    signal(SIGPIPE, SIG_IGN);
    struct sockaddr_in addr;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_port = htons((uint16_t)port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);     /* this machine only */
    struct MHD_Daemon *d = MHD_start_daemon(
        MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_EPOLL, (uint16_t)port, NULL, NULL, handle, NULL,
        MHD_OPTION_SOCK_ADDR, &addr, MHD_OPTION_THREAD_POOL_SIZE, (unsigned)THREADS,
        MHD_OPTION_CONNECTION_TIMEOUT, (unsigned)IDLE_SECONDS,
        MHD_OPTION_CONNECTION_LIMIT, (unsigned)MAX_CONNECTIONS,
        MHD_OPTION_PER_IP_CONNECTION_LIMIT, (unsigned)MAX_PER_ADDRESS, MHD_OPTION_END);
    if (!d) {
        fprintf(stderr, "%s: cannot listen on 127.0.0.1:%d (in use?)\n", host_progname, port);
        return 1;
    }
    const union MHD_DaemonInfo *info = MHD_get_daemon_info(d, MHD_DAEMON_INFO_BIND_PORT);
    printf("pointcalc: serving %s at http://127.0.0.1:%u/ (Ctrl-C to stop)\n", path,
           info ? info->port : (unsigned)port);
    fflush(stdout);
    signal(SIGINT, on_signal);
    signal(SIGTERM, on_signal);
    while (!stop) usleep(100 * 1000);   /* the signal may go to the server's thread */
    MHD_stop_daemon(d);
    return 0;
}
