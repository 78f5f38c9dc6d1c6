-- Benchmark: the inner loop of Stepanov's example 2 (an oval inscribed in a quadrilateral,
-- three lerps per step), a million steps, written three ways:
--   numbers   plain Lua numbers, as the QBasic listing does it (the baseline)
--   lerp      points and lerp():      A = lerp(P0, P1, c) ...
--   operators points and operators:   A = (P1 - P0)*c + P0 ...
-- Each form ends its step by reading the point's coordinates (M.x + M.y), as a drawing or a
-- writer would, so all three compute the same checksum.  Reports ns per step and the ratios
-- against plain numbers, under the generational GC (what the pointcalc host uses) and the
-- incremental GC.  Run: build/pointcalc bench/points.lua [steps [rounds]]
-- A benchmark, not a test: nothing here passes or fails.

local N = tonumber(arg and arg[1]) or 1000000
local cos, sin, pi, clock = math.cos, math.sin, math.pi, os.clock

local x0, y0, x1, y1, x2, y2, x3, y3 = 100, 100, 300, 150, 280, 200, 150, 300
local P0, P1, P2, P3 = P(x0, y0), P(x1, y1), P(x2, y2), P(x3, y3)

local function numbers()
  local s = 0
  for i = 0, N - 1 do
    local u = 2 * pi * i / N
    local c, d = (1 + cos(u)) / 2, (1 + sin(u)) / 2
    local xa = x0 + c * (x1 - x0)
    local ya = y0 + c * (y1 - y0)
    local xb = x3 + c * (x2 - x3)
    local yb = y3 + c * (y2 - y3)
    local x = xa + d * (xb - xa)
    local y = ya + d * (yb - ya)
    s = s + x + y
  end
  return s
end

local function with_lerp()
  local s = 0
  for i = 0, N - 1 do
    local u = 2 * pi * i / N
    local c, d = (1 + cos(u)) / 2, (1 + sin(u)) / 2
    local A = lerp(P0, P1, c)
    local B = lerp(P3, P2, c)
    local M = lerp(A, B, d)
    s = s + M.x + M.y
  end
  return s
end

local function with_operators()
  local s = 0
  for i = 0, N - 1 do
    local u = 2 * pi * i / N
    local c, d = (1 + cos(u)) / 2, (1 + sin(u)) / 2
    local A = (P1 - P0) * c + P0
    local B = (P2 - P3) * c + P3
    local M = (B - A) * d + A
    s = s + M.x + M.y
  end
  return s
end

-- Rounds interleave the three forms so that they see the same machine load; each form keeps
-- its best round.
local function measure(reps)
  local forms = {numbers, with_lerp, with_operators}
  local best, sums = {math.huge, math.huge, math.huge}, {}
  for _ = 1, reps do
    for k, f in ipairs(forms) do
      collectgarbage("collect")
      local t = clock()
      sums[k] = f()
      best[k] = math.min(best[k], clock() - t)
    end
  end
  for k = 2, 3 do
    assert(math.abs(sums[k] - sums[1]) < 1e-6 * math.abs(sums[1]), "the three forms disagree")
  end
  return best[1] * 1e9 / N, best[2] * 1e9 / N, best[3] * 1e9 / N
end

local function run(mode)
  collectgarbage(mode)
  local tn, tl, to = measure(tonumber(arg and arg[2]) or 5)
  print(string.format("%-13s numbers %6.1f ns/step   lerp %6.1f ns/step (%4.1fx)   operators %6.1f ns/step (%4.1fx)",
                      mode .. " GC:", tn, tl, tl / tn, to, to / tn))
end

print(string.format("Stepanov example 2, %d steps, 3 lerps per step", N))
run("generational")
run("incremental")
collectgarbage("generational")
