-- Korotky & Vitovtov Fig. 3a, 3b: the polynomial splines (7) and (9) against the elastic line
-- The pins A..E of Table A1 and their affine compression A'..E' (k = 0.5, toward the x axis).
-- 3a (left), free ends: yellow, the natural cubic spline y = S(x) of (7) and the same for the
-- compressed pins (positions 1', 2'); green, the elastic reference, the curve of least bending
-- energy through the pins (positions 1, 2).  The polynomial bulges well above the ruler on CD:
-- "a substantial difference", which the compression makes smaller.  3b (right), clamped ends:
-- the clamped spline (9) (its printed d3 = +0.0171 is a misprint: -0.0171 meets D) with end
-- slopes 0.2 and -0.3, and the compressed (9) with 0.1 and -0.15, against the elastic lines
-- with those end directions and the fixed lengths 7.70 and 5.51 of Fig. 2 (script 02).
-- Equal units on both axes (60 px a unit).
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local names = {"A", "B", "C", "D", "E"}
local half = map.scale({1, .5})
local low = {}
for i, p in ipairs(pts) do low[i] = half(p) end

local function panel(k)                 -- 320 x 400 px, world units equal
  view(k == 1 and 0 or 320, 0, k == 1 and 319 or 639, 399)
  window(.6, -.8, .6 + 320 / 60, -.8 + 400 / 60)
  line(P(.7, 0), P(5.8, 0), 8)          -- the axis of the compression
end
local function pins()
  for i = 1, 5 do
    line(pts[i], low[i], 8)             -- each pin and its image on one vertical
    circle(pts[i], .04, 15)
    circle(low[i], .04, 15)
    label(names[i], pts[i])
    label("$" .. names[i] .. "'$", low[i])
  end
end

-- 3a: free ends
panel(1)
local poly, coef = korotky.poly_spline(pts)
local poly_c = korotky.poly_spline(low)
local el, el_c = korotky.elastic(pts), korotky.elastic(low)
el:draw{color = 10}; el_c:draw{color = 10}
poly:draw{color = 14}; poly_c:draw{color = 14}
pins()
label("1'", poly(3.4)); label("1", el(2.5))
label("2'", poly_c(4.1)); label("2", el_c(2.7))
local dev_a = {korotky.deviation(poly, el), korotky.deviation(poly_c, el_c)}

-- 3b: clamped ends
panel(2)
local p9, k9 = korotky.poly_spline(pts, {ends = "clamped", s0 = .2, s1 = -.3})
local p9_c = korotky.poly_spline(low, {ends = "clamped", s0 = .1, s1 = -.15})
local e9, e9_c = korotky.elastic(pts, {ends = {.2, -.3}, length = 7.70}), korotky.elastic(low, {ends = {.1, -.15}, length = 5.51})
e9:draw{color = 10}; e9_c:draw{color = 10}
p9:draw{color = 11}; p9_c:draw{color = 11}
pins()
label("(9)", p9(3.6)); label("(9)'", p9_c(4.2))
local dev_b = {korotky.deviation(p9, e9), korotky.deviation(p9_c, e9_c)}

view(); window()
label("3a  free ends: (7)", P(8, 400), "e", 14)
label("3b  clamped ends: (9)", P(328, 400), "e", 11)
label(string.format("(7) CD: b, c, d = %.4f %.4f %.4f", coef[3][2], coef[3][3], coef[3][4]),
      P(8, 424), "e", 7)
label(string.format("(9) CD: d3 = %.4f, not +0.0171", k9[3][4]), P(328, 424), "e", 7)
label(string.format("deviation: %.3f (1'), %.3f (2')", dev_a[1], dev_a[2]), P(8, 448), "e", 7)
label(string.format("deviation: %.3f, %.3f (compressed)", dev_b[1], dev_b[2]), P(328, 448), "e", 7)
