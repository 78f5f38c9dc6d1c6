-- The curve side of the curvilinear-coordinates toolkit (docs/toolkit.md): plot, stroke{...},
-- and the drawing methods of the curve objects made by spline2, stroke and fourier
-- (c:each{...}, c:draw{...}).  Also the helpers shared with curvilinear.lua, kept in the
-- private table _tk: sampling ranges, brushes, map results.
local M = ...
local tk = M._tk
local floor, cos, sin, pi = math.floor, math.cos, math.sin, math.pi
local type, select, tostring = type, select, tostring

-- ---- errors in the house style -------------------------------------------------------------
-- The one layer is in C (stdlib/lua/pcl_util.c): tk.raise(msg) locates msg at the user's code
-- (the innermost function that is not an embedded helper), tk.argerror(fname, n, what,
-- expected, value) and tk.fielderror(fname, field, expected, value) word it, tk.shown(v) shows
-- a value as the messages do.
local error, shown = tk.raise, tk.shown

-- The options with colour = given as color = (a copy), for the code that reads opts.color.
local function as_color(opts)
  if opts.colour == nil then return opts end
  local o = {}
  for k, v in pairs(opts) do o[k] = v end
  o.color, o.colour = opts.colour, nil
  return o
end

-- tk.check_options(fname, opts, known) -> opts: the option tables of the Lua-written calls
-- (plot, c:each, stroke) checked as the C layer checks declared ones: an unknown key is an error
-- naming it with the nearest known one (known: a set {key = true}); colour = is color = (opts
-- comes back as a copy with color set).
function tk.check_options(fname, opts, known)
  for k in pairs(opts) do
    if type(k) ~= "string" then
      error(string.format("%s: the options hold [%s]; options are named (key = value)", fname, shown(k)), 3)
    end
    if not known[k] and not (k == "colour" and known.color) then
      local near = tk.nearest(k, known)
      error(string.format("%s: unknown option '%s' (%s)", fname, k,
        near and "did you mean '" .. near .. "'?" or "see :help " .. fname), 3)
    end
  end
  if opts.colour ~= nil and opts.color ~= nil then
    error(fname .. ": options 'color' and 'colour' are one option: give one", 3)
  end
  return as_color(opts)
end

local function ispoint(v) return getmetatable(v) == "point" end
tk.ispoint = ispoint

-- a curve object of spline2, stroke or fourier
function tk.iscurve(v)
  local mt = type(v) == "userdata" and getmetatable(v)
  return type(mt) == "table" and mt.__name == "curve"
end

local function callable(f)
  if type(f) == "function" then return true end
  local mt = getmetatable(f)
  return type(mt) == "table" and mt.__call ~= nil
end
tk.callable = callable

-- ---- sampling ranges ------------------------------------------------------------------------

-- An iterator over the parameter values of spec:
--   nil                      lo .. hi with `step` (default (hi - lo)/1000)
--   {a, b [, step] [, qb = true]}   like `for t = a, b, step` (step default (b - a)/1000);
--                            qb = true runs the loop as QBasic does (float32, qb.range)
--   a function               an iterator used as is (e.g. qb.range(0, 1, .001), one pass)
-- qb (the option of the whole call) makes every table range QBasic-faithful.
function tk.steps(spec, lo, hi, qb, fname, field)
  local a, b, step
  if spec == nil then
    a, b = lo, hi
  elseif type(spec) == "function" then
    return spec
  elseif type(spec) == "table" then
    a, b, step = spec[1], spec[2], spec[3]
    if spec.qb ~= nil then qb = spec.qb end
    if type(a) ~= "number" or type(b) ~= "number" or (step ~= nil and type(step) ~= "number") then
      tk.fielderror(fname or "draw", field or "t", "a range {a, b [, step]}", spec, 4)
    end
  else
    tk.fielderror(fname or "draw", field or "t", "a range {a, b [, step]} or an iterator", spec, 4)
  end
  step = step or (b - a) / 1000
  if step == 0 or step ~= step then
    tk.fielderror(fname or "draw", (field or "t") .. " step", "a nonzero number", step, 4)
  end
  if qb then
    if not (M.qb and M.qb.range) then error((fname or "draw") .. ": qb = true needs qb.range", 4) end
    return M.qb.range(a, b, step)
  end
  -- exactly Lua's numeric for (the accumulation of a plain Lua port)
  local t, first = a, true
  if step > 0 then
    return function()
      if first then first = false else t = t + step end
      if t <= b then return t end
    end
  end
  return function()
    if first then first = false else t = t + step end
    if t >= b then return t end
  end
