/* Nearest names and numbers as messages show them (names.h). */
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include "names.h"

int pc_edit_distance(const char *a, const char *b) {
    int n = (int)strlen(a), m = (int)strlen(b);
    if (n > 40 || m > 40) return 99;
    int d[41][41];
    for (int i = 0; i <= n; i++) d[i][0] = i;
    for (int j = 0; j <= m; j++) d[0][j] = j;
    for (int i = 1; i <= n; i++)
        for (int j = 1; j <= m; j++) {
            int ca = tolower((unsigned char)a[i - 1]), cb = tolower((unsigned char)b[j - 1]);
            int v = d[i - 1][j - 1] + (ca != cb);
            if (d[i - 1][j] + 1 < v) v = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < v) v = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && ca == tolower((unsigned char)b[j - 2]) &&
                tolower((unsigned char)a[i - 2]) == cb && d[i - 2][j - 2] + 1 < v)
                v = d[i - 2][j - 2] + 1;
            d[i][j] = v;
        }
    return d[n][m];
}

void pc_nearer_name(const char *name, const char *cand, const char **best, int *bestd) {
    int len = (int)strlen(name), d = pc_edit_distance(name, cand);
    if (d > (len <= 3 ? 1 : 2) || d == 0) return;
    if (d < *bestd || (d == *bestd && strcmp(cand, *best) < 0)) {
        *best = cand;
        *bestd = d;
    }
}

const char *pc_nearest_name(const char *name, const char *const *candidates) {
    const char *best = NULL;
    int bestd = 99;
    for (int i = 0; candidates[i]; i++) pc_nearer_name(name, candidates[i], &best, &bestd);
    return best;
}

char *pc_num_text(double x, char *buf, size_t size) {
    snprintf(buf, size, "%.14g", x == 0 ? 0.0 : x);
    return buf;
}
