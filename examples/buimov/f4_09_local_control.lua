-- Local control: moving one vertex moves only the part of the B-spline near it
-- Buimov §4.4, Fig. 4.9: seven vertices P0(0, 2), P1(2, 5), P2(5, 4), P3(4, 1), P5(8, 1),
-- P6(10, 4) with P4 in three places (5, 0), (6, 2), (7, 4). The book says order 5 and that the
-- start does not move; with k = 5 it moves a little (N4,5 reaches back to t = 0: P(0.3) is
-- (2.0930, 4.0366), (2.0934, 4.0375), (2.0939, 4.0384)); with k = 4 (knots
-- [0 0 0 0 1 2 3 4 4 4 4]), drawn here, the first span t < 1 is exactly the same for all three:
-- P(0.4) = (2.1333, 4.1280). The red dots mark t = 1, where the three curves part.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local base = {P(0, 2), P(2, 5), P(5, 4), P(4, 1), nil, P(8, 1), P(10, 4)}
fit{around = {P(-0.5, -0.5), P(10.6, 5.6)}, pad = 0.57, band = 20}
local colours = {14, 10, 11}
for j, p4 in ipairs{P(5, 0), P(6, 2), P(7, 4)} do
  base[5] = p4
  local c = buimov.bspline(base, 4)
  c:draw{color = colours[j]}
  dot(p4, "$P_4$", colours[j])
  mark(c(1), "dot", 5, 12)
end
base[5] = P(6, 2)
for i = 1, 6 do line(base[i], base[i + 1], 8) end
for i, p in ipairs(base) do if i ~= 5 then dot(p, "$P_" .. (i - 1) .. "$", 15) end end
local c = buimov.bspline(base, 4)
label(string.format("P(0.4) = (%.4f, %.4f)", c(0.4).x, c(0.4).y), c(0.4), nil, 7)
caption("k = 4: the three curves agree on 0 <= t <= 1 (red: t = 1)", "bottom", 7)
