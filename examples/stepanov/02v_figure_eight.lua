-- Example 2 (variant) — Figure-eight: the oval of a self-intersecting quadrilateral
-- The article remarks that if the 3rd and 4th vertices of Example 2 are swapped, two sides
-- of the quadrilateral cross and the inscribed oval turns into a figure-eight (a slender one,
-- crossing itself once, near (243, 205)). Same construction: the bilinear map
-- X = P0 + s1 (P1 - P0) + s2 (P3 - P0) + s1 s2 (P2 - P3 - P1 + P0) (§H block 3) of the circle
-- inscribed in the unit square, s1 = (1 + cos u)/2, s2 = (1 + sin u)/2.
-- The article has no listing or figure for it; the vertices are Example 2's with P2 and P3 swapped.

screen(12)
local P0, P1, P2, P3 = P(100, 100), P(300, 150), P(150, 300), P(280, 200)
line(P0, P1); line(P1, P2); line(P2, P3); line(P3, P0)

local Q = bilinear(P0, P1, P2, P3)
Q:draw(function(t)
  local u = 2*math.pi*t
  return (1 + math.cos(u))/2, (1 + math.sin(u))/2
end, {t = {0, 1, .001}, qb = true})
