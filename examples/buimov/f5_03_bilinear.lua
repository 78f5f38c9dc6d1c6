-- The bilinear surface of four corners
-- Buimov §5.2, Fig. 5.3: Q(u, w) = P(0,0)(1-u)(1-w) + P(0,1)(1-u)w + P(1,0)u(1-w) + P(1,1)uw with
-- P(0,0) = (0, 0, 1), P(0,1) = (0, 1, 0), P(1,0) = (1, 0, 0), P(1,1) = (1, 1, 1) (the book gives no
-- corners): a hyperbolic paraboloid whose u and w lines are straight; Q(0.5, 0.5) = (0.5, 0.5,
-- 0.5), the mean of the corners, and Q(0.25, 0.75) = (0.25, 0.75, 0.375).

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
local P00, P01, P10, P11 = P(0, 0, 1), P(0, 1, 0), P(1, 0, 0), P(1, 1, 1)
local s = surface.bilinear(P00, P10, P01, P11)          -- pointcalc's order: u first
local v = view3(-55, 25, 260, P(0.5, 0.5, 0.5), 320, 235)
camera(v, {hidden = "dashed"})
s:wireframe{nu = 8, nv = 8, boundary = true, color = 11}
camera(nil)
for _, c in ipairs{{P00, "$P(0,0)$"}, {P01, "$P(0,1)$"}, {P10, "$P(1,0)$"}, {P11,
  "$P(1,1)$"}} do dot3(v, c[1], c[2], 15) end
dot3(v, s(0.5, 0.5), "$Q(0.5, 0.5)$", 14)
caption(string.format("Q(0.5, 0.5) = (%g, %g, %g),  Q(0.25, 0.75) = (%g, %g, %g)",
  s(0.5, 0.5).x, s(0.5, 0.5).y, s(0.5, 0.5).z,
  s(0.25, 0.75).x, s(0.25, 0.75).y, s(0.25, 0.75).z), "bottom", 7)
