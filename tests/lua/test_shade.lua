-- Shaded surfaces through Lua: s:shade{nu, nv, color, light, ambient, mesh, map}: Lambert's
-- cosine law read back from a written file (a plane facing the light in the full colour, at 60
-- degrees in half), the plane's image covered exactly, the mesh over the fills, the nearer of
-- two overlapping quads on top, quads left out, and every argument error.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")

local W, H = 40, 40
-- the colour of pixel (x, y) of the canvas, from a PPM written now
local function rgb_at(x, y)
  local path = os.tmpname()
  save(path .. ".ppm")
  local f = assert(io.open(path .. ".ppm", "rb"))
  local data = f:read("a")
  f:close()
  os.remove(path .. ".ppm")
  os.remove(path)
  local header = data:match("^P6\n%d+ %d+\n255\n")
  local i = #header + (y * W + x) * 3 + 1
  return string.format("%02x%02x%02x", data:byte(i, i + 2))
end

local function fresh()
  screen{width = W, height = H}
  -- orthographic from +z, 10 px per unit, y up, the origin at pixel (5, 35)
  camera(map.translate(V(5, 35)) * map.scale({10, -10}) * map.orthographic("z"))
end

local function square(tilt)   -- the 3 x 3 square, turned by tilt about the x axis
  local c, s = math.cos(tilt), math.sin(tilt)
  return surface.bilinear(P(0, 0, 0), P(3, 0, 0), P(0, 3 * c, 3 * s), P(3, 3 * c, 3 * s))
end

-- facing the light: the full colour over exactly the image's pixels (centres 5..34)
fresh()
check.eq(square(0):shade{nu = 3, nv = 3, color = "#c87828", light = V(0, 0, 2)}, 9, "nine quads drawn")
check.eq(rgb_at(20, 20), "c87828", "facing the light: the full colour")
local base = point(20, 20)
local covered = 0
for y = 0, H - 1 do
  for x = 0, W - 1 do
    local inside = x >= 5 and x < 35 and y >= 5 and y < 35
    check.eq(point(x, y) == base, inside, "plane pixel " .. x .. "," .. y)
    if point(x, y) == base then covered = covered + 1 end
  end
end
check.eq(covered, 900, "the image covered once: 30 x 30 pixels")

-- at 60 degrees to the light: cos 60 = 1/2, half the colour (the plane turned, or the light)
fresh()
square(math.pi / 3):shade{nu = 3, nv = 3, color = "#c87828", light = V(0, 0, 1)}
check.eq(rgb_at(20, 30), "643c14", "plane at 60 degrees: half of c87828")
fresh()
square(0):shade{nu = 2, nv = 2, color = "#c87828", light = V(math.sin(math.pi / 3), 0, math.cos(math.pi / 3))}
check.eq(rgb_at(20, 20), "643c14", "light at 60 degrees: half")
-- ambient 0.5: 0.5 + 0.5 * 0.5 = 0.75 of the colour
fresh()
square(0):shade{nu = 2, nv = 2, color = "#c87828", light = V(math.sin(math.pi / 3), 0, math.cos(math.pi / 3)), ambient = 0.5}
check.eq(rgb_at(20, 20), "965a1e", "ambient 0.5 at 60 degrees: 3/4")
-- the headlight (no light): the viewer is at +z, so 60 degrees again; the default colour is
-- the drawing colour (15, white: ffffff -> 808080 rounded from 127.5 to even)
fresh()
square(math.pi / 3):shade{nu = 1, nv = 1}
check.eq(rgb_at(20, 30), "808080", "headlight, default colour white, at 60 degrees")
-- a palette colour as the base
fresh()
square(0):shade{nu = 1, nv = 1, color = 4, light = V(0, 0, 1)}
check.eq(rgb_at(20, 20), "aa0000", "base colour 4: VGA red")

-- the mesh: every quad's outline over its fill
fresh()
square(0):shade{nu = 3, nv = 3, color = "#ffffff", light = V(0, 0, 1), mesh = 14}
for y = 5, 35 do
  for x = 5, 35 do
    local line = (x - 5) % 10 == 0 or (y - 5) % 10 == 0
    check.eq(point(x, y) == 14, line, "mesh pixel " .. x .. "," .. y)
  end
end
fresh()
square(0):shade{nu = 1, nv = 1, color = "#ffffff", light = V(0, 0, 1), mesh = "#ff0000"}
check.eq(rgb_at(5, 20), "ff0000", "mesh as a true colour")

