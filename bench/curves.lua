-- Benchmark: drawing a curve.  A cubic Bezier and a degree-7 B-spline (12 control points) are
-- flattened in C into the canvas as one path (c:draw), against the same curves evaluated in
-- plain Lua (de Casteljau / de Boor on numbers) at the same number of points and drawn with
-- line() segments, and evaluated only (no drawing).  Reports the time per curve and the ratios.
-- Run: build/pointcalc bench/curves.lua [rounds].  A benchmark, not a test.
local ROUNDS = tonumber(arg and arg[1]) or 200
local clock = os.clock

local function timeit(f)
  local best = math.huge
  for _ = 1, 3 do
    local t0 = clock()
    for _ = 1, ROUNDS do f() end
    best = math.min(best, (clock() - t0) / ROUNDS)
  end
  return best
end

-- plain-Lua de Boor on numbers (xs, ys: control coordinates, knots open uniform)
local function deboor(p, knots, xs, ys, t)
  local k = p + 1
  while k < #xs and knots[k + 1] <= t do k = k + 1 end   -- knots[k] <= t < knots[k+1] (1-based)
  local dx, dy = {}, {}
  for j = 0, p do dx[j], dy[j] = xs[k - p + j], ys[k - p + j] end
  for r = 1, p do
    for j = p, r, -1 do
      local i = k - p + j
      local a = (t - knots[i]) / (knots[i + p + 1 - r] - knots[i])
      dx[j] = (1 - a) * dx[j - 1] + a * dx[j]
      dy[j] = (1 - a) * dy[j - 1] + a * dy[j]
    end
  end
  return dx[p], dy[p]
end

local function open_knots(n, p)
  local kn = {}
  for i = 1, n + p + 1 do
    if i <= p + 1 then kn[i] = 0 elseif i > n then kn[i] = n - p else kn[i] = i - p - 1 end
  end
  return kn
end

local cases = {}
do
  local pts = {P(60, 420), P(160, 40), P(480, 40), P(580, 420)}
  local xs, ys = {}, {}
  for i, q in ipairs(pts) do xs[i], ys[i] = q.x, q.y end
  cases[1] = {name = "cubic Bezier", c = bezier(pts), p = 3, xs = xs, ys = ys}
  local ctl, bx, by = {}, {}, {}
  for i = 1, 12 do
    local x, y = 40 + 50 * (i - 1), (i % 2 == 0) and 80 or 400
    ctl[i], bx[i], by[i] = P(x, y), x, y
  end
  cases[2] = {name = "degree-7 B-spline", c = bspline(ctl, 7), p = 7, xs = bx, ys = by}
end

print(string.format("%-18s %8s %12s %14s %14s %8s %8s", "curve", "vertices", "C path (us)",
  "Lua+line (us)", "Lua eval (us)", "ratio", "eval"))
for _, k in ipairs(cases) do
  local c = k.c
  local n = 0
  for _, pl in ipairs(c:flatten(.25)) do n = n + #pl end     -- the vertices the path gets
  local knots = open_knots(#k.xs, k.p)
  local t0, t1 = c.t0, c.t1
  local tc = timeit(function() c:draw{color = 14} end)
  local tl = timeit(function()
    local px, py = deboor(k.p, knots, k.xs, k.ys, t0)
    for i = 1, n - 1 do
      local t = t0 + (t1 - t0) * i / (n - 1)
      if t >= t1 then t = t1 - 1e-12 end
      local x, y = deboor(k.p, knots, k.xs, k.ys, t)
      line(px, py, x, y, 14)
      px, py = x, y
    end
  end)
  local te = timeit(function()
    local s = 0
    for i = 0, n - 1 do
      local t = t0 + (t1 - t0) * i / (n - 1)
      if t >= t1 then t = t1 - 1e-12 end
      local x, y = deboor(k.p, knots, k.xs, k.ys, t)
      s = s + x + y
    end
    return s
  end)
  print(string.format("%-18s %8d %12.1f %14.1f %14.1f %7.1fx %7.1fx", k.name, n, tc * 1e6,
    tl * 1e6, te * 1e6, tl / tc, te / tc))
  cls()
end
-- a benchmark draws to be timed, not to make a picture: leave no default output behind
local tmp = os.tmpname()
save(tmp .. ".ppm")
os.remove(tmp .. ".ppm")
os.remove(tmp)
