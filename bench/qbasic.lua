-- Benchmark of the QBasic front end: one drawing loop (an ellipse of N points, Example 1's
-- kind) run as a translated QBasic program, and the same loop written in Lua, twice: with
-- qb.range and qb.f32 (QBasic's float32 semantics by hand) and with plain doubles (the
-- baseline).  Figures are ratios to the baseline of the same run; translation time is apart.
--   pointcalc bench/qbasic.lua [N]
local N = tonumber(arg and arg[1]) or 300000
local clock = os.clock
local qbasic = require "qbasic"

local step = 1 / N
local source = table.concat({
  "SCREEN 12",
  "pi = 3.14159: x0 = 320: r = 200: n = 0",
  "FOR t = 0 TO 1 STEP " .. string.format("%.9g", step),
  "  u = 2 * pi * t",
  "  x = x0 + r * COS(u): y = 240 + 150 * SIN(u)",
  "  PSET (x, y), 14: n = n + 1",
  "NEXT t",
}, "\n")

local t0 = clock()
local lua_text = assert(qbasic.translate(source, "bench.bas"))
local chunk = assert(load(lua_text, "=bench.bas"))
local t_translate = clock() - t0

t0 = clock()
chunk()
local t_qbasic = clock() - t0

-- the same with QBasic's semantics written by hand
local f32, cos, sin = qb.f32, math.cos, math.sin
t0 = clock()
do
  local pi, x0, r = f32(3.14159), 320, 200
  for t in qb.range(0, 1, step) do
    local u = f32(2 * pi * t)
    local x, y = f32(x0 + r * cos(u)), f32(240 + 150 * sin(u))
    pset(x, y, 14)
  end
end
local t_f32 = clock() - t0

-- plain Lua numbers: the baseline
t0 = clock()
do
  local pi, x0, r = 3.14159, 320, 200
  for t = 0, 1, step do
    local u = 2 * pi * t
    pset(x0 + r * cos(u), 240 + 150 * sin(u), 14)
  end
end
local t_plain = clock() - t0

print(string.format("QBasic loop of %d points", N))
print(string.format("translate:           %.4f s (%d source lines)", t_translate, 7))
print(string.format("plain Lua (baseline): %.3f s", t_plain))
print(string.format("Lua with qb.range/f32: %.2f x baseline", t_f32 / t_plain))
print(string.format("translated QBasic:    %.2f x baseline", t_qbasic / t_plain))
-- nothing to keep: save to a temporary file so that the host writes no default picture
local tmp = os.tmpname()
save(tmp .. ".ppm")
os.remove(tmp .. ".ppm")
os.remove(tmp)
