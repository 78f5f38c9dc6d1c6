-- The linear Coons surface of four boundary curves
-- Buimov §5.4, Fig. 5.5: Q = P(u,0)(1-w) + P(u,1)w + P(0,w)(1-u) + P(1,w)u minus the bilinear
-- surface of the corners (the two ruled surfaces alone count each corner twice: Q(0,0) = 2P00).
-- The boundaries P(u, 0) = (u, 0, sin pi u) and the three straight edges P(u, 1) = (u, 1, 0),
-- P(0, w) = (0, w, 0), P(1, w) = (1, w, 0): Q(0.5, 0.5) = (0.5, 0.5, 0.5) and Q(0.25, 0.5) =
-- (0.25, 0.5, 0.353553); the boundary is reproduced, Q(0.5, 0) = (0.5, 0, 1).

local pi = math.pi
-- the view: azimuth and elevation with z up, scale px per unit, the point `to` at (cx, cy) px
local function view3(az, el, scale, to, cx, cy)
  return map.translate(V(cx or 320, cy or 235)) * map.scale({scale, -scale})
       * map.view{azimuth = az, elevation = el, to = to or P(0, 0, 0)}
end
-- a 3-D point marked and lettered (the letter on its image, so a hidden point keeps its name)
local function dot3(view, p, name, colour)
  mark(view(p), "dot", 4, colour); if name then label(name, view(p), nil, colour) end
end
local cu0 = curve(function(u) return P(u, 0, math.sin(pi * u)) end, 0, 1)
local s = surface.coons(cu0, bezier{P(0, 1, 0), P(1, 1, 0)}, bezier{P(0, 0, 0), P(0, 1, 0)},
  bezier{P(1, 0, 0), P(1, 1, 0)})
local v = view3(-50, 25, 250, P(0.5, 0.5, 0.4), 320, 235)
camera(v, {hidden = "dashed"})
s:wireframe{nu = 10, nv = 10, color = 11}
cu0:draw{color = 14}
camera(nil)
label("$P(u, 0)$", v(cu0(0.3)), nil, 14)
for _, uw in ipairs{{0.5, 0.5}, {0.25, 0.5}} do
  local q = s(uw[1], uw[2])
  dot3(v, q, string.format("Q(%g, %g)", uw[1], uw[2]), 15)
end
caption(string.format("Q(0.5, 0.5) = (%g, %g, %g),  Q(0.25, 0.5) = (%g, %g, %.6f)",
  s(0.5, 0.5).x, s(0.5, 0.5).y, s(0.5, 0.5).z,
  s(0.25, 0.5).x, s(0.25, 0.5).y, s(0.25, 0.5).z), "bottom", 7)
