/* The C baseline of bench/equations.lua: the two equations of that benchmark written as
 * hand-written C loops (what a C programmer would type: the coordinates and the book's
 * coefficients inline), sampled at N evenly spaced t in [0, 1] into an array, timed by CPU
 * time, best of R rounds.  Prints one line per equation: "NAME ns_per_sample checksum".
 * Run by bench/equations.lua (built beside the pointcalc program); a benchmark, not a test.
 * Usage: equations_c [N [R]] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double cpu_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* Stepanov's example 2: A = lerp(P0, P1, c), B = lerp(P3, P2, c), M = lerp(A, B, d) with
 * c = (1 + cos u)/2, d = (1 + sin u)/2, u = 2 pi t */
static void oval(long n, double *out) {
    const double x0 = 100, y0 = 100, x1 = 300, y1 = 150, x2 = 280, y2 = 200, x3 = 150, y3 = 300;
    for (long i = 0; i < n; i++) {
        double t = (double)i / (double)(n - 1), u = 2 * M_PI * t;
        double c = (1 + cos(u)) / 2, d = (1 + sin(u)) / 2;
        double xa = x0 + c * (x1 - x0), ya = y0 + c * (y1 - y0);
        double xb = x3 + c * (x2 - x3), yb = y3 + c * (y2 - y3);
        out[2 * i] = xa + d * (xb - xa);
        out[2 * i + 1] = ya + d * (yb - ya);
    }
}

/* Konopatsky (4.28): the order-6 curve through M_j = (j, y_j), y = 0 3 1 4 1 5 9, as the sum of
 * M_j times its row of coefficients of t̄^(6-i) t^i (the digest's corrected rows) */
static void order6(long n, double *out) {
    static const double rows[7][7] = {
        {1, -8.7, 22.7, -22.7, 8.7, -1, 0},        {0, 36, -133.2, 151.2, -61.2, 7.2, 0},
        {0, -45, 301.5, -418.5, 184.5, -22.5, 0},  {0, 40, -308, 600, -308, 40, 0},
        {0, -22.5, 184.5, -418.5, 301.5, -45, 0},  {0, 7.2, -61.2, 151.2, -133.2, 36, 0},
        {0, -1, 8.7, -22.7, 22.7, -8.7, 1}};
    static const double ys[7] = {0, 3, 1, 4, 1, 5, 9};
    for (long i = 0; i < n; i++) {
        double t = (double)i / (double)(n - 1), tb = 1 - t, tp[7], bp[7], mono[7];
        tp[0] = bp[0] = 1;
        for (int k = 1; k <= 6; k++) { tp[k] = tp[k - 1] * t; bp[k] = bp[k - 1] * tb; }
        for (int k = 0; k <= 6; k++) mono[k] = bp[6 - k] * tp[k];
        double x = 0, y = 0;
        for (int j = 0; j < 7; j++) {
            double phi = 0;
            for (int k = 0; k <= 6; k++) phi += rows[j][k] * mono[k];
            x += j * phi;
            y += ys[j] * phi;
        }
        out[2 * i] = x;
        out[2 * i + 1] = y;
    }
}

static void run(const char *name, void (*f)(long, double *), long n, int rounds, double *buf) {
    double best = 1e300, sum = 0;
    for (int r = 0; r < rounds; r++) {
        double t0 = cpu_now();
        f(n, buf);
        double dt = cpu_now() - t0;
        if (dt < best) best = dt;
    }
    for (long i = 0; i < 2 * n; i++) sum += buf[i];
    printf("%s %.2f %.10g\n", name, best * 1e9 / (double)n, sum);
}

int main(int argc, char **argv) {
    long n = argc > 1 ? atol(argv[1]) : 1000000;
    int rounds = argc > 2 ? atoi(argv[2]) : 5;
    if (n < 2 || rounds < 1) {
        fprintf(stderr, "usage: equations_c [N >= 2 [ROUNDS >= 1]]\n");
        return 2;
    }
    double *buf = malloc(sizeof *buf * 2 * (size_t)n);
    if (!buf) return 1;
    run("oval", oval, n, rounds, buf);
    run("order6", order6, n, rounds, buf);
    free(buf);
    return 0;
}