end

-- ---- brushes ----------------------------------------------------------------------------------

-- The plotting function of opts.brush: "pset" (one pixel, the default), "dot" (the listings'
-- `circle (x, y), 1` brush, about 3 px wide), or function(x, y, color).
function tk.brush(opts, fname)
  local brush, color = opts.brush or "pset", opts.color
  if brush == "pset" then
    local pset = M.pset
    if color == nil then return function(x, y) pset(x, y) end end
    return function(x, y) pset(x, y, color) end
  elseif brush == "dot" then
    local circle = M.circle
    return function(x, y) circle(x, y, 1, color) end
  elseif callable(brush) then
    return function(x, y) brush(x, y, color) end
  end
  tk.fielderror(fname or "draw", "brush", '"pset", "dot" or a function(x, y, color)', brush, 4)
end

-- x, y of a map's result: two numbers or a 2-D point (a point of another dimension is an
-- error: its z would be lost)
local function xy(a, b)
  if type(a) == "number" then return a, b end
  if ispoint(a) then
    if #a ~= 2 then
      error(string.format("a map or curve must return a 2-D point or two numbers, got the %d-D %s " ..
        "(draw it through a projection: camera(f) or map = f)", #a, tostring(a)), 3)
    end
    return a.x, a.y
  end
  error("a map or curve must return a 2-D point or two numbers, got " .. shown(a), 3)
end
tk.xy = xy

-- coordinates of a point or numbers, all of them
local function coords(a, ...)
  if type(a) == "number" then return a, ... end
  if ispoint(a) then return a:coords() end
  error("a curve must return a point or numbers, got " .. shown(a), 3)
end
tk.coords = coords

-- Functions known to take coordinates (x, y) as well as a point and to return x, y (the maps
-- of screenmap): a post-map may call them with numbers, building no point per sample.
tk.numeric_maps = setmetatable({}, {__mode = "k"})

-- A numeric post-map from opts.map: nil, a projection or system (anything with :xy), or a
-- function(X) -> point or x, y called with a point.
function tk.postmap(map, fname)
  if map == nil then return nil end
  if tk.numeric_maps[map] then return map end
  local mt = getmetatable(map)
  local okxy = (type(map) == "table" or (type(mt) == "table" and mt.__name == "map"))
    and map.xy
  if okxy then return function(...) return map:xy(...) end end
  if callable(map) then
    local P = M.P
    return function(...) return xy(map(P(...))) end
  end
  tk.fielderror(fname or "draw", "map", "a function, a projection or a coordinate system", map, 4)
end

-- Walk the samples of a curve: fn(x, y [, z ...]) for each.  curve is a function of t
-- (returning a point or numbers), a curve object (each piece over opts.t, default its own
-- range), or anything with :xy(t).
function tk.walk(curve, opts, fname, fn)
  local qb = opts.qb
  if tk.iscurve(curve) then
    if curve.kind == "stroke" or curve.kind == "spline2" then   -- each piece over its own t
      for i = 1, curve.pieces do
        for t in tk.steps(opts.t, 0, 1, qb, fname) do fn(curve:piece_xy(i, t)) end
      end
    else
      for t in tk.steps(opts.t, curve.lo, curve.hi, qb, fname) do fn(curve:xy(t)) end
    end
    return
  end
  if not callable(curve) then
    tk.argerror(fname, 1, "curve", "a function of t or a curve", curve, 4)
  end
  local spec = opts.t
  if spec == nil then error(fname .. ": give the parameter range t = {a, b, step}", 4) end
  for t in tk.steps(spec, 0, 1, qb, fname) do fn(coords(curve(t))) end
end

-- ---- paths ------------------------------------------------------------------------------------

-- Dots are drawn when asked for: a brush, dots = true, or qb = true in the options or the range
-- (the listings' own sampling, pixel for pixel); otherwise a curve is flattened and drawn as
-- one path.
local function wants_dots(opts)
  local t = opts.t
  return opts.brush ~= nil or opts.dots or opts.qb or (type(t) == "table" and t.qb) or false
end
tk.wants_dots = wants_dots

-- The map opts.map as a map object (drawn by the core), or nil with a numeric post-map
local function map_object(map)
  local mt = getmetatable(map)
  if type(mt) == "table" and mt.__name == "map" then return map end
end

-- Trace t -> f(t) over [a, b] as a path: f returns a point or numbers (any dimension, drawn
-- through map or the camera).  The step, if given, sets how finely the first subdivision
-- looks (a function may wiggle between samples the adaptive test never sees).
function tk.trace(f, a, b, step, opts, fname)
  local map = opts.map
  local obj = map ~= nil and map_object(map) or nil
  local g = f
  if map ~= nil and not obj then
    local post = tk.postmap(map, fname)
    g = function(t) return post(coords(f(t))) end
  end
  local pieces = 8
  if step and step ~= 0 then pieces = math.min(4096, math.max(1, math.ceil(math.abs(b - a) / math.abs(step) / 8))) end
  if a == b then return end
  if a > b then a, b = b, a end
  tk.draw_curve(M.curve(g, a, b), opts.color, opts.tol, obj, pieces, fname)
end

-- A dot plotter for samples of any dimension: 2-D as they are, others through the camera
-- (a 3-D sample without a projection is an error, never silently flattened).
function tk.through_camera(plot, fname)
  return function(x, y, z, ...)
    if z == nil then return plot(x, y) end
    local cam = M.camera()
    local n = 3 + select("#", ...)
    if not cam or cam.nin ~= n then
      error(string.format("%s: a %d-D curve needs a projection: set camera(f) or give map = f",
        fname, n), 2)
    end
    return plot(cam:xy(x, y, z, ...))
  end
end

-- ---- plot -------------------------------------------------------------------------------------

-- plot(f, {t = {a, b [, step]}, color = c, map = m, tol = px})   a path (the default)
-- plot(f, {t = {a, b, step}, brush = "pset"|"dot"|fn | dots = true | qb = true, ...})   dots
-- draws the curve t -> f(t) (a point or numbers; 3-D and more through map or the camera).
local PLOT_KEYS = {t = true, color = true, map = true, tol = true, brush = true, dots = true, qb = true}
function M.plot(f, opts)
  opts = opts or {}
  if type(opts) ~= "table" then tk.argerror("plot", 2, "opts", "a table", opts) end
  opts = tk.check_options("plot", opts, PLOT_KEYS)
  if not wants_dots(opts) then
    if tk.iscurve(f) then return f:draw(opts) end
    if not callable(f) then tk.argerror("plot", 1, "curve", "a function of t or a curve", f) end
    local r = opts.t
    if r == nil then error("plot: give the parameter range t = {a, b, step}", 2) end
    if type(r) ~= "table" or type(r[1]) ~= "number" or type(r[2]) ~= "number"
        or (r[3] ~= nil and type(r[3]) ~= "number") then
      tk.fielderror("plot", "t", "a range {a, b [, step]}", r)
    end
    return tk.trace(f, r[1], r[2], r[3], opts, "plot")
  end
  local plot, post = tk.brush(opts, "plot"), tk.postmap(opts.map, "plot")
  if post then
    tk.walk(f, opts, "plot", function(...) plot(post(...)) end)
  else
    tk.walk(f, opts, "plot", tk.through_camera(plot, "plot"))
  end
end

-- ---- the curve objects' methods -------------------------------------------------------------

local methods = tk.curve_methods

-- c:each{t = {a, b, step}, qb = false} -> iterator of point, piece, t (a stroke's pieces each
-- over their own t; other curves over their domain, piece 1)
function methods.each(c, opts)
  if not tk.iscurve(c) then tk.raise("c:each: call it as c:each(...), with a colon") end
  opts = opts or {}
  if type(opts) ~= "table" then tk.argerror("c:each", 1, "opts", "a table {t = {a, b, step}}", opts) end
  tk.check_options("c:each", opts, {t = true, qb = true})
  local P = M.P
  local pieced = c.kind == "stroke" or c.kind == "spline2"
  local lo, hi = c.lo, c.hi
  if pieced then lo, hi = 0, 1 end
  local np = pieced and c.pieces or 1
  local i, iter = 1, tk.steps(opts.t, lo, hi, opts.qb, "c:each")
  return function()
    while true do
      local t = iter()
      if t ~= nil then
        if not pieced then return c(t), 1, t end
        return P(c:piece_xy(i, t)), i, t
      end
      i = i + 1
      if i > np then return nil end
      iter = tk.steps(opts.t, lo, hi, opts.qb, "c:each")
    end
  end
end

-- c:draw{...} is in C (stdlib/lua/l_camera.c): it checks the options and draws a path through
-- the camera or a map object itself; dots, and maps that are plain functions, come here.

-- c:draw{t = {a, b, step}, brush = "pset"|"dot"|fn, dots = true, qb = false, ...}: dots at
-- those parameters, as the listings draw them
function tk.draw_dots(c, opts)
  opts = as_color(opts)
  local plot, post = tk.brush(opts, "c:draw"), tk.postmap(opts.map, "c:draw")
  if post then
    tk.walk(c, opts, "c:draw", function(...) plot(post(...)) end)
  else
    if c.dim ~= 2 then
      error(string.format("c:draw: a %d-D curve needs map = a projection (e.g. oblique(...))",
        c.dim), 3)
    end
    tk.walk(c, opts, "c:draw", plot)
  end
end

-- c:draw{map = function(X) ... end}: the path of the mapped points
function tk.draw_mapped(c, opts)
  opts = as_color(opts)
  return tk.trace(function(t) return c(t) end, c.lo, c.hi, nil, opts, "c:draw")
end

-- ---- stroke{...} ------------------------------------------------------------------------------

local NAN = 0 / 0

local huge = math.huge
local function finite(x) return x == x and x ~= huge and x ~= -huge end

-- per-node numbers: a number (every node), a list (nil entries -> dflt), or nil (dflt).
-- The core reads NaN as "use the default", so a NaN or infinity given here is an error.
local function pernode(s, name, k, dflt)
  local v = s[name]
  local out = {}
  if v == nil or type(v) == "number" then
    if v ~= nil and not finite(v) then tk.fielderror("stroke", name, "a finite number", v, 4) end
    local x = v == nil and dflt or v
    for i = 1, k do out[i] = x end
    return out
  end
  if type(v) ~= "table" then tk.fielderror("stroke", name, "a number or a list of numbers", v, 4) end
  for i = 1, k do
    local x = v[i]
    if x == nil then x = dflt
    elseif type(x) ~= "number" then tk.fielderror("stroke", name .. "[" .. i .. "]", "a number", x, 4)
    elseif not finite(x) then tk.fielderror("stroke", name .. "[" .. i .. "]", "a finite number", x, 4) end
    out[i] = x
  end
  return out
end

local function vectors(s, name, k, d)
  local v = s[name]
  if v == nil then return nil end
  if type(v) ~= "table" then tk.fielderror("stroke", name, "a list of vectors", v, 4) end
  local out = {}
  for i = 1, k do
    local e = v[i]
    if e == nil then
      for j = 1, d do out[(i - 1) * d + j] = NAN end
    else
      if not ispoint(e) or M.weight(e) ~= 0 then
        tk.fielderror("stroke", name .. "[" .. i .. "]", "a vector V(...)", e, 4)
      end
      if #e ~= d then
        tk.fielderror("stroke", name .. "[" .. i .. "]", "a " .. d .. "-D vector", e, 4)
      end
      for j = 1, d do out[(i - 1) * d + j] = e[j] end
    end
  end
  return out
end

-- stroke{nodes = {P, ...} | x = {...}, y = {...} [, z = {...}],
--        uin = ..., kink = ... [, uin2 = ..., kink2 = ...]   angles (turns unless radians = true)
--        | ein = {V, ...} [, eout = {V, ...}]                explicit directions
--        rin = ..., rout = ..., n = ..., m = ..., t0 = ...,  per node (number = every node)
--        g = smoothstep, closed = false, ccw = true, radians = false}
local STROKE_KEYS = {}
for k in ("nodes x y z uin kink uin2 kink2 ein eout rin rout n m t0 g closed ccw radians"):gmatch("%S+") do
  STROKE_KEYS[k] = true
end
function M.stroke(s)
  local fn = "stroke"
  if type(s) ~= "table" then tk.argerror(fn, 1, "spec", "a table {nodes = {...}, ...}", s) end
  tk.check_options(fn, s, STROKE_KEYS)
  -- the nodes
  local nodes, d, k = {}, nil, nil
  if s.nodes ~= nil then
    if type(s.nodes) ~= "table" then tk.fielderror(fn, "nodes", "a list of points", s.nodes) end
    k = #s.nodes
    for i = 1, k do
      local p = s.nodes[i]
      if not ispoint(p) or M.weight(p) ~= 1 then
        tk.fielderror(fn, "nodes[" .. i .. "]", "a point", p)
      end
      local n = #p
      d = d or n
      if n ~= d then
        error(string.format("stroke: nodes[%d] is %d-D, but nodes[1] is %d-D: dimensions cannot be mixed",
          i, n, d), 2)
      end
      for j = 1, d do nodes[(i - 1) * d + j] = p[j] end
    end
  elseif s.x ~= nil then
    local cols = { s.x, s.y, s.z }
    d = s.z ~= nil and 3 or 2
    for j = 1, d do
      if type(cols[j]) ~= "table" then
        tk.fielderror(fn, ({ "x", "y", "z" })[j], "a list of numbers", cols[j])
      end
    end
    k = #s.x
    for i = 1, k do
      for j = 1, d do
        local v = cols[j][i]
        if type(v) ~= "number" or not finite(v) then
          tk.fielderror(fn, ({ "x", "y", "z" })[j] .. "[" .. i .. "]", "a finite number", v)
        end
        nodes[(i - 1) * d + j] = v
      end
    end
  else
    error("stroke: give the nodes: nodes = {P(...), ...} or x = {...}, y = {...}", 2)
  end
  if k < 2 then error("stroke: a stroke needs at least 2 nodes, got " .. k, 2) end
  if d > 16 then error("stroke: nodes must be 1-D to 16-D, got " .. d .. "-D", 2) end
  -- the directions
  local ein, eout
  local angles = s.uin ~= nil or s.kink ~= nil or s.uin2 ~= nil or s.kink2 ~= nil
  if s.ein ~= nil or s.eout ~= nil then
    if angles then error("stroke: give the directions either as angles (uin, kink) or as vectors (ein, eout), not both", 2) end
    ein = vectors(s, "ein", k, d)
    eout = vectors(s, "eout", k, d) or ein
  elseif angles then
    if d ~= 2 and d ~= 3 then error("stroke: angles need 2-D or 3-D nodes, got " .. d .. "-D", 2) end
    local unit = s.radians and 1 or 2 * pi
    local uin, kink = pernode(s, "uin", k, NAN), pernode(s, "kink", k, 0)
    ein, eout = {}, {}
    if d == 2 then
      local ys = (s.ccw == false) and 1 or -1
      for i = 1, k do
        local u, uo = uin[i] * unit, (uin[i] + kink[i]) * unit
        ein[2 * i - 1], ein[2 * i] = cos(u), ys * sin(u)
        eout[2 * i - 1], eout[2 * i] = cos(uo), ys * sin(uo)
      end
    else
      local uin2, kink2 = pernode(s, "uin2", k, 0), pernode(s, "kink2", k, 0)
      for i = 1, k do
        local u1, u2 = uin[i] * unit, uin2[i] * unit
        local o1, o2 = (uin[i] + kink[i]) * unit, (uin2[i] + kink2[i]) * unit
        ein[3 * i - 2], ein[3 * i - 1], ein[3 * i] = cos(u1) * cos(u2), sin(u1) * cos(u2), sin(u2)
        eout[3 * i - 2], eout[3 * i - 1], eout[3 * i] = cos(o1) * cos(o2), sin(o1) * cos(o2), sin(o2)
      end
    end
  end
  -- side lengths and half-splines
  local rin = s.rin ~= nil and pernode(s, "rin", k, NAN) or nil
  local rout = s.rout ~= nil and pernode(s, "rout", k, NAN) or nil
  local n, m, t0 = pernode(s, "n", k, 2), pernode(s, "m", k, 2), pernode(s, "t0", k, .5)
  local closed = s.closed and true or false
  local last = closed and k or k - 1
  for i = 1, last do
    if not (n[i] > 0) then tk.fielderror(fn, "n[" .. i .. "]", "a positive number", n[i]) end
    if not (m[i] > 0) then tk.fielderror(fn, "m[" .. i .. "]", "a positive number", m[i]) end
    if not (t0[i] > 0 and t0[i] < 1) then
      tk.fielderror(fn, "t0[" .. i .. "]", "a number in (0, 1)", t0[i])
    end
  end
  if s.g ~= nil and not callable(s.g) then tk.fielderror(fn, "g", "a smoothstep (a function of t)", s.g) end
  local c, _, bad, msg = tk.stroke(d, closed, nodes, ein, eout, rin, rout, n, m, t0, s.g)
  if not c then error(string.format("stroke: node %d: %s", bad, msg), 2) end
  return c
end
