/* Animation: pointcalc script.lua --frames N -o out.svg|out.png (docs/live.md).
 *
 * The script declares its time parameter as a slider with {animate = true}; frame k runs the
 * script afresh with that slider at min + (max - min) k / (N - 1), exactly as --set would, so
 * frame k is pixel for pixel the headless render at that value.  A .png or .ppm output
 * becomes numbered frames (out-000.png, out-001.png, ...); an .svg output becomes one
 * animated SVG whose frames take turns (SMIL, looping; the first frame shows where SMIL does
 * not run), written at the end through pc_write_file like every picture (atomic, no device or
 * link replaced, the mode kept). */
#include "frames.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <lauxlib.h>
#include "host.h"
#include "pcl.h"

/* The animated slider of a run with the given settings: 1 with its name and range. */
static int find_animated(const char *script, const render_param *sets, int nsets,
                         const sandbox_config *cfg, render_param *t, double *lo, double *hi) {
    render_run r;
    int ok = render_script(script, sets, nsets, cfg, &r);
    if (!ok) {
        fprintf(stderr, "%s\n", r.error);
        render_close(&r);
        return 0;
    }
    pcl_push_params(r.L);
    lua_Integer n = luaL_len(r.L, -1);
    int found = 0;
    for (lua_Integer i = 1; i <= n && !found; i++) {
        lua_geti(r.L, -1, i);
        lua_getfield(r.L, -1, "animate");
        if (lua_toboolean(r.L, -1)) {
            lua_getfield(r.L, -2, "name");
            snprintf(t->name, sizeof t->name, "%s", lua_tostring(r.L, -1));
            lua_getfield(r.L, -3, "min");
            lua_getfield(r.L, -4, "max");
            *lo = lua_tonumber(r.L, -2);
            *hi = lua_tonumber(r.L, -1);
            lua_pop(r.L, 3);
            found = 1;
        }
        lua_pop(r.L, 2);
    }
    render_close(&r);
    if (!found)
        fprintf(stderr, "%s: %s declares no animated parameter: give one slider {animate = true}, "
                "e.g. slider(\"t\", 0, 1, 0, {animate = true})\n", host_progname, script);
    return found;
}

typedef struct { char *data; size_t size; } memory_file;

static int emit_memory(void *ud, FILE *f, char *why, size_t whylen) {
    (void)why, (void)whylen;
    const memory_file *m = ud;
    return fwrite(m->data, 1, m->size, f) == m->size ? PC_OK : PC_EIO;
}

/* out.png -> out-007.png */
static void numbered(const char *path, int k, char *buf, size_t len) {
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash)) dot = path + strlen(path);
    snprintf(buf, len, "%.*s-%03d%s", (int)(dot - path), path, k, dot);
}

/* Append one frame's SVG (the document as the writer makes it) to the animation: its body in
 * a group shown during its turn, its clip ids made unique. */
static void add_svg_frame(FILE *out, const char *svg, int k, int n, double seconds) {
    const char *body = strstr(svg, "<svg");
    body = body ? strchr(body, '>') : NULL;
    if (!body) return;
    body++;
    const char *end = strstr(body, "</svg>");
    if (!end) end = body + strlen(body);
    fprintf(out, "<g visibility=\"%s\">\n", k == 0 ? "visible" : "hidden");
    if (n > 1) {
        double a = (double)k / n, b = (double)(k + 1) / n;
        if (k == 0)
            fprintf(out, "<animate attributeName=\"visibility\" values=\"visible;hidden\" "
                    "keyTimes=\"0;%.6f\" dur=\"%.3fs\" calcMode=\"discrete\" repeatCount=\"indefinite\"/>\n",
                    b, seconds);
        else if (k == n - 1)
            fprintf(out, "<animate attributeName=\"visibility\" values=\"hidden;visible\" "
                    "keyTimes=\"0;%.6f\" dur=\"%.3fs\" calcMode=\"discrete\" repeatCount=\"indefinite\"/>\n",
                    a, seconds);
        else
            fprintf(out, "<animate attributeName=\"visibility\" values=\"hidden;visible;hidden\" "
                    "keyTimes=\"0;%.6f;%.6f\" dur=\"%.3fs\" calcMode=\"discrete\" repeatCount=\"indefinite\"/>\n",
                    a, b, seconds);
    }
    /* clip ids: id="cN" and url(#cN) inside tags become fK-cN; text between tags (a label's
     * own words, where the writer escapes '<') is never rewritten */
    int in_tag = 0;
    const char *run = body;
    for (const char *p = body; p < end; p++) {
        if (*p == '<') in_tag = 1;
        else if (*p == '>') in_tag = 0;
        else if (in_tag && (!strncmp(p, "id=\"c", 5) || !strncmp(p, "url(#c", 6))) {
            size_t head = *p == 'i' ? 4 : 5;   /* up to the quote or the # */
            fwrite(run, 1, (size_t)(p - run) + head, out);
            fprintf(out, "f%d-", k);
            run = p + head;
            p += head - 1;
        }
    }
    fwrite(run, 1, (size_t)(end - run), out);
    fputs("</g>\n", out);
}

