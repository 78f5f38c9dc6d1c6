-- Curvilinear coordinate systems (docs/toolkit.md): a system is a map (t1, t2) -> point that
-- draws its own coordinate grid and carries any curve given in (t1, t2) through it, "as a
-- lens" (Stepanov's method).  Builders: curvilinear(f), bilinear(P0, P1, P2, P3), ruled(A, B),
-- graphs(f, g), patch(S0, S1, S2, S3), with the helpers graph_on(A, B, f) and
-- screenmap(x0, y0, a).  Runs after curves.lua (file-name order), whose helpers it uses.
local M = ...
local tk = M._tk
local error = tk.raise        -- errors point at the user's line, not into this file
local xy, steps = tk.xy, tk.steps

local System = {}
System.__index = System
System.__name = "curvilinear system"

local function new(f)
  return setmetatable({ _xy = f }, System)
end

-- C(t1, t2) -> the point;  C:xy(t1, t2) -> its coordinates
function System.__call(self, t1, t2) return M.P(self._xy(t1, t2)) end
function System:xy(t1, t2)
  if getmetatable(self) ~= System then error("C:xy: call it as C:xy(...), with a colon") end
  return self._xy(t1, t2)
end
function System.__tostring() return "curvilinear system" end

local function issystem(v) return getmetatable(v) == System end

-- A method called with a dot (cv.clamp()) has no system as self: say how to call it.
local function need_self(self, name)
  if not issystem(self) then error(("C:%s: call it as C:%s(...), with a colon"):format(name, name)) end
end

-- curvilinear(f): f(t1, t2) returns a point or x, y (or is a system already)
function M.curvilinear(f)
  if issystem(f) then return f end
  if not tk.callable(f) then
    tk.argerror("curvilinear", 1, "f", "a function (t1, t2) -> point or x, y", f)
  end
  return new(function(t1, t2) return xy(f(t1, t2)) end)
end

local function plotter(opts, fname)
  local plot, post = tk.brush(opts, fname), tk.postmap(opts.map, fname)
  if post then return function(...) plot(post(...)) end end
  return plot
end

