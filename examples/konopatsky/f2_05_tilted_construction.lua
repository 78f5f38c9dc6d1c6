-- Konopatsky §2.1.1.1 (Fig. 2.5): the construction of the tilted ellipse
-- The digest's triangle A(0,0), B(4,3), C(5,-1), semi-axes m = 2, n = 1 and theta = pi/4: the
-- major axis CP meets line AB at K with angle AKC = theta (K = CP x AB falls beyond B here, so
-- AB is extended, dashed), tau = angle ACK = pi - alpha - theta; P = (K - C)m/CK + C; A rotated
-- about C by omega = tau + pi/2 towards B (underlined, as the book writes it) gives
-- Q = (A' - C)n/b + C; the ellipse (2.11) in the simplex CPQ (conic.tilted).
local A, B, C, m, n, th = P(0, 0), P(4, 3), P(5, -1), 2, 1, math.pi / 4
local e, Pa, Qa, K, Ar, tau = conic.tilted(A, B, C, th, m, n)
fit{around = {A, B, C, K, Ar, e(0), e(math.pi)}, pad = 0.5}
path({A, B, C, A}, {color = 9})
pen{dash = {4, 3}} line(B, K, 9) line(Pa, K, 7) line(Qa, Ar, 7) pen()
e:draw{color = 15}
line(C, Pa, 10) line(C, Qa, 10)
path({A, C, Ar}, {color = 8})
angle_mark(A, K, C, "$\\theta$", 36, 14)
angle_mark(A, C, K, "$\\tau$", 30, 11)
for _, p in ipairs{A, B, C} do mark(p, "dot", 5, 9) end
for _, p in ipairs{Pa, Qa} do mark(p, "dot", 5, 10) end
mark(K, "dot", 5, 14) mark(Ar, "dot", 5, 7)
label("$A$", A, nil, 9) label("$B$", B, nil, 9) label("$C$", C, nil, 9)
label("$P$", Pa, nil, 10) label("$Q$", Qa, nil, 10) label("$K$", K, nil, 14)
label("$\\underline{A}$", Ar, nil, 7)
label("$m$", lerp(C, Pa, 0.5), nil, 10) label("$n$", lerp(C, Qa, 0.5), nil, 10)
caption(string.format("theta = pi/4,  tau = %.4f,  |CP| = %g,  |CQ| = %g", tau, dist(C, Pa), dist(C, Qa)), "bottom", 7)
