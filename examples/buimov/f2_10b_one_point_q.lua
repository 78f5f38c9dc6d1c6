-- One-point perspectives by p only, q only and r only: the term q
-- Buimov §2.8.5, Fig. 2.10 b: the 4th column [0 q 0 1] gives h = qy + 1 and the vanishing point
-- [0 1/q 0 1] of the edges along y; q = 1/2, V_y = (0, 2), then the projection onto z = 0.

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

-- the edges along x, y and z (pairs), dashed on to their vanishing points V_x, V_y, V_z
local along = {{"AD", "BC", "EH", "FG"}, {"AB", "DC", "EF", "HG"}, {"AE", "BF", "CG", "DH"}}
local function vanishing(f, screen)
  local v = {f:vanishing_points()}
  for i, axis in ipairs{"x", "y", "z"} do
    if v[i] then
      local s = screen(v[i])
      pen{dash = {2, 3}}
      for _, e in ipairs(along[i]) do line(screen(f(cube[e:sub(2, 2)])), s, 8) end
      pen()
      mark(s, "dot", 5, 12); label("$V_" .. axis .. "$", s, nil, 12)
    end
  end
  return v
end

local f = map.orthographic("z") * map.perspective_pqr(0, 0.5, 0) * map.translate(V(-0.5, 0, 0))
local pts = {}
for _, n in ipairs(names) do pts[#pts + 1] = f(cube[n]) end
for _, v in pairs({f:vanishing_points()}) do pts[#pts + 1] = v end
local screen = framing(pts, 40, 30, 600, 430)
vanishing(f, screen)
box(screen * f, cube, 15)
caption("q = 1/2 (cube moved by -0.5 in x):  h = y/2 + 1,  $V_y$ = (0, 2)", "bottom", 7)
