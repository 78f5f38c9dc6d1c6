/* pointcalc: run geometry scripts (Lua or QBasic), write the canvas, or explore in the REPL.
 *
 * Exit status: 0 success, 1 script error, 2 usage error. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <lauxlib.h>
#include "host.h"
#include "pcl.h"
#include "frames.h"
#include "serve.h"
#include "print.h"

#define MAX_OUTPUTS 32
#define MAX_CHUNKS 32
#define MAX_SETS 64

static const char usage_text[] =
    "usage: pointcalc [options] [script [args...]]\n"
    "       pointcalc serve script [--port N]   a live page with the script's sliders\n"
    "  script        a Lua script, or a QBasic program (.bas); '-' reads standard input\n"
    "  -e CODE       run CODE (repeatable, before the script)\n"
    "  -i            enter the interactive REPL after running the script\n"
    "  --watch FILE  REPL: rewrite FILE (.png, .svg or .ppm) whenever the canvas changes\n"
    "  -o FILE       write the canvas to FILE when done: .png, .svg, .ppm, .pdf, .eps or\n"
    "                .ps (repeatable)\n"
    "  --paper       print theme for written files: white paper, dark ink\n"
    "  --print       the print look for .png and .svg too (PDF, EPS and PS always have it)\n"
    "  --dpi N       the print look at N dots per inch (PNG)\n"
    "  --size W[xH]  the print look at a size: 12cm, 12cmx8cm (cm, mm, in, pt, px)\n"
    "  --set NAME=VALUE  the value of the script's slider NAME (repeatable)\n"
    "  --frames N    write N frames of the slider declared {animate = true}: numbered\n"
    "                PNG/PPM files, or one animated SVG (--fps F, default 10); of a QBasic\n"
    "                program: the screen at every 1/F s of its virtual clock\n"
    "  --qbasic      treat the script as QBasic whatever its extension\n"
    "  --emit-lua    print the Lua translation of a QBasic program and exit\n"
    "  --input FILE  standard input from FILE: what INPUT, INKEY$... of a QBasic program read\n"
    "  --for S       a QBasic program that never ends: stop it after S seconds of its virtual\n"
    "                clock (TIMER, SLEEP, INKEY$ polls) and write the screen as it stands\n"
    "  --safe        safe mode: no processes, C modules, binary chunks or debug library;\n"
    "                files only under the folders given with --allow\n"
    "  --allow DIR   safe mode: the script may read and write files under DIR (repeatable)\n"
    "  --allow-hardlinks  safe mode: also files with other hard links under those folders\n"
    "  --timeout S   stop the script after S seconds (each REPL statement: S seconds)\n"
    "  --max-memory MB  stop the script when it uses more than MB megabytes\n"
    "  -v            print the version and exit\n"
    "  -h, --help    print this help and exit\n"
    "  --            end of options: everything after the script goes to it in `arg`\n"
    "Options -o, --paper, --print, --dpi, --size, --watch, --set, --frames and --fps may\n"
    "also follow the script; other arguments there reach the script in `arg`. With no\n"
    "script and a terminal on standard input, or with -i or --watch, the REPL starts.\n"
    "A script that draws but saves nothing writes SCRIPT.png in the current directory.\n";

typedef struct {
    const char *chunks[MAX_CHUNKS];
    int nchunks;
    const char *outputs[MAX_OUTPUTS];
    int noutputs;
    const char *script;
    const char *watch;     /* --watch FILE: implies the REPL */
    int script_index;      /* argv index of the script */
    int interactive, paper, qbasic, emit_lua;
    const char *input;             /* --input FILE: standard input for INPUT/INKEY$ */
    double run_for;                /* --for S: a QBasic program's virtual seconds */
    sandbox_config sandbox;
    render_param sets[MAX_SETS];   /* --set NAME=VALUE */
    int nsets;
    int print;                     /* --print, --dpi, --size: the print look */
    pc_figure fig;
    int nframes;                   /* --frames N */
    double fps;                    /* --fps F */
} options;

static int usage_error(const char *fmt, const char *what) {
    fprintf(stderr, "%s: ", host_progname);
    fprintf(stderr, fmt, what);
    fprintf(stderr, "\ntry 'pointcalc -h' for help\n");
    return 2;
}

static int ends_with(const char *s, const char *suffix) {
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcasecmp(s + n - m, suffix) == 0;
}

