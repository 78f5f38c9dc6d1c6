-- Reconstruction of a point of space from two views
-- Buimov §2.8.6: each view T (a projection onto z = 0) gives two equations (3.8.6.3) in x, y, z:
-- (T11 - T14 x*) x + (T21 - T24 x*) y + (T31 - T34 x*) z + (T41 - T44 x*) = 0 and the same with
-- y*; two views give four equations in three unknowns, solved by least squares (the book says
-- "by trial"). Left: the dimetric view (fz = 1/2), right: the two-point perspective of figure 2.12;
-- the point X = (0.7, 0.4, 0.9) of the cube is given only by its images X1, X2, and
-- buimov.reconstruct finds it again (the residual 0: consistent images).

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
local X = P(0.7, 0.4, 0.9)
local T1 = map.dimetric(0.5)
local T2 = map.orthographic("z") * map.perspective_pqr(0, 0, 0.5) * map.translate(V(0, -0.5, 0))
         * map.rotate(P(0, 0, 0), V(0, 1, 0), math.pi / 3)
local X1, X2 = T1(X), T2(X)
local R, residual = buimov.reconstruct({T1, T2}, {X1, X2})
for i, v in ipairs{{T1, X1, "$X_1$"}, {T2, X2, "$X_2$"}} do
  local pts = {}
  for _, n in ipairs(names) do pts[#pts + 1] = v[1](cube[n]) end
  local screen = framing(pts, 30 + 320 * (i - 1), 60, 290 + 320 * (i - 1), 360)
  box(screen * v[1], cube, 15)
  mark(screen(v[2]), "dot", 6, 12); label(v[3], screen(v[2]), nil, 12)
  label(i == 1 and "view 1: dimetric" or "view 2: figure 2.12", P(160 + 320 * (i - 1), 400), "c", 7)
end
caption(string.format("from X1 and X2 alone:  X = (%.4f, %.4f, %.4f), residual %.0e",
  R.x, R.y, R.z, residual), "bottom", 7)
