-- The B-spline basis functions of a polygon with a double vertex, k = 3
-- Buimov §4.4: the Cox-de Boor recursion N_i,1 = 1 on [q_i, q_i+1), N_i,k = (t - q_i) N_i,k-1 /
-- (q_i+k-1 - q_i) + (q_i+k - t) N_i+1,k-1 / (q_i+k - q_i+1) (the book prints the second
-- denominator q_i-k - q_i+1), 0/0 = 0, closed at t_max. The polygon P0, P1, P1, P2, P3, P4
-- (P1 doubled) of order 3 has the knots [0 0 0 1 1 2 3 3 3] (the book's "n = 3" is k = 3): the
-- double knot at t = 1 makes N1,3 and N2,3 meet in a corner there. A graph: t and N on
-- different scales (3 units of t across, N from 0 to 1 up).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local pts = {P(0, 0), P(1, 2), P(1, 2), P(3, 1), P(4, 2), P(5, 0)}
local q = buimov.knots(pts, 3)
window(-0.35, -0.25, 3.35, 1.2)
arrow(P(-0.1, 0), P(3.25, 0), "end", 8); arrow(P(0, -0.05), P(0, 1.12), "end", 8)
label("$t$", P(3.25, 0), "s", 8)
for t = 0, 3 do label(tostring(t), P(t, 0), "s", 7) end
local colours = {9, 10, 11, 12, 13, 14}
for i = 0, #pts - 1 do
  graph(function(t) return buimov.basis(i, 3, t, q) end, 0, 3, {color = colours[i + 1], n = 600})
  local peak, at = -1, 0
  for s = 0, 300 do local t = 3 * s / 300
  local v = buimov.basis(i, 3, t, q)
  if v > peak then peak, at = v, t end end
  label("$N_{" .. i .. ",3}$", P(at, peak), nil, colours[i + 1])
end
caption("knots [" .. table.concat(q, " ") .. "]: a double knot at t = 1", "bottom", 7)
