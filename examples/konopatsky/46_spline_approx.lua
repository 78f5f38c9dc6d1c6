-- Konopatsky §5.3 (Fig. 5.8, the second "Fig. 5.7" of the print): approximation of a C4 spline
-- The data nodes A1(0,0), A2(20,0), A3(45,-47), A4(55,335), A5(57,26), A6(62,387) (white) and
-- the book's printed result x = -320.19785 t(t - 1.383019)(t^2 - 0.05275t + 0.34039)(t^2 - 1.83595t + 1.22856),
-- y = -450355.86111 t(t - 0.14499)(t - 0.51387)(t - 1.11087)(t^2 - 1.72689t + 0.74554) (green),
-- redrawn from its equations (the spline's end conditions are not given).  Its optimal nodes
-- (red) are its points at t = j/6: an order-6 curve through 7 nodes, not the order-5 (4.25) the
-- text names (digest erratum); interp.lagrange through them gives the same curve (dashed).
local function xs(t) return -320.19785 * t * (t - 1.383019) * (t * t - 0.05275 * t + 0.34039) * (t * t - 1.83595 * t + 1.22856) end
local function ys(t) return -450355.86111 * t * (t - 0.14499) * (t - 0.51387) * (t - 1.11087) * (t * t - 1.72689 * t + 0.74554) end
window(-8, -1450, 72, 950)
line(P(-5, 0), P(70, 0), 8) line(P(0, -1300), P(0, 650), 8)
local printed = curve(function(t) return P(xs(t), ys(t)) end, 0, 1)
printed:draw{color = 10}
local nodes = {}
for j = 0, 6 do nodes[j + 1] = P(xs(j / 6), ys(j / 6)) end
pen{dash = {4, 3}} interp.lagrange(nodes):draw{color = 14} pen()
for _, p in ipairs(nodes) do circle(p, 0.6, 12) end
local data = {P(0, 0), P(20, 0), P(45, -47), P(55, 335), P(57, 26), P(62, 387)}
for i, p in ipairs(data) do circle(p, 0.8, 15) label("$A_" .. i .. "$", p, nil, 15) end
label("printed x(t), y(t) green; t = j/6 nodes red; order-6 curve through them dashed", P(-7, -1390), "e", 7)
