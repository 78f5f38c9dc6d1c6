-- The clamped cubic spline through four points, by uniform and by chord-length parameters
-- Buimov §4.2: the tridiagonal system of the joints with the given end tangents P'1 and P'n.
-- P = (0, 0), (1, 1), (2, -1), (3, 0), P'1 = P'4 = (1, 1): uniform (t_k = 1, yellow) gives the
-- inner tangents P'2 = P'3 = (1, -0.8) and P(0.5) = (0.5, 0.725) (the book's last right-hand
-- side 3(Pn - Pn-1) corrected to 3(Pn - Pn-2)); chord lengths (t_k = |P_k - P_k-1|, green) give
-- P'2 = P'3 = (0.505431, -0.147724). The end tangents are drawn from the end points, inside the
-- figure.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local pts = {P(0, 0), P(1, 1), P(2, -1), P(3, 0)}
local d = V(1, 1)
fit{around = {P(-0.4, -1.5), P(3.7, 1.7)}, pad = 0.29, band = 20}
for i = 1, #pts - 1 do line(pts[i], pts[i + 1], 8) end
local u, tu = buimov.spline(pts, {ends = "clamped", d0 = d, d1 = d})
local c, tc = buimov.spline(pts, {ends = "clamped", d0 = d, d1 = d, param = "chord"})
u:draw{color = 14}; c:draw{color = 10}
vector(pts[1], d * 0.5, 12); vector(pts[4], d * 0.5, 12)
label("$P'_1$", pts[1] + d * 0.5, nil, 12); label("$P'_n$", pts[4] + d * 0.5, nil, 12)
for i, p in ipairs(pts) do dot(p, "$P_" .. i .. "$", 15) end
caption(string.format("uniform: P'2 = (%g, %g);  chord: P'2 = (%.6f, %.6f)",
  tu[2].x, tu[2].y, tc[2].x, tc[2].y), "bottom", 7)
