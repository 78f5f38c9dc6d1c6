-- Korotky & Vitovtov Figs 1, 4a, 5a: Ferguson splines with free ends against the elastic line
-- Green: the elastic reference through the pins A..E.  Magenta: Example 1, the Ferguson spline
-- of fixed ratios lambda = 1, 2, 0.5 (system (22)).  Yellow: Example 3, the Ferguson spline with
-- the measured tangents at every pin, its moduli (28) found by Newton's method on (23).
-- Dashed: the end tangents of the ruler (slopes 1.134 and -2.460), which meet the x axis
-- where those of the compressed ruler do (Fig. 1).
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local names = {"A", "B", "C", "D", "E"}
local tg = {1.134, 2.840, 0.985, -1.8154, -2.460}   -- Example 3 (Table A2 prints -1.815 at D)

window(0, -1.1, 6.6, 5)
line(P(0, 0), P(6.5, 0), 8)
local el = korotky.elastic(pts)
local ex1 = korotky.ferguson_lambda(pts, {TA = tg[1], TE = tg[5], lambda = {1, 2, .5}})
local ex3, z = korotky.ferguson_tangents(pts, tg)
el:draw{color = 10}
ex1:draw{color = 13}
ex3:draw{color = 14}

-- the end tangents meet the axis at x = 0.4063 and 6.3537
pen{dash = {4, 3}}
local xA, xE = 1.2 - .9 / 1.134, 5.5 + 2.1 / 2.46
line(P(xA, 0), pts[1], 7)
line(pts[5], P(xE, 0), 7)
line(P(xA, 0), P(1.2, .45), 7)
line(P(5.5, 1.05), P(xE, 0), 7)
pen()
label(string.format("%.4f", xA), P(xA, 0), "s", 7)
label(string.format("%.4f", xE), P(xE, 0), "sw", 7)

for i = 1, 5 do
  circle(pts[i], .04, 15)
  label(names[i], pts[i], nil, 15)
  local t = ex3:tangent(i - 1)               -- the given tangent at each pin, short
  line(pts[i] - t * .25, pts[i] + t * .25, 14)
end
label("elastic", el(2.55), nil, 10)
label("Ex.1", ex1(2.3), nil, 13)
label(string.format("(28) z = %.4f %.4f %.4f %.4f %.4f %.4f", z[2], z[3], z[4], z[5], z[6], z[7]),
      P(.1, -.5), "e", 14)
label(string.format("deviation: Ex.3 %.3f   Ex.1 %.3f", korotky.deviation(ex3, el),
                    korotky.deviation(ex1, el)), P(.1, -.85), "e", 7)
