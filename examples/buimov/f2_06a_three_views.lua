-- The unit cube in three orthographic views: front, top and side, panels apart
-- Buimov §2.8.1-§2.8.2 (the top view is figure 2.6): the front view Pz onto z = 0 ([x y z 1] -> [x
-- y]), the top view Rx(90°) Pz ([x, -z]) above it and the side view Ry(-90°) Pz ([z, y]) on its
-- right, as a draughtsman lays them out. In each view the corners coincide in pairs, each pair
-- lettered once; the edges behind are covered by those in front (no hidden edge shows in these
-- views).

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
local pz = map.orthographic("z")
local O = P(0, 0, 0)
local views = {
  {"front: Pz", pz, 150, 300},
  {"top: Rx(90) Pz", pz * map.rotate(O, V(1, 0, 0), math.pi / 2), 150, 110},
  {"side: Ry(-90) Pz", pz * map.rotate(O, V(0, 1, 0), -math.pi / 2), 420, 300},
}
for _, v in ipairs(views) do
  local f = v[2]
  -- 120 px to the unit, the panel's square centred on (v[3], v[4])
  local c = f(P(0.5, 0.5, 0.5))
  local screen = map.translate(V(v[3], v[4])) * map.scale({120, -120})
      * map.translate(V(-c.x, -c.y))
  box(screen
      * f, cube, 15, nil, {A = true, B = true, C = true, D = true, E = true, F = true, G = true,
        H = true})
  local seen = {}
  for _, n in ipairs(names) do
    local q = (screen * f)(cube[n])
    local key = string.format("%.0f %.0f", q.x, q.y)
    if seen[key] then seen[key].text = seen[key].text .. "$, $" .. n else seen[key] = {text = n,
      at = q}
    seen[#seen + 1] = seen[key] end
  end
  for _, s in ipairs(seen) do label("$" .. s.text .. "$", s.at, nil, 15) end
  label(v[1], P(v[3], v[4] + 88), "c", 7)
end
caption("front [x y], top [x, -z], side [z, y]:  no panel overlaps another", "bottom", 7)
