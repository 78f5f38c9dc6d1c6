-- Konopatsky §2.1.4 (Fig. 2.15): the conic through five points by Pascal's hexagon A D M E B C
-- Natural coordinates p_D = .3, q_D = .8, p_E = .7, q_E = .6.  The corrected S = BE x AD, the
-- current U on CA, V = SU x CB and M = UE x VD at u = 0.6; the whole conic (green, a hyperbola
-- through its points at infinity) passes through all five points.  The book's printed S
-- (red) is the meet with the parallel to CB through E, so its curve (2.74) misses B.
local A, B, C, D, E = P(1, 0), P(0, 1), P(0, 0), P(0.3, 0.8), P(0.7, 0.6)
window(-0.8, -0.5, 2.0, 1.6)
path({A, B, C, A}, {color = 8})
local conic5, u = conic.five_points(A, B, C, D, E, {whole = true})
conic5:draw{color = 10}
local S = meet(B, E, A, D)
local U = lerp(C, A, 0.6)
local Vp = meet(S, U, C, B)
local M = meet(U, E, Vp, D)
pen{dash = {3, 2}}
line(B, S, 7) line(A, S, 7) line(S, Vp, 7) line(U, E, 7) line(Vp, D, 7)
pen()
local Sbook = P(0.7, 0.8 * (0.7 - 1) / (0.3 - 1))
circle(Sbook, 0.012, 12) label("S (printed)", Sbook, "e", 12)
for name, p in pairs{A = A, B = B, C = C, D = D, E = E, S = S, U = U, V = Vp, M = M} do
  circle(p, 0.012, 15)
end
label("A", A, nil, 15) label("B", B, nil, 15) label("C", C, nil, 15) label("D", D, nil, 15)
label("E", E, nil, 15) label("S", S, nil, 15) label("U", U, nil, 15) label("V", Vp, nil, 15)
label("M", M, nil, 15)
label(string.format("u: A 1, B %.2f, C 0, D %.2f, E %.4f", u.B, u.D, u.E), P(-0.75, -0.4), "e", 7)
