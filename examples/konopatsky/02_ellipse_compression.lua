-- Konopatsky §2.1.1.4 (Fig. 2.7): the ellipse as a compressed circle
-- Set E of the digest: C(0,0), A(4,0), B(0,2).  The circle of radius a about C, the point P on
-- it at the angle phi, its foot Q on CA and M on QP with QM/QP = b/a; the ellipse (2.24) in
-- green, the foci F1, F2 and the focal radii of M (|F1M| + |F2M| = 2a).  Circle and ellipse are
-- written as the book's point equations in the parameter f and compiled (docs/equations.md).
local C, A, B = P(0, 0), P(4, 0), P(0, 2)
local a, b = dist(C, A), dist(C, B)
local e = math.sqrt(a * a - b * b) / a
window(-5.5, -4.4, 5.5, 4.4)
line(P(-5, 0), P(5, 0), 8) line(P(0, -4.2), P(0, 4.2), 8)
local f = param "f"
pen{dash = {4, 3}}
curve((A - C)*math.cos(f) + V(0, a)*math.sin(f) + C, 0, 2*math.pi):draw{color = 8}
pen()
local E = (A - C)*math.cos(f) + (B - C)*math.sin(f) + C          -- (2.24)
curve(E, 0, 2*math.pi):draw{color = 10}
label("M = " .. E:show{["(A - C)"] = A - C, ["(B - C)"] = B - C, C = C}, P(-5.3, 3.9), "e", 10)
local phi = 1.0
local Pc = (A - C) * math.cos(phi) + (C + V(0, a) - C) * math.sin(phi) + C
local Q = (A - C) * math.cos(phi) + C
local M = lerp(Q, Pc, b / a)
local F1, F2 = (A - C) * e + C, (C - A) * e + C
line(C, Pc, 7) line(Q, Pc, 7)
line(F1, M, 11) line(F2, M, 11)
for _, p in ipairs{A, B, C, Pc, Q, M, F1, F2} do circle(p, 0.06, 15) end
label("$C$", C, nil, 15) label("$A$", A, nil, 15) label("$B$", B, nil, 15)
label("$P$", Pc, nil, 7) label("$Q$", Q, nil, 7) label("$M$", M, nil, 15)
label("$F_1$", F1, nil, 11) label("$F_2$", F2, nil, 11)
label(string.format("QM/QP = b/a = %.2f   |F1M| + |F2M| = %.4f = 2a", b / a, dist(F1, M) + dist(F2, M)),
      P(-5.3, -3.9), "e", 7)
