/* Konopatsky's chapter 1 (digest konopatsky_ch1_2.md §4): the moving-simplex surface on three
 * guides (Fig. 1.2), the theorem on triangle areas (1.2) with its corollaries (Figs. 1.3-1.6),
 * the O-theorem (1.4) (Fig. 1.7), the S- and V-theorems as determinants of parameters, and the
 * meet of a line and a plane by the V-theorem (§1.3.5), in 3-D and in n-D; with them the
 * polar (2.117) and rotation (2.138) point functions of §5.0, which use the same notation.
 * Points are Cartesian rows of n doubles (2 <= n <= PC_MAXDIM). */
#ifndef PC_KONOP_CH1_H
#define PC_KONOP_CH1_H

#include "surface.h"
#include "why_call.h"

/* (1.2) k = (1 + l1 l2 l3) / ((1 + l1)(1 + l2)(1 + l3)).  PC_EPOLE when some li = -1 (Bi at
 * infinity), PC_ENONFINITE. */
int pc_k_area_k(double l1, double l2, double l3, double *k);

typedef struct {
    double lambda[3];   /* l1 = (A1A2B1), l2 = (A2A3B2), l3 = (A3A1B3); +inf where Bi = A(i+1) */
    double abc[3];      /* the proof's a = (B1A1A2) = -1/(1 + l1), b, c */
    double k;           /* S_B1B2B3 / S_A1A2A3 = 1 + a + b + c + ab + ac + bc */
    int collinear;      /* corollary 1 (1.3): k = 0, i.e. l1 l2 l3 = -1 (Menelaus) */
} pc_k_areas;

/* The theorem on triangle areas for B1 on line A1A2, B2 on A2A3, B3 on A3A1 (a: A1, A2, A3 and
 * b: B1, B2, B3, 3 rows of n each).  The ratio of signed areas holds in any dimension (the
 * triangles share a plane, the theorem is affine).  The corollaries are its special places:
 * B3 = A3 gives k = ab (corollary 2), B1 = A1 and B3 = A3 give k = -b (corollary 3).
 * PC_ECOLLINEAR for a flat A1A2A3, PC_ENOTCOLLINEAR when a Bi is off its side line (beyond
 * 1e-9 of the triangle's size). */
int pc_k_area_theorem(int n, const double *a, const double *b, pc_k_areas *out);

/* (1.4) The O-theorem for the closed m-gon poly (m rows of n, m >= 3) and the line d1 d2 of its
 * plane: Bi = AiA(i+1) x d, ratios[i] = (AiA(i+1)Bi) (m doubles, may be NULL; -1 where a side
 * is parallel to d, Bi at infinity), *prod their product, which the theorem says is (-1)^m
 * (the print omits the closing factor (A_m A_1 B_m)); bpts (m rows of n + 1, homogeneous, may
 * be NULL) gets the Bi.  PC_EDOMAIN if d passes through a vertex, PC_ESKEW if d or a side is
 * off the polygon's plane, PC_ECOINCIDENT for repeated vertices. */
int pc_k_o_theorem(int n, int m, const double *poly, const double *d1, const double *d2,
                   double *ratios, double *bpts, double *prod);

/* The S- and V-theorems: the ratio of the measures of the simplex of the points with the
 * barycentric parameters rows (k + 1 rows of k + 1, each summing to 1) to the simplex's own is
 * det(rows) (S: k = 2, V: k = 3; the printed V-theorem is det/det of one matrix, = 1).
 * 1 <= k <= 8.  PC_EDOMAIN when a row does not sum to 1 within 1e-12. */
int pc_k_simplex_ratio(int k, const double *rows, double *ratio);
/* konopatsky.simplex_ratio: the same for nr rows of nc numbers, each failure explained by w
 * (why_call.h): no square matrix of 2 to 9 rows (argument 1), then pc_konop_why's row. */
int pc_k_simplex_ratio_rows(int nr, int nc, const double *rows, double *ratio, pc_why_call *w);

/* The meet K of the line A1A2 and the plane P1P2P3 (§1.3.5 with the V-theorem: the volume of
 * the tetrahedron M P1 P2 P3, M = (A2 - A1) lambda + A1, vanishes), in any dimension n >= 3
 * where the line and the plane span at most a 3-flat; out (n + 1, homogeneous) = K, *lambda its
 * parameter on the line, pq (2, may be NULL) its natural parameters in the plane:
 * K = (P1 - P3) p + (P2 - P3) q + P3.  PC_IMPROPER (out the direction A2 - A1, weight 0,
 * *lambda = inf) when the line is parallel to the plane; PC_ESAME_LINE when it lies in it;
 * PC_ESKEW (n > 3) when they do not meet; PC_ECOINCIDENT for A1 = A2; PC_ECOLLINEAR for a
 * flat P1P2P3. */
int pc_k_meet_line_plane(int n, const double *a1, const double *a2, const double *p1,
                         const double *p2, const double *p3, double *out, double *lambda,
                         double *pq);

/* (2.117)/(2.118) The point at distance rho from C at the angle phi from ray CA, turning
 * towards CB: M = (A - C) rho sin(gamma - phi)/(b sin gamma) + (B - C) rho sin phi/(a sin gamma)
 * + C; with rho = b it is (2.138), the rotation of A about C by phi towards B.  Any n.
 * PC_ECOLLINEAR for a flat CAB. */
int pc_k_polar(int n, const double *c, const double *a, const double *b, double rho, double phi,
               double *out);

/* Fig. 1.2, the moving-simplex method: the surface M(u, v) = (NA - NC) p(v) + (NB - NC) q(v)
 * + NC on the three guides NA(u), NB(u), NC(u) (curves of one dimension and one domain; the
 * book's are lines N = (P' - P)(phi(u) - phi(0))/(phi(1) - phi(0)) + P) with the generator
 * given by its natural parameters (p(v), q(v)) as a 2-D curve gen (any curve of the one type:
 * a conic of ch. 2 gives a surface of conic sections).  The surface retains the curves.
 * PC_EDIM for guides of different dimensions or a generator that is not 2-D, PC_EDOMAIN for
 * guides over different domains. */
/* What failed in pc_k_moving_simplex with status st, as text into buf (n bytes) with the
 * curves' dimensions (PC_EDIM) or NA's domain (PC_EDOMAIN); 0 (and nothing written) for
 * another status. */
int pc_k_moving_simplex_why(int st, const pc_curve *na, const pc_curve *nb, const pc_curve *nc,
                            const pc_curve *gen, char *buf, size_t n);
pc_surface *pc_k_moving_simplex(pc_curve *na, pc_curve *nb, pc_curve *nc, pc_curve *gen,
                                int *status);

#endif
