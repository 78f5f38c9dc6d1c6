-- Korotky (2015) Fig. 1c: a fragment of the bow planking by the four-sided construction in 4-D
-- The contour ABCD: the keel AD straight, the deck line BC a conic (in plan a conic arc from
-- the stem to the half beam, its height falling linearly), the frames AB (the stem, straight)
-- and CD (a rounded frame).  It is lifted into 4-D by a fourth coordinate t, the key: 0 on the
-- keel, 1 on the deck, and on the frames t = v, their own parameter from keel to deck.  The
-- surface is the set of meets of two pencils of 2-planes: omega(u) through the points BC(u),
-- AD(u) of one station and Z (at infinity on the z axis), delta(v) through X (at infinity on
-- the x axis) and the points AB(v), CD(v) of one key.  Above: the xyz projection, the planking,
-- whose longitudinal generators MN (v = const) are conics; below: the xyt projection, the
-- conoid with the plane of parallelism xt over the straight keel and the conic deck line.
-- The receding axis x at 36 degrees, 0.8 of its length; y and z or t as they are.
local L = 5                                    -- stem at y = 0, the frame CD at y = L
local xC, zA, zB, zD, zC = 1.4, .4, 1.2, 0, 1.1
-- the deck line's plan: a conic arc from the stem (x = 0, along the keel) to C, x = xC
local plan = korotky.conic_arc(P(0, 0), V(1, 1.6), P(xC, L), V(0, 1), P(1.05, 2.2))
local function deck(u) local q = plan(u); return P(q.x, q.y, zB + (zC - zB) * q.y / L, 1) end
local BC = curve(deck, 0, 1)
local AD = curve(function(u) return P(0, plan(u).y, zA + (zD - zA) * plan(u).y / L, 0) end, 0, 1)
local AB = curve(function(v) return P(0, 0, zA + (zB - zA) * v, v) end, 0, 1)
local CD = curve(function(v) return P(xC * v, L, zD + (zC - zD) * (1 - (1 - v)^2), v) end, 0, 1)
local Z, X = V(0, 0, 1, 0), V(1, 0, 0, 0)
local hull = korotky.two_pencils{omega = {BC, AD, Z}, delta = {X, AB, CD}}

local c, s = .8 * math.cos(math.pi / 5), .8 * math.sin(math.pi / 5)
local views = {
  {f = map.matrix({{c, 1, 0, 0, 0}, {s, 0, 1, 0, 0}, {0, 0, 0, 0, 1}}), ax = 3, x0 = 0},
  {f = map.matrix({{c, 1, 0, 0, 0}, {s, 0, 0, 1, 0}, {0, 0, 0, 0, 1}}), ax = 4, x0 = 0},
}
for k, view in ipairs(views) do
  view.f = map.translate(V(0, k == 1 and 2.9 or 0)) * view.f
end
window(-.5, -1, 7.5, 5)                        -- 8 x 6 units on 640 x 480: equal units
for _, view in ipairs(views) do
  camera(view.f)
  local o = P(0, 0, 0, 0)
  local e = {V(1.8, 0, 0, 0), V(0, 5.8, 0, 0), view.ax == 3 and V(0, 0, 1.5, 0) or V(0, 0, 0, 1.3)}
  for i, d in ipairs(e) do
    line(o, o + d, 8)
    label(({"x", "y", view.ax == 3 and "z" or "t"})[i], o + d, nil, 8)
  end
  hull:wireframe{nu = 8, nv = 6, color = 11}
  BC:draw{color = 14}; AD:draw{color = 14}; AB:draw{color = 14}; CD:draw{color = 14}
  label("A", AD(0)); label("B", BC(0)); label("C", BC(1)); label("D", AD(1))
  local M, N = hull(0, .5), hull(1, .5)
  hull:iso("v", .5):draw{color = 12}
  label("M", M); label("N", N)
  camera(nil)
end
label("G(xyz): the planking, MN a conic", P(-.4, 2.45), "e", 11)
label("G(xyt): the conoid over the keel and the deck line", P(-.4, -.55), "e", 11)
