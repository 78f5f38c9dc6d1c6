-- Point equations (param "t"): the same points as the plain Lua function at 1000 parameter
-- values (1e-12 relative), exact tangents, normals and curvatures of curve(M, t0, t1),
-- surfaces, families M(t; s), the book's notation, math.* and the smoothsteps on equations,
-- numbers untouched by the wrappers, the membership condition when an equation is made, mixed
-- dimensions and every other error in the house style.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local pi, cos, sin, sqrt = math.pi, math.cos, math.sin, math.sqrt
local same = check.same_within(1e-12)

local t = param "t"
eq(tostring(t), "t", "a parameter prints as its name")
eq(param "t", t, "one parameter per name")
eq(t.dim, 0, "a parameter is a scalar")

-- 1000 parameter values: the equation against the Lua function it is written like ----------
local function agree(M, f, a, b, what)
  local worst = 0
  for i = 0, 999 do
    local u = a + (b - a) * i / 999
    local p, q = M(u), f(u)
    for k = 1, #q do
      local d = math.abs(p[k] - q[k]) / math.max(1, math.abs(q[k]))
      if d > worst then worst = d end
    end
  end
  check.truthy(worst <= 1e-12, what .. ": 1000 values within 1e-12 (worst " .. worst .. ")")
end

local A, B, C = P(0, 0), P(1, 2), P(4, 0)
local M = A*bar(t)^2 + 2*B*t*bar(t) + C*t^2                       -- §5.3, the parabola
agree(M, function(t) return A*bar(t)^2 + 2*B*t*bar(t) + C*t^2 end, -0.5, 1.5, "Bezier form")

local f = param "f"
local E = (A - C)*math.cos(f) + (B - C)*math.sin(f) + C            -- (2.24)
agree(E, function(f) return (A - C)*math.cos(f) + (B - C)*math.sin(f) + C end, 0, 2*pi, "(2.24)")

-- Stepanov example 2's oval: three lerps of the sampled smooth functions
local P0, P1, P2, P3 = P(100, 100), P(300, 150), P(280, 200), P(150, 300)
local function oval(t)
  local u = 2*pi*t
  local c, d = (1 + cos(u))/2, (1 + sin(u))/2
  return lerp(lerp(P0, P1, c), lerp(P3, P2, c), d)
end
agree(oval(t), oval, 0, 1, "example 2's oval")

-- the same function of a number and of a parameter: every operation and function
local function zoo(t)
  local s = smooth.sine(t) + smooth.cubic(t) + smooth.power(3)(t) + smooth.half(2, 3, .4)(t)
  local r = math.sqrt(1 + t^2) + math.exp(-t) * math.log(2 + t) + math.abs(t - .5) + math.tan(t/2)
  local v = V(1, 2)*s + V(-2, 1)*(r / (1 + t*t)) + V(0, 1)*(2^t) + V(1, 0)*t^2.5
  local w = unit(v)*3 + V(1, 1)*dot(v, V(1, -1)) + V(0, 1)*cross(v, V(2, 1))
  return P(0.5, -1) + w + (v - w)*(-t)/2
end
agree(zoo(t), zoo, 0.01, 1, "every operation")
local Pt = P(t, t^2)                                              -- coordinates as equations
agree(Pt, function(t) return P(t, t^2) end, -2, 2, "P(t, t^2)")

-- curves: exact tangents, normals, curvature -----------------------------------------------------
local r = 2.5
local circle = curve(P(1, -1) + V(r, 0)*math.cos(f) + V(0, r)*math.sin(f), 0, 2*pi)
eq(circle.kind, "equation", "kind"); eq(circle.dim, 2, "dim"); eq(circle.closed, true, "closed")
for u = 0, 6, .5 do
  near(circle:curvature(u), 1/r, 1e-13, "circle curvature 1/r at " .. u)
  same(circle:tangent(u), V(-sin(u), cos(u)), "circle tangent at " .. u)
  same(circle:normal(u), V(-cos(u), -sin(u)), "circle normal at " .. u)
  same(circle:deriv(u, 2), V(-r*cos(u), -r*sin(u)), "C'' at " .. u)
end
near(circle:length(), 2*pi*r, 1e-9, "circumference")
local parab = curve(P(-1, 1)*bar(t)^2 + 2*P(0, -1)*t*bar(t) + P(1, 1)*t^2, 0, 1)   -- y = x^2
near(parab:curvature(.5), 2, 1e-13, "parabola: curvature 2 at the vertex")
same(parab(.75), P(.5, .25), "parabola point")
local l, rr = parab:split(.5)
same(l(.25), parab(.25), "split keeps the points"); same(rr(.75), parab(.75), "right part")
local lo, hi = parab:bbox()
same(lo, P(-1, 0), "bbox low corner", 1e-9); same(hi, P(1, 1), "bbox high corner", 1e-9)
-- a Lua-function curve keeps working beside it
local luac = curve(function(u) return P(u, u^2) end, -1, 1)
near(luac:curvature(0), 2, 1e-5, "a Lua curve still differences")

