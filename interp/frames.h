/* Animation frames: pointcalc script --frames N -o out.svg|out.png (frames.c, docs/live.md). */
#ifndef PC_FRAMES_H
#define PC_FRAMES_H

#include "render.h"

/* Render nframes frames of the script's animated slider (with the other --set values) into
 * each output: numbered PNG/PPM frames, or one animated SVG at fps frames per second.
 * paper: the print theme; cfg: the safe mode and limits of each run.  Returns the exit status (0, or 1 with a message on stderr). */
int frames_main(const char *script, int nframes, double fps, const render_param *sets, int nsets,
                const char *const *outputs, int noutputs, int paper, const sandbox_config *cfg);

/* A QBasic program's animation (the state that will run it): frame k is the screen when its
 * virtual clock reaches (k + 1) / fps; after nframes the program is stopped.  begin: 1 if set
 * up; end (after the run; ran = it succeeded or was stopped by the frames): writes the frames
 * still missing (the last screen) and the SVGs, returns the exit status. */
int frames_qbasic_begin(lua_State *L, int nframes, double fps, const char *const *outputs,
                        int noutputs);
int frames_qbasic_end(lua_State *L, int ran);

#endif
