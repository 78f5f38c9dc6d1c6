-- A ruled surface between two curves
-- Buimov §5.3, Fig. 5.4: Q(u, w) = P(u, 0)(1 - w) + P(u, 1) w, straight lines (the rulings, grey)
-- from each point of P(u, 0) = (2u, 0, 0.6 sin 2 pi u) to the point of P(u, 1), the segment from
-- (0, 1.5, 1) to (2, 1.5, 0.2) (the book gives no curves); both edge curves are reproduced.

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
local c0 = curve(function(u) return P(2 * u, 0, 0.6 * math.sin(2 * pi * u)) end, 0, 1)
local c1 = bezier{P(0, 1.5, 1), P(2, 1.5, 0.2)}
local s = surface.ruled(c0, c1)
local v = view3(-60, 25, 150, P(1, 0.75, 0.3), 320, 235)
camera(v, {hidden = "dashed"})
s:wireframe{nu = 16, nv = 0, color = 8}
c0:draw{color = 14}; c1:draw{color = 10}
camera(nil)
label("$P(u, 0)$", v(c0(0.25)), nil, 14); label("$P(u, 1)$", v(c1(0.5)), nil, 10)
caption("Q(u, w) = P(u, 0)(1 - w) + P(u, 1) w:  the rulings w from 0 to 1", "bottom", 7)
