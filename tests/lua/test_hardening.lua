-- Issue 15, items 7-9: values that used to pass silently, messages that named no function or
-- line, and userdata forged with the debug library.  Each check failed before its fix.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local here = arg[0]:match("[^/]*$")       -- messages are located at this file's lines

-- ---- 7. silently accepted bad values --------------------------------------------------------

-- one strict "#rrggbb" parser for every colour argument
for _, bad in ipairs { "#12345g", "#-1-1-1", "# 1 2 3", "#fff", "#1234567", "#12 456", "12345678" } do
  check.err(function() palette(1, bad) end, "palette: argument #2 (colour) must be", "palette " .. bad)
  check.err(function() pset(1, 1, bad) end, "pset: argument #3 (colour) must be", "pset " .. bad)
  check.err(function() line(0, 0, 5, 5, bad) end, "line: argument #5 (colour) must be", "line " .. bad)
end
check.err(function() palette(1, "#12345g") end, '"#12345g"', "the string is shown")
check.err(function() palette(1, "10") end, "palette: argument #2 (colour)", "a numeric string is no colour")
check.err(function() palette(1, {"10", 20, 30}) end, "palette: argument #2 (colour)", "nor in a table")
screen(12)
palette(1, "#A0b0C0")                     -- both cases of hexadecimal digits
pset(0, 0, 1)
check.eq(point(0, 0), 1, "palette with a good colour")
pset(1, 0, "#0aFf10")
check.truthy(point(1, 0) >= 256, "a true colour")

-- numeric strings are no coordinates
check.err(function() pset("10", "20") end, "pset: argument #1 (x) must be a number or a point, got \"10\"")
check.err(function() pset(10, "20") end, "pset: argument #2 (y) must be a number or a point, got \"20\"")
check.err(function() line(0, 0, "5", 5) end, "line: argument #3", "line's second point")
check.err(function() pset("10", "20") end, here .. ":", "located at the caller's line")

-- lerp: two points give a point at every t (the weight is not rounded away)
local p = lerp(P(0, 0), P(1, 0), 1e16)
check.eq(p.w, 1, "lerp at t = 1e16 has weight 1")
check.eq(p.x, 1e16, "lerp at t = 1e16")
check.eq(tostring(lerp(P(0, 0), P(2, 4), 0.25)), "P(0.5, 1)", "lerp unchanged at ordinary t")
check.eq(lerp(V(1, 0), V(0, 1), 1e16).w, 0, "two vectors give a vector")
check.err(function() return lerp(P(0, 0), P(2, 0), 1e308) end,
  "lerp: the result is out of range (not finite) for t = 1e+308")
check.err(function() return lerp(1, 3, 1e308) end, "lerp: the result is out of range")

-- divide: a huge lambda gives a point next to Y, never an infinity
local A, B = P(1, 0), P(2, 0)
check.eq(tostring(divide(A, B, 1e308)), "P(2, 0)", "divide(A, B, 1e308) is Y")
check.eq(tostring(divide(A, B, -1e308)), "P(2, 0)", "and -1e308 too")
check.eq(tostring(divide(A, B, 2)), "P(1.6666666666667, 0)", "(X + 2Y)/3")
check.eq(tostring(divide(A, B, 1)), "P(1.5, 0)", "the midpoint")
check.eq(divide(A, B, -1).w, 0, "lambda = -1: the improper point")
check.near(sr(A, B, divide(A, B, 7)), 7, 1e-12, "(XYZ) = lambda")
check.err(function() return divide(P(-1e308, 0), P(1e308, 0), -0.5) end,
  "divide: the point is out of range (not finite) for lambda = -0.5")

-- screenmap: finite numbers, scales other than 0
check.err(function() screenmap(0 / 0, 0, 1) end, "screenmap: argument #1 (x0) must be a finite number")
check.err(function() screenmap(0, math.huge, 1) end, "screenmap: argument #2 (y0) must be a finite number")
check.err(function() screenmap(0, 0, 0) end, "screenmap: argument #3 (a) must be a finite number other than 0")
check.err(function() screenmap(0, 0, 1, -math.huge) end, "screenmap: argument #4 (b)")
local sm = screenmap(320, 240, 100)
check.eq(select(2, sm(1, 1)), 140, "screenmap still maps")