int frames_main(const char *script, int nframes, double fps, const render_param *sets, int nsets,
                const char *const *outputs, int noutputs, int paper, const sandbox_config *cfg) {
    render_param params[66];
    if (nsets > 64) nsets = 64;
    memcpy(params, sets, sizeof(render_param) * (size_t)nsets);
    double lo, hi;
    if (!find_animated(script, sets, nsets, cfg, &params[nsets], &lo, &hi)) return 1;
    int np = nsets + 1;
    for (int i = 0; i < nsets; i++)      /* --set of the animated parameter itself: ignored */
        if (!strcmp(params[i].name, params[nsets].name)) params[i].name[0] = 0;

    /* an animated SVG is made in memory, then written as one file */
    FILE **svgs = calloc((size_t)noutputs, sizeof(FILE *));
    memory_file *mem = calloc((size_t)noutputs, sizeof(memory_file));
    int status = !svgs || !mem;
    for (int j = 0; j < noutputs && !status; j++) {
        if (pc_format_from_path(outputs[j]) != PC_FMT_SVG) continue;
        svgs[j] = open_memstream(&mem[j].data, &mem[j].size);
        if (!svgs[j]) {
            fprintf(stderr, "%s: cannot write '%s': out of memory\n", host_progname, outputs[j]);
            status = 1;
        }
    }
    double seconds = nframes / (fps > 0 ? fps : 10);
    for (int k = 0; k < nframes && !status; k++) {
        params[nsets].value = nframes > 1 ? lo + (hi - lo) * k / (nframes - 1) : lo;
        render_run r;
        if (!render_script(script, params, np, cfg, &r)) {
            fprintf(stderr, "frame %d (%s = %.17g): %s\n", k, params[nsets].name,
                    params[nsets].value, r.error);
            render_close(&r);
            status = 1;
            break;
        }
        if (paper) pcl_set_theme(r.L, PC_THEME_PAPER);
        for (int j = 0; j < noutputs && !status; j++) {
            if (svgs[j]) {
                size_t len;
                char *svg = render_encode(&r, PC_FMT_SVG, &len);
                if (!svg) { status = 1; break; }
                if (k == 0) {   /* the first frame's header opens the document */
                    const char *body = strstr(svg, "<svg");
                    const char *gt = body ? strchr(body, '>') : NULL;
                    if (gt) fwrite(svg, 1, (size_t)(gt + 1 - svg), svgs[j]);
                    fputs("\n", svgs[j]);
                }
                add_svg_frame(svgs[j], svg, k, nframes, seconds);
                free(svg);
            } else {
                char path[4096], err[512];
                numbered(outputs[j], k, path, sizeof path);
                if (pc_write_file(pcl_canvas(r.L), path, pcl_theme(r.L), err, sizeof err) != PC_OK) {
                    fprintf(stderr, "%s: %s\n", host_progname, err);
                    status = 1;
                }
            }
        }
        render_close(&r);
    }
    for (int j = 0; svgs && j < noutputs; j++) {
        if (!svgs[j]) continue;
        fputs("</svg>\n", svgs[j]);
        if (fclose(svgs[j]) != 0) status = 1;
        char err[600];
        if (!status && pc_write_file_emit(outputs[j], emit_memory, &mem[j], err, sizeof err) != PC_OK) {
            fprintf(stderr, "%s: %s\n", host_progname, err);
            status = 1;
        }
        free(mem[j].data);
    }
    free(svgs);
    free(mem);
    if (!status)
        fprintf(stderr, "%s: %d frames of %s from %.17g to %.17g\n", host_progname, nframes,
                params[nsets].name, lo, hi);
    return status;
}

