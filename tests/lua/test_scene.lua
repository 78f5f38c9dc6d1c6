-- The 3-D scene through Lua: with camera(f, {hidden = ...}) a line behind a sphere is left out
-- (or dashed) in the written picture whatever the order of the calls; map.view with z up;
-- one iso family; the silhouette of a sphere is its outline circle.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local pi, cos, sin = math.pi, math.cos, math.sin

local function ppm(path)
  local f = assert(io.open(path, "rb"))
  local data = f:read("a")
  f:close()
  local w, header = data:match("^P6%s+(%d+)%s+%d+%s+255%s()")
  return function(x, y)
    local o = header + (y * tonumber(w) + x) * 3
    return data:byte(o) * 65536 + data:byte(o + 1) * 256 + data:byte(o + 2)
  end
end

local sph = surface(function(u, v) return P(cos(u) * cos(v), sin(u) * cos(v), sin(v)) end,
  0, 2 * pi, -pi / 2, pi / 2)
-- seen from +z, y up: 100 px per unit about the centre of the screen
local view = map.view { from = P(0, 0, 10), to = P(0, 0, 0), up = V(0, 1, 0) }
local f = map.translate(V(320, 240)) * map.scale({ 100, -100 }) * view
check.eq(tostring(f(P(1, 0, 0))), "P(420, 240)", "x to the right")
check.eq(tostring(f(P(0, 1, 5))), "P(320, 140)", "up is up, depth does not show")

