-- Korotky & Vitovtov Fig. 1: the original and the affinely compressed ruler with free ends
-- The pins A..E of Table A1 and their images A'..E' under the compression toward the x axis
-- with k = 0.5 (the pins move along the verticals).  Green: the two rulers, each the elastic
-- line through its pins (the curve of least bending energy, free length, unloaded ends),
-- continued beyond A and E by the straight free ends.  Dashed: the measured end tangents
-- (Tables A2, A3: slopes 1.134, 0.567 at A, A' and -2.460, -1.230 at E, E'): each pair meets
-- on the x axis, at x = 0.4063 and 6.3537, as the article observes.  Equal units on both axes.
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local names = {"A", "B", "C", "D", "E"}
local half = map.scale({1, .5})
local low = {}
for i, p in ipairs(pts) do low[i] = half(p) end

window(-.75, -1.2, 7.25, 4.8)                  -- 8 x 6 units on 640 x 480: 80 px a unit
line(P(-.5, 0), P(7, 0), 8)                     -- the axis of the compression
label("x", P(7, 0), "n", 8)
for _, set in ipairs{pts, low} do
  local el = korotky.elastic(set)
  el:draw{color = 10}
  local n = #set - 1                            -- the free ends: straight, along the end tangents
  line(set[1], set[1] - el:tangent(0) * .45, 10)
  line(set[5], set[5] + el:tangent(n) * .45, 10)
end
-- the measured end tangents: slope at A and E, halved for A' and E'
local xA, xE = 1.2 - .9 / 1.134, 5.5 + 2.1 / 2.46
pen{dash = {4, 3}}
for _, k in ipairs{1, .5} do
  line(P(xA, 0), P(1.2, .9 * k), 7)
  line(P(5.5, 2.1 * k), P(xE, 0), 7)
end
pen()
label(string.format("%.4f", xA), P(xA, 0), "s", 7)
label(string.format("%.4f", xE), P(xE, 0), "s", 7)
for i = 1, 5 do
  line(pts[i], low[i], 8)                       -- each pin and its image on one vertical
  circle(pts[i], .04, 15)
  circle(low[i], .04, 15)
  label(names[i], pts[i])
  label("$" .. names[i] .. "'$", low[i])
end
label("ruler ABCDE and its compression A'B'C'D'E' (k = 0.5), free ends", P(-.6, -.85), "e", 7)