-- a grid range {a, b, step [, fine step] [, fine = {a', b', step'}]}: the values of the lines
-- (a, b, step) and the samples along the lines of the other family (the same range with the
-- fine step, or the range `fine`)
local function checkrange(r, field, fname)
  if type(r) ~= "table" or type(r[1]) ~= "number" or type(r[2]) ~= "number"
      or type(r[3]) ~= "number" then
    tk.fielderror(fname, field, "a range {a, b, step [, fine step]}", r, 4)
  end
  local fine = r.fine
  if fine ~= nil then
    if type(fine) ~= "table" or type(fine[1]) ~= "number" or type(fine[2]) ~= "number" then
      tk.fielderror(fname, field .. ".fine", "a range {a, b, step}", fine, 4)
    end
    fine = { fine[1], fine[2], fine[3] or (fine[2] - fine[1]) / 1000, qb = r.qb }
  else
    fine = { r[1], r[2], r[4] or (r[2] - r[1]) / 1000, qb = r.qb }
  end
  return { r[1], r[2], r[3], qb = r.qb }, fine
end

-- C:grid{t1 = {a, b, step [, fine]}, t2 = {a, b, step [, fine]}, family = "t1"|"t2",
--        color = c, map = m [, brush = "pset"|"dot"|fn | dots = true | qb = true]}
-- draws each line as one path (the fine step sets how finely it is first looked at), or, with
-- a brush, dots = true or qb = true, as dots at the fine steps like the listings.
-- draws the lines t1 = const (t1 = a, a + step, ..., each traced along t2 with t2's fine step)
-- and the lines t2 = const likewise; family = "t1" draws only the lines t1 = const.
-- The fine step defaults to a thousandth of the range; t1 = {a, b, step, fine = {a', b',
-- step'}} traces the lines t2 = const over another range than the values of the lines t1.
function System:grid(opts)
  need_self(self, "grid")
  local fname = "C:grid"
  if type(opts) ~= "table" then tk.argerror(fname, 1, "opts", "a table {t1 = ..., t2 = ...}", opts) end
  local plot, f, qb, family = plotter(opts, fname), self._xy, opts.qb, opts.family
  if family ~= nil and family ~= "t1" and family ~= "t2" then
    tk.fielderror(fname, "family", '"t1", "t2" or nil (both)', family)
  end
  local c1, f1 = checkrange(opts.t1, "t1", fname)
  local c2, f2 = checkrange(opts.t2, "t2", fname)
  if not tk.wants_dots(opts) then      -- each line one path, traced with its fine step
    if family ~= "t2" then
      for t1 in steps(c1, 0, 1, qb, fname, "t1") do
        tk.trace(function(t2) return f(t1, t2) end, f2[1], f2[2], f2[3], opts, fname)
      end
    end
    if family ~= "t1" then
      for t2 in steps(c2, 0, 1, qb, fname, "t2") do
        tk.trace(function(t1) return f(t1, t2) end, f1[1], f1[2], f1[3], opts, fname)
      end
    end
    return
  end
  if family ~= "t2" then
    for t1 in steps(c1, 0, 1, qb, fname, "t1") do
      for t2 in steps(f2, 0, 1, qb, fname, "t2") do plot(f(t1, t2)) end
    end
  end
  if family ~= "t1" then
    for t2 in steps(c2, 0, 1, qb, fname, "t2") do
      for t1 in steps(f1, 0, 1, qb, fname, "t1") do plot(f(t1, t2)) end
    end
  end
end

-- C:draw(curve, {t = {a, b [, step]}, color, map}): the curve given in the system's parameters
-- (a function t -> t1, t2 or a 2-D point (t1, t2), or a curve object) seen through the system,
-- as one path; with a brush, dots = true or qb = true, dots at the steps as the listings draw.
function System:draw(curve, opts)
  need_self(self, "draw")
  opts = opts or {}
  if type(opts) ~= "table" then tk.argerror("C:draw", 2, "opts", "a table", opts) end
  local f = self._xy
  local function through(t1, t2, extra)    -- (t1, t2) are the system's two parameters
    if extra ~= nil then
      error("C:draw: the curve must give the system's two parameters (t1, t2), got three or more", 2)
    end
    return f(t1, t2)
  end
  if not tk.wants_dots(opts) and opts.t ~= nil then
    if not tk.callable(curve) then tk.argerror("C:draw", 1, "curve", "a function of t or a curve", curve) end
    local r = opts.t
    if type(r) ~= "table" or type(r[1]) ~= "number" or type(r[2]) ~= "number" then
      tk.fielderror("C:draw", "t", "a range {a, b [, step]}", r)
    end
    local coords = tk.coords
    return tk.trace(function(t) return through(coords(curve(t))) end, r[1], r[2], r[3], opts, "C:draw")
  end
  local plot = plotter(opts, "C:draw")
  tk.walk(curve, opts, "C:draw", function(...) plot(through(...)) end)
end

-- C:pre(g): the system (t1, t2) -> C(g(t1, t2)), g returning two numbers or a 2-D point
-- (a reparametrisation: a homothety, the plane -> square map squash01, ...)
function System:pre(g)
  need_self(self, "pre")
  if not tk.callable(g) then tk.argerror("C:pre", 1, "g", "a function (t1, t2) -> t1', t2'", g) end
  local f = self._xy
  return new(function(t1, t2) return f(xy(g(t1, t2))) end)
end

-- C:post(h): the system (t1, t2) -> h(C(t1, t2)), h(x, y) returning two numbers or a point
-- (e.g. screenmap(320, 240, 100) from mathematical to screen coordinates)
function System:post(h)
  need_self(self, "post")
  if not tk.callable(h) then tk.argerror("C:post", 1, "h", "a function (x, y) -> x', y'", h) end
  local f = self._xy
  return new(function(t1, t2) return xy(h(f(t1, t2))) end)
end

-- C:clamp{t1 = true, t2 = true, qb = false}: the system with the clamped smoothstep s(t)
-- (examples 20-22) applied to the chosen parameters (both when none is named).  qb = true
-- reproduces the listings' strict IF chain: at t exactly 0, 1/2 or 1 the previous s is kept
-- (starting from 0, as QBasic's undeclared variables do).
function System:clamp(opts)
  need_self(self, "clamp")
  opts = opts or {}
  if type(opts) ~= "table" then tk.argerror("C:clamp", 1, "opts", "a table {t1 = ..., t2 = ...}", opts) end
  local c1, c2 = opts.t1, opts.t2
  if c1 == nil and c2 == nil then c1, c2 = true, true end
  local f, clamp = self._xy, M.smooth.clamp
  if opts.qb then
    local q, s1, s2 = M.smooth.clamp_qb, 0, 0
    return new(function(t1, t2)
      if c1 then s1 = q(t1, s1); t1 = s1 end
      if c2 then s2 = q(t2, s2); t2 = s2 end
      return f(t1, t2)
    end)
  end
  return new(function(t1, t2)
    if c1 then t1 = clamp(t1) end
    if c2 then t2 = clamp(t2) end
    return f(t1, t2)
  end)
end

-- ---- builders ---------------------------------------------------------------------------------

-- bilinear(P0, P1, P2, P3): X = P0 + t1 (P1 - P0) + t2 (P3 - P0) + t1 t2 (P2 - P3 - P1 + P0)
function M.bilinear(P0, P1, P2, P3)
  return new(tk.bilinear(P0, P1, P2, P3))
end

-- ruled(A, B): C(t1, t2) = A(t1) + t2 (B(t1) - A(t1)); A, B return 2-D points or x, y
function M.ruled(A, B)
  if not tk.callable(A) then tk.argerror("ruled", 1, "A", "a curve (a function of t1)", A) end
  if not tk.callable(B) then tk.argerror("ruled", 2, "B", "a curve (a function of t1)", B) end
  return new(function(t1, t2)
    local ax, ay = xy(A(t1))
    local bx, by = xy(B(t1))
    return ax + t2 * (bx - ax), ay + t2 * (by - ay)
  end)
end

-- graphs(f, g): the system between the graphs y = f(x) and y = g(x): C(x, t) =
-- (x, f(x) + t (g(x) - f(x))) (example 19)
function M.graphs(f, g)
  if not tk.callable(f) then tk.argerror("graphs", 1, "f", "a function of x", f) end
  if not tk.callable(g) then tk.argerror("graphs", 2, "g", "a function of x", g) end
  return new(function(x, t)
    local fx = f(x)
    return x, fx + t * (g(x) - fx)
  end)
end

-- the numeric form t -> x, y of each curve made by graph_on, which patch() evaluates in its
-- inner loop instead of building a point per side and sample (weak keys: curves may be freed)
local numeric = setmetatable({}, { __mode = "k" })

-- graph_on(A, B, f [, a, b]): the graph of f erected on the segment AB (example 23), a curve
-- t -> A + t (B - A) + f(a + t (b - a)) perp(B - A), perp(x, y) = (y, -x), t in [0, 1]
-- (on a y-down screen perp points to the left of A -> B, i.e. "up" when AB runs to the right).
function M.graph_on(A, B, f, a, b)
  local fname = "graph_on"
  if not tk.ispoint(A) or #A ~= 2 then tk.argerror(fname, 1, "A", "a 2-D point", A) end
  if not tk.ispoint(B) or #B ~= 2 then tk.argerror(fname, 2, "B", "a 2-D point", B) end
  if not tk.callable(f) then tk.argerror(fname, 3, "f", "a function", f) end
  a, b = a or 0, b or 1
  if type(a) ~= "number" then tk.argerror(fname, 4, "a", "a number", a) end
  if type(b) ~= "number" then tk.argerror(fname, 5, "b", "a number", b) end
  local ox, oy, bx, by = A.x, A.y, B.x, B.y
  local ex, ey = bx - ox, by - oy
  if ex == 0 and ey == 0 then   -- no axis: the frame, and the graph, would collapse onto A
    tk.argerror(fname, 2, "B", "a point other than A (AB is the graph's axis)", B)
  end
  local frame, P = tk.frame_point, M.P
  local function gxy(t) return frame(ox, oy, ex, ey, t, f(a + t * (b - a))) end
  local curve = function(t) return P(gxy(t)) end
  numeric[curve] = gxy
  return curve
end

-- patch(S0, S1, S2, S3): the system inside the curvilinear quadrilateral with sides
-- S0: A0 -> A1, S1: A1 -> A2, S2: A2 -> A3, S3: A3 -> A0 (curves over [0, 1]), by the
-- blend of example 25: C(t1, 0) = S0(t1), C(1, t2) = S1(t2), C(t1, 1) = S2(1 - t1),
-- C(0, t2) = S3(1 - t2).
function M.patch(S0, S1, S2, S3)
  local fname = "patch"
  local sides = { S0, S1, S2, S3 }
  for i = 1, 4 do
    if not tk.callable(sides[i]) then
      tk.argerror(fname, i, "S" .. (i - 1), "a curve (a function of t in [0, 1])", sides[i])
    end
  end
  local function sidexy(S) return numeric[S] or function(t) return xy(S(t)) end end
  local s0, s1, s2, s3 = sidexy(S0), sidexy(S1), sidexy(S2), sidexy(S3)
  local a1x, a1y = s1(0)
  local a2x, a2y = s1(1)
  local a0x, a0y = s3(1)
  local a3x, a3y = s3(0)
  local e1x, e1y, e3x, e3y = a2x - a1x, a2y - a1y, a3x - a0x, a3y - a0y
  if e1x == 0 and e1y == 0 then error("patch: side S1 starts and ends at the same point", 2) end
  if e3x == 0 and e3y == 0 then error("patch: side S3 starts and ends at the same point", 2) end
  local coords, blend = tk.frame_coords, tk.patch_blend
  return new(function(t1, t2)
    local u0x, u0y = s0(t1)
    local u2x, u2y = s2(1 - t1)
    local xi1, eta1 = coords(a1x, a1y, e1x, e1y, s1(t2))
    local xi3, eta3 = coords(a0x, a0y, e3x, e3y, s3(1 - t2))
    return blend(u0x, u0y, u2x, u2y, xi1, eta1, xi3, eta3, t1)
  end)
end

-- screenmap(x0, y0, a [, b]): (x, y) -> (x0 + a x, y0 - b y), b = a: mathematical
-- coordinates (y up) onto the screen, the listings' `xe = x0 + a*x: ye = y0 - a*y`
function M.screenmap(x0, y0, a, b)
  local fname = "screenmap"
  -- finite numbers (screenmap(0/0, 0, 1) would put every point at NaN), scales not 0 (a map
  -- that sends the whole plane to one line is degenerate)
  local function check(n, what, v, nonzero)
    if type(v) ~= "number" then tk.argerror(fname, n, what, "a number", v) end
    if v ~= v or v == math.huge or v == -math.huge or (nonzero and v == 0) then
      tk.argerror(fname, n, what, nonzero and "a finite number other than 0" or "a finite number", v)
    end
  end
  check(1, "x0", x0)
  check(2, "y0", y0)
  check(3, "a", a, true)
  b = b or a
  check(4, "b", b, true)
  local f = function(x, y)
    if type(x) ~= "number" then x, y = xy(x) end
    return x0 + a * x, y0 - b * y
  end
  tk.numeric_maps[f] = true     -- map = screenmap(...) is called with numbers (no point per sample)
  return f
end