local function row(order, mode)
  screen(12)
  camera(f, { hidden = mode })
  if order == 1 then line(P(-2, 0, -1.5), P(2, 0, -1.5), 14) end
  sph:wireframe { nu = 0, nv = 0 }   -- no lines: the sphere only hides
  if order == 2 then line(P(-2, 0, -1.5), P(2, 0, -1.5), 14) end
  local out = os.tmpname() .. ".ppm"
  save(out)
  local px = ppm(out)
  os.remove(out)
  local got = {}
  for x = 120, 520, 10 do got[#got + 1] = px(x, 240) ~= 0 and "#" or "." end
  return table.concat(got)
end
local want = string.rep("#", 11) .. string.rep(".", 19) .. string.rep("#", 11)   -- |x - 320| < 100 hidden
check.eq(row(1, "hide"), want, "drawn before the sphere: the hidden part is left out")
check.eq(row(2, "hide"), want, "drawn after it: the same")
check.eq(row(1, "show"), string.rep("#", 41), "show: everything")
local dashed = row(1, "dashed")
check.truthy(dashed:sub(12, 30):find("#") and dashed:sub(12, 30):find("%."), "dashed: some of the hidden part")
-- labels of 3-D points: the one behind the sphere is left out, the front one placed
screen(12)
camera(f, { hidden = "hide" })
label("N", P(0, 0.5, 0.87))
label("S", P(0, 0, -1))
sph:wireframe { nu = 0, nv = 0 }
local texts = {}
for _, l in ipairs(placed_labels()) do texts[#texts + 1] = l.text .. (l.auto and "*" or "") end
check.eq(table.concat(texts, " "), "N*", "only the seen label, placed automatically")
camera(nil)

-- an arrowed path of 3-D points joins the scene: its shaft hidden behind the sphere, and its
-- head drawn only where its tip is seen, whatever the order of the calls
local function arrow_pixels(tip_z, sphere_first)
  screen(12)
  camera(f, { hidden = "hide" })
  if sphere_first then sph:wireframe { nu = 0, nv = 0 } end
  path({ P(-2, 0.5, tip_z), P(0, 0.5, tip_z) }, { arrow = "end", color = 14 })
  if not sphere_first then sph:wireframe { nu = 0, nv = 0 } end
  local out = os.tmpname() .. ".ppm"
  save(out)
  local px = ppm(out)
  os.remove(out)
  -- the tip at (320, 190): the head 9 px back from it spreads 2.7 px each side of the shaft
  local head = 0
  for x = 312, 319 do for y = 186, 194 do if y ~= 190 and px(x, y) ~= 0 then head = head + 1 end end end
  return head, px(150, 190) ~= 0, px(300, 190) ~= 0
end
for _, first in ipairs { true, false } do
  local head, outside, inside = arrow_pixels(-1.5, first)
  check.eq(head .. " " .. tostring(outside) .. " " .. tostring(inside), "0 true false",
    "the tip behind the sphere: no head, the shaft hidden over the sphere, drawn beside it")
  head, outside, inside = arrow_pixels(1.5, first)
  check.truthy(head > 8 and outside and inside, "the tip in front: the head and the whole shaft")
end
camera(nil)

-- a shaded surface hides the scene's strokes behind it, whatever the order of the calls, and
-- a stroke in front is drawn over its shading
local function shaded_row(z, shade_first)
  screen(12)
  camera(f, { hidden = "hide" })
  if shade_first then sph:shade { nu = 24, nv = 12, color = 9 } end
  line(P(-2, 0, z), P(2, 0, z), 14)
  if not shade_first then sph:shade { nu = 24, nv = 12, color = 9 } end
  local out = os.tmpname() .. ".ppm"
  save(out)
  local px = ppm(out)
  os.remove(out)
  local yellow = px(130, 240)   -- the line beside the sphere: colour 14
  local got = {}
  for x = 120, 520, 10 do got[#got + 1] = px(x, 240) == yellow and "#" or "." end
  return table.concat(got)
end
for _, first in ipairs { true, false } do
  check.eq(shaded_row(-1.5, first), want, "behind the shaded sphere: the line hidden over it")
  check.eq(shaded_row(1.5, first), string.rep("#", 41), "in front of it: drawn over the shading")
end
camera(nil)

-- a scene's label is read by label's own declaration: bad math fails at the call, as in 2-D,
-- not when the picture is written; its options are checked and kept till it is drawn
local function svg_text(path)
  local f = assert(io.open(path, "rb"))
  local data = f:read("a")
  f:close()
  os.remove(path)
  return data
end
figure {}
camera(map.orthographic("z"), { hidden = "dashed" })
line(P(0, 0, 0), P(100, 100, 0), 15)
check.err(function() label("$\\nosuch A$", P(50, 50, 0)) end,
  "label: label '$\\nosuch A$': unknown command '\\nosuch' at character 2", "bad math in a scene: at the call")
check.err(function() label("A", P(50, 50, 0), "ne", { size = 500 }) end,
  "label: option 'size' must be 1 to 200 pt", "a scene label's size is checked")
check.err(function() label("A", P(50, 50, 0), "ne", { sise = 5 }) end,
  "unknown option 'sise'", "a scene label's options are not silently dropped")
check.err(function() label("A", P(50, 50, 0), "up") end, "argument #3 (direction)", "its direction")
label("$\\tilde A$", P(50, 50, 0), "se", { size = 20, halo = false })
label("B", P(100, 100, 0), "ne")
local sout = os.tmpname() .. ".svg"
save(sout)
local svg = svg_text(sout)
check.truthy(svg:find('font%-size="20.000"[^>]*data%-label="%$\\tilde A%$"'), "the scene label at its size 20 pt")
check.truthy(not svg:find('stroke="#ffffff"[^>]*data%-label="%$\\tilde A%$"'), "halo = false kept: no halo")
check.truthy(svg:find('font%-size="10.000"[^>]*stroke="#ffffff"'), "the other label at the figure's size, haloed")
camera(nil)
screen(12)

-- one iso family: nu = 4, nv = 0 draws the meridians (seen from +z: the two diameters) and no
-- parallel; nu = 0, nv = 4 the parallels (circles of radius 0, 70.7, 100 px) and no meridian
screen(12)
camera(f)
sph:wireframe { nu = 4, nv = 0, color = 10 }
check.eq(point(320, 190), 10, "the meridian u = pi/2")
check.eq(point(370, 190), 0, "no parallel v = pi/4")
cls()
sph:wireframe { nu = 0, nv = 4, color = 10 }
check.eq(point(320, 190), 0, "no meridian")
check.eq(point(370, 190), 10, "the parallel v = pi/4, radius 70.7 px")
-- the silhouette of the sphere seen from +z: the circle of radius 100 px
cls()
sph:wireframe { nu = 0, nv = 0, silhouette = true, color = 12 }
local on, off = 0, 0
for k = 0, 71 do
  local a = 2 * pi * k / 72
  for r = 97, 103, .25 do
    if point(math.floor(320 + r * cos(a) + .5), math.floor(240 + r * sin(a) + .5)) == 12 then on = on + 1 break end
  end
end
check.eq(on, 72, "the outline circle all round")
check.eq(point(320, 240), 0, "and nothing inside")
-- the boundary alone: a unit square patch seen from +z shows its four edges, nothing inside
cls()
local sq = surface(function(u, v) return P(u, v, 0) end, 0, 1, 0, 1)
sq:wireframe { nu = 0, nv = 0, boundary = true, color = 13 }
check.eq(point(370, 240) .. point(420, 190) .. point(370, 140) .. point(320, 190) .. point(370, 190),
  "131313130", "the four edges of the square (320..420, 140..240 px) and not its middle")
-- path() with 3-D points goes into the scene too: drawn before the sphere, hidden by it
screen(12)
camera(f, { hidden = "hide" })
path({ P(-2, 0, -1.5), P(0, 0, -1.5), P(2, 0, -1.5) }, { color = 14 })
sph:wireframe { nu = 0, nv = 0 }
local pout = os.tmpname() .. ".ppm"
save(pout)
local ppx = ppm(pout)
os.remove(pout)
check.eq((ppx(150, 240) ~= 0 and "#" or ".") .. (ppx(320, 240) ~= 0 and "#" or ".") ..
  (ppx(490, 240) ~= 0 and "#" or "."), "#.#", "the path's middle behind the sphere is left out")

-- pset() with a 3-D point too: the dot behind the sphere is left out, the one in front drawn
screen(12)
camera(f, { hidden = "dashed" })
pset(P(0.5, 0, -1.5), 14)    -- behind: at (370, 240)
pset(P(-0.5, 0, 1.5), 14)    -- in front: at (270, 240)
sph:wireframe { nu = 0, nv = 0 }
pout = os.tmpname() .. ".ppm"
save(pout)
ppx = ppm(pout)
os.remove(pout)
check.eq(ppx(370, 240), 0, "a dot behind the sphere is left out")
check.eq(ppx(270, 240) ~= 0, true, "a dot in front of it is drawn")

-- fit{} sees the scene through the camera: a line drawn small in a corner fills the view
-- (10 px in), and the sphere still hides its middle
screen(12)
local small = map.translate(V(60, 60)) * map.scale({ 10, -10 }) * view   -- 10 px a unit
camera(small, { hidden = "hide" })
line(P(-2, 0, -1.5), P(2, 0, -1.5), 14)
sph:wireframe { nu = 0, nv = 0 }
fit { margin = 10 }
local out = os.tmpname() .. ".ppm"
save(out)
local px = ppm(out)
os.remove(out)
check.eq(px(12, 240) ~= 0 and px(627, 240) ~= 0 and px(8, 240) == 0 and px(631, 240) == 0, true,
  "the line from x = 10 to 629, the whole view but the margin")
check.eq(px(320, 240), 0, "its middle still behind the sphere")
check.eq(px(100, 240) ~= 0, true, "beside the sphere, solid")
check.err(function() camera(f, { hidden = "maybe" }) end,
  'camera: option \'hidden\' must be "show", "dashed" or "hide", got "maybe"', "bad mode")
check.err(function() camera(f, { hiden = "hide" }) end,
  "camera: unknown option 'hiden' (did you mean 'hidden'?)", "a misspelt key of camera")
check.err(function() map.view { from = P(1, 1, 1), to = P(1, 1, 1) } end,
  "map.view: from and to coincide", "no line of sight")
check.err(function() sph:wireframe { nu = -1 } end, "s:wireframe: option 'nu' must be an integer from 0 to 1000, got -1", "count")
print(arg[0] .. ": " .. check.count .. " checks passed")
