-- The drawing layer through Lua: each statement, its defaults, points as coordinates, and
-- every argument error.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")

-- SCREEN 12 is the default
local w, h, n = size()
check.eq(w, 640, "width"); check.eq(h, 480, "height"); check.eq(n, 16, "colours")
check.eq(select(1, color()), 15, "default foreground")

-- PSET/PRESET/POINT with exact pixels and rounding
pset(10.5, 20.4, 4)
check.eq(point(10, 20), 4, "pset rounds 10.5 to 10 (ties to even)")
pset(11.5, 20, 5)
check.eq(point(12, 20), 5, "pset rounds 11.5 to 12")
pset(30, 30)
check.eq(point(30, 30), 15, "pset default colour")
preset(30, 30)
check.eq(point(30, 30), 0, "preset default colour")
check.eq(point(-1, 0), -1, "point outside the screen")

-- LINE: segment, box, filled box, continuation
line(0, 100, 9, 100, 2)
for x = 0, 9 do check.eq(point(x, 100), 2, "line pixel " .. x) end
line(20, 110, 24, 113, 3, "b")
check.eq(point(22, 110), 3, "box top"); check.eq(point(22, 112), 0, "box inside empty")
line(20, 120, 24, 123, 6, "bf")
check.eq(point(22, 122), 6, "filled box inside")
line(50, 50, 60, 50, 1)
line_to(60, 60, 7)
check.eq(point(60, 55), 7, "line_to continues from the last point")
local lx, ly = last_point()
check.eq(lx, 60, "last point x"); check.eq(ly, 60, "last point y")
line(200, 200, 210, 200, nil, "B")
check.eq(point(205, 200), 15, "box with default colour (empty colour argument)")

-- CIRCLE and PAINT
circle(300, 300, 20, 14)
check.eq(point(320, 300), 14, "circle right"); check.eq(point(300, 280), 14, "circle top")
paint(300, 300, 1, 14)
check.eq(point(300, 300), 1, "painted inside"); check.eq(point(330, 300), 0, "not outside")
circle(400, 300, 20, 9, 0, math.pi / 2)
check.eq(point(420, 300), 9, "arc start"); check.eq(point(380, 300), 0, "arc skips the left")
circle(450, 300, 10, 12, nil, nil, 0.5)
check.eq(point(460, 300), 12, "aspect<1 keeps x radius"); check.eq(point(450, 295), 12, "aspect<1 halves y")

-- points as coordinates
local A, B = P(100, 400), P(110, 400)
pset(A, 13)
check.eq(point(A), 13, "pset(point) and point(point)")
line(A, B, 11)
check.eq(point(105, 400), 11, "line(point, point, colour)")
line(A, 120, 410, 10)
check.eq(point(120, 410), 10, "line(point, x, y, colour)")
circle(P(500, 100), 5, 10)
check.eq(point(505, 100), 10, "circle(point, r, colour)")
check.err(function() pset(V(1, 2)) end, "membership", "a vector is not a location")
check.err(function() pset(P(1, 2) * 2) end, "V()", "weighted value suggests V()")
check.err(function() pset(P(1, 2, 3)) end, "2-D", "a 3-D point on the canvas")

-- WINDOW maps world coordinates with y up
window(0, 0, 64, 48)
pset(0, 0, 2)
check.eq(point(0, 0), 2, "point reads world coordinates")
window()
check.eq(point(0, 479), 2, "world origin is the bottom-left pixel")
window(P(0, 0), P(64, 48), "screen")
pset(1, 1, 3)
window()
check.eq(point(10, 10), 3, "window screen keeps y down")

-- VIEW
view(600, 0, 639, 39, 8, nil)
pset(0, 0, 4)
view()
check.eq(point(600, 0), 4, "view offsets coordinates")
check.eq(point(620, 20), 8, "view fill colour")

-- PALETTE and COLOR: what the written file shows for attributes 1, 2, 3 (read back from a PPM)
local function ppm_rgb(path, x, y)
  local f = assert(io.open(path, "rb"))
  local data = f:read("a")
  f:close()
  local header = data:match("^P6\n%d+ %d+\n255\n")
  local i = #header + (y * 640 + x) * 3 + 1
  return string.format("%02x%02x%02x", data:byte(i, i + 2))
end
pset(1, 470, 1) pset(2, 470, 2) pset(3, 470, 3)
palette(1, 63)                 -- QBasic: 65536*b + 256*g + r, 6 bits each: bright red
palette(2, "#123456")
palette(3, { 1, 2, 3 })
local ppm = os.tmpname() .. ".ppm"
save(ppm)
check.eq(ppm_rgb(ppm, 1, 470), "ff0000", "palette(1, 63): red 63 widens to 255")
check.eq(ppm_rgb(ppm, 2, 470), "123456", "palette(2, \"#123456\")")
check.eq(ppm_rgb(ppm, 3, 470), "010203", "palette(3, {1, 2, 3})")
palette(1, 65536 * 42)         -- blue 42 (0xaa), as VGA's default colour 1
palette()
save(ppm)
check.eq(ppm_rgb(ppm, 2, 470), "00aa00", "palette() restores the default colour 2")
os.remove(ppm)
color(9)
pset(5, 5)
check.eq(point(5, 5), 9, "color sets the foreground")

