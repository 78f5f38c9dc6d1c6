-- The figure layout through Lua: labels placed when the picture is written (in the file, not
-- on the canvas), markers, arrows, dimension lines and angle marks with their numbers, ticks,
-- hatching and centre lines, with their pixels and argument errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")

-- the colour index of pixel (x, y) of a binary PPM written by save (the screen theme)
local function ppm_pixel(path, x, y)
  local f = assert(io.open(path, "rb"))
  local data = f:read("a")
  f:close()
  local w, h, header = data:match("^P6%s+(%d+)%s+(%d+)%s+255%s()")
  local o = header + (y * tonumber(w) + x) * 3
  return data:byte(o), data:byte(o + 1), data:byte(o + 2)
end

-- a label on the crossing of two lines, the NE quadrant full of ink: written in the SE
screen(12)
line(0, 200, 639, 200)
line(300, 0, 300, 479)
for y = 100, 196, 4 do line(301, y, 400, y) end
label("Label", P(300, 200), nil, 14)
local placed = placed_labels()
check.eq(placed[1].side, "se", "the first free side")
check.eq(placed[1].x * 1000 + placed[1].y, 308208, "SE, 8 px off the point: at 3 its ascent would touch the line")
check.eq(point(310, 214), 0, "the canvas keeps the label pending")
local out = os.tmpname() .. ".ppm"
save(out)
local r, g, b = ppm_pixel(out, 0, 0)
check.eq(r + g + b, 0, "black paper")
local yellow = 0
for y = 208, 223 do
  for x = 308, 347 do
    local r2, g2, b2 = ppm_pixel(out, x, y)
    if r2 == 255 and g2 == 255 and b2 == 85 then yellow = yellow + 1 end
  end
end
check.truthy(yellow > 40, "the file has the label's glyphs in its box, " .. yellow .. " pixels")
os.remove(out)