-- a surface folded over itself: u in [0, 1] flat, u in [1, 2] folded back over it at 45
-- degrees, up or down; seen from +z the nearer part is the one that shows
for _, h in ipairs{1, -1} do
  fresh()
  local fold = surface(function(u, v)
    if u <= 1 then return P(u, v, 0) end
    return P(2 - u, v, h * (u - 1))
  end, 0, 2, 0, 1)
  check.eq(fold:shade{nu = 2, nv = 1, color = "#c8c8c8", light = V(0, 0, 1)}, 2, "fold: two quads")
  check.eq(rgb_at(10, 30), h > 0 and "8d8d8d" or "c8c8c8", "fold " .. h .. ": the nearer quad on top")
end

-- map = f instead of the camera; quads without an image left out (a corner at infinity)
fresh()
camera(nil)
local f = map.translate(V(5, 35)) * map.scale({10, -10}) * map.orthographic("z")
local holed = surface(function(u, v)
  if u == 2 and v == 2 then return V(1, 1, 0) end
  return P(u, v, 0)
end, 0, 2, 0, 2)
check.eq(holed:shade{nu = 2, nv = 2, map = f, light = V(0, 0, 1)}, 3, "a corner at infinity leaves its quad out")
check.eq(point(20, 20), 0, "the quad left out is not drawn")
check.eq(rgb_at(10, 30), "ffffff", "the others are (white, the default)")

-- errors
fresh()
local s = square(0)
check.err(function() s:shade(5) end, "s:shade: argument #1 (opts) must be a table {nu =, nv =, color =, light =, ambient =, mesh =, map =}, got 5", "opts")
check.err(function() s:shade{nu = 0} end, "s:shade: option 'nu' must be an integer from 1 to 1024, got 0", "nu")
check.err(function() s:shade{nv = 2.5} end, "s:shade: option 'nv' must be an integer from 1 to 1024, got 2.5", "nv")
check.err(function() s:shade{color = "#ff00"} end, "s:shade: option 'color' must be a colour number 0..15 or \"#rrggbb\", got \"#ff00\"", "colour string")
check.err(function() s:shade{color = 99} end, "s:shade: option 'color' must be a colour number 0..15 or \"#rrggbb\", got 99", "colour number")
check.err(function() s:shade{mesh = true} end, "s:shade: option 'mesh' must be a colour number 0..15 or \"#rrggbb\", got boolean", "mesh")
check.err(function() s:shade{light = P(0, 0, 1)} end, "s:shade: option 'light' must be a 3-D vector (the direction towards the light), got P(0, 0, 1)", "light point")
check.err(function() s:shade{light = V(0, 1)} end, "s:shade: option 'light' must be a 3-D vector (the direction towards the light), got V(0, 1)", "light 2-D")
check.err(function() s:shade{light = V(0, 0, 0)} end, "s:shade: option 'light' must be a nonzero vector (the direction towards the light), got V(0, 0, 0)", "light zero")
check.err(function() s:shade{ambient = 2} end, "s:shade: option 'ambient' must be a number from 0 to 1, got 2", "ambient")
check.err(function() s:shade{map = 3} end, "s:shade: option 'map' must be a map, got 3", "map")
check.err(function() surface.bilinear(P(0, 0), P(1, 0), P(0, 1), P(1, 1)):shade() end,
  "s:shade: shading needs a 3-D surface seen through a projection, this one is 2-D", "2-D surface")
camera(nil)
check.err(function() s:shade() end, "s:shade: a 3-D object needs a projection: set one with camera(f) or give map = f", "no camera")
fresh()
local failing = surface(function(u, v)
  if u > 0.5 then error("no value here") end
  return P(u, v, 0)
end, 0, 1, 0, 1)
check.err(function() failing:shade{nu = 2, nv = 2} end, "no value here", "the function's error")
camera(nil)

-- a true colour's attribute (above the screen's 16) is a colour of s:shade as well
fresh()
square(0):shade{nu = 1, nv = 1, color = "#c87828", light = V(0, 0, 1)}
local true_attr = point(20, 20)
check.truthy(true_attr > 15, "a true colour has an attribute above 15")
fresh()
square(0):shade{nu = 1, nv = 1, color = "#c87828", light = V(0, 0, 1)}
check.eq(square(0):shade{nu = 1, nv = 1, color = true_attr, light = V(0, 0, 1)}, 1, "the attribute accepted")
check.eq(rgb_at(20, 20), "c87828", "and drawn in its colour")

check.done()