static int set_watch(options *o, const char *path) {
    if (!path) return usage_error("%s", "option --watch needs a file name");
    if (pc_format_from_path(path) == PC_FMT_UNKNOWN)
        return usage_error("cannot watch '%s': the extension must be .png, .svg or .ppm", path);
    o->watch = path;
    o->interactive = 1;
    return 0;
}

/* --timeout S, --max-memory MB: a positive finite number */
static int set_limit(double *out, const char *opt, const char *value) {
    if (!value) return usage_error("option %s needs a number", opt);
    char *end;
    errno = 0;
    double v = strtod(value, &end);
    if (end == value || *end || errno || !(v > 0) || v > 1e9) {
        fprintf(stderr, "%s: option %s must be a positive number, got '%s'\n", host_progname, opt,
                value);
        fprintf(stderr, "try 'pointcalc -h' for help\n");
        return 2;
    }
    *out = v;
    return 0;
}

static int add_output(options *o, const char *path) {
    if (!path) return usage_error("%s", "option -o needs a file name");
    if (pc_format_from_path(path) == PC_FMT_UNKNOWN)
        return usage_error("cannot write '%s': the extension must be .png, .svg, .ppm, .pdf, "
                           ".eps or .ps", path);
    if (o->noutputs == MAX_OUTPUTS) return usage_error("%s", "too many -o options");
    o->outputs[o->noutputs++] = path;
    return 0;
}

/* --set NAME=VALUE, --frames N, --fps F: 1 if argv[*i] was one of them (*rc then holds a
 * usage error, or -1), 0 if not.  They may come before or after the script. */
static int live_option(options *o, int argc, char **argv, int *i, int *rc) {
    const char *a = argv[*i], *v = *i + 1 < argc ? argv[*i + 1] : NULL;
    *rc = -1;
    if (!strcmp(a, "--set")) {
        if (!v || o->nsets == MAX_SETS || !render_parse_param(v, &o->sets[o->nsets]))
            *rc = usage_error("%s", "--set needs name=value with a finite number, e.g. --set k=0.5");
        else o->nsets++;
    } else if (!strcmp(a, "--frames")) {
        char *end;
        long n = v ? strtol(v, &end, 10) : 0;
        if (!v || *end || n < 1 || n > 10000)
            *rc = usage_error("%s", "--frames needs a number of frames 1..10000");
        else o->nframes = (int)n;
    } else if (!strcmp(a, "--print")) {
        o->print = 1;
        return 1;
    } else if (!strcmp(a, "--dpi")) {
        char *end;
        double d = v ? strtod(v, &end) : 0;
        if (!v || *end || !(d >= 10 && d <= 2400)) *rc = usage_error("%s", "--dpi needs a resolution 10..2400");
        else o->fig.dpi = d, o->print = 1;
    } else if (!strcmp(a, "--size")) {
        char err[200];
        if (!v) *rc = usage_error("%s", "--size needs a size such as 12cm or 12cmx8cm");
        else if (pc_parse_size(v, &o->fig.width, &o->fig.height, err, sizeof err) != PC_OK)
            *rc = usage_error("%s", err);
        else o->print = 1;
    } else if (!strcmp(a, "--fps")) {
        char *end;
        double f = v ? strtod(v, &end) : 0;
        if (!v || *end || !(f > 0 && f <= 1000)) *rc = usage_error("%s", "--fps needs a number of frames per second");
        else o->fps = f;
    } else {
        return 0;
    }
    (*i)++;
    return 1;
}

