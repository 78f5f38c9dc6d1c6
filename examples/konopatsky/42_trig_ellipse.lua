-- Konopatsky §4.11 (Fig. 4.12 a, b): the ellipse through three points by the trigonometric prototype (4.40)
-- Chosen nodes M1(0,0), M2(3,3), M3(7,1) at t = 0, pi/2, pi: M = (cos t/2 - sin t/2 + 1/2)M1 +
-- M2 sin t + (-cos t/2 - sin t/2 + 1/2)M3.  (a) t in [0, pi]: the arc through the three points;
-- (b) t in [0, 2 pi]: the whole ellipse, centred at the midpoint of M1M3.
local function mark(p, name, _, c) circle(p, 0.08, c or 15) label(name, p, nil, c or 15) end
local M = {P(0, 0), P(3, 3), P(7, 1)}
for i, t1 in ipairs{math.pi, 2 * math.pi} do
  view(5 + (i - 1) * 315, 60, 310 + (i - 1) * 315, 420)
  window(-2.5, -4.5, 9.5, 5.5)
  interp.prototype("trig", M, 0, t1):draw{color = 10}
  for j, p in ipairs(M) do mark(p, "$M_" .. j .. "$", "n") end
  if i == 2 then mark(mid(M[1], M[3]), "centre", "s", 7) end
  label(i == 1 and "(a) t in [0, pi]" or "(b) t in [0, 2 pi]", P(-2.2, -4), "e", 7)
end