-- errors name the function, the argument and what it must be
check.err(function() circle(1, 2) end, "circle: argument #3 (radius) must be a non-negative number, got nil", "circle radius nil")
check.err(function() circle(1, 2, -3) end, "circle: argument #3 (radius) must be a non-negative number, got -3", "negative radius")
check.err(function() circle(1, 2, 3, 1, 7) end, "circle: argument #5 (start angle) must be a number between -2*pi and 2*pi, got 7", "angle range")
check.err(function() circle(1, 2, 3, 1, nil, nil, 0) end, "circle: argument #7 (aspect) must be a positive number, got 0", "aspect")
check.err(function() pset(1, 2, 16) end, "pset: argument #3 (colour) must be a colour number 0..15 or \"#rrggbb\", got 16", "colour range")
check.err(function() pset("a", 2) end, "pset: argument #1 (x) must be a number or a point, got \"a\"", "x type")
check.err(function() pset(1, 0 / 0) end, "pset: argument #2 (y) must be a finite number", "NaN")
check.err(function() line(1, 2, 3) end, "line: argument #4 (end y) must be a number or a point, got nil", "line end")
check.err(function() line(1, 2, 3, 4, 1, "x") end, "line: argument #6 (style) must be \"b\" (box) or \"bf\" (filled box)", "line style")
check.err(function() paint(1, 2, 3, 99) end, "paint: argument #4 (border colour) must be a colour number 0..15 or \"#rrggbb\", got 99", "paint border")
check.err(function() window(0, 0, 0, 5) end, "window: window (0, 0)-(0, 5) has zero width or height", "flat window")
check.err(function() view(0, 0, 700, 10) end, "view: view (0, 0)-(700, 10) is not inside the 640x480 screen", "view outside")
check.err(function() palette(16, 0) end, "palette: argument #1 (attribute) must be an attribute 0..15, got 16", "palette attr")
check.err(function() palette(1, 64) end, "palette: argument #2 (colour)", "palette colour")
check.err(function() screen(10) end, "screen: argument #1 (mode) must be 12", "screen mode")
check.err(function() save(42) end, "save: argument #1 (path) must be a file name, got 42", "save path")
check.err(function() save("x.gif") end, "save: argument #1 (path) must be a file name ending in .png, .svg, .ppm, .pdf, .eps or .ps", "save extension")
check.err(function() save("no_such_dir/x.png") end, "save: cannot write 'no_such_dir/x.png': No such file or directory", "save unwritable")

-- a NaN where a number is optional is still wrong, not "not given"
check.err(function() circle(1, 2, 3, 1, 0 / 0) end, "circle: argument #5 (start angle) must be a number between -2*pi and 2*pi, got", "NaN start")
check.err(function() circle(1, 2, 3, 1, 0, 0 / 0) end, "circle: argument #6 (end angle) must be a number between -2*pi and 2*pi, got", "NaN end")
check.err(function() circle(1, 2, 3, 1, nil, nil, 0 / 0) end, "circle: argument #7 (aspect) must be a positive number, got", "NaN aspect")
-- coordinates beyond any screen say so instead of wrapping around
check.err(function() view(0, 0, 1e30, 1e30) end, "view: view (0, 0)-(1e+30, 1e+30) is not inside the 640x480 screen", "huge view")
check.err(function() view(-1e30, 0, 10, 10) end, "is not inside the 640x480 screen", "huge negative view")
check.eq(point(639, 479), 0, "the view is still the whole screen")
-- a finite coordinate that WINDOW maps beyond any double: an error, no pixel anywhere
window(0, 0, 1, 1)
check.err(function() pset(1e308, 0) end, "pset: coordinates (1e+308, 0) are too far outside the window", "window overflow")
check.err(function() preset(1e308, 0) end, ": preset: coordinates (1e+308, 0) are too far", "preset names itself")
check.err(function() line_to(1e308, 0) end, ": line_to: coordinates (1e+308, 0) are too far", "line_to names itself")
check.err(function() circle(0, 0, 1e308) end, ": circle: radius 1e+308 is too large for the window", "radius overflow")
check.err(function() window(-1e308, 0, 1e308, 1) end, "window: window (-1e+308, 0)-(1e+308, 1) is too large", "huge window")
window()

-- SCREEN 13 and custom sizes
screen(13)
w, h, n = size()
check.eq(w, 320, "screen 13 width"); check.eq(n, 256, "screen 13 colours")
pset(1, 1, 200)
check.eq(point(1, 1), 200, "256 colours")
screen { width = 100, height = 50 }
w, h, n = size()
check.eq(w * 1000 + h, 100050, "screen{width=, height=}")
check.eq(point(1, 1), 0, "screen clears")
check.err(function() screen { width = 0, height = 5 } end, "screen: option 'width' must be an integer from 1 to 16384, got 0", "screen width")
check.err(function() screen { width = 2 ^ 32 + 640, height = 480 } end, "screen: option 'width' must be an integer from 1 to 16384, got 4294967936", "width beyond int")
check.err(function() screen { width = 10, height = (1 << 32) + 48 } end, "screen: option 'height' must be an integer from 1 to 16384, got 4294967344", "height beyond int")
check.err(function() screen { width = 10, height = 10, colors = (1 << 32) + 16 } end, "screen: option 'colors' must be 2, 4, 16 or 256, got 4294967312", "colours beyond int")
check.err(function() screen { width = 10, height = 10, colors = 8 } end, "screen: option 'colors' must be 2, 4, 16 or 256, got 8", "colours not a mode's")
check.err(function() screen { width = 10 } end, "screen: option 'height' must be an integer from 1 to 16384, got nil", "height missing")
check.err(function() screen { widht = 300 } end, "screen: unknown option 'widht' (did you mean 'width'?)", "a misspelt key")
check.err(function() screen { width = 10, height = 10, colours = 16 } end, "screen: unknown option 'colours' (did you mean 'colors'?)", "colours is not colors")
check.eq(select(1, size()), 100, "a refused screen leaves the canvas as it was")

check.done()
