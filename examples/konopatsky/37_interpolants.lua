-- Konopatsky §4.3-4.4 (Figs. 4.1, 4.2): interpolation curves of orders 2 and 3
-- Chosen nodes (the book prints none).  The curve through M1..M(n+1) at t = j/n (green) is the
-- Bezier curve on the control polygon (grey) whose inner points are the book's C = -M1/2 + 2M2 -
-- M3/2 (4.9) and C1, C2 of (4.14)-(4.15) (interp.controls); the nodes in white.
local function mark(p, name, _, c) circle(p, 0.08, c or 15) label(name, p, nil, c or 15) end
local sets = {{P(0, 0), P(4, 5), P(9, 1)}, {P(0, 0), P(2, 4), P(6, 5), P(9, 1)}}
for i, nodes in ipairs(sets) do
  view(5 + (i - 1) * 315, 60, 310 + (i - 1) * 315, 420)
  window(-1.5, -2.5, 10.5, 10.8)
  local ctrl = interp.controls(nodes)
  path(ctrl, {color = 8})
  for j = 2, #ctrl - 1 do mark(ctrl[j], #ctrl == 3 and "C" or "C" .. (j - 1), "n", 7) end
  interp.lagrange(nodes):draw{color = 10}
  for j, p in ipairs(nodes) do mark(p, "$M_" .. j .. "$", j == 1 and "sw" or "se") end
  label(i == 1 and "order 2 (4.10), t = 0, 1/2, 1" or "order 3 (4.16), t = 0, 1/3, 2/3, 1", P(-1.3, -2), "e", 7)
end
