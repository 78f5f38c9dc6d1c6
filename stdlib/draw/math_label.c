/* Math in labels (math_label.h): a recursive-descent parser that lays out as it reads.
 *
 * The sizes and shifts follow TeX's text style in spirit (The TeXbook, appendix G, rules 17-18,
 * rounded): a script is 0.7 of its base (0.5 at most two levels down), a subscript sits 0.22 em
 * below its base's baseline, a superscript 0.38 em above; A_1^2 puts both at the same x. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "math_label.h"
#include "status.h"

const pc_mcommand pc_math_commands[] = {
    {"alpha", "\u03b1", 1}, {"beta", "\u03b2", 1}, {"gamma", "\u03b3", 1}, {"delta", "\u03b4", 1},
    {"epsilon", "\u03f5", 1}, {"varepsilon", "\u03b5", 1}, {"zeta", "\u03b6", 1},
    {"eta", "\u03b7", 1}, {"theta", "\u03b8", 1}, {"vartheta", "\u03d1", 1}, {"iota", "\u03b9", 1},
    {"kappa", "\u03ba", 1}, {"lambda", "\u03bb", 1}, {"mu", "\u03bc", 1}, {"nu", "\u03bd", 1},
    {"xi", "\u03be", 1}, {"pi", "\u03c0", 1}, {"rho", "\u03c1", 1}, {"sigma", "\u03c3", 1},
    {"tau", "\u03c4", 1}, {"upsilon", "\u03c5", 1}, {"phi", "\u03d5", 1}, {"varphi", "\u03c6", 1},
    {"chi", "\u03c7", 1}, {"psi", "\u03c8", 1}, {"omega", "\u03c9", 1},
    /* capitals are upright, as in TeX */
    {"Gamma", "\u0393", 0}, {"Delta", "\u0394", 0}, {"Theta", "\u0398", 0}, {"Lambda", "\u039b", 0},
    {"Xi", "\u039e", 0}, {"Pi", "\u03a0", 0}, {"Sigma", "\u03a3", 0}, {"Upsilon", "\u03a5", 0},
    {"Phi", "\u03a6", 0}, {"Psi", "\u03a8", 0}, {"Omega", "\u03a9", 0},
    {"infty", "\u221e", 0}, {"cdot", "\u22c5", 0}, {"times", "\u00d7", 0}, {"pm", "\u00b1", 0},
    {"mp", "\u2213", 0}, {"le", "\u2264", 0}, {"leq", "\u2264", 0}, {"ge", "\u2265", 0},
    {"geq", "\u2265", 0}, {"ne", "\u2260", 0}, {"neq", "\u2260", 0}, {"approx", "\u2248", 0},
    {"equiv", "\u2261", 0}, {"sim", "\u223c", 0}, {"cong", "\u2245", 0}, {"angle", "\u2220", 0},
    {"parallel", "\u2225", 0}, {"perp", "\u22a5", 0}, {"to", "\u2192", 0},
    {"rightarrow", "\u2192", 0}, {"leftarrow", "\u2190", 0}, {"in", "\u2208", 0},
    {"cap", "\u2229", 0}, {"cup", "\u222a", 0}, {"circ", "\u2218", 0}, {"partial", "\u2202", 0},
    {"nabla", "\u2207", 0}, {"sum", "\u2211", 0}, {"int", "\u222b", 0}, {"ldots", "\u2026", 0},
    {"triangle", "\u25b3", 0}, {"deg", "\u00b0", 0}, {"prime", "\u2032", 0},
    {",", "\u2009", 0}, {" ", " ", 0}, {"{", "{", 0}, {"}", "}", 0}, {"$", "$", 0},
    {"\\", "\\", 0}, {"_", "_", 0}, {"^", "^", 0},
};
const size_t pc_math_ncommands = sizeof pc_math_commands / sizeof pc_math_commands[0];

typedef struct {
    const char *label, *s;     /* the whole label; s: the cursor */
    double size, asc, desc;    /* the label's size, the font's ascent and descent per em */
    pc_measure_fn measure;
    void *ctx;
    pc_mlayout *L;
    double x;                  /* the pen position */
    char *err; size_t errlen;
    int status;
    size_t ctext, cruns, cdecos;   /* the capacities of the layout's arrays */
    double last_end;               /* the pen after the last run (-1: moved since) */
} parser;

static int fail(parser *p, const char *at, const char *fmt, ...) {
    if (p->status != PC_OK) return p->status;
    long ch = 1;   /* the position in characters, 1-based */
    for (const char *q = p->label; q < at && *q; q++)
        if (((unsigned char)*q & 0xc0) != 0x80) ch++;
    char what[160];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (p->err && p->errlen)
        snprintf(p->err, p->errlen, "label '%.60s': %s at character %ld", p->label, what, ch);
    return p->status = PC_EARG;
}

