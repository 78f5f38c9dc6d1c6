-- Benchmark of the drawing layer: a million PSET calls from Lua, then the time to write the
-- picture as PNG, SVG and PPM and the sizes of the files.  The baseline is the same loop
-- computing the same coordinates without drawing, so the pset figure is the cost of the call.
--   pointcalc bench/draw.lua [N]
local N = tonumber(arg and arg[1]) or 1000000
local cos, sin, clock = math.cos, math.sin, os.clock

-- a dense Lissajous figure: every point lands on screen, consecutive points are close
local function coords(i)
  local t = 2 * math.pi * i / N
  return 320 + 300 * sin(3 * t), 240 + 220 * sin(4 * t + 0.5)
end

screen(12)
local t0 = clock()
local sink = 0
for i = 0, N - 1 do
  local x, y = coords(i)
  sink = sink + x + y
end
local t_base = clock() - t0

t0 = clock()
for i = 0, N - 1 do
  local x, y = coords(i)
  pset(x, y, 1 + i % 15)
end
local t_pset = clock() - t0
local per_call = (t_pset - t_base) / N

print(string.format("pset: %d calls in %.3f s (loop alone %.3f s): %.0f ns per call, %.2f million calls/s",
  N, t_pset, t_base, per_call * 1e9, 1e-6 / per_call))

local tmp = os.tmpname()
for _, ext in ipairs { "png", "svg", "ppm" } do
  local path = tmp .. "." .. ext
  t0 = clock()
  save(path)
  local dt = clock() - t0
  local f = assert(io.open(path, "rb"))
  local size = f:seek("end")
  f:close()
  os.remove(path)
  print(string.format("write %s: %.3f s, %d bytes", ext:upper(), dt, size))
end
os.remove(tmp)
if sink ~= sink then print(sink) end
