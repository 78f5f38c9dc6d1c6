-- Korotky & Vitovtov Figs 2, 3b, 4b, 5b: clamped ends
-- The ruler clamped at A and E (slopes 0.2 and -0.3, the short thick bars).  Green: the elastic
-- reference with those end directions (free length).  Cyan: the clamped polynomial spline (9)
-- (its printed d3 = +0.0171 is a misprint: -0.0171 meets D).  Magenta: Example 2, the Ferguson
-- spline of lambda = 1, 2, 1 (pos. 2) and 1, 3, 1 (pos. 3).  Yellow: Example 4, the authors'
-- substitution (24)-(26) from w_A = w_B(1) = 2, giving (29).
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local names = {"A", "B", "C", "D", "E"}
local tg = {0.2, 5.16, 0.83, -4.36, -0.3}

window(0, -1.1, 6.6, 5.4)
local el = korotky.elastic(pts, {ends = {tg[1], tg[5]}})
local p9, k9 = korotky.poly_spline(pts, {ends = "clamped", s0 = .2, s1 = -.3})
local ex2 = korotky.ferguson_lambda(pts, {TA = .2, TE = -.3, lambda = {1, 2, 1}})
local ex2b = korotky.ferguson_lambda(pts, {TA = .2, TE = -.3, lambda = {1, 3, 1}})
local ex4, z = korotky.ferguson_substitution(pts, tg, 2, 2)
el:draw{color = 10}
p9:draw{color = 11}
ex2:draw{color = 13}
ex2b:draw{color = 5}
ex4:draw{color = 14}

-- the clamps: short thick bars along the end directions
pen{width = 3}
for _, e in ipairs{{pts[1], .2}, {pts[5], -.3}} do
  local t = unit(V(1, e[2]))
  line(e[1] - t * .35, e[1] + t * .05, 7)
end
pen()
for i = 1, 5 do
  circle(pts[i], .04, 15)
  label(names[i], pts[i], nil, 15)
end
label("(9)", p9(3.6), nil, 11)
label("2", ex2(2.3), nil, 13)
label("3", ex2b(2.5), nil, 5)
label("elastic", el(3.4), nil, 10)
label(string.format("(29) %.3f %.3f %.3f %.3f %.3f  w_E = %.3f", z[3], z[4], z[5], z[6], z[7], z[8]),
      P(.1, -.45), "e", 14)
label(string.format("(9) d3 on CD = %.4f; deviation: (29) %.3f  Ex.2 %.3f  (9) %.3f", k9[3][4],
                    korotky.deviation(ex4, el), korotky.deviation(ex2, el), korotky.deviation(p9, el)),
      P(.1, -.8), "e", 7)
