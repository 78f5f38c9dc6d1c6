-- A Bezier polygon and its curve
-- Buimov §4.3, Fig. 4.4: P(t) = sum P_i J_n,i(t), 0 <= t <= 1, through P0 and Pn, tangent there
-- to the polygon: P'(0) = n (P1 - P0), P'(1) = n (Pn - Pn-1). The cubic on (1, 1), (2, 3),
-- (4, 3), (3, 1) (the book gives no points) has P(0.5) = (2.75, 2.5), P'(0) = (3, 6).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local pts = {P(1, 1), P(2, 3), P(4, 3), P(3, 1)}
local b = bezier(pts)
fit{around = {P(-0.3, -0.3), P(4.6, 3.5)}, pad = 0.34, band = 20}
axes{x = {-0.3, 4.6}, y = {-0.3, 3.5}, ticks = 0, labels = false, color = 8}
label("$x$", P(4.6, 0), "s", 8); label("$y$", P(0, 3.5), "w", 8)
polygon(pts)
b:draw{color = 14}
dot(b(0.5), "P(0.5) = (2.75, 2.5)", 14)
vector(pts[1], b:deriv(0) / 6, 12); label("$P'(0)/6$", pts[1] + b:deriv(0) / 6, nil, 12)
caption(string.format("P'(0) = (%g, %g),  P'(1) = (%g, %g)",
  b:deriv(0).x, b:deriv(0).y, b:deriv(1).x, b:deriv(1).y), "bottom", 7)
