/* inkcmp A.ppm B.ppm [RADIUS [THRESHOLD]]: compare two pictures as line drawings.
 * Ink is every pixel that is not the background colour (black).  Prints which share of the
 * ink of each picture lies within RADIUS pixels (Euclidean, default 2) of ink of the other,
 * and exits 0 when both shares reach THRESHOLD (default 0.95), 1 otherwise, 2 on bad input.
 * A test tool of the gallery tests, not part of the product. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct { int w, h; unsigned char *ink; } picture;

static int read_ppm(const char *path, picture *p) {
    FILE *f = fopen(path, "rb");
    if (!f) { fprintf(stderr, "inkcmp: cannot open '%s'\n", path); return 0; }
    int maxval;
    if (fscanf(f, "P6 %d %d %d", &p->w, &p->h, &maxval) != 3 || maxval != 255 || fgetc(f) == EOF ||
        p->w <= 0 || p->h <= 0) {
        fprintf(stderr, "inkcmp: '%s' is not a binary PPM\n", path);
        fclose(f);
        return 0;
    }
    size_t n = (size_t)p->w * p->h;
    unsigned char *rgb = malloc(3 * n);
    p->ink = malloc(n);
    int ok = rgb && p->ink && fread(rgb, 3, n, f) == n;
    if (ok)
        for (size_t i = 0; i < n; i++) p->ink[i] = rgb[3 * i] | rgb[3 * i + 1] | rgb[3 * i + 2];
    else fprintf(stderr, "inkcmp: '%s' is truncated\n", path);
    free(rgb);
    fclose(f);
    return ok;
}

/* share of a's ink pixels with ink of b within radius r; *count receives a's ink */
static double near_share(const picture *a, const picture *b, int r, long *count) {
    long ink = 0, near = 0;
    for (int y = 0; y < a->h; y++)
        for (int x = 0; x < a->w; x++) {
            if (!a->ink[(size_t)y * a->w + x]) continue;
            ink++;
            int found = 0;
            for (int dy = -r; dy <= r && !found; dy++)
                for (int dx = -r; dx <= r && !found; dx++) {
                    int xx = x + dx, yy = y + dy;
                    if (dx * dx + dy * dy > r * r || xx < 0 || yy < 0 || xx >= b->w || yy >= b->h) continue;
                    found = b->ink[(size_t)yy * b->w + xx] != 0;
                }
            near += found;
        }
    *count = ink;
    return ink ? (double)near / ink : 0;
}

int main(int argc, char **argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: inkcmp A.ppm B.ppm [RADIUS [THRESHOLD]]\n");
        return 2;
    }
    int r = argc > 3 ? atoi(argv[3]) : 2;
    double threshold = argc > 4 ? atof(argv[4]) : 0.95;
    picture a, b;
    if (!read_ppm(argv[1], &a) || !read_ppm(argv[2], &b)) return 2;
    if (a.w != b.w || a.h != b.h) {
        fprintf(stderr, "inkcmp: sizes differ: %dx%d and %dx%d\n", a.w, a.h, b.w, b.h);
        return 1;
    }
    long na, nb;
    double sa = near_share(&a, &b, r, &na), sb = near_share(&b, &a, r, &nb);
    printf("ink: %ld px, %.1f%% within %d px of the other's; other: %ld px, %.1f%%\n", na,
           100 * sa, r, nb, 100 * sb);
    free(a.ink);
    free(b.ink);
    if (na == 0 || nb == 0) {
        printf("inkcmp: a picture has no ink\n");
        return 1;
    }
    return sa >= threshold && sb >= threshold ? 0 : 1;
}
