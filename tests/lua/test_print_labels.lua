-- Automatic labels in the print look: placed by their real (Pango) boxes at the figure's
-- size, clear of each other, and drawn in the SVG, the PDF and a PNG at any dpi where they
-- were placed; curves plotted dot by dot print as strokes.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local dir = os.getenv("TMPDIR") or "/tmp"
local base = dir .. "/pc_test_print_labels_" .. tostring(math.random(1e9))

local function read(path)
  local f = assert(io.open(path, "rb"))
  local s = f:read("a")
  f:close()
  os.remove(path)
  return s
end

local function overlaps(placed)
  local k = 0
  for i, a in ipairs(placed) do
    for j = i + 1, #placed do
      local o = placed[j]
      if a.x < o.x + o.w and o.x < a.x + a.w and a.y < o.y + o.h and o.y < a.y + a.h then k = k + 1 end
    end
  end
  return k
end

-- the VGA look: 8 x 16 cells
screen(12)
label("Дельта", P(300, 200))
check.eq(placed_labels()[1].w, 48, "VGA: six cells")

-- the print look at 480 pt for 640 pixels (0.75 pt a pixel), 10 pt labels: Pango's box with
-- its halo, not the cells; the dpi changes nothing
screen(12)
figure{width = "480pt", size = 10}
label("Дельта", P(300, 200))
local p = placed_labels()[1]
check.truthy(p.w > 30 and p.w < 48 and p.w ~= math.floor(p.w), "print: Pango's width " .. p.w)
check.truthy(p.h > 18 and p.h < 22, "print: the height of 10 pt with the halo " .. p.h)
figure{width = "480pt", size = 10, dpi = 300}
check.eq(placed_labels()[1].w, p.w, "the dpi does not change the box")
figure{width = "480pt", size = 20}
check.near(placed_labels()[1].h, 2 * p.h, 1e-6, "twice the size, twice the box")

-- a crowd of 30 math labels round 10 close points: no overlaps, all inside
screen(12)
figure{width = "480pt", size = 10}
for i = 0, 9 do
  local q = P(60 + 14 * (i % 5), 60 + 14 * (i // 5))
  mark(q)
  for k = 1, 3 do label("$" .. string.char(64 + k) .. "_{" .. i .. "}$", q) end
end
local placed = placed_labels()
check.eq(#placed, 30, "30 labels")
check.eq(overlaps(placed), 0, "no overlaps with the print boxes")
local outside = 0
for _, a in ipairs(placed) do
  if a.x < 0 or a.y < 0 or a.x + a.w > 640 or a.y + a.h > 480 then outside = outside + 1 end
end
check.eq(outside, 0, "all inside")

-- the SVG draws each label in its box: the <text>'s x is the box's left side in pt plus the
-- 1.6 pt halo, and a 300-dpi PNG and the PDF are written from the same places
screen(12)
figure{width = "480pt", size = 10}
line(P(0, 240), P(639, 240))
label("M", P(320, 240))
p = placed_labels()[1]
check.truthy(p.y + p.h <= 240 or p.y > 240, "clear of the line")
save(base .. ".svg")
local svg = read(base .. ".svg")
local x = tonumber(svg:match('<text x="([%d.]+)"'))
check.near(x, p.x * 0.75 + 1.6, 0.001, "the SVG's text at the placed box")

-- a label with a direction keeps its side and gap with its print box
screen(12)
figure{width = "480pt", size = 10}
label("A", P(100, 100), "ne")
p = placed_labels()[1]
check.eq(p.x, 103, "ne: 3 px right of the point")
check.eq(p.y + p.h, 98, "ne: its bottom 3 px above the point's pixel")

-- a circle plotted dot by dot prints as one stroked path through the dots, not as squares;
-- an isolated dot stays the square of its pixel (0.75 pt and a hair)
screen(12)
figure{width = "480pt"}
for t = 0, 2 * math.pi, 0.002 do pset(P(320 + 100 * math.cos(t), 240 + 100 * math.sin(t))) end
pset(P(10, 10))
save(base .. "_dots.svg")
svg = read(base .. "_dots.svg")
local paths, strokes = 0, 0
for _ in svg:gmatch('<path') do paths = paths + 1 end
for _ in svg:gmatch('<path[^>]-stroke="#000000"') do strokes = strokes + 1 end
check.eq(paths, 2, "the curve and the lone dot")
check.eq(strokes, 1, "the curve stroked")
check.truthy(svg:find('<path d="M7.500 7.500h0.760v0.760h%-0.760Z" fill="#000000"/>', 1) ~= nil,
             "the lone dot: its pixel's square")
local first = svg:match('<path d="M([%d. ]+)L')
check.eq(first, "315.375 180.375", "the curve starts at the first dot's pixel centre (420.5, 240.5) * 0.75")
print(arg[0] .. ": " .. check.count .. " checks passed")
