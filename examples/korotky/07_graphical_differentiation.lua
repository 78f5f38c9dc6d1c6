-- Korotky & Vitovtov: the slopes at the pins by graphical differentiation (their ref. [11])
-- The article measured the ruler's tangents tg delta at A..E from its drawing.  Here the
-- drawing is the polynomial spline (7) sampled every 0.01 in x; korotky.graphical_slope fits
-- a parabola to the 7 samples nearest each pin (one-sided at A and E) and gives back the
-- spline's slopes 1.2174, 2.2319, 2.0329, -2.0516, -2.2742 to 1e-3.  Below, the pole
-- construction: the line through the pole p (at distance H left of the axis) parallel to a
-- tangent cuts the axis at H tg delta; carried across to the pin's x it is a point of the
-- derivative curve (grey: the slopes at every sample).  Equal units on both axes.
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local names = {"A", "B", "C", "D", "E"}
local c7 = korotky.poly_spline(pts)
local samples = {}
for i = 0, 430 do samples[#samples + 1] = c7(1.2 + i / 100) end
window(-3.2, -4.0, 9.2, 5.3)                -- 12.4 x 9.3 units: 51.6 px a unit both ways
line(P(-1, 0), P(6.2, 0), 8)
path(samples, {color = 11})
-- the derivative panel: its zero line at y = -2.4, H = 0.6
local y0, H = -2.4, .6
local pole, axis = P(-.9, y0), -.9 + H
line(P(-1, y0), P(6.2, y0), 8)
line(P(axis, y0 - 1.8), P(axis, y0 + 1.8), 8)
local deriv = {}
for x = 1.2, 5.5, .05 do deriv[#deriv + 1] = P(x, y0 + H * korotky.graphical_slope(samples, x)) end
path(deriv, {color = 7})
pset(pole, 15)
label("p", pole)
label("H", P(pole.x + H / 2, y0))
for i, p in ipairs(pts) do
  local m = korotky.graphical_slope(samples, p.x)
  local d = unit(V(1, m)) * .9
  line(p - d, p + d, 14)                            -- the tangent at the pin
  label(string.format("%s %.4f", names[i], m), p)
  local q = P(axis, y0 + H * m)                     -- the pole line meets the axis
  line(pole, q, 7)
  pen{dash = {2, 3}}
  line(q, P(p.x, q.y), 8)
  pen{}
  pset(P(p.x, q.y), 14)
  label(names[i], P(p.x, q.y))
end
label("(7) sampled every 0.01: tg $\\delta$ at the pins by a local parabola", P(-3.1, 5.15), "e", 7)