/* ---- a QBasic program's own animation: pointcalc prog.bas --frames N [--fps F] -o out ------
 * The program runs once; frame k is the screen shown when its virtual clock (TIMER, SLEEP,
 * WAIT &H3DA: docs/qbasic.md) reaches (k + 1) / F seconds.  After N frames the program is
 * ended there; one that ends sooner repeats its last screen, so there are always N frames. */
static struct {
    int nframes, taken, status;
    double fps;
    const char *const *outputs;
    int noutputs;
    FILE **svgs;
    memory_file *mem;
} Q;

static void capture(lua_State *L) {
    int k = Q.taken++;
    render_run r = {.L = L};
    for (int j = 0; j < Q.noutputs && !Q.status; j++) {
        if (Q.svgs[j]) {
            size_t len;
            char *svg = render_encode(&r, PC_FMT_SVG, &len);
            if (!svg) { Q.status = 1; break; }
            if (k == 0) {
                const char *body = strstr(svg, "<svg");
                const char *gt = body ? strchr(body, '>') : NULL;
                if (gt) fwrite(svg, 1, (size_t)(gt + 1 - svg), Q.svgs[j]);
                fputs("\n", Q.svgs[j]);
            }
            add_svg_frame(Q.svgs[j], svg, k, Q.nframes, Q.nframes / Q.fps);
            free(svg);
        } else {
            char path[4096], err[512];
            numbered(Q.outputs[j], k, path, sizeof path);
            if (pc_write_file(pcl_canvas(L), path, pcl_theme(L), err, sizeof err) != PC_OK) {
                fprintf(stderr, "%s: %s\n", host_progname, err);
                Q.status = 1;
            }
        }
    }
}

/* qbasic_screen.FRAME(): take the next frame; true when it was the last one */
static int l_frame(lua_State *L) {
    if (Q.taken < Q.nframes) capture(L);
    lua_pushboolean(L, Q.taken >= Q.nframes || Q.status);
    return 1;
}

int frames_qbasic_begin(lua_State *L, int nframes, double fps, const char *const *outputs,
                        int noutputs) {
    memset(&Q, 0, sizeof Q);
    Q.nframes = nframes;
    Q.fps = fps > 0 ? fps : 10;
    Q.outputs = outputs;
    Q.noutputs = noutputs;
    Q.svgs = calloc((size_t)noutputs, sizeof(FILE *));
    Q.mem = calloc((size_t)noutputs, sizeof(memory_file));
    if (!Q.svgs || !Q.mem) return 0;
    for (int j = 0; j < noutputs; j++) {
        if (pc_format_from_path(outputs[j]) != PC_FMT_SVG) continue;
        Q.svgs[j] = open_memstream(&Q.mem[j].data, &Q.mem[j].size);
        if (!Q.svgs[j]) {
            fprintf(stderr, "%s: cannot write '%s': out of memory\n", host_progname, outputs[j]);
            return 0;
        }
    }
    lua_getglobal(L, "require");
    lua_pushliteral(L, "qbasic_screen");
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
        fprintf(stderr, "%s: %s\n", host_progname, lua_tostring(L, -1));
        lua_pop(L, 1);
        return 0;
    }
    lua_pushcfunction(L, l_frame);
    lua_setfield(L, -2, "FRAME");
    lua_pushnumber(L, 1.0 / Q.fps);
    lua_setfield(L, -2, "FRAME_DT");
    lua_pop(L, 1);
    return 1;
}

int frames_qbasic_end(lua_State *L, int ran) {
    if (ran)
        while (Q.taken < Q.nframes && !Q.status) capture(L);   /* the last screen, held */
    int status = Q.status || !ran;
    for (int j = 0; Q.svgs && j < Q.noutputs; j++) {
        if (!Q.svgs[j]) continue;
        fputs("</svg>\n", Q.svgs[j]);
        if (fclose(Q.svgs[j]) != 0) status = 1;
        char err[600];
        if (!status && pc_write_file_emit(Q.outputs[j], emit_memory, &Q.mem[j], err, sizeof err) != PC_OK) {
            fprintf(stderr, "%s: %s\n", host_progname, err);
            status = 1;
        }
        free(Q.mem[j].data);
    }
    free(Q.svgs);
    free(Q.mem);
    Q.svgs = NULL;
    Q.mem = NULL;
    if (!status)
        fprintf(stderr, "%s: %d frames, one every %g virtual seconds\n", host_progname, Q.nframes,
                1.0 / Q.fps);
    return status;
}
