-- A block turned by 90° about the x, the y and the z axis
-- Buimov §2.3, Fig. 2.2 a, b, c: Rx(90°) = [[1,0,0,0],[0,0,1,0],[0,-1,0,0],[0,0,0,1]] sends y to z,
-- Ry(90°) = [[0,0,-1,0],[0,1,0,0],[1,0,0,0],[0,0,0,1]] sends z to x and Rz(90°) sends x to y (a
-- positive turn is counter-clockwise seen from the positive end of the axis). The block
-- 1 x 0.5 x 0.25 (grey) and its image (colour), each pair in its own panel, isometric view.

-- the unit cube lettered as in Fig. 2.12: A at the origin, B on y, D on x, E on z
local names = {"A", "B", "C", "D", "E", "F", "G", "H"}
local cube = {A = P(0, 0, 0), B = P(0, 1, 0), C = P(1, 1, 0), D = P(1, 0, 0),
              E = P(0, 0, 1), F = P(0, 1, 1), G = P(1, 1, 1), H = P(1, 0, 1)}
local faces = {"ABCD", "EFGH", "ABFE", "DCGH", "ADHE", "BCGF"}
local edges = {"AB", "BC", "CD", "DA", "EF", "FG", "GH", "HE", "AE", "BF", "CG", "DH"}

-- the screen map that frames the 2-D points pts at equal units inside the pixel box x0..x1, y0..y1
local function framing(pts, x0, y0, x1, y1)
  local lx, ly, hx, hy = math.huge, math.huge, -math.huge, -math.huge
  for _, q in ipairs(pts) do
    lx, ly, hx, hy = math.min(lx, q.x), math.min(ly, q.y), math.max(hx, q.x), math.max(hy, q.y)
  end
  local s = math.min((x1 - x0) / math.max(hx - lx, 1e-9), (y1 - y0) / math.max(hy - ly, 1e-9))
  return map.translate(V((x0 + x1) / 2, (y0 + y1) / 2)) * map.scale({s, -s})
       * map.translate(V(-(lx + hx) / 2, -(ly + hy) / 2))
end

-- a box (corners keyed A..H) through view (3-D -> screen): its faces hide, its edges are drawn,
-- dashed where hidden; every corner lettered, the hidden ones too (placed on their images), but
-- those in the set skip
local function box(view, pts, colour, star, skip)
  camera(view, {hidden = "dashed"})
  for _, q in ipairs(faces) do
    local function c(i) return pts[q:sub(i, i)] end
    surface.bilinear(c(1), c(2), c(4), c(3)):wireframe{nu = 0, nv = 0}
  end
  for _, e in ipairs(edges) do line(pts[e:sub(1, 1)], pts[e:sub(2, 2)], colour) end
  camera(nil)
  for _, n in ipairs(names) do
    if not (skip and skip[n]) then
      label("$" .. n .. (star or "") .. "$", view(pts[n]), nil, colour)
    end
  end
end
local block = {}
for _, n in ipairs(names) do block[n] = P(cube[n].x, 0.5 * cube[n].y, 0.25 * cube[n].z) end
local f = map.isometric()
local O = P(0, 0, 0)
local turns = {{"$R_x(90^\\circ)$", V(1, 0, 0)}, {"$R_y(90^\\circ)$", V(0, 1, 0)},
  {"$R_z(90^\\circ)$", V(0, 0, 1)}}
for i, t in ipairs(turns) do
  local R = map.rotate(O, t[2], math.pi / 2)
  local img = {}
  for _, n in ipairs(names) do img[n] = R(block[n]) end
  -- one frame for the three panels (the same scale), each panel 213 px wide
  local screen = map.translate(V(82 + 213 * (i - 1), 265)) * map.scale({110, -110})
  camera(screen * f)
  for _, ax in ipairs{{V(1.15, 0, 0), "$x$"}, {V(0, 1.15, 0), "$y$"}, {V(0, 0, 1.15), "$z$"}} do
    arrow(O, O + ax[1], "end", 8)
  end
  camera(nil)
  for _, ax in ipairs{{V(1.15, 0, 0), "$x$"}, {V(0, 1.15, 0), "$y$"}, {V(0, 0, 1.15), "$z$"}} do
    label(ax[2], (screen * f)(O + ax[1]), nil, 8)
  end
  box(screen
      * f, block, 7, nil, {A = true, B = true, C = true, D = true, E = true, F = true, G = true,
        H = true})
  box(screen * f, img, 14, "^*", {B = true, C = true, E = true, F = true, G = true, H = true})
  label(t[1], P(107 + 213 * (i - 1), 390), "c", 15)
end
caption("a positive turn: counter-clockwise seen from the axis' positive end", "bottom", 7)
