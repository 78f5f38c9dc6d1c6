-- Konopatsky §4.4 (Fig. 4.2): the interpolation curve of order 3
-- Chosen nodes (the book prints none): the curve through M1..M4 at t = 0, 1/3, 2/3, 1 (green)
-- is the cubic Bezier curve on the control polygon (grey) whose inner points are C1, C2 of
-- (4.14)-(4.15) (interp.controls); the nodes in white, x(t) and y(t) at the top.
local function mark(p, name, _, c) circle(p, 0.08, c or 15) label(name, p, nil, c or 15) end
local sets = {{P(0, 0), P(4, 5), P(9, 1)}, {P(0, 0), P(2, 4), P(6, 5), P(9, 1)}}
for i, nodes in pairs{[2] = sets[2]} do
  fit{around = {P(-1.5, -2.5), P(10.5, 10.8)}}
  local ctrl = interp.controls(nodes)
  path(ctrl, {color = 8})
  for j = 2, #ctrl - 1 do mark(ctrl[j], #ctrl == 3 and "$C$" or "$C_" .. (j - 1) .. "$", "n", 7) end
  local c = interp.lagrange(nodes)
  c:draw{color = 10}
  local ex, ey = konopatsky.equation(c)          -- the curve's x(t), y(t) as ch. 4 prints them
  text{x = 8, y = 14, text = ex, units = "device", color = 10}
  text{x = 8, y = 32, text = ey, units = "device", color = 10}
  for j, p in ipairs(nodes) do mark(p, "$M_" .. j .. "$", j == 1 and "sw" or "se") end
  label(i == 1 and "order 2 (4.10), t = 0, 1/2, 1" or "order 3 (4.16), t = 0, 1/3, 2/3, 1", P(-1.3, -2), "e", 7)
end
