/* pointcalc serve SCRIPT [--port N]: the live page (docs/live.md).
 *
 * libmicrohttpd serves, on 127.0.0.1 only, one thread handling the requests in turn:
 *   /            the page (interp/live_page.lua: static HTML and a small script)
 *   /params      JSON: the script's name, its sliders ({name, min, max, default, step,
 *                animate}, from a run with the defaults) and that run's error, if any
 *   /render?k=v  the figure as SVG with those slider values (422 and the message on an error);
 *                &format=png for PNG (the page's downloads)
 *   /script      the script's text (shown beside the figure)
 *   /version     the script file's modification time: the page polls it to reload on save
 * Every render is a fresh Lua state with a time limit (render.c). */
#include "serve.h"
#include <arpa/inet.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <lauxlib.h>
#include <microhttpd.h>
#include "host.h"
#include "pcl.h"
#include "render.h"

#define RENDER_SECONDS 2    /* a run longer than this is stopped: an edit cannot hang the page */
#define MAX_PARAMS 64

static const char *script;
static sandbox_config cfg;   /* the safe mode: the page runs the script on the browser's behalf */

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
    return html;
}

/* The slider values of the query string (only names the script could declare). */
typedef struct { render_param p[MAX_PARAMS]; int n; int bad, png; } query;

static enum MHD_Result each_arg(void *cls, enum MHD_ValueKind kind, const char *key,
                                const char *value) {
    (void)kind;
    query *q = cls;
    char text[128];
    if (!strcmp(key, "format")) {   /* not a slider: the download's format */
        q->png = value && !strcmp(value, "png");
        q->bad |= !value || (strcmp(value, "png") && strcmp(value, "svg"));
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

static enum MHD_Result do_render(struct MHD_Connection *con) {
    query q = {.n = 0};
    MHD_get_connection_values(con, MHD_GET_ARGUMENT_KIND, each_arg, &q);
    if (q.bad) return reply_text(con, 400, "bad query: use name=number for sliders, format=svg|png");
    render_run r;
    if (!render_script(script, q.p, q.n, &cfg, &r)) {
        render_close(&r);
        return reply_text(con, 422, r.error);
    }
    size_t len;
    char *svg = render_encode(&r, !q.png, &len);
    render_close(&r);
    if (!svg) return reply_text(con, 500, r.error);
    return reply(con, 200, q.png ? "image/png" : "image/svg+xml", svg, len);
}

static enum MHD_Result do_params(struct MHD_Connection *con) {
    render_run r;
    int ok = render_script(script, NULL, 0, &cfg, &r);
    buf b = {0};
    const char *name = strrchr(script, '/');
    puts_(&b, "{\"script\": ");
    put_json_string(&b, name ? name + 1 : script);
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
    if (!b.s) return MHD_NO;
    return reply(con, 200, "application/json", b.s, b.n);
}

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
        size_t len;
        char *html = page_html(&len);
        return html ? reply(con, 200, "text/html; charset=utf-8", html, len)
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
    /* the script may read files beside it (data, images), nothing else */
    static char folder[4096];
    snprintf(folder, sizeof folder, "%s", path);
    char *slash = strrchr(folder, '/');
    if (!slash) snprintf(folder, sizeof folder, ".");
    else if (slash == folder) folder[1] = 0;    /* a script in / */
    else *slash = 0;
    cfg = sandbox_untrusted;
    cfg.nallow = 1;
    cfg.allow[0] = folder;
    cfg.timeout = RENDER_SECONDS;
    struct sockaddr_in addr;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_port = htons((uint16_t)port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);     /* this machine only */
    struct MHD_Daemon *d = MHD_start_daemon(MHD_USE_INTERNAL_POLLING_THREAD, (uint16_t)port, NULL,
                                            NULL, handle, NULL, MHD_OPTION_SOCK_ADDR, &addr,
                                            MHD_OPTION_END);
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
