-- Beyond QBasic through Lua: "#rrggbb" colours, the pen, QBasic's LINE style, paths, labels and
-- text, with their exact pixels and every argument error.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")

-- colours: "#rrggbb" anywhere a colour is taken; one attribute per colour
screen(12)
pset(10, 10, "#ff8000")
pset(11, 10, "#FF8000")
check.eq(point(10, 10), 256, "the first true colour is attribute 256")
check.eq(point(11, 10), point(10, 10), "the same colour shares its attribute")
line(0, 20, 9, 20, "#00ff00")
check.eq(point(5, 20), 257, "line takes a true colour")
circle(100, 100, 20, "#0000ff")
paint(100, 100, "#ff8000", "#0000ff")
check.eq(point(100, 100), 256, "paint colour and border as strings")
color("#00ff00")
pset(30, 30)
check.eq(point(30, 30), 257, "color() takes one")
view(200, 200, 250, 250, "#102030", "#ff8000")
check.eq(point(0, 0), 259, "view fill (after #0000ff, 258)")
view()
check.eq(point(199, 199), 256, "view border")
for _, bad in ipairs { "#ff80", "ff8000", "#ff80000", "#gg8000", "# ff800" } do
  check.err(function() pset(1, 2, bad) end,
    'pset: argument #3 (colour) must be a colour number 0..15 or "#rrggbb", got "' .. bad .. '"', "bad colour " .. bad)
end
check.err(function() circle(1, 2, 3, {}) end, 'circle: argument #4 (colour) must be a colour number 0..15 or "#rrggbb", got table', "colour type")
check.err(function() paint(1, 2, 3, "red") end, 'paint: argument #4 (border colour) must be a colour number 0..15 or "#rrggbb", got "red"', "border string")
screen(13)
pset(1, 1, "#ff8000")
check.eq(point(1, 1), 256, "a 256-colour screen takes true colours too; SCREEN forgot the old ones")

-- the pen: width and dashes
screen(12)
pen { width = 3 }
line(10, 50, 20, 50, 4)
for y = 48, 52 do
  local want = (y >= 49 and y <= 51) and 4 or 0
  check.eq(point(15, y), want, "width 3 row " .. y)
