-- Maps and numerics through Lua (docs/toolkit.md): squash/squash01 (examples 26-28), oblique
-- and projection (examples 32-34), oresme (example 31), bisect (example 30), and their errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local pi = math.pi

local same = check.same_within(1e-9)             -- points/vectors equal within tol

-- the plane onto the open square
near(squash(0), 0, 0, "squash(0)"); near(squash(1), 1 / math.sqrt(2), 1e-15, "squash(1)")
near(320 + 200 * squash(5), 516.1, .05, "example 26: the outermost line at x = 516")
local a, b = squash(-5, 1)
near(a, -5 / math.sqrt(26), 1e-15, "squash(p, q): p"); near(b, 1 / math.sqrt(2), 1e-15, "squash(p, q): q")
near(squash(math.huge), 1, 0, "squash(inf) = 1")
near(squash01(0), .5, 0, "squash01(0)"); near(squash01(-10), .0025, 2e-5, "example 28: radius 10 -> .0025")
near(select(2, squash01(0, 10)), .9975, 2e-5, "squash01(p, q)")
err(function() squash("x") end, "squash: argument #1 (p) must be a number other than NaN, got \"x\"", "squash string")
err(function() squash(0 / 0) end, "squash: argument #1 (p) must be a number other than NaN", "squash NaN")
err(function() squash01(1, 0 / 0) end, "squash01: argument #2 (q) must be a number other than NaN", "squash01 NaN")

-- oblique projection by four screen points
local pr = oblique(P(320, 240), 150, .3, -pi / 3)
same(pr(P(1, 0, 1)), P(395, 278.9711431703 - 150), "example 33: node (1, 0, 1) at (395, 129)")
same(pr(P(1, 0, -1)), P(395, 428.9711431703), "node (1, 0, -1) at (395, 429)")
same(pr(1, 0, -1), P(395, 428.9711431703), "pr(x, y, z)")
same(pr.C0, P(320, 240), "C0"); same(pr.C3, P(320, 90), "C3 = C0 + (0, -r)")
same(pr.C1, P(320 + 150 * math.cos(-pi / 3), 240 - 150 * .3 * math.sin(-pi / 3)), "C1")
local x, y = pr:xy(P(0, 1, 0))
same(P(x, y), pr.C2, "pr:xy of the y unit point is C2")
local p34 = oblique(P(320, 400), 60, .3, pi / 5)
local ux, uy = p34:xy(1, 0, 0)
near(ux - 320, 48.5, .05, "example 34: x axis 48.5 px"); near(uy - 400, -10.6, .05, "x axis -10.6 px")
local vx, vy = p34:xy(0, 1, 0)
near(vx - 320, -35.3, .05, "example 34: y axis -35.3 px"); near(vy - 400, -14.6, .05, "y axis -14.6 px")
-- example 32's rotating radial axis is the projection of (cos a, sin a, 0)
local p32 = oblique(P(320, 400), 150, .3, pi / 6)
same(p32(P(math.cos(.7), math.sin(.7), 0)), P(320 + 150 * math.cos(pi / 6 + .7), 400 - 150 * .3 * math.sin(pi / 6 + .7)), "example 32")
-- the same map as the point engineers' affine (3-D -> 2-D by four image points)
if affine then
  local f = affine({P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(0, 0, 1)}, {pr.C0, pr.C1, pr.C2, pr.C3})
  same(f(P(.3, -.2, .7)), pr(P(.3, -.2, .7)), "oblique = affine by C0..C3", 1e-9)
