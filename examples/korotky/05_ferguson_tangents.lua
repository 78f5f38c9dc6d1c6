-- Korotky & Vitovtov Fig. 5a, 5b: Ferguson splines with the measured tangents
-- 5a (left), free ends: Example 3, the tangent directions measured at every pin (Table A2,
-- -1.8154 at D) and w_A = w_E = 1; the moduli (28) come from Newton's method on system (23)
-- (yellow, the given tangents as short strokes), against the elastic line (green): "less than
-- 0.4 %".  5b (right), clamped ends (slopes 0.2 and -0.3, the bars outside the span): Example 4,
-- the authors' substitution (24)-(26) from w_A = w_B(1) = 2, giving (29), against the elastic
-- line with those end directions and the length 7.70 of Fig. 2: "less than 1.5 %".  Equal units on both axes (60 px a unit).
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
local tg = {1.134, 2.840, 0.985, -1.8154, -2.460}
local el = korotky.elastic(pts)
local ex3, z = korotky.ferguson_tangents(pts, tg)
el:draw{color = 10}
ex3:draw{color = 14}
for i = 1, 5 do
  local t = ex3:tangent(i - 1)
  line(pts[i] - t * .25, pts[i] + t * .25, 15)
end
pins()
label("(28)", ex3(2.4)); label("1", el(2.6))
local d3 = korotky.deviation(ex3, el)

panel(2)
local tc = {0.2, 5.16, 0.83, -4.36, -0.3}
local ec = korotky.elastic(pts, {ends = {.2, -.3}, length = 7.70})
local ex4, z4 = korotky.ferguson_substitution(pts, tc, 2, 2)
ec:draw{color = 10}
ex4:draw{color = 14}
clamps(.2, -.3)
pins()
label("(29)", ex4(2.4)); label("1", ec(3.4))
local d4 = korotky.deviation(ex4, ec)

view(); window()
label("5a  free ends: Example 3, (28)", P(8, 404), "e", 14)
label("5b  clamped ends: Example 4, (29)", P(328, 404), "e", 14)
label(string.format("z = %.4f %.4f %.4f", z[2], z[3], z[4]), P(8, 426), "e", 7)
label(string.format("    %.4f %.4f %.4f", z[5], z[6], z[7]), P(8, 446), "e", 7)
label(string.format("z = %.3f %.3f %.3f %.3f", z4[3], z4[4], z4[5], z4[6]), P(328, 426), "e", 7)
label(string.format("    %.3f, $w_E$ = %.3f", z4[7], z4[8]), P(328, 446), "e", 7)
label(string.format("deviation from 1: %.3f", d3), P(8, 466), "e", 7)
label(string.format("deviation from 1: %.3f", d4), P(328, 466), "e", 7)
