/* Text of messages that is not tied to Lua: the name nearest to a misspelt one (the "did you
 * mean" of unknown options and globals), and numbers as messages show them. */
#ifndef PC_NAMES_H
#define PC_NAMES_H

#include <stddef.h>

/* Edit distance of a and b, case-insensitive, a swap of neighbours counting as one edit
 * (lrep -> lerp); 99 when either is longer than 40 characters. */
int pc_edit_distance(const char *a, const char *b);
/* Keep cand in *best (at distance *bestd, 99 at first) if it is a better suggestion for name:
 * near enough (1 edit for names of up to 3 characters, 2 for longer), not name itself, and
 * nearer than *best or as near and first in alphabetical order. */
void pc_nearer_name(const char *name, const char *cand, const char **best, int *bestd);
/* The best suggestion for name among the candidates (NULL-ended), or NULL. */
const char *pc_nearest_name(const char *name, const char *const *candidates);
/* x as points print their coordinates: %.14g, and 0 for -0; returns buf. */
char *pc_num_text(double x, char *buf, size_t size);

#endif
