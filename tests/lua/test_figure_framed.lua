-- A figure{} framed when it is written (no screen(), no window): what is measured in pixels
-- comes out in the frame's pixels.  Its own file: a fresh canvas that no screen() has made
-- pixel-addressed.  The 4 x 3 legs below frame to 151.67 px a unit, the corner at (16.17, 467).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")

local function read(path)
  local f = assert(io.open(path, "rb"))
  local data = f:read("a")
  f:close()
  os.remove(path)
  return data
end

figure {}
line(P(0, 0), P(4, 0), 15)
line(P(0, 0), P(0, 3), 15)
local scale, ox, oy = (479 - 24) / 3, (639 - 4 * (479 - 24) / 3) / 2, 467

-- a dimension 20 px right of the vertical leg: its text 3 px right of the line, at its middle
check.eq(dimension(P(0, 3), P(0, 0), 20), 3, "the world's length")
-- an angle mark: its text 22 px (radius 20 + 2) from the vertex along the bisector
check.near(angle_mark(P(4, 0), P(0, 0), P(0, 3), "R", 20), math.pi / 2, 1e-15, "the world's angle")
local got = {}
for _, l in ipairs(placed_labels()) do got[l.text] = l end
check.eq(got["3"].x, math.floor(ox + 20 + 0.5) + 3, "the dimension's text: 20 + 3 px off the leg, not 20 units")
check.near(got["3"].y + got["3"].h / 2, (12 + oy) / 2, 1, "at the leg's middle")
local rx, ry = ox + 22 * math.sqrt(0.5), oy - 22 * math.sqrt(0.5)
check.near(got.R.x, rx + 3, 1.5, "the angle's text beside the bisector's point, 22 px out")
check.near(got.R.y + got.R.h, ry - 3 + 1, 1.5, "above it (side ne)")
check.eq(got.R.side, "ne", "its side faces away from the vertex")

-- label options survive the framing (the labels are drawn again there)
cls()
line(P(0, 0), P(4, 0), 15)
label("A", P(4, 0), "se", { size = 20, halo = false })
label("B", P(4, 3), "nw", { size = 5 })
local svg = os.tmpname() .. ".svg"
save(svg)
local data = read(svg)
local sizes = {}
for size in data:gmatch('<text[^>]-font%-size="([%d.]+)"') do sizes[#sizes + 1] = size end
check.eq(table.concat(sizes, " "), "20.000 5.000", "each label at its own size after framing")
check.truthy(not data:find('font%-size="20.000"[^>]*stroke="#ffffff"'), "halo = false kept")

-- a legend is in device units: in the corner, 8 px in, whatever the framing (not upside down
-- in the middle of the picture, nor a part of what is framed)
cls()
line(P(0, 0), P(4, 0), 12)
line(P(0, 0), P(0, 3), 9)
legend({ { "horizontal", 12 }, { "vertical", 9 } }, "ne")
local entries = placed_labels()
check.eq(#entries, 2, "the two entries")
check.eq(entries[1].text .. " " .. entries[1].y .. " " .. entries[2].y, "horizontal 12.0 30.0",
  "the entries 4 px into the box 8 px from the top, one under the other")
check.near(entries[1].x, 640 - 8 - (38 + entries[1].w) + 32, 1, "the box 8 px from the right edge")

-- axes: drawn once framed, through the frame: tick labels with the world's numbers, at equal
-- units on both axes, 5 px off their ticks, and all inside the picture (framed with room)
cls()
graph(function(x) return x * x / 4 end, 0, 4)
check.eq(axes { x = { 0, 4 }, y = { 0, 4 } }, 10, "five ticks on each axis")
local xs, ys = {}, {}
for _, l in ipairs(placed_labels()) do
  check.truthy(l.x >= 0 and l.y >= 0 and l.x + l.w <= 640 and l.y + l.h <= 480, "tick label " .. l.text .. " inside")
  local t = l.side == "s" and xs or ys
  t[#t + 1] = l
end
check.eq(#xs .. " " .. #ys, "4 4", "four labels on each axis (none at the crossing)")
local dx, dy = xs[2].x - xs[1].x, (ys[1].y + ys[1].h / 2) - (ys[2].y + ys[2].h / 2)
check.near(dx, dy, 1.5, "equal units: a unit as long on both axes")
check.truthy(dx > 80, "the framing's scale, not 1 px a unit")
local axis_y = ys[1].y + ys[1].h / 2 + dy   -- the x axis: one unit under the label "1"
check.near(xs[1].y, axis_y + 5, 1.5, "x labels 5 px under the axis")
print(arg[0] .. ": " .. check.count .. " checks passed")