static int grow(void **buf, size_t *cap, size_t need, size_t elem) {
    if (need <= *cap) return 1;
    size_t n = *cap ? *cap * 2 : 16;
    while (n < need) n *= 2;
    void *b = realloc(*buf, n * elem);
    if (!b) return 0;
    *buf = b;
    *cap = n;
    return 1;
}


/* Append one run of n bytes in a style at the pen, advancing it. */
static void emit(parser *p, const char *s, size_t n, int italic, double size, double rise) {
    if (p->status != PC_OK || n == 0) return;
    pc_mlayout *L = p->L;
    if (!grow((void **)&L->text, &p->ctext, L->ntext + n + 1, 1) ||
        !grow((void **)&L->runs, &p->cruns, L->nruns + 1, sizeof *L->runs)) {
        p->status = PC_ENOMEM;
        return;
    }
    pc_mrun *last = L->nruns ? &L->runs[L->nruns - 1] : NULL;
    memcpy(L->text + L->ntext, s, n);
    if (last && last->italic == italic && last->size == size && last->rise == rise &&
        p->last_end == p->x) {
        last->len += n;   /* the same style straight after: one run, measured whole */
        p->x = last->x + p->measure(p->ctx, L->text + last->first, last->len, italic, size);
    } else {
        L->runs[L->nruns++] = (pc_mrun){L->ntext, n, italic, size, p->x, rise};
        p->x += p->measure(p->ctx, s, n, italic, size);
    }
    L->ntext += n;
    L->text[L->ntext] = 0;
    p->last_end = p->x;
    if (rise + p->asc * size > L->ascent) L->ascent = rise + p->asc * size;
    if (p->desc * size - rise > L->descent) L->descent = p->desc * size - rise;
}

static double level_size(const parser *p, int level) {
    return level == 0 ? p->size : level == 1 ? p->size * 0.7 : p->size * 0.5;
}

static void parse_seq(parser *p, int level, double rise, int upright, char end);

/* The top of the runs from run index r0 on: where a bar over them goes. */
static double top_of(const parser *p, size_t r0) {
    double top = 0;
    for (size_t i = r0; i < p->L->nruns; i++) {
        const pc_mrun *r = &p->L->runs[i];
        double t = r->rise + 0.7 * r->size;   /* about the height of a capital */
        if (t > top) top = t;
    }
    return top;
}

/* The bottom of the runs from run index r0 on (negative: below the baseline): where a line
 * under them goes; a descender is about 0.22 em deep. */
static double bottom_of(const parser *p, size_t r0) {
    double bottom = 0;
    for (size_t i = r0; i < p->L->nruns; i++) {
        const pc_mrun *r = &p->L->runs[i];
        double b = r->rise - 0.22 * r->size;
        if (b < bottom) bottom = b;
    }
    return bottom;
}

/* The space TeX puts around a relation (= < >, thickmuskip, about 0.28 em) and a binary
 * operator (+ -, medmuskip, about 0.22 em), in text style only (none in scripts, as TeX). */
static double op_space(const char *utf8, int level) {
    if (level > 0) return 0;
    static const char *rel[] = {"=", "<", ">", "\u2264", "\u2265", "\u2260", "\u2248", "\u2261",
                                "\u223c", "\u2245", "\u2192", "\u2190", "\u2208", "\u2225", "\u22a5"};
    static const char *bin[] = {"+", "\u2212", "\u00d7", "\u22c5", "\u00b1", "\u2213", "\u2229",
                                "\u222a", "\u2218"};
    for (size_t i = 0; i < sizeof rel / sizeof rel[0]; i++)
        if (!strcmp(utf8, rel[i])) return 0.28;
    for (size_t i = 0; i < sizeof bin / sizeof bin[0]; i++)
        if (!strcmp(utf8, bin[i])) return 0.22;
    return 0;
}

/* A symbol of math, with the space around it that its class asks for (not at the start, where
 * TeX treats a binary operator as a sign). */
static void emit_symbol(parser *p, const char *utf8, int italic, int level, double rise) {
    double sp = p->x > 0 ? op_space(utf8, level) * level_size(p, level) : 0;
    p->x += sp;
    emit(p, utf8, strlen(utf8), italic, level_size(p, level), rise);
    p->x += sp;
}

/* One character of math: letters italic (unless upright), the rest upright; '-' is a minus. */
static void parse_char(parser *p, int level, double rise, int upright) {
    const unsigned char *u = (const unsigned char *)p->s;
    if (*u == '-' || *u == '+' || *u == '=' || *u == '<' || *u == '>') {
        emit_symbol(p, *u == '-' ? "\u2212" : (char[]){(char)*u, 0}, 0, level, rise);
        p->s++;
        return;
    }
    size_t n = *u < 0x80 ? 1 : *u < 0xe0 ? 2 : *u < 0xf0 ? 3 : 4;
    for (size_t i = 1; i < n; i++)
        if (!p->s[i]) n = i;
    int letter = (*u < 0x80 && ((*u | 32) >= 'a' && (*u | 32) <= 'z')) ||
                 (n == 2 && (*u == 0xce || *u == 0xcf || *u == 0xd0 || *u == 0xd1));
    emit(p, p->s, n, letter && !upright, level_size(p, level), rise);
    p->s += n;
}