-- a rational quadratic (a conic arc) written as a weighted sum over its weight: a quarter circle
local w = sqrt(2)/2
local Q = (P(1, 0)*bar(t)^2 + P(1, 1)*(2*w*t*bar(t)) + P(0, 1)*t^2) / (bar(t)^2 + 2*w*t*bar(t) + t^2)
local qc = curve(Q, 0, 1)
for u = 0, 1, .1 do
  near(dist(qc(u), P(0, 0)), 1, 1e-14, "on the unit circle at " .. u)
  near(qc:curvature(u), 1, 1e-12, "curvature 1 at " .. u)
end

-- the order-6 interpolation curve (4.28) through (j, y_j), at t = 3/10: (9/5, 33729/78125)
local rows = {{1, -8.7, 22.7, -22.7, 8.7, -1, 0}, {0, 36, -133.2, 151.2, -61.2, 7.2, 0},
  {0, -45, 301.5, -418.5, 184.5, -22.5, 0}, {0, 40, -308, 600, -308, 40, 0},
  {0, -22.5, 184.5, -418.5, 301.5, -45, 0}, {0, 7.2, -61.2, 151.2, -133.2, 36, 0},
  {0, -1, 8.7, -22.7, 22.7, -8.7, 1}}
local ys = {0, 3, 1, 4, 1, 5, 9}
local function order6(t)
  local M6
  for j = 1, 7 do
    local phi = 0
    for i = 0, 6 do phi = phi + rows[j][i + 1] * bar(t)^(6 - i) * t^i end
    M6 = M6 and M6 + P(j - 1, ys[j])*phi or P(j - 1, ys[j])*phi
  end
  return M6
