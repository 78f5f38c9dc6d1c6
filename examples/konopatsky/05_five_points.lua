-- Konopatsky §2.1.4 (Fig. 2.15): the conic through five points by Pascal's hexagon A D M E B C
-- Natural coordinates p_D = .3, q_D = .8, p_E = .7, q_E = .6 (C(0,0), A(1,0), B(0,1)).  The
-- corrected S = BE x AD, the current U on CA, V = SU x CB and M = UE x VD at u = 0.6
-- (conic.five_scheme); the special points on CA that give each point's u: U_B = BE x CA,
-- U_D = CA x ED, R = CB x ED and U_E = RS x CA.  The whole conic (green, a hyperbola through
-- its points at infinity) passes through all five points.  The book's printed S (red) is the
-- meet with the parallel to CB through E, so its curve (2.74) misses B.
local A, B, C, D, E = P(1, 0), P(0, 1), P(0, 0), P(0.3, 0.8), P(0.7, 0.6)
local s = conic.five_scheme(A, B, C, D, E, 0.6)
local conic5, u = conic.five_points(A, B, C, D, E, {whole = true})
fit{around = {C, s.U_E, s.V, A, B}, pad = 0.15}
line(C, s.U_E + V(0.1, 0), 8) line(C, s.V + V(0, 0.1), 8)
line(A, B, 8)
conic5:draw{color = 10}
pen{dash = {3, 2}}
line(s.S, s.U_B, 7) line(A, s.S, 7) line(s.S, s.V, 7) line(s.U, E, 7) line(s.V, s.M, 7)
line(s.R, s.U_D, 9) line(s.R, s.U_E, 9)
pen()
local Sbook = P(0.7, 0.8 * (0.7 - 1) / (0.3 - 1))
mark(Sbook, "dot", 5, 12) label("$S$ (printed)", Sbook, nil, 12)
for _, p in ipairs{A, B, C, D, E} do mark(p, "dot", 5, 15) end
for _, p in ipairs{s.S, s.U, s.V} do mark(p, "dot", 5, 11) end
for _, p in ipairs{s.U_B, s.U_D, s.R, s.U_E} do mark(p, "dot", 5, 9) end
mark(s.M, "dot", 6, 14)
label("$A$", A) label("$B$", B) label("$C$", C) label("$D$", D) label("$E$", E)
label("$S$", s.S, nil, 11) label("$U$", s.U, nil, 11) label("$V$", s.V, nil, 11)
label("$U_B$", s.U_B, nil, 9) label("$U_D$", s.U_D, nil, 9) label("$R$", s.R, nil, 9)
label("$U_E$", s.U_E, nil, 9) label("$M$", s.M, nil, 14)
caption(string.format("u: A 1, B %.2f, C 0, D %.2f, E %.4f", u.B, u.D, u.E), "bottom", 7)
