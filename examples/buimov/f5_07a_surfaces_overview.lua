-- Every surface of the textbook as an iso-line wireframe, hidden lines dashed
-- Buimov ch. 5: the sphere patch of figure 5.2 (th in [0, pi/2], ph in [pi/4, pi/2]) with its
-- corner normals N = S_th x S_ph (inwards; N_B = -(e1 + e3)/2, corrected), a bilinear surface
-- (figure 5.3), a ruled surface between a sine and a line (figure 5.4), the linear Coons patch of
-- test vector 35 (figure 5.5), a bicubic Hermite F-patch (zero twists), the 4 x 4 Bezier patch with
-- its net (figure 5.6), a B-spline surface of orders 3 x 3 on the book's knots, and a surface of
-- revolution (not in the book; Rogers & Adams); one figure per book figure is in the f5_*
-- scripts. All through one axonometric view with the z
-- axis up: Rx(-90°) first (z becomes the picture's y), then the book's Ry(phi) Rx(theta) Pz.
local pi = math.pi
local view = map.axonometric(math.rad(35), math.rad(25))
    * map.rotate(P(0, 0, 0), V(1, 0, 0), -pi / 2)

local function panel(col, row, title, scale, centre)
  local ox, oy = 80 + 160 * col, 125 + 240 * row
  camera(map.translate(V(ox, oy)) * map.scale({scale, -scale}) * view
      * map.translate(V(-centre.x, -centre.y, -centre.z)),
         {hidden = "dashed"})   -- one scene per panel: the Bezier net too is dashed behind its patch
  label(title, P(ox, oy + 100), "c", 15)
end

-- the sphere patch and its corner normals (scaled by 1/2, red)
panel(0, 0, "sphere patch", 95, P(0.4, 0.4, 0.4))
local sp = buimov.sphere(0, pi / 2, pi / 4, pi / 2)
sp:wireframe{nu = 6, nv = 6, color = 11}
for _, c in ipairs{{0, pi / 2, "A"}, {0, pi / 4, "B"}, {pi / 2, pi / 4, "C"}, {pi / 2, pi / 2,
  "D"}} do
  local S, _, _, _, N = buimov.sphere_frame(c[1], c[2])
  line(S, S + N * 0.5, 12); label("$" .. c[3] .. "$", S, nil, 15)
end

panel(1, 0, "bilinear", 85, P(0.5, 0.5, 0.5))
surface.bilinear(P(0, 0, 1), P(1, 0, 0), P(0, 1, 0), P(1, 1, 1)):wireframe{nu = 8, nv = 8,
  color = 11}

panel(2, 0, "ruled", 60, P(1, 0.5, 0.5))
local sine = curve(function(t) return P(2 * t, 0, 0.6 * math.sin(2 * pi * t)) end, 0, 1)
surface.ruled(sine, bezier{P(0, 1.5, 1), P(2, 1.5, 0.2)}):wireframe{nu = 12, nv = 6, color = 11}

panel(3, 0, "linear Coons", 85, P(0.5, 0.5, 0.3))
local cu0 = curve(function(u) return P(u, 0, math.sin(pi * u)) end, 0, 1)
surface.coons(cu0, bezier{P(0, 1, 0), P(1, 1, 0)}, bezier{P(0, 0, 0), P(0, 1, 0)}, bezier{P(1, 0,
  0), P(1, 1, 0)})
  :wireframe{nu = 10, nv = 10, color = 11}
cu0:draw{color = 14}

-- the F-patch: corners and tangents, no twists (Buimov §5.5)
panel(0, 1, "Hermite F-patch", 80, P(0.5, 0.5, 0.3))
surface.hermite{
  P = {P(0, 0, 0), P(1, 0, 0.3), P(0, 1, 0.2), P(1, 1, 0)},
  Pu = {V(1, 0, 1.5), V(1, 0, -1), V(1, 0, 1), V(1, 0, -1.5)},
  Pv = {V(0, 1, 1), V(0, 1, 1), V(0, 1, -1), V(0, 1, -1)},
  Puv = {V(0, 0, 0), V(0, 0, 0), V(0, 0, 0), V(0, 0, 0)},
}:wireframe{nu = 10, nv = 10, color = 11}

-- the 4 x 4 Bezier net of test vector 36 (z = 1 in the middle), the net grey
panel(1, 1, "Bezier 4 x 4", 32, P(1.5, 1.5, 0.4))
local net = {}
for i = 0, 3 do
  net[i + 1] = {}
  for j = 0, 3 do net[i + 1][j + 1] = P(i, j,
    (i == 1 or i == 2) and (j == 1 or j == 2) and 1.5 or 0) end
end
for i = 1, 4 do for j = 1, 3 do line(net[i][j], net[i][j + 1], 8)
line(net[j][i], net[j + 1][i], 8) end end
surface.bezier(net):wireframe{nu = 10, nv = 10, color = 11}

-- a B-spline surface of orders 3 x 3 on a 5 x 5 net, with the book's open knots
panel(2, 1, "B-spline 3 x 3", 27, P(2, 2, 0.3))
local bnet = {}
for i = 0, 4 do
  bnet[i + 1] = {}
  for j = 0, 4 do bnet[i + 1][j + 1] = P(i, j, ((i + j) % 3 == 0) and 1.2 or 0) end
end
local kn = buimov.knots({P(0), P(1), P(2), P(3), P(4)}, 3)
surface.bspline(bnet, 2, 2, kn, kn):wireframe{nu = 10, nv = 10, color = 11}

-- a vase turned about the z axis (a B-spline profile)
panel(3, 1, "revolution", 45, P(0, 0, 1.2))
local profile = buimov.bspline({P(0.6, 0, 0), P(1.2, 0, 0.4), P(0.4, 0, 1.2), P(0.5, 0, 2), P(0.9,
  0, 2.4)}, 3)
surface.revolution(profile, P(0, 0, 0), V(0, 0, 1)):wireframe{nu = 8, nv = 16, color = 11}
camera(nil)
