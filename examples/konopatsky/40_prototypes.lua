-- Konopatsky §4.11 (Fig. 4.8): interpolation curves on other prototypes through the same four nodes
-- Chosen nodes (the book does not give its own) at t = 0, 1/3, 2/3, 1: on the Desargues arc (3.6),
-- i.e. (4.35) (red; the book finds it "most preferable" for such a layout), the cubic
-- interpolant (4.16) (green) and the fractional-rational prototype (4.36), i.e. (4.37) (brown).
local function mark(p, name, _) circle(p, 0.08, 15) label(name, p, nil, 15) end
local M = {P(0, 0), P(1.5, 4), P(6, 5.5), P(9, 1)}
window(-1, -1.5, 10.5, 7.1)
interp.prototype("desargues", M):draw{color = 12}
interp.lagrange(M):draw{color = 10}
interp.prototype("rational", M):draw{color = 6}
for j, p in ipairs(M) do mark(p, "$M_" .. j .. "$", j < 3 and "nw" or "ne") end
label("Desargues (4.35)", P(-0.8, -0.6), "e", 12)
label("cubic (4.16)", P(3.2, -0.6), "e", 10)
label("rational (4.37)", P(6.2, -0.6), "e", 6)
