-- The isometric view of the unit cube
-- Buimov §2.8.4, Fig. 2.8: Phi = 45°, sin^2 theta = 1/3 (theta = 35.264390°): every axis is
-- foreshortened by sqrt(2/3) = 0.816497, and the x axis is drawn at 30° to the horizontal
-- (tan alpha = sin Phi sin theta / cos Phi; the book prints squares, which give 18.43°).

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

local f = map.isometric()
local pts = {}
for _, n in ipairs(names) do pts[#pts + 1] = f(cube[n]) end
local screen = framing(pts, 40, 30, 600, 430)
box(screen * f, cube, 15)
caption(string.format("$\\Phi$ = 45°, $\\theta$ = 35.264°:  fx, fy, fz = %.4f, %.4f, %.4f",
  map.foreshortening(f)), "bottom", 7)
