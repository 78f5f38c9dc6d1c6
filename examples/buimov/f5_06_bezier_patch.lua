-- The 4 x 4 Bezier patch and its control net
-- Buimov §5.6, Fig. 5.6: Q(u, w) = [(1-u)^3, 3(1-u)^2 u, 3(1-u)u^2, u^3] [P_ij] [the same in w]^T;
-- only the four corners of the net lie on the patch. The net P_ij = (i, j, z_ij), i, j = 0..3,
-- with z = 1 on the inner 2 x 2 and 0 elsewhere (the book gives no net): Q(0.5, 0.5) =
-- (1.5, 1.5, 0.5625), Q(0.25, 0.5) = (0.75, 1.5, 0.421875). The net and the patch are one scene:
-- the net is dashed where the patch hides it.

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
for i = 0, 3 do
  net[i + 1] = {}
  for j = 0, 3 do net[i + 1][j + 1] = P(i, j,
    (i == 1 or i == 2) and (j == 1 or j == 2) and 1 or 0) end
end
local s = surface.bezier(net)
local v = view3(-60, 18, 120, P(1.5, 1.5, 0.3), 320, 230)
camera(v, {hidden = "dashed"})
s:wireframe{nu = 10, nv = 10, color = 11}
net_lines(net, 8)
camera(nil)
for _, c in ipairs{{1, 1}, {1, 4}, {4, 1}, {4, 4}} do
  dot3(v, net[c[1]][c[2]], "$P_{" .. c[1] .. c[2] .. "}$", 15)
end
dot3(v, net[2][2], "$P_{22}$", 7)
dot3(v, s(0.5, 0.5), "$Q(0.5, 0.5)$", 14)
caption(string.format("Q(0.5, 0.5) = (%g, %g, %g):  only P11, P14, P41, P44 lie on the patch",
  s(0.5, 0.5).x, s(0.5, 0.5).y, s(0.5, 0.5).z), "bottom", 7)
