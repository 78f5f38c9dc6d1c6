-- fit{around = points, pad = p}: the window round the points set before drawing, equal units at
-- the view's aspect, 3-D points through the camera; its pixels and its errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")

-- where a world point is drawn, in device pixels: pset it, then look with the window off
local function pixel_of(p, colour)
  pset(p, colour)
  window()
  local hits = {}
  for y = 0, 479 do for x = 0, 639 do if point(x, y) == colour then hits[#hits + 1] = {x, y} end end end
  return hits
end

screen(12)
-- the triangle (0,0), (4,0), (2,3) with pad 0.5: 4 world units high over the 479-pixel span,
-- 119.75 px a unit on both axes, centred on x = 2 (pixel 319.5)
local A, B, C = P(0, 0), P(4, 0), P(2, 3)
fit { around = { A, B, C }, pad = 0.5 }
local h = pixel_of(A, 14)
check.eq(#h, 1, "one pixel for A")
check.eq(h[1][1], 80, "A at 319.5 - 2 * 119.75")
check.eq(h[1][2], 419, "A 0.5 + 3 units below the top: 419.125")
cls()
fit { around = { A, B, C }, pad = 0.5 }
h = pixel_of(P(0, 3), 13)
check.eq(h[1][1], 80, "x = 0 at the same column")
check.eq(h[1][2], 60, "y = 3 half a unit below the top: 59.875")
-- equal units: a circle of radius 1 spans as many pixels across as up and down
cls()
fit { around = { A, B, C }, pad = 0.5 }
circle(P(2, 1.5), 1, 15)
window()
local x0, x1, y0, y1 = 640, -1, 480, -1
for y = 0, 479 do for x = 0, 639 do if point(x, y) == 15 then
  x0, x1, y0, y1 = math.min(x0, x), math.max(x1, x), math.min(y0, y), math.max(y1, y)
end end end
check.eq(x1 - x0, y1 - y0, "the circle as wide as high")
check.truthy(math.abs((x1 - x0) - 2 * 119.75) <= 1, "2 units = 239.5 px")
-- aspect = "fill": the box plus pad, each axis its own scale
cls()
fit { around = { P(0, 0), P(639, 479) }, aspect = "fill" }
h = pixel_of(P(10, 20), 12)
check.eq(h[1][1], 10, "fill: the box is the view, x")
check.eq(h[1][2], 459, "fill: y up")

-- 3-D: through the camera, the same frame as the projected points in 2-D
cls()
local iso = map.isometric()
local pts = { P(0, 0, 0), P(2, 0, 0), P(0, 3, 0), P(0, 0, 1.5) }
camera(iso)
fit { around = pts, pad = 0.2 }
pset(pts[2], 11)
camera(nil)
window()
local flat = {}
for i, p in ipairs(pts) do flat[i] = iso(p) end
fit { around = flat, pad = 0.2 }
pset(flat[2], 10)
window()
local n11, n10 = 0, 0
for y = 0, 479 do for x = 0, 639 do
  local v = point(x, y)
  if v == 11 then n11 = n11 + 1 elseif v == 10 then n10 = n10 + 1 end
end end
check.eq(n11, 0, "the 3-D point drawn where its projection is (overdrawn by it)")
check.eq(n10, 1, "the projection's pixel")

-- band = 39: those pixels kept free at the bottom (a caption's line); the triangle framed in the
-- 440 px above at 110 px a unit, its pad's lower edge on row 440, centred on x = 2 (319.5)
cls()
fit { around = { A, B, C }, pad = 0.5, band = 39 }
h = pixel_of(P(2.25, 0), 12)
check.eq(#h, 1, "one pixel for (2.25, 0)")
check.eq(h[1][1], 347, "x = 2.25: 319.5 + 0.25 * 110")
check.eq(h[1][2], 385, "y = 0: half a unit above row 440")
cls()
fit { around = { A, B, C }, pad = 0.5, band = 39 }
h = pixel_of(P(2.25, 3), 12)
check.eq(h[1][2], 55, "y = 3: half a unit below the top")
cls()

-- errors name the call and the option
check.err(function() fit { around = { A, B }, margin = 5 } end,
  "fit: margin frames what is drawn (in pixels); with around give pad (world units)", "margin with around")
check.err(function() fit { pad = 1 } end,
  "fit: pad is the room round the points of around: give around too (or margin)", "pad alone")
check.err(function() fit { around = { A }, pad = 0 } end,
  "fit: the points around are one point and pad is 0: give a pad > 0", "one point")
check.err(function() fit { around = { A, B }, pad = -1 } end, "fit: option 'pad' must be", "negative pad")
check.err(function() fit { around = {} } end, "fit: option 'around' must hold at least 1", "no points")
check.err(function() fit { around = { P(0, 0, 0), P(1, 1, 1) } } end,
  "fit: option 'around' [1] must be a 2-D point (or an n-D one through the camera), got a 3-D point", "3-D without a camera")
check.err(function() fit { band = 20 } end,
  "fit: band is the caption's room under the points of around: give around too", "band alone")
check.err(function() fit { around = { A, B }, pad = 1, band = 479 } end,
  "fit: band must be a number of pixels >= 0 and below the view's 479, got 479", "band too tall")
check.err(function() fit { around = { A, B }, band = -1 } end, "fit: option 'band' must be", "negative band")
check.done()