/* Returns -1 to go on, or an exit status. Script arguments are left in argv from script_index. */
static int parse(int argc, char **argv, options *o) {
    int i = 1, rc;
    for (; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--")) { i++; break; }
        if (a[0] != '-' || !strcmp(a, "-")) break;
        if (!strcmp(a, "-e")) {
            if (++i == argc) return usage_error("%s", "option -e needs a chunk of code");
            if (o->nchunks == MAX_CHUNKS) return usage_error("%s", "too many -e options");
            o->chunks[o->nchunks++] = argv[i];
        } else if (!strcmp(a, "-o")) {
            int rc = add_output(o, i + 1 < argc ? argv[++i] : NULL);
            if (rc) return rc;
        } else if (!strcmp(a, "--watch")) {
            int rc = set_watch(o, i + 1 < argc ? argv[++i] : NULL);
            if (rc) return rc;
        } else if (!strcmp(a, "-i")) o->interactive = 1;
        else if (!strcmp(a, "--paper")) o->paper = 1;
        else if (!strcmp(a, "--qbasic")) o->qbasic = 1;
        else if (!strcmp(a, "--emit-lua")) o->emit_lua = 1;
        else if (!strcmp(a, "--input")) {
            if (++i == argc) return usage_error("%s", "option --input needs a file name");
            o->input = argv[i];
        }
        else if (!strcmp(a, "--for")) {
            int rc = set_limit(&o->run_for, a, i + 1 < argc ? argv[++i] : NULL);
            if (rc) return rc;
        }
        else if (!strcmp(a, "--safe")) o->sandbox.safe = 1;
        else if (!strcmp(a, "--allow-hardlinks")) o->sandbox.allow_hardlinks = 1;
        else if (live_option(o, argc, argv, &i, &rc)) {
            if (rc >= 0) return rc;
        }
        else if (!strcmp(a, "--allow")) {
            if (++i == argc) return usage_error("%s", "option --allow needs a folder");
            if (o->sandbox.nallow == SANDBOX_MAX_ALLOW)
                return usage_error("%s", "too many --allow options");
            o->sandbox.allow[o->sandbox.nallow++] = argv[i];
        } else if (!strcmp(a, "--timeout")) {
            int rc = set_limit(&o->sandbox.timeout, a, i + 1 < argc ? argv[++i] : NULL);
            if (rc) return rc;
        } else if (!strcmp(a, "--max-memory")) {
            int rc = set_limit(&o->sandbox.max_memory_mb, a, i + 1 < argc ? argv[++i] : NULL);
            if (rc) return rc;
        }
        else if (!strcmp(a, "-v") || !strcmp(a, "--version")) {
            printf("pointcalc %s (%s)\n", PCL_VERSION, LUA_RELEASE);
            return 0;
        } else if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage_text, stdout);
            return 0;
        } else return usage_error("unknown option '%s'", a);
    }
    if (i < argc) {
        o->script = argv[i];
        o->script_index = i;
        /* -o, --paper and --watch after the script still belong to pointcalc, up to a "--" */
        int out = i + 1;
        for (int j = i + 1; j < argc; j++) {
            if (!strcmp(argv[j], "--")) {
                while (++j < argc) argv[out++] = argv[j];
                break;
            }
            if (!strcmp(argv[j], "-o")) {
                int rc = add_output(o, j + 1 < argc ? argv[++j] : NULL);
                if (rc) return rc;
            } else if (!strcmp(argv[j], "--watch")) {
                int rc = set_watch(o, j + 1 < argc ? argv[++j] : NULL);
                if (rc) return rc;
            } else if (!strcmp(argv[j], "--paper")) o->paper = 1;
            else if (!strcmp(argv[j], "--input") && j + 1 < argc) o->input = argv[++j];
            else if (!strcmp(argv[j], "--for")) {
                int rc = set_limit(&o->run_for, "--for", j + 1 < argc ? argv[++j] : NULL);
                if (rc) return rc;
            }
            else if (live_option(o, argc, argv, &j, &rc)) {
                if (rc >= 0) return rc;
            } else argv[out++] = argv[j];
        }
        argv[out] = NULL;
    }
    if (o->script && (ends_with(o->script, ".bas"))) o->qbasic = 1;
    if (o->script && strcmp(o->script, "-")) {
        struct stat st;   /* a folder opens and then fails to read: say so now */
        int e = access(o->script, R_OK) != 0 ? errno : 0;
        if (!e && stat(o->script, &st) == 0 && S_ISDIR(st.st_mode)) e = EISDIR;
        if (e) {
            fprintf(stderr, "%s: cannot open '%s': %s\n", host_progname, o->script, strerror(e));
            return 2;
        }
    }
    if (o->emit_lua && !o->script) return usage_error("%s", "--emit-lua needs a QBasic program");
    if (o->input && !o->script) return usage_error("%s", "--input needs a script");
    if (o->input && !freopen(o->input, "r", stdin)) {   /* INPUT, INKEY$... read standard input */
        fprintf(stderr, "%s: cannot open '%s': %s\n", host_progname, o->input, strerror(errno));
        return 2;
    }
    if (o->nframes && (!o->script || !o->noutputs))
        return usage_error("%s", "--frames needs a script and an output: -o out.svg or -o out.png");
    if (o->sandbox.nallow && !o->sandbox.safe)
        return usage_error("%s", "--allow belongs to the safe mode: add --safe");
    char err[600];
    if (!sandbox_check_config(&o->sandbox, err, sizeof err)) return usage_error("%s", err);
    return -1;
}

