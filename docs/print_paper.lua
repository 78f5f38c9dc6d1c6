-- A figure for a paper: the quadratic curve M = A0 bar(t)^2 + 2 A1 t bar(t) + A2 t^2
figure{width = "8cm", height = "5cm", size = 9}
window(-0.3, -0.25, 4.3, 2.6)
local A0, A1, A2 = P(0, 0), P(1.6, 2.2), P(4, 0.3)
pen "thin"   line(A0, A1) line(A1, A2)                          -- the control polygon
pen "hidden" line(A0, A2)                                        -- the chord
pen "main"   bezier{A0, A1, A2}:draw()                           -- the curve
pen()
local t = 0.35
local M = A0 * (1 - t)^2 + A1 * 2 * t * (1 - t) + A2 * t^2
for _, p in ipairs{A0, A1, A2, M} do circle(p, 0.03) end
label("$A_0$", A0, "sw") label("$A_1$", A1, "n") label("$A_2$", A2, "se")
label("$M(t)$, $t = 0.35$", M, "nw")
label("$\\overline{A_0 A_2}$", mid(A0, A2), "s")
label("$M = A_0\\bar{t}^2 + 2A_1 t\\bar{t} + A_2 t^2$", P(2.05, 2.35), "e", {size = 8, halo = false})
