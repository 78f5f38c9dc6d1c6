/* Math in labels: the text between $...$ of a label, parsed and laid out in pure C.
 *
 * "$A_1$", "$\varphi$", "$\bar{t}$", "$\overline{AB}$", "$M''$", "$P_{0,3}^{2}$": letters are
 * italic, digits and punctuation upright; `_` and `^` take one character or a {group} (nested);
 * primes become ′ ″; Greek letters and symbols by name (the table in math_label.c, docs/print.md);
 * \bar, \overline, \vec and \tilde put a line, an arrow or a wave over their group, \underline a
 * line under it; \mathrm{} is upright.
 * Text outside $ is plain UTF-8, as it is; "\$" is a dollar sign.
 *
 * The layout is independent of the renderer: it asks a measuring function for the advance of
 * each run, so the print look (Pango) and the VGA look (8-pixel cells) share it, and every
 * output of one figure puts the same run at the same place. */
#ifndef PC_MATH_LABEL_H
#define PC_MATH_LABEL_H

#include <stddef.h>

/* One run of text of one style: text[first .. first+len) of the layout's text. */
typedef struct {
    size_t first, len;
    int italic;          /* 1: italic (math letters); 0: upright */
    double size;         /* the run's font size (the label's size times 0.7 a level, at least 0.5) */
    double x;            /* the run's left edge, from the label's origin */
    double rise;         /* its baseline above the label's baseline (subscripts are negative) */
} pc_mrun;

/* A line over a stretch of the label (\bar, \overline), an arrow (\vec), a wave (\tilde) or a
 * line under it (\underline: rise negative, below the baseline). */
enum { PC_DECO_BAR, PC_DECO_VEC, PC_DECO_TILDE, PC_DECO_UNDER };
typedef struct {
    int kind;
    double x0, x1;       /* its extent along the baseline */
    double rise;         /* its height above the label's baseline */
} pc_mdeco;

typedef struct {
    char *text;            /* the runs' characters, UTF-8 (Greek and symbols resolved) */
    size_t ntext;
    pc_mrun *runs; size_t nruns;
    pc_mdeco *decos; size_t ndecos;
    double width;          /* the advance of the whole label */
    double ascent, descent;   /* above and below its baseline (descent positive) */
    int math;              /* the label had a $...$ */
} pc_mlayout;

/* The advance of n bytes of UTF-8 at a size, italic or not (the renderer's font metrics). */
typedef double (*pc_measure_fn)(void *ctx, const char *utf8, size_t n, int italic, double size);

/* Does the label contain math (an unescaped '$')?  Labels without it are drawn as they were. */
int pc_has_math(const char *label);

/* Parse and lay out label at font size `size`; ascent_em, descent_em: the font's ascent and
 * descent per unit of size.  PC_OK, PC_ENOMEM, or PC_EARG with a message in err naming the
 * label and the position (1-based character):  "label '$A_{1$': unbalanced '{' at character 4". */
int pc_math_layout(const char *label, double size, double ascent_em, double descent_em,
                   pc_measure_fn measure, void *ctx, pc_mlayout *out, char *err, size_t errlen);
void pc_mlayout_free(pc_mlayout *l);
/* The same for text taken as it is (QBasic's PRINT): one upright run. */
int pc_plain_layout(const char *text, double size, double ascent_em, double descent_em,
                    pc_measure_fn measure, void *ctx, pc_mlayout *out);

/* The label as plain UTF-8 (math resolved, markup dropped): what a writer without runs puts. */
int pc_math_plain(const char *label, char *out, size_t outlen);

/* Is the label's math well formed?  PC_OK, or pc_math_layout's status and message (for a call
 * that records a label now and lays it out later: a label of a 3-D scene). */
int pc_math_check(const char *label, char *err, size_t errlen);

/* The command table, for the docs and the tests: name, its UTF-8 result, its style. */
typedef struct { const char *name, *utf8; int italic; } pc_mcommand;
extern const pc_mcommand pc_math_commands[];
extern const size_t pc_math_ncommands;

#endif