/* The global `arg`, as lua.c builds it: arg[0] the script, arg[1..] its arguments. */
static void set_arg(lua_State *L, char **argv, int script_index) {
    int n = 0;
    while (argv[script_index + n + 1]) n++;
    lua_createtable(L, n, script_index + 1);
    for (int i = 0; argv[i]; i++) {
        lua_pushstring(L, argv[i]);
        lua_rawseti(L, -2, i - script_index);
    }
    lua_setglobal(L, "arg");
}

static void push_script_args(lua_State *L, char **argv, int script_index, int *n) {
    *n = 0;
    for (int i = script_index + 1; argv[i]; i++, (*n)++) {
        luaL_checkstack(L, 2, "too many arguments to the script");   /* 100 args overflowed */
        lua_pushstring(L, argv[i]);
    }
}

/* The default output: the script's base name with .png, in the current directory. */
static void default_output(const options *o, char *buf, size_t len) {
    const char *name = "pointcalc";
    if (o->script) name = strcmp(o->script, "-") ? o->script : "stdin";
    const char *base = strrchr(name, '/');
    base = base ? base + 1 : name;
    const char *dot = strrchr(base, '.');
    int n = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
    snprintf(buf, len, "%.*s.png", n, base);
}

/* --print, --dpi, --size: the print look, over what the script's figure{} set. */
static int apply_print(lua_State *L, const options *o) {
    if (!o->print) return 1;
    pc_canvas *c = pcl_canvas(L);
    pc_figure f = c->figure;
    if (o->fig.dpi) f.dpi = o->fig.dpi;
    if (o->fig.width) f.width = o->fig.width, f.height = o->fig.height;
    if (pc_figure_set(c, &f) == PC_OK) return 1;
    fprintf(stderr, "%s: %s\n", host_progname, pc_canvas_error(c));
    return 0;
}

static int write_outputs(lua_State *L, const options *o, int repl_ran) {
    if (!apply_print(L, o)) return 0;
    pc_canvas *c = pcl_canvas(L);
    pc_theme theme = pcl_theme(L);
    char err[512];
    int ok = 1;
    for (int i = 0; i < o->noutputs; i++) {
        if (pc_write_file(c, o->outputs[i], theme, err, sizeof err) != PC_OK) {
            fprintf(stderr, "%s: %s\n", host_progname, err);
            ok = 0;
        }
    }
    if (o->noutputs == 0 && pc_canvas_dirty(c) && !repl_ran) {
        char path[512];
        default_output(o, path, sizeof path);
        if (pc_write_file(c, path, theme, err, sizeof err) != PC_OK) {
            fprintf(stderr, "%s: %s\n", host_progname, err);
            ok = 0;
        } else {
            fprintf(stderr, "%s: wrote %s (the script drew but saved nothing; use -o to choose)\n",
                    host_progname, path);
        }
    }
    return ok;
}

/* pointcalc serve SCRIPT [--port N] */
static int serve_command(int argc, char **argv) {
    const char *script = NULL;
    long port = 8080;
    for (int i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--port") && i + 1 < argc) {
            char *end;
            port = strtol(argv[++i], &end, 10);
            if (*end || port < 0 || port > 65535) return usage_error("%s", "--port needs a port number 0..65535");
        } else if (argv[i][0] == '-' && strcmp(argv[i], "-")) {
            return usage_error("serve: unknown option '%s'", argv[i]);
        } else if (!script) {
            script = argv[i];
        } else {
            return usage_error("%s", "serve takes one script");
        }
    }
    if (!script || !strcmp(script, "-")) return usage_error("%s", "serve needs a script file");
    if (access(script, R_OK) != 0) {
        fprintf(stderr, "%s: cannot open '%s': %s\n", host_progname, script, strerror(errno));
        return 2;
    }
    return serve_main(script, (int)port);
}

/* A QBasic program that ends in text mode: its text screen drawn into the canvas
 * (qbasic_screen.TEXT_PICTURE, qbasic_textscreen.lua), so -o writes what QBasic shows. */