-- smoothsteps: finite values, or an error; never NaN
check.eq(smooth.sine(1e308), 0, "sine at an even integer")
check.eq(smooth.sine(2 ^ 53 + 1), 0, "2^53 + 1 is even in doubles")
check.near(smooth.sine(0.25), (1 - math.cos(math.pi / 4)) / 2, 1e-16, "sine at 1/4 unchanged")
check.near(smooth.sine(3.5), 0.5, 1e-15, "period 2: s(3.5) = s(1.5)")
check.near(smooth.sine(-0.5), 0.5, 1e-15, "an even function")
check.err(function() return smooth.cubic(1e308) end, "smooth.cubic: the value at t = 1e+308 is out of range")
check.err(function() return smooth.power(3, -1e200) end, "smooth.power: the value at t = -1e+200 is out of range")
check.err(function() return smooth.half(2, 3, 0.5)(1e200) end, "g: the value at t = 1e+200 is out of range")

-- ---- 8. messages that name the function, the argument and the line -------------------------

local c = bezier { P(0, 0), P(1, 2), P(3, 0) }
check.err(function() c:draw(5) end, here .. ":", "c:draw(5) located")
check.err(function() c:draw(5) end, "c:draw: argument #1 (opts) must be a table {color =, tol =, map =, closed =, t =, brush =, dots =, qb =}, got 5")
check.err(function() c:each(5) end, "c:each: argument #1 (opts) must be a table")
check.err(function() c:each(5) end, here .. ":", "c:each(5) located")
local C = curvilinear(function(t1, t2) return t1, t2 end)
check.err(function() C:draw(c, 5) end, "C:draw: argument #2 (opts) must be a table, got 5")
check.err(function() return approx.mse(function() return "x" end, {0, 1}) end,
  here .. ":", "approx.mse's callback error located")
check.err(function() return approx.mse(function() return "x" end, {0, 1}) end,
  "approx.mse: the function must return a number, got string")
check.err(function() return affine({P(0, 0)}, complex(1, 2)) end,
  "affine: argument #2 (image points) must be a table of points or a simplex, got complex")
local z = complex(1, 2)
check.err(function() return z.point(5) end, "z:point: must be called on a complex number, as z:point(...)")
check.err(function() return z.point(5) end, here .. ":", "z.point(5) located")
check.eq(tostring(z:point()), "P(1, 2)", "z:point() still works")
check.err(function() return smooth.half(2, 3, 0.5).deriv(5, 0.5) end, "g:deriv: must be called on a half-spline, as g:deriv(...)")

-- the arc length of a callback curve far outside its range: the adaptive quadrature has a
-- budget (the speed by differences is noise at 1e-10; it used to run for hours)
local parabola = curve(function(t) return P(t, t * t) end, 0, 1)
local function F(t) return t / 2 * math.sqrt(1 + 4 * t * t) + math.log(2 * t + math.sqrt(1 + 4 * t * t)) / 4 end
local clock0 = os.clock()
local len = parabola:length(480, 65535)
check.truthy(os.clock() - clock0 < 10, "c:length far outside the range ends")
check.near(len / (F(65535) - F(480)), 1, 1e-6, "and is the arc length")
check.near(parabola:length(0, 1), F(1) - F(0), 1e-9, "the ordinary length unchanged")

-- ---- 5. no limit on VIEW changes ------------------------------------------------------------

-- 70,000 VIEWs (more than the 65,535 a 16-bit index held), each drawn in: the drawing is kept
screen(12)
for i = 0, 69999 do
  view(i % 7, 0, 100, 50)
  pset(0, 0, 1 + i % 7)                  -- the view's corner: screen pixel (i % 7, 0)
end
view()
for k = 0, 6 do check.eq(point(k, 0), 1 + k, "the last dot of view " .. k) end
local svgname = os.tmpname() .. ".svg"
save(svgname)
local fh = assert(io.open(svgname))
local svgtext = fh:read("a")
fh:close()
os.remove(svgname)
local _, nclip = svgtext:gsub("<clipPath", "")
check.eq(nclip, 7, "one clipPath per distinct rectangle")
local _, ngroups = svgtext:gsub('<g clip%-path=', "")
check.eq(ngroups, 70000, "each run of ops in its clip group")

-- ---- 9. forged userdata ---------------------------------------------------------------------

-- a file handle, and objects of other types, given a binding's metatable
local function forge(victim, genuine)
  debug.setmetatable(victim, debug.getmetatable(genuine))
  return victim
end

