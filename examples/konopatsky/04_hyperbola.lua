-- Konopatsky §2.1.2 (Figs. 2.10, 2.12): the hyperbola in simplex CAB and its focal parametrisation
-- Set H: C(0,0), A(3,0), B(0,2).  The fundamental rectangle, the asymptotes (dashed), the foci;
-- (2.56) drawn by the focal angle at F1: the branch through A (green, phi in the corrected range)
-- and the other branch (yellow, the book's printed range).  Both run through their points at
-- infinity, where the path breaks instead of crossing the plane.
local C, A, B = P(0, 0), P(3, 0), P(0, 2)
local c = math.sqrt(13)
window(-9, -6, 9, 6)
line(P(-8.5, 0), P(8.5, 0), 8) line(P(0, -5.8), P(0, 5.8), 8)
path({P(3, 2), P(-3, 2), P(-3, -2), P(3, -2), P(3, 2)}, {color = 8})
pen{dash = {4, 3}}
line(P(-9, -6), P(9, 6), 7) line(P(-9, 6), P(9, -6), 7)
pen()
local H = {C = C, A = A, B = B, by = "focal"}
conic.hyperbola(H):draw{color = 10}
H.branch = 2
conic.hyperbola(H):draw{color = 14}
local F1, F2 = P(c, 0), P(-c, 0)
for _, p in ipairs{A, B, C, F1, F2} do circle(p, 0.08, 15) end
label("C", C, nil, 15) label("A", A, nil, 15) label("B", B, nil, 15)
label("F1", F1, nil, 11) label("F2", F2, nil, 11)
