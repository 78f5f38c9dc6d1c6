-- Central projection: the projectors from a centre through the object to the picture plane
-- Buimov §2.8, Fig. 2.5: a perspective projection sends every point along the line from the
-- centre of projection C through it to the picture plane; here the plane z = 0 (its frame grey),
-- C = (0, 0, -k) with k = 2.5 (§2.8.5: x* = x/(z/k + 1)), and the unit cube beyond the plane
-- at (0.4, 0.3, 1). Its image in the plane is drawn in colour; the projectors are dashed where
-- the cube hides them. Seen from the azimuth -70°, elevation 20°, z up.

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
local k = 2.5
local Cc = P(0, 0, -k)
local obj = {}
for _, n in ipairs(names) do obj[n] = cube[n] + V(0.4, 0.3, 1) end
local pr = map.orthographic("z") * map.perspective_pqr(0, 0, 1 / k)
local img = {}
for _, n in ipairs(names) do local q = pr(obj[n]); img[n] = P(q.x, q.y, 0) end
-- z to the right, y up, x towards the viewer a little: a view from the azimuth -60°
local view = map.translate(V(330, 225)) * map.scale({88, -88})
    * map.view{azimuth = -70, elevation = 20, to = P(0.5, 0.5, 0)}
camera(view)
for _, c in ipairs{{P(-0.6, -0.6, 0), P(1.6, -0.6, 0)}, {P(1.6, -0.6, 0), P(1.6, 1.6, 0)},
                   {P(1.6, 1.6, 0), P(-0.6, 1.6, 0)}, {P(-0.6, 1.6, 0), P(-0.6, -0.6, 0)}} do
  line(c[1], c[2], 8)
end
line(Cc, P(0, 0, 2.4), 7)                                -- the z axis through the centre
for _, e in ipairs(edges) do line(img[e:sub(1, 1)], img[e:sub(2, 2)], 14) end
camera(nil)
camera(view, {hidden = "dashed"})
for _, q in ipairs(faces) do
  local function c(i) return obj[q:sub(i, i)] end
  surface.bilinear(c(1), c(2), c(4), c(3)):wireframe{nu = 0, nv = 0}
end
for _, e in ipairs(edges) do line(obj[e:sub(1, 1)], obj[e:sub(2, 2)], 15) end
for _, n in ipairs{"E", "F", "G", "H"} do line(Cc, obj[n], 12) end
camera(nil)
mark(view(Cc), "dot", 5, 12); label("$C$", view(Cc), nil, 12)
label("$z = 0$", view(P(1.6, 1.6, 0)), nil, 8); label("$z$", view(P(0, 0, 2.4)), nil, 7)
for _, n in ipairs{"E", "F", "G", "H"} do label("$" .. n .. "$", view(obj[n]), nil, 15)
label("$" .. n .. "^*$", view(img[n]), nil, 14) end
caption("C = (0, 0, -k), k = 2.5:  x* = x/(z/k + 1), y* = y/(z/k + 1)", "bottom", 7)
