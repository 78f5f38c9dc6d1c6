-- Benchmark: point equations sampled at a million parameter values, three ways in one run:
--   compiled   the equation built on param "t" and sampled in C into one buffer:
--              M:sample(0, 1, N, buf) (the C loop too writes into one array)
--   Lua        the same computation written with plain Lua numbers (the baseline)
--   C          hand-written C loops (bench/equations_c.c, built beside the pointcalc program)
-- for two equations:
--   oval       Stepanov's example 2: lerp(lerp(P0, P1, c), lerp(P3, P2, c), d),
--              c = (1 + cos u)/2, d = (1 + sin u)/2, u = 2 pi t
--   order6     Konopatsky's order-6 interpolation curve (4.28) through 7 points, written as
--              the book prints it: M_j times its row of coefficients of t̄^(6-i) t^i
-- Every form computes all N points and a checksum of their coordinates (the three must agree).
-- Aim (issue 13): compiled >= 5x faster than Lua, and within 2x of C.
-- Run: build/pointcalc bench/equations.lua [N [rounds]].  Not a test: nothing passes or fails.

local N = tonumber(arg and arg[1]) or 1000000
local R = tonumber(arg and arg[2]) or 5
local pi, cos, sin, clock = math.pi, math.cos, math.sin, os.clock

-- ---- the equations -------------------------------------------------------------------------
local t = param "t"
local P0, P1, P2, P3 = P(100, 100), P(300, 150), P(280, 200), P(150, 300)
local function oval_eq(t)
  local u = 2*pi*t
  local c, d = (1 + cos(u))/2, (1 + sin(u))/2
  return lerp(lerp(P0, P1, c), lerp(P3, P2, c), d)
end

local rows = {{1, -8.7, 22.7, -22.7, 8.7, -1, 0}, {0, 36, -133.2, 151.2, -61.2, 7.2, 0},
  {0, -45, 301.5, -418.5, 184.5, -22.5, 0}, {0, 40, -308, 600, -308, 40, 0},
  {0, -22.5, 184.5, -418.5, 301.5, -45, 0}, {0, 7.2, -61.2, 151.2, -133.2, 36, 0},
  {0, -1, 8.7, -22.7, 22.7, -8.7, 1}}
local ys = {0, 3, 1, 4, 1, 5, 9}
local function order6_eq(t)
  local M
  for j = 1, 7 do
    local phi = 0
    for i = 0, 6 do
      if rows[j][i + 1] ~= 0 then phi = phi + rows[j][i + 1] * bar(t)^(6 - i) * t^i end
    end
    M = M and M + P(j - 1, ys[j])*phi or P(j - 1, ys[j])*phi
  end
  return M
end

-- ---- plain Lua numbers ------------------------------------------------------------------------
local function oval_lua()
  local x0, y0, x1, y1, x2, y2, x3, y3 = 100, 100, 300, 150, 280, 200, 150, 300
  local s = 0
  for i = 0, N - 1 do
    local u = 2 * pi * (i / (N - 1))
    local c, d = (1 + cos(u)) / 2, (1 + sin(u)) / 2
    local xa, ya = x0 + c * (x1 - x0), y0 + c * (y1 - y0)
    local xb, yb = x3 + c * (x2 - x3), y3 + c * (y2 - y3)
    s = s + (xa + d * (xb - xa)) + (ya + d * (yb - ya))
  end
  return s
end

local function order6_lua()
  local s = 0
  for i = 0, N - 1 do
    local t = i / (N - 1)
    local tb = 1 - t
    local x, y = 0, 0
    for j = 1, 7 do
      local r = rows[j]
      local phi = r[1]*tb^6 + r[2]*tb^5*t + r[3]*tb^4*t^2 + r[4]*tb^3*t^3 + r[5]*tb^2*t^4
                + r[6]*tb*t^5 + r[7]*t^6
      x = x + (j - 1) * phi
      y = y + ys[j] * phi
    end
    s = s + x + y
  end
  return s
end

-- ---- timing ---------------------------------------------------------------------------------------
local function best(f)
  local b, v = math.huge, nil
  for _ = 1, R do
    collectgarbage("collect")
    local c0 = clock()
    v = f()
    b = math.min(b, clock() - c0)
  end
  return b * 1e9 / N, v
end

-- the C loops: equations_c beside the program running this script
local function c_loops()
  local dir = (arg and arg[-1] or ""):match("^(.*)/[^/]*$") or "."
  local prog = dir .. "/equations_c"
  local f = io.open(prog, "r")
  if not f then return {} end
  f:close()
  local p = io.popen(string.format("%q %d %d", prog, N, R))
  local out = {}
  for line in p:lines() do
    local name, ns, sum = line:match("^(%S+) (%S+) (%S+)$")
    if name then out[name] = {tonumber(ns), tonumber(sum)} end
  end
  p:close()
  return out
end

print(string.format("Point equations sampled at %d parameter values (best of %d rounds)", N, R))
local C = c_loops()
for _, case in ipairs{{"oval", oval_eq, oval_lua, "Stepanov example 2's oval"},
                      {"order6", order6_eq, order6_lua, "Konopatsky's order-6 curve (4.28)"}} do
  local name, eqf, luaf, title = case[1], case[2], case[3], case[4]
  local M = eqf(t)
  local buf = M:sample(0, 1, N)          -- the buffer, reused by every round as the C loop does
  local tc, sc = best(function() return M:sample(0, 1, N, buf):sum() end)
  local tl, sl = best(luaf)
  assert(math.abs(sc - sl) <= 1e-9 * math.abs(sl), name .. ": compiled and Lua disagree")
  local line = string.format("%-34s compiled %6.1f ns   Lua %6.1f ns (compiled %4.1fx faster)",
                             title, tc, tl, tl / tc)
  local c = C[name]
  if c then
    assert(math.abs(c[2] - sl) <= 1e-9 * math.abs(sl), name .. ": C and Lua disagree")
    line = line .. string.format("   C %5.1f ns (compiled %3.1fx the C loop)", c[1], tc / c[1])
  else
    line = line .. "   (equations_c not found beside the program: no C figure)"
  end
  print(line)
end
