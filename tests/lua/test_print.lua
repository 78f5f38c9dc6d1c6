-- The print look from Lua: figure{}, physical and named pens, label options and math, save()
-- to PDF/EPS/PNG/SVG in the print look, and every argument error.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local dir = os.getenv("TMPDIR") or "/tmp"
local base = dir .. "/pc_test_print_" .. tostring(os.time()) .. "_" .. tostring(math.random(1e6))

local function read(path)
  local f = assert(io.open(path, "rb"))
  local s = f:read("a")
  f:close()
  os.remove(path)
  return s
end

-- a math label is laid out in the VGA look too: the subscript below the base's baseline
screen(12)
cls()
label("$A_1$", 100, 100, "se")   -- the cell box's top-left pixel at (103, 103)
local lowest_a, lowest_1 = 0, 0
for y = 103, 125 do
  for x = 103, 110 do if point(x, y) ~= 0 then lowest_a = y end end
  for x = 111, 118 do if point(x, y) ~= 0 then lowest_1 = y end end
end
check.eq(lowest_a, 114, "the A stands on the 8x16 cell's baseline")
check.eq(lowest_1 > lowest_a, true, "the subscript goes lower")

-- math errors name the label and the character
check.err(function() label("$A_{1$", 0, 0) end, "label: label '$A_{1$': unbalanced '{' at character 4", "brace")
check.err(function() label("$\\nope$", 0, 0) end, "unknown command '\\nope' at character 2", "command")
check.err(function() text(0, 0, "$x") end, "text: label '$x': unclosed '$' at character 1", "unclosed")
label("costs \\$5", 0, 0)   -- an escaped dollar is a dollar

-- label options
label("$\\varphi$", 50, 50, "n", {size = 12, font = "sans", halo = false})
label("B", 50, 50, {size = "14pt"})
check.err(function() label("A", 0, 0, {colour = 3}) end,
  "label: unknown option 'colour' (the options are font, size, halo)", "unknown label option")
check.err(function() label("A", 0, 0, {halo = 1}) end, "label: option 'halo' must be a boolean, got 1", "halo")
check.err(function() label("A", 0, 0, {size = 0}) end, "label: option 'size' must be 1 to 200 pt, got 0 pt", "size")
check.err(function() label("A", 0, 0, {font = "No Such Face"}) end,
  "label: font 'No Such Face' is not installed", "font")

-- pens
pen "main"
pen "thin"
pen "hidden"
pen "centre"
pen{width = "0.5mm", dash = {"3mm", "1.5mm"}}
pen{width = "0.8pt"}
pen()
check.err(function() pen "bold" end, "pen: unknown pen \"bold\"", "pen name")
check.err(function() pen{width = "2furlongs"} end, "pen: option 'width' unknown unit 'furlongs'", "pen unit")
check.err(function() pen{width = "0.01mm"} end, "pen: width must be 0.1..100 pt", "pen range")
check.err(function() pen{width = "1mm", dash = {"1mm"}} end, "an even number", "pen dash")

-- figure
check.err(function() figure(3) end, "figure: argument #1 (options) must be a table", "figure arg")
check.err(function() figure{widht = "12cm"} end,
  "figure: unknown option 'widht' (did you mean 'width'?)", "figure key")
check.err(function() figure{width = 12} end,
  "figure: option 'width' must be a length with its unit such as \"12cm\" or \"0.5mm\", got 12", "figure unit")
check.err(function() figure{width = "12"} end,
  "figure: option 'width' the length '12' needs a unit (cm, mm, in, pt or px)", "no unit")
check.err(function() figure{dpi = 3} end, "figure: option 'dpi' must be a number from 10 to 2400, got 3", "dpi")
check.err(function() figure{size = 0} end, "figure: option 'size' must be 1 to 200 pt, got 0 pt", "figure size")
check.err(function() figure{font = "No Such Face"} end, "font 'No Such Face' is not installed", "figure font")
check.err(function() figure{width = "300cm", dpi = 600} end, "at most 20000 a side", "too many pixels")

-- PDF and EPS are always the print look; PNG and SVG after figure{}
screen(12)
window(-1, -1, 1, 1)
line(-1, -1, 1, 1)
label("$P_0$ угол", 0, 0)
save(base .. ".pdf")
check.eq(read(base .. ".pdf"):sub(1, 5), "%PDF-", "a PDF")
save(base .. ".eps")
check.eq(read(base .. ".eps"):sub(1, 23), "%!PS-Adobe-3.0 EPSF-3.0", "an EPS")
save(base .. ".svg")
local vga = read(base .. ".svg")
check.eq(vga:find("font-family=\"monospace\"", 1, true) ~= nil, true, "without figure{} the SVG is the VGA look")
figure{width = "12cm", dpi = 300}
save(base .. ".svg")
local svg = read(base .. ".svg")
check.eq(svg:find("CMU Serif", 1, true) ~= nil, true, "the print SVG names its font")
check.eq(svg:find("<tspan[^>]*font%-style=\"italic\"[^>]*>P</tspan>") ~= nil, true, "P italic in a tspan")
check.eq(svg:find("width=\"340.157pt\"", 1, true) ~= nil, true, "12 cm wide")
save(base .. ".png")
local png = read(base .. ".png")
local w = string.unpack(">I4", png, 17)
check.eq(w, 1417, "12 cm at 300 dpi is 1417 pixels wide")

check.done()
