-- A trimetric view of the unit cube: three different foreshortenings
-- Buimov §2.8.3: the book's T = Ry(Phi) Rx(theta) Pz with any angles is a trimetric view (the
-- book does not name it); with Phi = 30°, theta = 40° the axes shrink by
-- fx = sqrt(cos^2 Phi + sin^2 Phi sin^2 theta) = 0.9237, fy = cos theta = 0.7660 and
-- fz = sqrt(sin^2 Phi + cos^2 Phi sin^2 theta) = 0.7483 (map.foreshortening). Hidden edges dashed.

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

local f = map.axonometric(math.rad(30), math.rad(40))
local pts = {}
for _, n in ipairs(names) do pts[#pts + 1] = f(cube[n]) end
local screen = framing(pts, 40, 30, 600, 430)
box(screen * f, cube, 15)
caption(string.format("$\\Phi$ = 30°, $\\theta$ = 40°:  fx, fy, fz = %.4f, %.4f, %.4f",
  map.foreshortening(f)), "bottom", 7)