/* What `_` `^` and the accents take: one character, one command, or a {group}. */
static void parse_atom(parser *p, int level, double rise, int upright, const char *what);

static void parse_command(parser *p, int level, double rise, int upright) {
    const char *at = p->s++;   /* the backslash */
    const char *name = p->s;
    size_t n = 0;
    while ((name[n] | 32) >= 'a' && (name[n] | 32) <= 'z') n++;
    if (n == 0 && name[0]) n = 1;   /* \, \{ \$ ... */
    if (n == 0) {
        fail(p, at, "'\\' at the end");
        return;
    }
    p->s += n;
    static const struct { const char *name; int kind; } accents[] = {
        {"bar", PC_DECO_BAR}, {"overline", PC_DECO_BAR}, {"vec", PC_DECO_VEC},
        {"tilde", PC_DECO_TILDE}, {"underline", PC_DECO_UNDER}};
    for (size_t a = 0; a < sizeof accents / sizeof accents[0]; a++) {
        if (strlen(accents[a].name) != n || strncmp(name, accents[a].name, n)) continue;
        char what[16];
        snprintf(what, sizeof what, "\\%s", accents[a].name);
        double x0 = p->x;
        size_t r0 = p->L->nruns;
        p->last_end = -1;   /* its group in runs of its own (not merged into the one before) */
        parse_atom(p, level, rise, upright, what);
        p->last_end = -1;   /* nor what follows into its last */
        if (p->status != PC_OK) return;
        pc_mlayout *L = p->L;
        if (!grow((void **)&L->decos, &p->cdecos, L->ndecos + 1, sizeof *L->decos)) {
            p->status = PC_ENOMEM;
            return;
        }
        int kind = accents[a].kind;
        double s = level_size(p, level);
        /* a bar or a tilde over one letter is narrower than the letter, as TeX's accents */
        double inset = (a == 0 || kind == PC_DECO_TILDE) ? 0.12 * (p->x - x0) : 0;
        if (kind == PC_DECO_UNDER) {   /* below the lowest run's descenders, as TeX's rule */
            double y = bottom_of(p, r0) - 0.08 * s;
            L->decos[L->ndecos++] = (pc_mdeco){kind, x0, p->x, y};
            if (0.04 * s - y > L->descent) L->descent = 0.04 * s - y;
            return;
        }
        /* the wave's amplitude (0.06 em each side) sits it a little higher than a bar */
        double top = top_of(p, r0) + (kind == PC_DECO_TILDE ? 0.18 : 0.12) * s;
        L->decos[L->ndecos++] = (pc_mdeco){kind, x0 + inset, p->x - inset, top};
        double up = kind == PC_DECO_TILDE ? 0.12 : 0.08;
        if (top + up * s > L->ascent) L->ascent = top + up * s;
        return;
    }
    if (n == 6 && !strncmp(name, "mathrm", 6)) {
        parse_atom(p, level, rise, 1, "\\mathrm");
        return;
    }
    for (size_t i = 0; i < pc_math_ncommands; i++) {
        const pc_mcommand *m = &pc_math_commands[i];
        if (strlen(m->name) == n && !strncmp(m->name, name, n)) {
            emit_symbol(p, m->utf8, m->italic && !upright, level, rise);
            return;
        }
    }
    fail(p, at, "unknown command '\\%.*s'", (int)(n > 30 ? 30 : n), name);
}

static void parse_atom(parser *p, int level, double rise, int upright, const char *what) {
    while (*p->s == ' ') p->s++;
    const char *at = p->s;
    if (*p->s == '{') {
        p->s++;
        parse_seq(p, level, rise, upright, '}');
        if (p->status == PC_OK && *p->s != '}') fail(p, at, "unbalanced '{'");
        else p->s++;
    } else if (*p->s == '\\') {
        parse_command(p, level, rise, upright);
    } else if (!*p->s || *p->s == '$' || *p->s == '}' || *p->s == '_' || *p->s == '^') {
        fail(p, at, "%s needs a character or a {group} after it", what);
    } else {
        parse_char(p, level, rise, upright);
    }
}

