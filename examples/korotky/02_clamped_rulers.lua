-- Korotky & Vitovtov Fig. 2: the original and the affinely compressed ruler with clamped ends
-- The pins A..E of Table A1 and their images A'..E' (k = 0.5 toward the x axis).  The ruler
-- is clamped at A and E: the thick bars are the clamps, outside the span as the article draws
-- them, along the clamp directions (Tables A4, A5: slopes 0.2 and -0.3, halved to 0.1 and
-- -0.15 for the compressed ruler).  Green: each ruler as the elastic line through its pins
-- with those end directions and a fixed length between the clamps, which the article does
-- not give: 7.70 and 5.51, the lengths whose slopes at B, C, D come nearest the measured ones
-- (within 1.1 and 1.3 degrees; with the length left free up to 5 degrees off).  Equal units.
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local names = {"A", "B", "C", "D", "E"}
local half = map.scale({1, .5})
local low = {}
for i, p in ipairs(pts) do low[i] = half(p) end

window(-.25, -1.2, 7.75, 4.8)                  -- 8 x 6 units on 640 x 480: 80 px a unit
line(P(0, 0), P(7.5, 0), 8)                     -- the axis of the compression
label("x", P(7.5, 0), "n", 8)
for k, set in ipairs{pts, low} do
  local sA, sE = .2 * (k == 1 and 1 or .5), -.3 * (k == 1 and 1 or .5)
  korotky.elastic(set, {ends = {sA, sE}, length = k == 1 and 7.70 or 5.51}):draw{color = 10}
  -- the clamps: thick bars from the end pin outwards, along the clamp direction
  local tA, tE = unit(V(1, sA)), unit(V(1, sE))
  pen{width = 4}
  line(set[1] - tA * .6, set[1], 7)
  line(set[5], set[5] + tE * .6, 7)
  pen()
end
for i = 1, 5 do
  line(pts[i], low[i], 8)                       -- each pin and its image on one vertical
  circle(pts[i], .04, 15)
  circle(low[i], .04, 15)
  label(names[i], pts[i])
  label("$" .. names[i] .. "'$", low[i])
end
label("ruler ABCDE and its compression A'B'C'D'E' (k = 0.5), clamped ends", P(-.1, -.85), "e", 7)