static void qbasic_text_picture(lua_State *L) {
    int top = lua_gettop(L);
    lua_getfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);   /* package.loaded, even sandboxed */
    if (lua_istable(L, -1)) lua_getfield(L, -1, "qbasic_screen");
    else lua_pushnil(L);
    if (lua_istable(L, -1)) lua_getfield(L, -1, "TEXT_PICTURE");
    else lua_pushnil(L);
    if (lua_isfunction(L, -1) && lua_pcall(L, 0, 0, 0) != LUA_OK) {
        fprintf(stderr, "%s: the text screen: %s\n", host_progname, lua_tostring(L, -1));
    }
    lua_settop(L, top);
}

int main(int argc, char **argv) {
    if (argc > 1 && !strcmp(argv[1], "serve")) return serve_command(argc, argv);
    options o = {0};
    int rc = parse(argc, argv, &o);
    if (rc >= 0) return rc;
    if (o.nframes && !o.qbasic)
        return frames_main(o.script, o.nframes, o.fps > 0 ? o.fps : 10, o.sets, o.nsets,
                           o.outputs, o.noutputs, o.paper, &o.sandbox);

    lua_State *L = host_new_state(&o.sandbox);
    if (!L) return 1;
    if (o.paper) pcl_set_theme(L, PC_THEME_PAPER);
    if (!apply_print(L, &o)) return 2;
    for (int i = 0; i < o.nsets; i++) pcl_param_set(L, o.sets[i].name, o.sets[i].value);

    if (o.emit_lua) {
        int ok = host_emit_lua(L, o.script);
        lua_close(L);
        return ok ? 0 : 1;
    }

    int ok = 1;
    if (o.script) set_arg(L, argv, o.script_index);
    for (int i = 0; ok && i < o.nchunks; i++) {
        if (luaL_loadbufferx(L, o.chunks[i], strlen(o.chunks[i]), "=(command line)", "t") != LUA_OK) {
            fprintf(stderr, "%s\n", lua_tostring(L, -1));
            lua_pop(L, 1);
            ok = 0;
        } else ok = host_pcall(L, 0);
    }
    int ran_something = o.nchunks > 0;
    if (ok && o.script && o.qbasic && o.run_for > 0) {
        /* --for: the QBasic runtime's budget of virtual seconds (qbasic_screen.lua) */
        lua_getglobal(L, "require");
        lua_pushliteral(L, "qbasic_screen");
        if (lua_pcall(L, 1, 1, 0) == LUA_OK) {
            lua_pushnumber(L, o.run_for);
            lua_setfield(L, -2, "RUN_FOR");
        }
        lua_pop(L, 1);
    }
    /* --frames of a QBasic program: taken as it runs, by its virtual clock (frames.c) */
    int qframes = ok && o.script && o.qbasic && o.nframes;
    if (qframes && !frames_qbasic_begin(L, o.nframes, o.fps, o.outputs, o.noutputs)) ok = 0;
    int run_failed = 0;   /* the script was translated and ran, but stopped with an error */
    if (ok && o.script) {
        ok = host_load_script(L, o.script, o.qbasic);
        if (ok) {
            int n;
            push_script_args(L, argv, o.script_index, &n);
            ok = host_pcall(L, n);
            run_failed = !ok;
        }
        ran_something = 1;
    } else if (ok && !ran_something && !o.interactive && !isatty(STDIN_FILENO)) {
        /* like lua: standard input is the script, unless -i (or --watch) asked for the REPL,
         * which then reads it */
        ok = host_load_script(L, "-", o.qbasic) && host_pcall(L, 0);
        ran_something = 1;
    }
    if (qframes) {   /* the frames are the pictures; a stopped run still writes them */
        int status = frames_qbasic_end(L, ok || host_limit_stopped);
        lua_close(L);
        return ok ? status : 1;
    }
    int repl = ok && (o.interactive || !ran_something);
    if (repl) host_repl(L, o.watch);
    if (o.qbasic && o.noutputs > 0 && (ok || run_failed)) qbasic_text_picture(L);
    if (ok) ok = write_outputs(L, &o, repl);
    else if (o.qbasic && (host_limit_stopped ||
                          (run_failed && (o.noutputs > 0 || pc_canvas_dirty(pcl_canvas(L)))))) {
        /* a QBasic program that never ends (a screen saver, a bouncing ball) stopped by
         * --timeout or --max-memory, or one stopped by a runtime error it did not trap (its
         * message, with the .bas line, is above): the screen as it stood is its picture */
        fprintf(stderr, "%s: writing the screen as it stood when the program was stopped\n",
                host_progname);
        write_outputs(L, &o, 0);
    }
    lua_close(L);
    return ok ? 0 : 1;
}
