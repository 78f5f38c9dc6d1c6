-- Benchmark: Konopatsky's chapters 4-5 in C against the same computation in plain Lua in the
-- same run.  (1) The Runge search: the optimal 6 nodes (m = 100) by approx.optimal_nodes, and
-- by a plain-Lua Nelder-Mead with the same parametrisation, starts and stopping rule, calling
-- the same Lua function f.  (2) Sampling an order-6 interpolation curve at 10000 parameters:
-- c(t) of interp.lagrange against Lagrange's weights in plain Lua numbers.
-- Run: build/pointcalc bench/konopatsky.lua.  A benchmark, not a test.
local clock = os.clock
local runge = function(x) return 1 / (1 + 25 * x * x) end

-- ---- (1) the search in plain Lua ------------------------------------------------------------
local function mse(f, x, m)
  local N, y, sse = #x, {}, 0
  for j = 1, N do y[j] = f(x[j]) end
  for i = 0, m do
    local t, xt, yt = i / m, 0, 0
    for j = 1, N do
      local w, tj = 1, (j - 1) / (N - 1)
      for q = 1, N do
        if q ~= j then local tq = (q - 1) / (N - 1); w = w * (t - tq) / (tj - tq) end
      end
      xt, yt = xt + w * x[j], yt + w * y[j]
    end
    local r = f(xt) - yt
    sse = sse + r * r
  end
  return sse / (m + 1)
end

local function z_to_nodes(z, a, b, N)
  local mx = 0
  for i = 1, #z do mx = math.max(mx, z[i]) end
  local e, s = {math.exp(-mx)}, math.exp(-mx)
  for i = 1, #z do e[i + 1] = math.exp(z[i] - mx); s = s + e[i + 1] end
  local x, c = {a}, 0
  for i = 1, N - 1 do c = c + e[i] / s; x[i + 1] = a + (b - a) * c end
  x[N] = b
  return x
end

local function nelder_mead(f, x, step, ftol, xtol, maxiter)
  local n, p, v = #x, {}, {}
  for i = 0, n do
    p[i] = {table.unpack(x)}
    if i > 0 then p[i][i] = p[i][i] + step end
    v[i] = f(p[i])
  end
  for _ = 1, maxiter do
    for i = 1, n do                    -- stable insertion sort
      local j = i
      while j > 0 and v[j] < v[j - 1] do
        v[j], v[j - 1], p[j], p[j - 1] = v[j - 1], v[j], p[j - 1], p[j]; j = j - 1
      end
    end
    local size = 0
    for i = 1, n do for k = 1, n do size = math.max(size, math.abs(p[i][k] - p[0][k])) end end
    if v[n] - v[0] <= ftol * (math.abs(v[0]) + 1e-300) and size <= xtol then break end
    local cen = {}
    for k = 1, n do local s = 0; for i = 0, n - 1 do s = s + p[i][k] end; cen[k] = s / n end
    local xr = {}
    for k = 1, n do xr[k] = 2 * cen[k] - p[n][k] end
    local fr = f(xr)
    if fr < v[0] then
      local xe = {}
      for k = 1, n do xe[k] = 3 * cen[k] - 2 * p[n][k] end
      local fe = f(xe)
      if fe < fr then p[n], v[n] = xe, fe else p[n], v[n] = xr, fr end
    elseif fr < v[n - 1] then
      p[n], v[n] = xr, fr
    else
      local xc = {}
      for k = 1, n do xc[k] = cen[k] + 0.5 * (p[n][k] - cen[k]) end
      local fc = f(xc)
      if fc < v[n] then p[n], v[n] = xc, fc
      else
        for i = 1, n do
          for k = 1, n do p[i][k] = p[0][k] + 0.5 * (p[i][k] - p[0][k]) end
          v[i] = f(p[i])
        end
      end
    end
  end
  local best = 0
  for i = 1, n do if v[i] < v[best] then best = i end end
  return p[best], v[best]
end

local function optimal_nodes_lua(f, a, b, N, m)
  local obj = function(z) return mse(f, z_to_nodes(z, a, b, N), m) end
  local best, bz = math.huge
  for start = 0, 2 do
    local x = {}
    for j = 1, N do
      local s = (j - 1) / (N - 1)
      if start == 1 then s = 0.5 - 0.5 * math.cos(math.pi * s)
      elseif start == 2 then s = 0.5 + 0.5 * (2 * s - 1) * math.abs(2 * s - 1) end
      x[j] = a + (b - a) * s
    end
    local z = {}
    for i = 1, N - 2 do z[i] = math.log((x[i + 2] - x[i + 1]) / (x[2] - x[1])) end
    local step, prev, fz = 0.5, obj(z)
    for round = 0, 39 do
      z, fz = nelder_mead(obj, z, step, 1e-13, 1e-10, 4000)
      if round > 0 and not (fz < prev * (1 - 1e-9)) then break end
      prev, step = fz, math.max(step * 0.5, 1e-4)
    end
    if fz < best then best, bz = fz, z end
  end
  return z_to_nodes(bz, a, b, N), best
end

local t0 = clock()
local xc, mc = approx.optimal_nodes(runge, -1, 1, 6)
local tc = clock() - t0
t0 = clock()
local xl, ml = optimal_nodes_lua(runge, -1, 1, 6, 100)
local tl = clock() - t0
print(string.format("Runge search, 6 nodes, m = 100: C %.3f s (MSE %.6g, node %.6f), plain Lua %.3f s "
                    .. "(MSE %.6g, node %.6f): %.1fx", tc, mc, xc[2], tl, ml, xl[2], tl / tc))

-- ---- (2) sampling an order-6 interpolation curve ---------------------------------------------
local nodes = {P(0, 0), P(1, 3), P(2, 1), P(3, 4), P(4, 1), P(5, 5), P(6, 9)}
local c = interp.lagrange(nodes)
local xs, ys = {}, {}
for j, p in ipairs(nodes) do xs[j], ys[j] = p.x, p.y end
local S = 10000
local function best_of(f)
  local b = math.huge
  for _ = 1, 5 do local t1 = clock(); f(); b = math.min(b, clock() - t1) end
  return b
end
local sx = 0
local tcurve = best_of(function()
  for i = 0, S do local M = c(i / S); sx = sx + M.x end
end)
local tlua = best_of(function()
  for i = 0, S do
    local t, x, y = i / S, 0, 0
    for j = 1, 7 do
      local w, tj = 1, (j - 1) / 6
      for q = 1, 7 do if q ~= j then local tq = (q - 1) / 6; w = w * (t - tq) / (tj - tq) end end
      x, y = x + w * xs[j], y + w * ys[j]
    end
    sx = sx + x
  end
end)
print(string.format("order-6 curve, %d samples: c(t) %.0f ns/sample, plain Lua weights %.0f ns/sample: %.1fx",
                    S + 1, tcurve / (S + 1) * 1e9, tlua / (S + 1) * 1e9, tlua / tcurve))