-- crowds: 30 labels round 10 points, no two boxes overlap and all stay on the screen
cls()
for i = 0, 9 do
  local p = P(20 + 12 * (i % 5), 20 + 12 * (i // 5))
  mark(p)
  for k = 1, 3 do label(string.char(64 + k) .. i, p) end
end
placed = placed_labels()
check.eq(#placed, 30, "30 labels")
local overlaps, outside = 0, 0
for i, a in ipairs(placed) do
  if a.x < 0 or a.y < 0 or a.x + a.w > 640 or a.y + a.h > 480 then outside = outside + 1 end
  for j = i + 1, #placed do
    local o = placed[j]
    if a.x < o.x + o.w and o.x < a.x + a.w and a.y < o.y + o.h and o.y < a.y + a.h then
      overlaps = overlaps + 1
    end
  end
end
check.eq(overlaps, 0, "no overlaps")
check.eq(outside, 0, "all inside")

-- markers and arrows
cls()
mark(P(100, 100), "dot", 5, 14)
check.eq(point(102, 100), 14, "a filled dot of diameter 5")
check.eq(point(103, 100), 0, "and no more")
mark(P(200, 100), "open", 9, 14)
check.eq(point(200, 100), 0, "an open circle is empty inside")
mark(P(200, 200), "cross", 9, 12)
check.eq(point(200, 200), 12, "a cross meets at its centre")
arrow(P(100, 300), P(300, 300), "end", 10)
check.eq(point(299, 300), 10, "the tip")
check.eq(point(292, 302), 10, "the head's width")
vector(P(100, 400), V(100, 0), 11)
check.eq(point(199, 400), 11, "vector(A, v) ends at A + v")
path({ P(10, 450), P(100, 450), P(100, 400) }, { arrow = "both", color = 13 })
check.eq(point(100, 402), 13, "path: a head at its end")
check.eq(point(13, 450), 13, "and at its start")
check.err(function() path({ P(1, 1), P(2, 2) }, { arrow = "up" }) end,
  'path: option \'arrow\' must be "none", "end", "start" or "both", got "up"', "bad arrow")
check.err(function() mark(P(1, 1), "star") end,
  'mark: argument #2 (style) must be "dot", "open", "cross", "plus" or "square", got "star"', "bad style")
check.err(function() arrow(P(1, 1), P(1, 1)) end,
  "arrow: the two points coincide: no direction for the head", "no direction")

-- dimension lines and angle marks carry the numbers
cls()
window(0, 0, 8, 6)
check.near(dimension(P(1, 1), P(4, 5), 15), 5, 1e-12, "the measured length")
check.near(angle_mark(P(3, 1), P(1, 1), P(1, 3)), math.pi / 2, 1e-15, "a right angle")
check.near(angle_mark(P(3, 1), P(1, 1), P(3, 3), "a"), math.pi / 4, 1e-15, "45 degrees")
local texts = {}
for _, l in ipairs(placed_labels()) do texts[#texts + 1] = l.text end
check.eq(table.concat(texts, "|"), "5|90\u{b0}|a", "the texts written")
check.err(function() dimension(P(1, 1), P(1, 1)) end,
  "dimension: the two points coincide: nothing to measure", "zero length")
check.err(function() angle_mark(P(1, 1), P(1, 1), P(2, 2)) end,
  "angle_mark: a side has no length (A or B is the vertex O)", "degenerate angle")
window()

-- ticks, hatching, centre lines
cls()
ticks(P(100, 100), P(200, 100), 2)
check.eq(point(148, 96), 15, "two ticks about the middle")
hatch({P(300, 300), P(400, 300), P(400, 400), P(300, 400)}, 10, 0, 9)
check.eq(point(350, 310), 9, "a hatch line every 10 px")
check.eq(point(350, 315), 0, "and nothing between")
check.eq(point(350, 295), 0, "nothing outside the region")
check.err(function() hatch({P(1, 1), P(2, 2)}) end,
  "hatch: argument #1 (points) must hold at least 3 points, got 2", "too few points")
centre_line(P(110, 450), P(200, 450), 10)
local got = {}
for x = 100, 119 do got[#got + 1] = point(x, 450) == 15 and "#" or "." end
check.eq(table.concat(got), "############...##...", "long dash, dot")


-- framing: a small figure in world units fills the screen at equal units, its label inside
screen(12)
window(0, 0, 100, 100)
line(P(10, 10), P(30, 10))
line(P(10, 10), P(10, 20))
label("C", P(30, 10), "e", 14)
fit { margin = 20 }
local L = placed_labels()[1]
check.truthy(L.x >= 20 and L.x + L.w <= 620 and L.y >= 20 and L.y + L.h <= 460, "the label inside the margin")
check.eq(point(30, 10), 15, "the segment's end, in world units, drawn where later drawing goes")
pset(P(20, 10), 13)
check.eq(point(20, 10), 13, "later drawing uses the new frame")
check.err(function() fit { aspect = "round" } end,
  'fit: option \'aspect\' must be "equal" or "fill", got "round"', "bad aspect")
-- captions and device-unit text survive any window
cls()
window(-1000, -1000, -999, -999)
caption("Fig. 1", "bottom", 14)
text { x = 5, y = 5, text = "corner", units = "device", color = 13 }
placed = placed_labels()
check.eq(placed[1].x * 1000 + placed[1].y + placed[1].h, 296000 + 477, "the caption centred (48 px wide at 320), its last row 3 px up from the bottom")
check.eq(placed[2].x * 1000 + placed[2].y, 5005, "device units: pixel (5, 5)")
window()

-- axes, graphs and legends
screen(12)
window(-1, -1.5, 7, 1.5)
check.eq(axes { x = { 0, 2 * math.pi }, y = { -1, 1 }, ticks = 6 }, 7 + 5, "ticks 0 .. 6 by 1 and -1 .. 1 by 0.5")
graph(math.sin, 0, 2 * math.pi, { color = 12 })
check.eq(point(math.pi / 2, 1), 12, "the graph's top")
graph(function(x) return 1 / (x - 3) end, 2, 4, { color = 10 })
check.eq(point(3, 0.8), 0, "broken at the pole, no vertical line across it")
legend({ { "sin", 12 }, { "1/(x-3)", 10 } }, "ne")
local names = {}
for _, l in ipairs(placed_labels()) do names[#names + 1] = l.text end
check.eq(table.concat(names, " "), "1 2 3 4 5 6 -1 -0.5 0.5 1 sin 1/(x-3)", "tick labels, then the legend's names")
check.err(function() axes { x = { 1, 0 } } end, "axes: option 'x' must be {lo, hi} with lo < hi", "bad range")
check.err(function() legend({ 5 }) end, "legend: argument #1 (entries) [1] must be {name, colour}", "bad entry")
window()
-- every function of the figure layout is declared on the argument layer (docs/bindings.md)
for _, name in ipairs { "placed_labels", "mark", "arrow", "vector", "dimension", "angle_mark", "ticks",
  "hatch", "centre_line", "fit", "caption", "text", "axes", "graph", "legend", "map.view" } do
  check.truthy(pointcalc._decl[name], name .. " has a declaration")
end
print(arg[0] .. ": " .. check.count .. " checks passed")