local samples = (function() local t = param "t"; return (P(t, t)):sample(0, 1, 3) end)()
local genuine = {
  point = P(1, 2), curve = c, surface = surface.bilinear(P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(1, 1, 1)),
  map = affine({P(0, 0), P(1, 0), P(0, 1)}, {P(1, 1), P(3, 1), P(1, 2)}),
  simplex = simplex(P(0, 0), P(1, 0), P(0, 1)), complex = complex(1, 2), mobius = mobius(complex(0.5, 0)),
  halfspline = smooth.half(2, 3, 0.5), oresme = oresme(0.5, 3), equation = param "u",
  samples = samples,
}
-- how each type is used: a call that reads the object
local use = {
  point = function(v) return v.x + dist(v, P(0, 0)) end,
  curve = function(v) return v:xy(0.5) end,
  surface = function(v) return v(0.5, 0.5) end,
  map = function(v) return v(P(0, 0)) end,
  simplex = function(v) return v:coords(P(0, 0)) end,
  complex = function(v) return v.re + v:abs() end,
  mobius = function(v) return v(complex(0, 0)) end,
  halfspline = function(v) return v(0.25) end,
  oresme = function(v) return v(0.5) end,
  equation = function(v) return v + 1 end,
  samples = function(v) return v:sum() end,
}
local forged = 0
for name, obj in pairs(genuine) do
  -- a real file handle (16 bytes, two pointers) given the type's metatable
  local f = forge(io.tmpfile(), obj)
  check.err(function() return use[name](f) end, "forged", name .. " from a file handle")
  -- an object of another type given it: a point of every size, a complex number
  for _, other in ipairs { P(1, 2), P(1, 2, 3, 4, 5), complex(0, 0), oresme(0.5, 2) } do
    if debug.getmetatable(other) ~= debug.getmetatable(obj) then
      forge(other, obj)
      check.err(function() return use[name](other) end, "forged", name .. " from another type")
    end
  end
  forged = forged + 1
end
check.eq(forged, 11, "every type forged")
check.err(function() return dist(P(0, 0), forge(io.tmpfile(), P(0, 0))) end,
  "dist: argument #2 is a forged point", "the message names the function and argument")
check.err(function() return use.point(forge(io.tmpfile(), P(0, 0))) end, here .. ":", "located")
-- the genuine ones still work
check.eq(use.point(genuine.point), 1 + math.sqrt(5), "a genuine point")
check.eq(use.complex(genuine.complex), 1 + math.sqrt(5), "a genuine complex number")

-- a drawing function's canvas, the random state and a range iterator replaced by upvalue
-- (upvalue 1 of a declared function is its declaration, upvalue 2 the canvas)
local box = select(2, debug.getupvalue(pset, 2))
debug.setupvalue(pset, 2, P(1, 2))
check.err(function() pset(1, 1) end, "pset: the canvas was replaced")
debug.setupvalue(pset, 2, "x")
check.err(function() pset(1, 1) end, "pset: the canvas was replaced")
debug.setupvalue(pset, 2, box)
-- a declaration swapped for another's is refused where it is attempted (the layer trusts
-- upvalue 1 without asking Lua which function runs)
local preset_decl = select(2, debug.getupvalue(preset, 1))
check.err(function() debug.setupvalue(pset, 1, preset_decl) end,
  "debug.setupvalue: upvalue 1 of a declared function is its declaration, which cannot be replaced")
check.err(function() debug.setupvalue(pset, 1, io.stdout) end, "cannot be replaced")
check.eq(getmetatable(preset_decl), "declaration", "a declaration's metatable is hidden")
check.eq(debug.setupvalue(pset, 2, box), "", "the other upvalues are set as before")
pset(2, 2, 4)
check.eq(point(2, 2), 4, "pset works again with its canvas")
local state = select(2, debug.getupvalue(qb.rnd, 2))   -- upvalue 1 is its declaration
debug.setupvalue(qb.rnd, 2, "x")
check.err(function() return qb.rnd() end, "qb.rnd: its random-number state was replaced")
debug.setupvalue(qb.rnd, 2, state)
check.truthy(qb.rnd() < 1, "qb.rnd works again")
local it = qb.range(1, 3)
debug.setupvalue(it, 1, 5)
check.err(function() return it() end, "its range was replaced")

-- blocks (QBasic GET/PUT)
local blk = get_block(0, 0, 3, 3)
local fb = forge(io.tmpfile(), blk)
check.err(function() put_block(0, 0, fb) end, "put_block: argument #3 is a forged block")
check.err(function() return fb.w end, "forged block")

-- the forged objects are collected without harm (their __gc refuses them)
genuine, fb, box = nil, nil, nil
collectgarbage()
collectgarbage()
check.eq(tostring(P(3, 4)), "P(3, 4)", "still running after the collection")

check.done()
