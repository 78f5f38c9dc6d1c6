-- Korotky (2015) Fig. 2d, 2e, 2f: the shell on the contour ABCD for a convex, straight, concave l
-- The contour and its determinant are those of Fig. 2a, 2b (script 11): the frontal conic
-- links AB (y = 4) and DC (y = 0), the lateral waves AD and BC, the conoid (AD, p) and the
-- cylindroid (BC, q).  In each plane y = const the generator is the conic through U0 on AD,
-- V0 on BC and T on the guide l = LL', tangent to the rulings U0 P and V0 Q.  The guide l
-- decides the fullness: bowed up by 0.8 (2d), straight (2e), bowed down to z = 0 at its
-- middle (2f).  In 2f l crosses the chord U0 V0 twice: there T lies on the chord, the weight
-- is 0 and the generators a and c are straight; between them the arcs are concave (w < 0).
-- Perspective, equal units; the shell hides what lies behind it (the scene's hidden lines).
local r3 = math.sqrt(3)
local function wave(x)   -- a lateral link: x fixed, z = 0.3 sin(pi y / 4), as a curve in y
  return curve(function(y) return P(x, y, .3 * math.sin(math.pi * y / 4)) end, 0, 4)
end
local AD, BC = wave(0), wave(6)
local p = bezier{P(1, 0, 1), P(1, 4, r3)}
local q = bezier{P(5, 0, 1), P(5.6, 2, 1.55), P(5, 4, r3)}
local L, L1 = P(3, 4, 3), P(3, 0, 2)
local guides = {
  {name = "2d  l convex", l = bezier{L1, P(3, 2, 4.1), L}},
  {name = "2e  l straight", l = bezier{L1, L}},
  {name = "2f  l concave", l = bezier{L1, P(3, 2, -2.5), L}},
}
-- where the guide's T lies on the chord U0 V0 (the straight generators): z_l(y) = z_AD(y)
local function straight_at(l)
  local f = function(u) return l(u).z - AD(4 * u).z end
  local roots, n = {}, 200
  for i = 0, n - 1 do
    local a, b = i / n, (i + 1) / n
    if f(a) * f(b) < 0 then
      for _ = 1, 50 do local m = (a + b) / 2; if f(a) * f(m) <= 0 then b = m else a = m end end
      roots[#roots + 1] = (a + b) / 2
    end
  end
  return roots
end

local at = {{160, 140}, {480, 140}, {330, 355}}   -- 2d, 2e above, 2f below
local caption_at = {P(20, 30), P(340, 30), P(20, 300)}
for k, g in ipairs(guides) do
  local x0, y0 = at[k][1], at[k][2]
  camera(map.translate(V(x0, y0)) * map.scale({27, -27}) *
         map.perspective(P(-3, -10, 7), P(3, 2, 1)), {hidden = "dashed"})
  local s = korotky.conic_sweep{U = AD, V = BC, T = g.l, P = p, Q = q}
  s:wireframe{nu = 9, nv = 0, color = 11, boundary = true}
  g.l:draw{color = 14}
  label("A", P(0, 4, 0)); label("B", P(6, 4, 0)); label("C", P(6, 0, 0)); label("D", P(0, 0, 0))
  label("l", g.l(.5))
  for i, u in ipairs(straight_at(g.l)) do
    line(AD(4 * u), BC(4 * u), 12)
    label(i == 1 and "a" or "c", AD(4 * u))
  end
  camera(nil)
  label(g.name, caption_at[k], "e", 11)
end
