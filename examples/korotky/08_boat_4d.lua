-- Korotky (2015) Fig. 1a: the fishing boat whose parts the 4-D constructions model
-- The prototype of Fig. 1: the hull is four copies of the bow planking of Fig. 1c (script
-- 10), mirrored in the keel's vertical plane and about the midship frame CD (a double-ender),
-- and the sail is the triangle ABC of Fig. 1b (script 09), set on the deck with its luff AC
-- along the mast.  Each is the xyz projection of a 4-D surface (the meets of two pencils of
-- 2-planes); here they are one 3-D scene, seen in axonometry at equal units: the hull and the
-- sail hide what lies behind them (dashed).
local L, xC, zA, zB, zD, zC = 5, 1.4, .4, 1.2, 0, 1.1
local plan = korotky.conic_arc(P(0, 0), V(1, 1.6), P(xC, L), V(0, 1), P(1.05, 2.2))
local BC = curve(function(u) local q = plan(u); return P(q.x, q.y, zB + (zC - zB) * q.y / L, 1) end, 0, 1)
local AD = curve(function(u) return P(0, plan(u).y, zA + (zD - zA) * plan(u).y / L, 0) end, 0, 1)
local AB = curve(function(v) return P(0, 0, zA + (zB - zA) * v, v) end, 0, 1)
local CD = curve(function(v) return P(xC * v, L, zD + (zC - zD) * (1 - (1 - v)^2), v) end, 0, 1)
local Z, X = V(0, 0, 1, 0), V(1, 0, 0, 0)
local bow = korotky.two_pencils{omega = {BC, AD, Z}, delta = {X, AB, CD}}

-- the sail of Fig. 1b: x its camber, y its height, z along its foot (script 09)
local sA, sB, sC = P(0, 0, 0, 0), P(0, 0, 4, 4), P(0, 6, .3, 2)
local sail = korotky.two_pencils{omega = {sC, bezier{sA, P(1.6, 0, 2, 2), sB}, Z},
                                 delta = {X, bezier{sA, P(0, 3, -.2, 1), sC}, bezier{sB, P(0, 3, 2.9, 3), sC}}}
local mast_y, deck_z = 3, zB + (zC - zB) * 3 / L
local function onboat(p) return P(.5 * p.x, mast_y + .8 * p.z, deck_z + .8 * p.y) end

-- the hull's four patches: (x, y) mirrored in x = 0 and about y = L; the sail
local parts = {}
for _, sx in ipairs{1, -1} do
  for _, fy in ipairs{false, true} do
    parts[#parts + 1] = surface(function(u, v)
      local p = bow(u, v)
      return P(sx * p.x, fy and 2 * L - p.y or p.y, p.z) end, 0, 1, 0, 1)
  end
end
local sail3 = surface(function(u, v) return onboat(sail(u, v)) end, 0, 1, 0, 1)

camera(map.translate(V(320, 250)) * map.scale({36, -36}) *
       map.view{azimuth = -35, elevation = 28} * map.translate(V(0, -L, -2.4)), {hidden = "dashed"})
for _, s in ipairs(parts) do s:wireframe{nu = 6, nv = 4, color = 11, boundary = true} end
sail3:wireframe{nu = 6, nv = 6, color = 14, boundary = true}
line(onboat(sA), onboat(sC), 15)                          -- the luff along the mast
label("A", onboat(sA)); label("B", onboat(sB)); label("C", onboat(sC))
camera(nil)
label("hull: four patches of Fig. 1c;  sail: Fig. 1b", P(20, 460), "e", 7)
