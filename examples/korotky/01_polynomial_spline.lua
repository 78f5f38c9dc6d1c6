-- Korotky & Vitovtov Fig. 3a: the polynomial spline (7) against the elastic line
-- The pins A..E of Table A1 and their affine compression A'..E' (k = 0.5, toward the x axis).
-- Yellow: the natural cubic spline y = S(x) of (7) and the same for the compressed pins
-- (positions 1', 2'); green: the elastic reference, the curve of least bending energy through
-- the pins (positions 1, 2).  The polynomial bulges well above the ruler on CD: "a
-- substantial difference", which the compression makes smaller.
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local names = {"A", "B", "C", "D", "E"}
local half = map.scale({1, .5})
local low = {}
for i, p in ipairs(pts) do low[i] = half(p) end

window(0, -1, 6.4, 5.4)
line(P(0, 0), P(6.3, 0), 8)                 -- the axis of the compression
label("x", P(6.3, 0), nil, 8)

local poly, coef = korotky.poly_spline(pts)
local poly_c = korotky.poly_spline(low)
local el = korotky.elastic(pts)
local el_c = korotky.elastic(low)
el:draw{color = 10}
el_c:draw{color = 10}
poly:draw{color = 14}
poly_c:draw{color = 14}

for i = 1, 5 do
  circle(pts[i], .04, 15)
  circle(low[i], .04, 15)
  label(names[i], pts[i], nil, 15)
  label(names[i] .. "'", low[i], nil, 7)
  line(pts[i], low[i], 8)                   -- each pin and its image on one vertical
end
label("1'", poly(3.3), nil, 14)
label("1", el(2.5), nil, 10)
label("2'", poly_c(3.3), nil, 14)
label("2", el_c(2.7), nil, 10)
label(string.format("(7): S_CD = 4 %+.4f h %+.4f h^2 %+.4f h^3", coef[3][2], coef[3][3], coef[3][4]),
      P(.1, -.45), "e", 14)
label(string.format("deviation from the elastic line: %.3f (1')  %.3f (2')",
                    korotky.deviation(poly, el), korotky.deviation(poly_c, el_c)), P(.1, -.75), "e", 7)
