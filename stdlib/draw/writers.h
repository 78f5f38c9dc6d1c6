/* The three writers: PNG (libpng) and binary PPM render the raster; SVG renders the display
 * list as vectors.  All write atomically: a temporary file in the target directory, renamed
 * into place only when complete, so a failed save leaves no file behind. */
#ifndef PC_WRITERS_H
#define PC_WRITERS_H

#include <stdio.h>
#include "canvas.h"

typedef enum { PC_THEME_SCREEN = 0, PC_THEME_PAPER = 1 } pc_theme;
typedef enum { PC_FMT_UNKNOWN = -1, PC_FMT_PNG, PC_FMT_SVG, PC_FMT_PPM,
               PC_FMT_PDF, PC_FMT_EPS, PC_FMT_PS } pc_format;   /* the last three: print.h */

/* The colours a writer uses: the canvas palette, or its print version (white paper, dark ink). */
void pc_theme_palette(const pc_canvas *c, pc_theme theme, pc_rgb out[256]);

/* The colour of an attribute in a writer: a palette attribute through the theme's palette
 * `pal` (from pc_theme_palette), a true colour as given.  Every writer resolves through it. */
static inline pc_rgb pc_attr_rgb(const pc_canvas *c, const pc_rgb pal[256], int attr) {
    return attr < 256 ? pal[attr] : c->palette[attr];
}

/* Format from the file name's extension (case-insensitive), PC_FMT_UNKNOWN otherwise. */
pc_format pc_format_from_path(const char *path);

/* Encode to an open stream.  Return PC_OK or PC_EIO. */
int pc_encode_ppm(const pc_canvas *c, pc_theme theme, FILE *out);
int pc_encode_png(const pc_canvas *c, pc_theme theme, FILE *out);
int pc_encode_svg(const pc_canvas *c, pc_theme theme, FILE *out);

/* Encode in format fmt to an open stream, in the look the canvas asks for (as pc_write_file
 * below): labels placed at write time, PDF/EPS/PS and a figure{}'s PNG/SVG in the print look.
 * PC_OK, PC_ENOMEM, PC_EIO, or PC_EARG with the reason in why. */
int pc_encode(const pc_canvas *c, pc_format fmt, pc_theme theme, FILE *f, char *why, size_t whylen);

/* Write to `path` in the format its extension names, atomically.  PDF, EPS and PS are the
 * print look (print.h); PNG and SVG are the print look when the canvas's figure is on (a
 * script's figure{}, the command line's --print, --dpi or --size), the VGA look otherwise.  On failure returns
 * PC_EIO (or PC_EARG for an unknown extension) and puts
 * "cannot write 'PATH': REASON" into err.  The rules (links, non-regular files, read-only
 * files, signals) are in write_file.c and docs/safety.md. */
int pc_write_file(const pc_canvas *c, const char *path, pc_theme theme, char *err, size_t errlen);

/* The same rules for any content: emit(ud, f, why, whylen) writes the file's bytes to f and
 * returns PC_OK or an error code (PC_ENOMEM, PC_EIO; with a reason in why for PC_EARG).  For writers of their own (animation frames). */
typedef int (*pc_emit_fn)(void *ud, FILE *f, char *why, size_t whylen);
int pc_write_file_emit(const char *path, pc_emit_fn emit, void *ud, char *err, size_t errlen);

/* Remove the temporary file of a write in progress, if any.  Async-signal-safe: for a
 * program's own fatal-signal or time-limit handler. */
void pc_write_file_abort(void);

#endif
