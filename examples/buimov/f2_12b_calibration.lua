-- Camera calibration from six reference points
-- Buimov §2.8.6: the twelve unknowns T11, T12, T14, ..., T44 of a projection onto z = 0 satisfy
-- two equations for each point of space and its image, [x, 0, -x x*, y, 0, -y x*, z, 0, -z x*,
-- 1, 0, -x*] T = 0 and the like with y* (the book prints +x*, +y*); with T44 = 1 (Rogers &
-- Adams' normalisation, not in the book) six points fix the camera by least squares. The images
-- of six corners of the cube under the figure 2.12 camera (circles) give back that camera:
-- buimov.calibrate returns it, and the whole cube drawn through it lands on the circles.

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
local camera_in = map.orthographic("z") * map.perspective_pqr(0, 0, 0.5)
    * map.translate(V(0, -0.5, 0))
                * map.rotate(P(0, 0, 0), V(0, 1, 0), math.pi / 3)
local refs = {"A", "B", "C", "D", "E", "G"}
local space, images = {}, {}
for i, n in ipairs(refs) do space[i] = cube[n]; images[i] = camera_in(cube[n]) end
local found, rms = buimov.calibrate(space, images)
local pts = {}
for _, n in ipairs(names) do pts[#pts + 1] = found(cube[n]) end
local screen = framing(pts, 60, 40, 580, 420)
box(screen * found, cube, 15)
for _, q in ipairs(images) do mark(screen(q), "open", 13, 12) end
caption(string.format("six reference points A, B, C, D, E, G:  rms %.1e in the picture",
  rms), "bottom", 7)
