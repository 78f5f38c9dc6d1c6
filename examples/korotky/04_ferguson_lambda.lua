-- Korotky & Vitovtov Fig. 4a, 4b: Ferguson splines of fixed ratios lambda (system (22))
-- 4a (left), free ends: Example 1, lambda = 1, 2, 0.5 at B, C, D, w_A = w_E = 1, the end
-- directions the measured slopes 1.134 and -2.460 (magenta), against the elastic line (green):
-- "the error reaches 4 %".  4b (right), clamped ends (slopes 0.2 and -0.3, the bars): Example 2,
-- lambda = 1, 2, 1 (position 2, magenta) and 1, 3, 1 (position 3, red), against the elastic
-- line with those end directions and the length 7.70 of Fig. 2: "more than 10 %".  Five controls to tune by trial, so the
-- authors do not recommend it.  Equal units on both axes (60 px a unit).
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local names = {"A", "B", "C", "D", "E"}

local function panel(k)                 -- 320 x 400 px, world units equal
  view(k == 1 and 0 or 320, 0, k == 1 and 319 or 639, 399)
  window(.6, -.8, .6 + 320 / 60, -.8 + 400 / 60)
  line(P(.7, 0), P(5.8, 0), 8)
end
local function pins()
  for i = 1, 5 do
    circle(pts[i], .04, 15)
    label(names[i], pts[i])
  end
end
local function clamps(sA, sE)         -- thick bars outside the span, along the clamp directions
  pen{width = 4}
  line(pts[1] - unit(V(1, sA)) * .35, pts[1], 7)
  line(pts[5], pts[5] + unit(V(1, sE)) * .35, 7)
  pen()
end

panel(1)
local el = korotky.elastic(pts)
local ex1 = korotky.ferguson_lambda(pts, {TA = 1.134, TE = -2.460, lambda = {1, 2, .5}})
el:draw{color = 10}
ex1:draw{color = 13}
pins()
label("Ex. 1", ex1(2.3)); label("1", el(2.6))
local d1 = korotky.deviation(ex1, el)

panel(2)
local ec = korotky.elastic(pts, {ends = {.2, -.3}, length = 7.70})
local ex2 = korotky.ferguson_lambda(pts, {TA = .2, TE = -.3, lambda = {1, 2, 1}})
local ex2b = korotky.ferguson_lambda(pts, {TA = .2, TE = -.3, lambda = {1, 3, 1}})
ec:draw{color = 10}
ex2:draw{color = 13}
ex2b:draw{color = 12}
clamps(.2, -.3)
pins()
label("2", ex2(2.3)); label("3", ex2b(2.5)); label("1", ec(3.4))
local d2, d3 = korotky.deviation(ex2, ec), korotky.deviation(ex2b, ec)

view(); window()
label("4a  free ends: Example 1", P(8, 404), "e", 13)
label("4b  clamped ends: Example 2", P(328, 404), "e", 13)
label(string.format("deviation from 1: %.3f", d1), P(8, 430), "e", 7)
label(string.format("deviation: %.3f (2), %.3f (3)", d2, d3), P(328, 430), "e", 7)
