/* Animation frames: pointcalc script --frames N -o out.svg|out.png (frames.c, docs/live.md). */
#ifndef PC_FRAMES_H
#define PC_FRAMES_H

#include "render.h"

/* Render nframes frames of the script's animated slider (with the other --set values) into
 * each output: numbered PNG/PPM frames, or one animated SVG at fps frames per second.
 * paper: the print theme; cfg: the safe mode and limits of each run.  Returns the exit status (0, or 1 with a message on stderr). */
int frames_main(const char *script, int nframes, double fps, const render_param *sets, int nsets,
                const char *const *outputs, int noutputs, int paper, const sandbox_config *cfg);

#endif
