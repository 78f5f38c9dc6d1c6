-- The unit cube in every projection of the textbook, with its vanishing points
-- Buimov ch. 2.8: the orthographic top view Rx(90°) Pz (corrected: (x, y, z) -> (x, -z)), the
-- dimetric view with fz = 1/2, the isometric view (0.8165 on every axis), the oblique cavalier
-- and cabinet views (Rogers & Adams; not in the book), and the perspective transforms with one,
-- two and three vanishing points ([1/p 0 0 1], [0 1/q 0 1], [0 0 1/r 1], corrected), each
-- followed by the projection onto z = 0. Vanishing points are red, labelled Vx, Vy, Vz; the
-- edges that run to them are dashed.
local cube = {A = P(0, 0, 0), B = P(0, 1, 0), C = P(1, 1, 0), D = P(1, 0, 0),
              E = P(0, 0, 1), F = P(0, 1, 1), G = P(1, 1, 1), H = P(1, 0, 1)}
local edges = {"AB", "BC", "CD", "DA", "EF", "FG", "GH", "HE", "AE", "BF", "CG", "DH"}
local pz = map.orthographic("z")
local rx90 = map.rotate(P(0, 0, 0), V(1, 0, 0), math.pi / 2)

-- the edges along x, y and z, which run to Vx, Vy, Vz
local along = {{"A", "D", "B", "C", "E", "H", "F", "G"}, {"A", "B", "D", "C", "E", "F", "H", "G"},
               {"A", "E", "B", "F", "C", "G", "D", "H"}}

-- a panel 213 x 160 with the picture map f (3-D -> 2-D), the cube moved by `shift` first
local function panel(col, row, title, f, scale, centre, shift, vps)
  local ox, oy = 107 + 213 * col, 72 + 160 * row
  local screen = map.translate(V(ox, oy)) * map.scale({scale, -scale}) * map.translate(V(-centre.x, -centre.y))
  local view = screen * f * map.translate(shift or V(0, 0, 0))
  camera(view)
  for _, e in ipairs(edges) do line(cube[e:sub(1, 1)], cube[e:sub(2, 2)], 11) end
  for _, n in ipairs{"A", "G"} do label(n, cube[n], nil, 7) end
  camera(nil)
  if vps then
    local names = {"Vx", "Vy", "Vz"}
    local v = {(f * map.translate(shift or V(0, 0, 0))):vanishing_points()}
    for i = 1, 3 do
      if v[i] then
        local s = screen(v[i])
        pen{dash = {2, 3}}
        for j = 2, 8, 2 do line(view(cube[along[i][j]]), s, 8) end
        pen()
        circle(s, 3, 12); label(names[i], s, nil, 12)
      end
    end
  end
  label(title, P(ox, oy + 70), "c", 15)
end

panel(0, 0, "top view Rx(90) Pz", pz * rx90, 60, P(0.5, -0.5))
panel(1, 0, "dimetric fz = 1/2", map.dimetric(0.5), 55, P(0.65, 0.4))
panel(2, 0, "isometric", map.isometric(), 50, P(0.7, 0.4))
panel(0, 1, "cavalier 45", map.cavalier(), 42, P(0.85, 0.85))
panel(1, 1, "cabinet 45", map.cabinet(), 55, P(0.7, 0.7))
-- the front view (onto z = 0) and the side view (onto x = 0, Ry(-90) Pz) side by side
panel(2, 1, "front and side views", pz, 45, P(1.4, 0.5))
panel(2, 1, "", pz * map.rotate(P(0, 0, 0), V(0, 1, 0), -math.pi / 2), 45, P(-0.4, 0.5))
-- one point: r = 1/2 (the eye at z = -2), the cube moved to x, y = -0.5 as in the book's
-- centred figure; the z edges run to Vz = (0, 0)
local one = map.matrix({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0.5}, {0, 0, 0, 1}}, "row")
panel(0, 2, "one point, r = 1/2", pz * one, 75, P(0, 0), V(-0.5, -0.5, 0), true)
-- two points (Fig 2.12): Ry(60°), moved down by 0.6, then r = 1/k, k = 2: Vx = -k cot 60°,
-- Vz = k tan 60° on the x axis, the y edges stay parallel
local two = one * map.translate(V(0, -0.6, 0)) * map.rotate(P(0, 0, 0), V(0, 1, 0), math.pi / 3)
panel(1, 2, "two points (Fig 2.12)", pz * two, 38, P(1.15, -0.3), nil, true)
-- three points: p = q = r = 1/2, vanishing points [2 0 0], [0 2 0], [0 0 2] -> (0, 0)
local three = map.matrix({{1, 0, 0, 0.5}, {0, 1, 0, 0.5}, {0, 0, 1, 0.5}, {0, 0, 0, 1}}, "row")
panel(2, 2, "three points, p=q=r=1/2", pz * three, 42, P(0.9, 0.9), V(0.1, 0.1, 0.1), true)