/* A sequence up to `end` ('$' or '}', not consumed). */
static void parse_seq(parser *p, int level, double rise, int upright, char end) {
    double base_end = p->x;   /* where the last base ended: both scripts start there */
    double script_end = -1;   /* the farther end of a script already attached */
    while (p->status == PC_OK && *p->s && *p->s != end) {
        char ch = *p->s;
        const char *at = p->s;
        if (ch == ' ') {
            p->s++;
        } else if (ch == '_' || ch == '^') {
            p->s++;
            const char *what = ch == '_' ? "'_'" : "'^'";
            if (script_end >= 0) p->x = base_end;   /* A_1^2: the second script at the same x */
            double s = level_size(p, level);
            parse_atom(p, level + 1, rise + (ch == '_' ? -0.22 : 0.38) * s, upright, what);
            if (p->x < script_end) p->x = script_end;
            script_end = p->x;
        } else if (ch == '\'') {
            int k = 0;
            while (*p->s == '\'') p->s++, k++;
            static const char *primes[] = {"\u2032", "\u2033", "\u2034"};
            for (; k > 0; k -= 3)
                emit(p, primes[(k > 3 ? 3 : k) - 1], 3, 0, level_size(p, level), rise);
            base_end = p->x;   /* M'_1: the subscript after the prime */
            script_end = -1;
        } else if (ch == '}') {
            fail(p, at, "unbalanced '}'");
        } else if (ch == '$') {
            return;   /* a '$' before a group's '}': the group reports its '{' */
        } else {
            parse_atom(p, level, rise, upright, "");
            base_end = p->x;
            script_end = -1;
        }
    }
}

int pc_has_math(const char *label) {
    for (const char *s = label; *s; s++) {
        if (*s == '\\' && s[1] == '$') s++;
        else if (*s == '$') return 1;
    }
    return 0;
}

int pc_math_layout(const char *label, double size, double ascent_em, double descent_em,
                   pc_measure_fn measure, void *ctx, pc_mlayout *out, char *err, size_t errlen) {
    memset(out, 0, sizeof *out);
    parser p = {label, label, size, ascent_em, descent_em, measure, ctx, out, 0, err, errlen,
                PC_OK, 0, 0, 0, -1};
    out->ascent = ascent_em * size;
    out->descent = descent_em * size;
    while (p.status == PC_OK && *p.s) {
        const char *t = p.s;
        /* plain text up to the next unescaped '$' */
        while (*p.s && *p.s != '$' && !(*p.s == '\\' && p.s[1] == '$')) p.s++;
        emit(&p, t, (size_t)(p.s - t), 0, size, 0);
        if (*p.s == '\\') {
            emit(&p, "$", 1, 0, size, 0);
            p.s += 2;
        } else if (*p.s == '$') {
            const char *open = p.s++;
            out->math = 1;
            parse_seq(&p, 0, 0, 0, '$');
            if (p.status == PC_OK && *p.s != '$') fail(&p, open, "unclosed '$'");
            else p.s++;
        }
    }
    out->width = p.x;
    if (p.status != PC_OK) {
        if (p.status == PC_ENOMEM && err && errlen) snprintf(err, errlen, "out of memory for a label");
        pc_mlayout_free(out);
    }
    return p.status;
}

int pc_plain_layout(const char *text, double size, double ascent_em, double descent_em,
                    pc_measure_fn measure, void *ctx, pc_mlayout *out) {
    memset(out, 0, sizeof *out);
    parser p = {text, text, size, ascent_em, descent_em, measure, ctx, out, 0, NULL, 0,
                PC_OK, 0, 0, 0, -1};
    out->ascent = ascent_em * size;
    out->descent = descent_em * size;
    emit(&p, text, strlen(text), 0, size, 0);
    out->width = p.x;
    if (p.status != PC_OK) pc_mlayout_free(out);
    return p.status;
}

void pc_mlayout_free(pc_mlayout *l) {
    free(l->text);
    free(l->runs);
    free(l->decos);
    memset(l, 0, sizeof *l);
}

static double count_chars(void *ctx, const char *s, size_t n, int italic, double size) {
    (void)ctx; (void)italic; (void)size;
    double k = 0;
    for (size_t i = 0; i < n; i++) k += ((unsigned char)s[i] & 0xc0) != 0x80;
    return k;
}

int pc_math_plain(const char *label, char *out, size_t outlen) {
    pc_mlayout l;
    int st = pc_math_layout(label, 1, 1, 0, count_chars, NULL, &l, NULL, 0);
    if (st != PC_OK) return st;
    snprintf(out, outlen, "%s", l.text ? l.text : "");
    pc_mlayout_free(&l);
    return PC_OK;
}

int pc_math_check(const char *label, char *err, size_t errlen) {
    if (!pc_has_math(label)) return PC_OK;
    pc_mlayout l;
    int st = pc_math_layout(label, 1, 1, 0, count_chars, NULL, &l, err, errlen);
    if (st == PC_OK) pc_mlayout_free(&l);
    return st;
}
