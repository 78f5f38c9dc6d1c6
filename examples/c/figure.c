/* A figure drawn with libpointcalc from C (docs/c-api.md):
 *   cc figure.c $(pkg-config --cflags --libs pointcalc) -o figure && ./figure oval.png
 * Stepanov's example 2 (an oval inscribed in a quadrilateral: M and N run along two opposite
 * sides, the oval's point along MN), the quadrilateral's diagonals with their meet, and a cubic
 * Bezier curve drawn as one path. The format follows the extension: .png, .svg or .ppm. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <pointcalc.h>

static int check(int status, const char *what) {
    if (status != PC_OK && status != PC_IMPROPER) {
        fprintf(stderr, "figure: %s: %s\n", what, pc_strerror(status));
        exit(1);
    }
    return status;
}

int main(int argc, char **argv) {
    const char *out = argc > 1 ? argv[1] : "figure.png";
    pc_canvas *c = pc_canvas_new_mode(12);   /* QBasic's SCREEN 12: 640x480, 16 colours */
    if (!c) return 1;

    /* the quadrilateral ABCD, as homogeneous points (x, y | 1) */
    double A[3] = {100, 100, 1}, B[3] = {300, 150, 1}, C[3] = {280, 200, 1}, D[3] = {150, 300, 1};
    const double *q[4] = {A, B, C, D};
    for (int i = 0; i < 4; i++)
        check(pc_line(c, q[i][0], q[i][1], q[(i + 1) % 4][0], q[(i + 1) % 4][1], 15), "line");

    /* the oval: M = lerp(A, B, s), N = lerp(D, C, s), the point lerp(M, N, r) */
    for (int k = 0; k <= 1000; k++) {
        double u = 2 * M_PI * k / 1000.0, s = (1 + cos(u)) / 2, r = (1 + sin(u)) / 2;
        double M[3], N[3], X[3];
        pc_lerp(2, A, B, s, M);
        pc_lerp(2, D, C, s, N);
        pc_lerp(2, M, N, r, X);
        check(pc_pset(c, X[0], X[1], 14), "pset");
    }

    /* the diagonals AC and BD and their meet K */
    double K[2], lambda;
    check(pc_meet(2, A, C, B, D, K, &lambda, NULL, NULL), "meet");
    check(pc_line(c, A[0], A[1], C[0], C[1], 8), "line");
    check(pc_line(c, B[0], B[1], D[0], D[1], 8), "line");
    check(pc_circle(c, K[0], K[1], 4, 12, NAN, NAN, NAN), "circle");
    check(pc_text(c, K[0], K[1], "K", PC_ANCHOR_NE, 6, 1, 12), "text");
    printf("K = (%.4f, %.4f), lambda = %.4f\n", K[0], K[1], lambda);

    /* a cubic Bezier curve, flattened to 1/4 pixel and drawn as one path */
    double cp[4 * 3] = {360, 400, 1, 420, 120, 1, 560, 120, 1, 600, 400, 1};
    int status = PC_OK;
    pc_curve *bz = pc_curve_bezier(2, 4, cp, &status);
    if (!bz) check(status, "bezier");
    pc_polyline pl = {0};
    check(pc_curve_flatten(bz, 0, 1, NULL, NULL, 0.25, &pl), "flatten");
    check(pc_path(c, pl.n, pl.xy, NULL, 0, 0, 11), "path");
    printf("Bezier: %zu vertices\n", pl.n);
    pc_polyline_free(&pl);
    pc_curve_release(bz);

    char err[256];
    if (pc_write_file(c, out, PC_THEME_SCREEN, err, sizeof err) != PC_OK) {
        fprintf(stderr, "figure: %s\n", err);
        pc_canvas_free(c);
        return 1;
    }
    pc_canvas_free(c);
    return 0;
}
