/* The points of the monograph's ruler schemes, not only their parameters (digest
 * konopatsky_ch1_2.md §5.4, §5.6): every point is a homogeneous row of dim + 1 (weight 0 for a
 * point at infinity), built by the scheme's own meets, so a figure can draw and label each. */
#ifndef PC_KONOP_SCHEMES_H
#define PC_KONOP_SCHEMES_H

/* §2.1.6, Fig. 2.21, the engineering discriminant at u: T1 the chord's midpoint, K = (T1 - C)k
 * + C the shoulder point, T = A u' + B u, N its harmonic conjugate on AB (at infinity at
 * u = 1/2), P = AK x CT, Q = BK x CT and M = AQ x BP, which is (2.97) at u.  Rows in that
 * order: T1, K, T, N, P, Q, M.  PC_ECOLLINEAR for a flat ABC, PC_EDOMAIN for k = 0 (the arc
 * collapses to C) or where a meet of the scheme is undefined (u = 0 or 1: T = A or B, or
 * lines that coincide). */
enum { PC_ED_T1, PC_ED_K, PC_ED_T, PC_ED_N, PC_ED_P, PC_ED_Q, PC_ED_M, PC_ED_NPTS };
int pc_conic_ed_scheme(int dim, const double *a, const double *b, const double *c, double k,
                       double u, double *out);

/* §2.1.4, Fig. 2.15, Pascal's hexagon A D M E B C at u: S = BE x AD, U = (A - C)u + C,
 * V = SU x CB, M = UE x VD, and the special points U_B = BE x CA, U_D = CA x ED, R = CB x ED,
 * U_E = RS x CA, which fix the u of B, D, E.  Rows: S, U, V, M, U_B, U_D, R, U_E.  PC_ECOLLINEAR
 * for a flat ABC, PC_EDOMAIN when a meet of the scheme is undefined at this u (lines that
 * coincide: u at a given point's own special value, or four points collinear). */
enum { PC_P5_S, PC_P5_U, PC_P5_V, PC_P5_M, PC_P5_UB, PC_P5_UD, PC_P5_R, PC_P5_UE, PC_P5_NPTS };
int pc_conic_five_scheme(int dim, const double *a, const double *b, const double *c,
                         const double *d, const double *e, double u, double *out);

/* §3.6 the chain of M_n (Figs. 3.9, 3.10) at t: P_1..P_n on AC with P_0 = A, P_(n+1) = C and
 * P_i = P_(i-1) + t (P_(i+1) - P_(i-1)); Q_1..Q_n likewise on CB (Q_0 = C, Q_(n+1) = B); and
 * M = P_n + t (Q_1 - P_n), the point of oneratio.smooth's arc (digest konopatsky_ch3_5.md §1.6:
 * for n = 2, AP1/AP2 = P1P2/P1C = CQ1/CQ2 = Q1Q2/Q1B = P2M/P2Q1 = t).  p, q: n rows of dim
 * each, m: dim.  1 <= n <= 40.  PC_ECOLLINEAR for a flat ABC. */
int pc_oneratio_smooth_chain(int dim, const double *a, const double *b, const double *c, int n,
                             double t, double *p, double *q, double *m);

/* §2.6 the parameters u the cubic of two cones (conic.cones) must avoid, sorted into u (at most
 * 5), their count in *n: (2.148)'s pole u = f_Q f_P'/(f_Q f_P' - f_P f_Q'), where A, P, Q
 * cannot be collinear; (2.151) u = (1 +- 1/sqrt(1 - 2 f_P))/2 (the print's "-1/2(...)" corrected:
 * the roots sum to 1), where the ED denominator of P vanishes (f_P < 1/2); (2.153) the roots of
 * Q's denominator f_Q^2 f_P'^2 u'^2 + f_P^2 f_Q'^2 u^2 + 2 (f_P - f_P^2) f_Q'^2 u u' (real for
 * f_Q <= 1/2).  PC_ENONFINITE for NaN/inf. */
int pc_cones_excluded(double fp, double fq, double *u, int *n);

/* The foci F1, F2, the eccentricity e and the focal parameter p of the ellipse of centre C with
 * the semi-axes CA, CB (the major one carries the foci: F = C +- c (A - C)/a, c^2 = a^2 - b^2), or
 * (hyperbola != 0) of the hyperbola of centre C, vertex A and imaginary semi-axis CB
 * (c^2 = a^2 + b^2, the foci on CA), in any dimension (the plane CAB).  p = b^2/a.  F1 is on
 * the side of A (of B when CB is the major axis).  PC_EDOMAIN unless CA and CB are perpendicular
 * (within 1e-9: conjugate semi-diameters are not axes), PC_ECOLLINEAR for a zero semi-axis. */
int pc_conic_foci(int dim, const double *c, const double *a, const double *b, int hyperbola,
                  double *f1, double *f2, double *e, double *p);

/* (2.105) Ceva's arc read by the engineering discriminant (§2.1.7): at t the point
 * M3 = A1 (1 - t3) + A2 t3 on A1A2 and M = M3 (1 - r) + A3 r on the median-like line A3M3, with
 * t3 = (1 - t)^2/(k t^2 + (1 - t)^2) and r = t(1 - t)/(1 - t(1 - k t)); M is (2.104) at t.
 * out: M3 then M (2 rows of dim), *t3 and *r.  PC_ECOLLINEAR for a flat A1A2A3, PC_EPOLE where
 * a denominator vanishes (a point at infinity of a hyperbola), PC_EDOMAIN for k = 0. */
int pc_conic_ceva_scheme(int dim, const double *a1, const double *a2, const double *a3, double k,
                         double t, double *out, double *t3, double *r);

/* The focal-simplex forms (2.17) and (2.55), corrected (digest §5.1, §5.2): the point at the
 * focal angle phi of the ellipse of centre C and semi-axes CA, CB (F = F2 = C - (A - C) e, phi
 * from F2 towards A) or of the hyperbola of vertex A and imaginary semi-axis CB (F = F1 = C +
 * (A - C) e), written in the simplex A B F: M = (A - F) pa + (B - F) pb + F with
 *   ellipse:   pa = b(b cos phi - c sin phi)/(a(1 - e cos phi)(a + c)),
 *   hyperbola: pa = b(b cos phi + c sin phi)/(a(1 - e cos phi)(a - c))  (the print: - c sin, c - a),
 *   pb = b sin phi/(a(1 - e cos phi)); the same points as (2.18), (2.56).  out: M then F (2 rows
 * of dim), pab: pa, pb.  Unless CA, CB are perpendicular (and a > b for the ellipse: the foci
 * on CA) PC_EDOMAIN for the hyperbola, PC_EDOMAIN2 for the ellipse; PC_EPOLE where
 * 1 - e cos phi = 0 (an asymptote's direction). */
int pc_conic_focal_point(int dim, const double *c, const double *a, const double *b,
                         int hyperbola, double phi, double *out, double pab[2]);

#endif