end
check.eq(point(9, 50), 4, "round cap")
pen { dash = { 4, 2 } }
line(10, 60, 30, 60, 4)
local got = {}
for x = 10, 30 do got[#got + 1] = point(x, 60) == 4 and "#" or "." end
check.eq(table.concat(got), "####..####..####..###", "dashed line")
pen()
line(10, 70, 30, 70, 4)
check.eq(point(14, 70), 4, "pen() restores the solid pen")
check.err(function() pen { width = 0 } end, "pen: option 'width' must be a number 1..256 (pixels) or a length such as \"0.5mm\", got 0", "pen width")
check.err(function() pen { dash = { 1, 2, 3 } } end, "pen: option 'dash' must be a list of on, off lengths (an even number, at most 16), got table", "odd dash")
check.err(function() pen { dash = { 1, -2 } } end, "pen: option 'dash' must be a positive number (pixels), got -2", "negative dash")
check.err(function() pen(3) end, "pen: argument #1 (pen) must be a table {width =, dash =} or a pen's name (\"main\", \"thin\", \"hidden\", \"centre\"), got 3", "pen type")

-- QBasic's LINE style after the box flag
line(100, 0, 100, 15, 2, nil, 0xAAAA)
got = {}
for y = 0, 15 do got[#got + 1] = point(100, y) == 2 and "#" or "." end
check.eq(table.concat(got), "#.#.#.#.#.#.#.#.", "&HAAAA")
line(110, 0, 110, 31, 2, nil, -256)   -- &HFF00 as QBasic's signed INTEGER
check.eq(point(110, 7), 2, "&HFF00 on"); check.eq(point(110, 8), 0, "&HFF00 off")
line(120, 0, 130, 5, 2, "b", 0x8000)
check.eq(point(130, 5), 2, "styled box: bit 15 at the second corner")
check.eq(point(125, 5), 0, "styled box: the rest off")
line(140, 0, 150, 5, 2, "bf", 0x8000)
check.eq(point(145, 3), 2, "a filled box ignores the style")
check.err(function() line(1, 2, 3, 4, 1, nil, 70000) end, "line: argument #7 (line style) must be a 16-bit pattern -32768..65535, got 70000", "style range")

-- paths
cls()
path({ P(10, 10), P(50, 10), P(50, 40) }, { closed = true, color = "#ff8000" })
check.eq(point(30, 10), 256, "path segment")
check.eq(point(30, 25), 256, "closing segment")
local lx, ly = last_point()
check.eq(lx * 1000 + ly, 50040, "the cursor is at the last point")
path({ P(60, 60), P(70, 60) })
check.eq(point(65, 60), 15, "default colour")
check.err(function() path(5) end, "path: argument #1 (points) must be a list of 2-D points, got 5", "path type")
check.err(function() path({}) end, "path: argument #1 (points) must be a list of at least one point, got table", "empty path")
check.err(function() path({ P(1, 2), 3 }) end, "path: argument #1 (points) [2] must be a 2-D point, got 3", "path item")
check.err(function() path({ P(1, 2) }, { color = 99 }) end, "path: option 'color' must be a colour number 0..15 or \"#rrggbb\", got 99", "path colour")

-- label: the text beside the point, 3 px off; text: the cell's top-left at the point
local function ink_box(col)
  local x0, y0, x1, y1 = 1e9, 1e9, -1, -1
  for y = 0, 199 do
    for x = 0, 319 do
      if point(x, y) == col then
        x0, y0 = math.min(x0, x), math.min(y0, y)
        x1, y1 = math.max(x1, x), math.max(y1, y)
      end
    end
  end
  return x0, y0, x1, y1
end
screen(13)
local X, Y = 160, 100
local sides = {
  ne = function(x0, y0, x1, y1) return x0 >= X + 3 and y1 <= Y - 3 end,
  n  = function(x0, y0, x1, y1) return x0 < X and x1 > X and y1 <= Y - 3 end,
  nw = function(x0, y0, x1, y1) return x1 <= X - 3 and y1 <= Y - 3 end,
  w  = function(x0, y0, x1, y1) return x1 <= X - 3 and y0 < Y and y1 > Y end,
  sw = function(x0, y0, x1, y1) return x1 <= X - 3 and y0 >= Y + 3 end,
  s  = function(x0, y0, x1, y1) return x0 < X and x1 > X and y0 >= Y + 3 end,
  se = function(x0, y0, x1, y1) return x0 >= X + 3 and y0 >= Y + 3 end,
  e  = function(x0, y0, x1, y1) return x0 >= X + 3 and y0 < Y and y1 > Y end,
  c  = function(x0, y0, x1, y1) return x0 < X and x1 > X and y0 < Y and y1 > Y end,
}
for dir, ok in pairs(sides) do
  cls()
  label("HM", P(X, Y), dir, 14)
  check.truthy(ok(ink_box(14)), "label " .. dir)
end
cls()
label("H", X, Y)
check.eq(ink_box(15), 1e9, "without a direction a label waits for the picture to be written")
local placed = placed_labels()
check.eq(#placed, 1, "one label to place")
check.eq(placed[1].side, "ne", "on an empty screen it goes to ne")
check.truthy(placed[1].auto and sides.ne(placed[1].x, placed[1].y, placed[1].x + 7, placed[1].y + 15),
  "3 px off, as label(text, P, \"ne\") puts it")
cls()
label(42, X, Y, "s", "#ff8000", 2)
local x0, y0, x1, y1 = ink_box(256)
check.truthy(y0 >= Y + 3 and y1 - y0 > 16, "a number as text, scale 2, a true colour")
cls()
text(10, 20, "A", 12)
-- the VGA 'A': rows 2..11 of the cell, its apex pixel in column 3 of row 2
check.eq(point(13, 22), 12, "text: the apex of the A")
x0, y0, x1, y1 = ink_box(12)
check.eq(x0 * 1000 + y0, 10022, "text: the ink starts at the cell's left column, row 2")
check.eq(y1, 31, "text: the last row of ink is row 11")
check.err(function() label() end, "label: argument #1 (text) must be a string, got nil", "missing text")
check.err(function() label("a") end, "label: argument #2 (x) must be a number or a point, got nil", "missing point")
check.err(function() label("a", 1, 2, "up") end, 'label: argument #4 (direction) must be one of "n" "ne" "e" "se" "s" "sw" "w" "nw" "c", got "up"', "bad direction")
check.err(function() label("a", P(1, 2), 5) end, 'label: argument #3 (direction) must be one of "n" "ne" "e" "se" "s" "sw" "w" "nw" "c", got 5', "direction type")
check.err(function() label("a", 1, 2, "n", 3, 9) end, "label: argument #6 (scale) must be an integer from 1 to 8, got 9", "bad scale")
check.err(function() label("a", 1, 2, "n", "#12345") end, 'label: argument #5 (colour) must be a colour number 0..255 or "#rrggbb", got "#12345"', "label colour")
check.err(function() label("\255", 1, 2) end, "label: invalid UTF-8 at byte 1", "invalid UTF-8")
check.err(function() text(1, 2) end, "text: argument #3 (text) must be a string, got nil", "text missing")
check.err(function() text(1, 2, "a", 1, 0) end, "text: argument #5 (scale) must be an integer from 1 to 8, got 0", "text scale")

check.done()
