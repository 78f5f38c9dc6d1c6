-- A 5 x 3 Bezier patch: degree 4 in u, 2 in w
-- Buimov §5.6, Fig. 5.7 (the book's "3 x 5"): Q = [(1-u)^4, 4(1-u)^3 u, 6(1-u)^2 u^2, 4(1-u)u^3,
-- u^4] P_5x3 [(1-w)^2, 2(1-w)w, w^2]^T; the boundary Q(0, w) is the parabola of P11, P12, P13. The
-- net (i, 1.5 j, z) with the centre P32 raised to z = 2 (the book gives none; the rest of the
-- middle row at 0.6): moving the centre moves the middle of the patch, not its boundaries. The net
-- is dashed where the patch hides it.

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
-- the control net, one scene with the patch: dashed where the patch hides it
local function net_lines(net, colour)
  for i = 1, #net do for j = 1, #net[1] do
    if j < #net[1] then line(net[i][j], net[i][j + 1], colour) end
    if i < #net then line(net[i][j], net[i + 1][j], colour) end
  end end
end

local net = {}
for i = 0, 4 do
  net[i + 1] = {}
  for j = 0, 2 do net[i + 1][j + 1] = P(i, 1.5
      * j, j == 1 and (i == 2 and 2 or (i > 0 and i < 4) and 0.6 or 0) or 0) end
end
local s = surface.bezier(net)
local v = view3(-55, 20, 105, P(2, 1.5, 0.4), 320, 230)
camera(v, {hidden = "dashed"})
s:wireframe{nu = 12, nv = 8, color = 11}
net_lines(net, 8)
s:wireframe{nu = 0, nv = 0, boundary = true, color = 14}
camera(nil)
for _, c in ipairs{{1, 1}, {1, 3}, {5, 1}, {5, 3}, {3, 2}} do
  dot3(v, net[c[1]][c[2]], "$P_{" .. c[1] .. c[2] .. "}$", c[1] == 3 and 12 or 15)
end
caption(string.format("degree 4 x 2:  Q(0.5, 0.5) = (%g, %g, %.4f)",
  s(0.5, 0.5).x, s(0.5, 0.5).y, s(0.5, 0.5).z), "bottom", 7)