end
local pj = projection(P(0, 0), P(1, 0), P(0, 1), P(1, 1))
same(pj(P(2, 3, 4)), P(6, 7), "projection by four given points")
-- a projection is a map (docs/maps.md): it prints as one, composes and has the map methods
truthy(tostring(pj) == "affine map 3-D -> 2-D [1 0 1 | 0; 0 1 1 | 0]", "tostring: [M | t]")
eq(getmetatable(pr).__name, "map", "the one map type")
truthy(pr:is_affine() and pr.nin == 3 and pr.nout == 2, "a 3-D -> 2-D affine map")
same((pj * map.translate(V(1, 1, 1)))(P(0, 0, 0)), P(2, 2), "composes with other maps")
same(pr(V(0, 0, 1)), V(0, -150), "a vector goes to a vector")
err(function() pr(P(1, 2)) end, "pr: argument #1 is 2-D, but the map takes 3-D: dimensions cannot be mixed", "2-D point")
err(function() pr:xy(V(1, 2, 3)) end, "xy: argument #1 (X) must be a point (weight 1), got weight 0", "vector")
err(function() pr("x") end, "pr: takes a 3-D point or vector, or 3 coordinates; got string", "string")
err(function() pr:xy(1, 2) end, "xy: takes a 3-D point or vector, or 3 coordinates; got number", "two numbers")
err(function() oblique(P(0, 0), "r", 1, 1) end, "oblique: argument #2 (r) must be a finite number, got \"r\"", "oblique r")
err(function() projection(P(0, 0), P(1, 0), P(0, 1, 0), P(1, 1)) end, "projection: argument #3 (C2) is 3-D, but argument #1 (C0) is 2-D (mixed dimensions)", "mixed")

-- Oresme lambda-functions: example 31
local o1, o2 = oresme(.3, 12, 1, 2), oresme(.2, 12, 1, 2)
eq(#o1, 4096, "2^12 cells"); eq(o1.m, 12, "m"); eq(o1.lambda, .3, "lambda")
near(o1(.5), 1.7, 1e-15, "y1(1/2) = 1.7"); near(o2(.5), 1.8, 1e-15, "y2(1/2) = 1.8")
near(o1[1024], .3 * 1 + .7 * 1.7, 1e-15, "y1(1/4)"); eq(o1[0], 1, "y(0)"); eq(o1[4096], 2, "y(n)")
eq(o1[4097], nil, "past the end: nil")
near(o1(.5 - 1e-6), o1[2047], 0, "lookup by INT(t n)")
near(o1(-1), 1, 0, "clamped below"); near(o1(2), 2, 0, "clamped above")
local inc = true
for j = 0, 4095 do if o1[j] >= o1[j + 1] then inc = false end end
truthy(inc, "increasing")
near(oresme(.5, 4)(.25), .25, 1e-15, "lambda = 1/2: the identity on [0, 1]")
eq(tostring(o1), "oresme(0.3, 12)", "tostring")
err(function() oresme(.3, 30) end, "oresme: argument #2 (m) must be an integer 0..24 (2^m cells), got 30", "m too big")

-- bisection: example 30 (u(x) = x^3 + x + c on [-c, 0])
local root, it = bisect(function(x) return x ^ 3 + x + 1 end, -1, 0, .001)
near(root, -0.6823278038280193, .001, "root with the listing's tolerance")
truthy(it >= 9 and it <= 11, "about 10 halvings")
near(bisect(function(x) return x ^ 3 + x + 1 end, -1, 0), -0.6823278038280193, 1e-9, "default tolerance")
eq(bisect(function(x) return x ^ 3 + x end, 0, 0, .001), 0, "c = 0: the bracket [-0, 0]")
eq(bisect(function(x) return x ^ 3 + x + 2 end, -2, 0, .001), -1, "an exact zero at a midpoint")
err(function() bisect(function(x) return x * x + 1 end, -1, 1) end, "bisect: f(a) and f(b) have the same sign (f(-1) = 2, f(1) = 2): the interval brackets no root", "no bracket")
err(function() bisect(function(x) return "a" end, 0, 1) end, "bisect: f(0) must return a number, got string", "f result")
err(function() bisect(function(x) return x > .3 and math.huge or -1 end, 0, 1) end, "bisect: f(1) must return a finite number, got inf", "f inf")
err(function() bisect(function(x) return x < .5 and -1 or 0 / 0 end, 0, 1) end, "bisect: f(1) must return a finite number", "f NaN")
err(function() bisect(5, 0, 1) end, "bisect: argument #1 (f) must be a function, got 5", "f")
err(function() bisect(math.sin, 0) end, "bisect: argument #3 (b) must be a finite number, got nil", "b")
check.done()