end
local M6 = order6(t)
same(M6(.3), P(9/5, 33729/78125), "(4.28) at t = 3/10")
agree(M6, order6, 0, 1, "(4.28)")
local s6 = M6:sample(0, 1, 7)
eq(#s6, 7, "samples"); same(s6[4], P(3, 4), "sample 4 is node 4")
near(s6:sum(), 21 + 23, 1e-11, "sum of the nodes' coordinates")
eq(M6:sample(0, 1, 7, s6), s6, "sampled again into the same object")
same(s6[7], P(6, 9), "the last node")
err(function() return M6:sample(0, 1, 8, s6) end, "M:sample: argument #4 (into) must be samples of 8 2-D values", "wrong size")

-- surfaces -----------------------------------------------------------------------------------------
local u, v = param "u", param "v"
local S = lerp(lerp(P(0, 0, 0), P(1, 0, 0), u), lerp(P(0, 1, 0), P(1, 1, 1), u), v)   -- z = uv
local s = surface(S, 0, 1, 0, 1)
same(s(.3, .8), P(.3, .8, .24), "bilinear surface")
local n = s:normal(.3, .8)
same(n, unit(V(-.8, -.3, 1)), "exact normal")
local Su, Sv = select(2, s:partials(.3, .8))
same(Su, V(1, 0, .8), "dS/du"); same(Sv, V(0, 1, .3), "dS/dv")

-- families: M(t; s) at values of s ----------------------------------------------------------------
local sp = param "s"
local Fam = lerp(lerp(A, B, sp), lerp(B, C, sp), t)            -- a moving simplex: de Casteljau
eq(#Fam.params, 2, "two parameters")
eq(Fam.params[1], "t", "in the order they were made"); eq(Fam.params[2], "s", "then s")
same(Fam(.25, .5), lerp(lerp(A, B, .5), lerp(B, C, .5), .25), "M(t, s) positional")
same(Fam{t = .25, s = .5}, Fam(.25, .5), "M{t =, s =}")
err(function() return Fam{t = .25, ss = .5} end, "Fam: unknown option 'ss' (did you mean 's'?)", "M{...} with a misspelt parameter")
err(function() return Fam{t = .25, s = .5, zzz = 1} end, "Fam: unknown option 'zzz' (the options are t, s)", "M{...} with an unknown key")
local F5 = Fam:with{s = .5}
eq(#F5.params, 1, "one parameter left")
same(F5(.25), Fam(.25, .5), "instantiated")
eq(Fam:with{s = .5}, F5, "the same instance twice is one equation")
local diag = Fam:with{s = t}                                    -- s = t: the parabola of A, B, C
same(diag(.3), lerp(lerp(A, B, .3), lerp(B, C, .3), .3), "s = t")
truthy(curve(F5, 0, 1), "an instance is a curve")

-- the book's notation --------------------------------------------------------------------------------
eq(M:show{A = A, B = B, C = C}, "A*bar(t)^2 + 2*B*t*bar(t) + C*t^2", "Bezier form in the book's letters")
eq(tostring(M), "P(0, 0)*bar(t)^2 + 2*P(1, 2)*t*bar(t) + P(4, 0)*t^2", "tostring")
eq(tostring(E), "V(-4, 0)*cos(f) + V(-3, 2)*sin(f) + P(4, 0)", "(2.24) with A - C folded")
eq(tostring((1 - t^2)/(1 + t^2)), "(1 - t^2)/(1 + t^2)", "a quotient")
eq(tostring(smooth.sine(t)), "smooth.sine(t)", "a smoothstep")

-- the wrappers leave numbers alone ------------------------------------------------------------------------
eq(math.sin(0.5), sin(0.5), "math.sin of a number")
eq(math.abs(-3), 3, "math.abs of an integer"); eq(math.type(math.abs(-3)), "integer", "stays an integer")
eq(math.log(8, 2), 3, "log with a base")
eq(math.sqrt(2), 2^0.5, "sqrt")
same((P(0, 0) + V(1, 0)*math.log(t, 2) + V(0, 1)*t)(8), P(3, 8), "log base 2 of an equation", 1e-12)

-- errors ---------------------------------------------------------------------------------------------------
err(function() return curve(A*t + B*t, 0, 1) end,
  "curve: argument #1 (equation) has weight 2 at t = 1, so it is neither a point (weight 1) nor a vector (weight 0): the coefficients of a point equation must sum to 1 for a point and to 0 for a vector (the membership condition)",
  "membership condition at construction")
err(function() return curve((B - A)*t, 0, 1) end,
  "curve: argument #1 (equation) is a vector equation (weight 0), not a point", "a vector equation")
err(function() return A*t + P(1, 2, 3) end,
  "cannot add a 2-D point equation and the 3-D value P(1, 2, 3): dimensions cannot be mixed", "mixed dimensions")
err(function() return lerp(A, P(1, 2, 3), t) end,
  "lerp: argument #2 (B) is 3-D, but argument #1 (A) is 2-D (mixed dimensions)", "lerp mixed")
err(function() return A*t + 1 end, "cannot add a 2-D point equation and a number", "point plus number")
err(function() return (A*t) * (B*t) end, "cannot multiply a 2-D point equation by a 2-D point equation: use dot(u, v)", "value times value")
err(function() return t / A end, "cannot divide a scalar equation by the 2-D value P(0, 0)", "divide by a point")
err(function() return t / 0 end, "division of an equation by zero", "divide by zero")
err(function() return A*t + {} end, "cannot add a 2-D point equation and a table", "a table")
err(function() return (A*t)^2 end, "cannot raise a 2-D point equation to a number", "power of a value")
err(function() return math.sin(A*t) end, "math.sin: argument #1 (x) must be a number or a scalar equation", "sin of a value")
err(function() return dot(A*t + B*bar(t), V(1, 0)) end, "dot: argument #1 (u) must be a vector (weight 0)", "dot of a point")
err(function() return unit(V(0, 0)*t) end, "unit: the zero vector has no direction", "unit of zero")
err(function() return curve(t, 0, 1) end, "curve: argument #1 (equation) must be a point equation, got a scalar equation", "scalar curve")
err(function() return curve(Fam, 0, 1) end, "curve: argument #1 (equation) depends on t and s, but a curve has 1 parameter", "two parameters")
err(function() return curve(M, 1, 0) end, "curve: argument #3 (t1) must be greater than t0", "empty domain")
err(function() return surface(M, 0, 1, 0, 1) end, "surface: argument #1 (equation) depends on t, but a surface has 2 parameters", "one-parameter surface")
err(function() return Fam(.5) end, "Fam: needs 2 parameter values (t and s), got 1", "too few values")
err(function() return Fam:with{x = 1} end, "M:with: unknown option 'x' (did you mean 's'?)", "unknown parameter")
err(function() return Fam:with{zzz = 1} end, "M:with: unknown option 'zzz' (the options are t, s)", "unknown parameter, none near")
err(function() return Fam:with{s = A} end, "M:with: option 's' must be a number or a scalar equation, got P(", "a point for a parameter")
err(function() return Fam{t = .25} end, "Fam: option 's' must be a finite number, got nil", "M{...} without a parameter")
err(function() return Fam{t = "a", s = 1} end, "Fam: option 't' must be a finite number, got \"a\"", "M{...} with a string")
err(function() return Fam(.25, {}) end, "Fam: argument #2 (s) must be a finite number, got table", "M(t, s) with a table")
err(function() return math.log(t)(-1) end, "M: the value at t = -1 is not finite (NaN or infinite: outside the domain of a function, or a division by zero)", "non-finite with its parameter")
err(function() return param "" end, "param: argument #1 (name) must be a name of 1 to 31 characters", "empty name")
err(function() return param(3) end, "param: argument #1 (name) must be a name of 1 to 31 characters, got 3", "a number")
err(function() return math.log(t):sample(-1, 1, 3) end, "M:sample: the value at t = -1 is not finite", "sample outside the domain")

check.done()
