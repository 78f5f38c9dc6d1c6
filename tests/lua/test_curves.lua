-- The curve builders through Lua (docs/toolkit.md): spline2 (example 5), stroke (examples 10,
-- 13, 33, 34), fourier (example 12), plot, the objects' each/draw, exact pixels, QBasic-faithful
-- sampling, and the argument errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local pi, cos, sin = math.pi, math.cos, math.sin

local same = check.same_within(1e-9)             -- points/vectors equal within tol

-- spline2: example 5 with the listing's arithmetic, t from -1 to 3 -----------------------------
local p5, r, u0, u1 = 3.14159, 100, 7 * 3.14159 / 15, .9 * 3.14159
local A, B = P(300, 200), P(350, 400)
local c5 = spline2(A, V(cos(u0), sin(u0)) * r, B, V(cos(u1), sin(u1)) * r)
eq(tostring(c5), "spline2(2-D)", "tostring"); eq(c5.kind, "spline2", "kind"); eq(c5.pieces, 1, "one piece")
for t = -1, 3, .25 do
  local xa, ya = 300 + t * r * cos(u0), 200 + t * r * sin(u0)
  local xb, yb = 350 + (t - 1) * r * cos(u1), 400 + (t - 1) * r * sin(u1)
  local g = -2 * t ^ 3 + 3 * t ^ 2
  local x, y = c5:xy(t)
  near(x, xa + g * (xb - xa), 1e-9, "example 5 x at t = " .. t)
  near(y, ya + g * (yb - ya), 1e-9, "example 5 y at t = " .. t)
end
same(c5(0), A, "X(0) = A"); same(c5(1), B, "X(1) = B")
local a0, p0, q0, b0 = c5:controls()
same(p0, A + V(cos(u0), sin(u0)) * r, "P = A + a"); same(q0, B - V(cos(u1), sin(u1)) * r, "Q = B - b")
-- another smoothstep: the sine one, a half-spline, any Lua function
local lin = spline2(P(0, 0), V(1, 0), P(10, 0), V(1, 0), function(t) return t end)
near(lin:xy(.5), 5, 1e-12, "g = identity: straight")
local s = spline2(P(0, 0), V(0, 3), P(10, 0), V(0, -3), smooth.sine)
local sx, sy = s:xy(.5)
-- M = (0, 1.5), N = Q + (B - Q)/2 = (10, 1.5), g(1/2) = 1/2: X = (5, 1.5)
near(sx, 5, 1e-12, "sine: symmetric x"); near(sy, 1.5, 1e-12, "sine: halfway between the sides' midpoints")
local h = spline2(P(0, 0), V(1, 1), P(2, 0), V(1, -1), smooth.half(8, 2, .5))
same(h(1), P(2, 0), "half-spline g: through B")

-- stroke: example 10 ---------------------------------------------------------------------------------
local X10, Y10 = {100, 200, 300, 400}, {300, 150, 50, 100}
local uin, rin, rout = {0, .3, .85, 0}, {50, 60, 40, 50}, {70, 30, 80, 40}
local n10, m10, t010 = {2, 4, 6, 2}, {7, 5, 3, 2}, {.3, .5, .7, .2}
local S = stroke{x = X10, y = Y10, uin = uin, kink = 0, rin = rin, rout = rout, n = n10, m = m10, t0 = t010}
eq(tostring(S), "stroke(4 nodes, 3 pieces, 2-D)", "tostring"); eq(S.pieces, 3, "pieces"); eq(S.dim, 2, "dim")
eq(S.closed, false, "open")
for i = 1, 3 do
  local uo, ui = 2 * pi * uin[i], 2 * pi * uin[i + 1]
  local v1, w1 = X10[i] + rout[i] * cos(uo), Y10[i] - rout[i] * sin(uo)
  local v2, w2 = X10[i + 1] - rin[i + 1] * cos(ui), Y10[i + 1] + rin[i + 1] * sin(ui)
  local n, m, t0 = n10[i], m10[i], t010[i]
  local c1 = m / ((n - n * t0 + m * t0) * t0 ^ (n - 1))
  local c2 = (1 - c1 * t0 ^ n) / ((1 - t0) ^ m)
  for t = 0, 1, .125 do
    local xa, ya = X10[i] + t * (v1 - X10[i]), Y10[i] + t * (w1 - Y10[i])
    local xb, yb = v2 + t * (X10[i + 1] - v2), w2 + t * (Y10[i + 1] - w2)
    local g = t < t0 and c1 * t ^ n or 1 - c2 * (1 - t) ^ m
    local x, y = S:piece_xy(i, t)
    near(x, xa + g * (xb - xa), 1e-9, "example 10 piece " .. i .. " x at " .. t)
    near(y, ya + g * (yb - ya), 1e-9, "example 10 piece " .. i .. " y at " .. t)
  end
  same(S:piece(i, 0), P(X10[i], Y10[i]), "piece " .. i .. " starts at its node")
  same(S:piece(i, 1), P(X10[i + 1], Y10[i + 1]), "piece " .. i .. " ends at the next node")
end
same(S(0), P(100, 300), "S(0)"); same(S(2), P(300, 50), "S(2) = node 3"); same(S(3), P(400, 100), "S(3) = end")
same(S(1.5), S:piece(2, .5), "global parameter")
-- the same stroke from points, angles in radians
local S2 = stroke{nodes = {P(100, 300), P(200, 150), P(300, 50), P(400, 100)}, radians = true,
  uin = {0, .6 * pi, 1.7 * pi, 0}, rin = rin, rout = rout, n = n10, m = m10, t0 = t010}
same(S2:piece(2, .37), S:piece(2, .37), "nodes = points, radians")
-- a kink: the outgoing direction is the incoming one turned by the kink
local K = stroke{nodes = {P(0, 0), P(100, 0), P(200, 0)}, uin = {0, 0, 0}, kink = {0, .25, 0}, rin = 30, rout = 30}
local _, pk = K:controls(2)
same(pk, P(100, -30), "kink .25 turn: leaves upward on the screen (ccw)")
local Kc = stroke{nodes = {P(0, 0), P(100, 0), P(200, 0)}, uin = 0, kink = {0, .25, 0}, rin = 30, rout = 30, ccw = false}
local _, pc = Kc:controls(2)
same(pc, P(100, 30), "ccw = false: (cos u, sin u)")
-- chord tangents and chord/3 sides, closed (the reconstructions of examples 13 and 29)
local sq = stroke{nodes = {P(0, 0), P(3, 0), P(3, 3), P(0, 3)}, closed = true}
eq(sq.pieces, 4, "closed: as many pieces as nodes"); eq(sq.closed, true, "closed")
local _, pq = sq:controls(1)
same(pq, P(1 / math.sqrt(2), -1 / math.sqrt(2)), "tangent at node 1 parallel to N2 - N4")
same(sq(4), P(0, 0), "back at the first node")
same(mid(sq(.3), sq(2.3)), P(1.5, 1.5), "symmetric about the centre")
-- a custom smoothstep for every piece (example 6: the cubic)
local cub = stroke{nodes = {P(0, 0), P(10, 0)}, ein = {V(1, 0), V(1, 0)}, rin = 3, rout = 3, g = smooth.cubic}
local _, cy = cub:xy(.3)
near(cy, 0, 1e-12, "cubic g on a straight quadrilateral")
-- a Lua smoothstep reaches _tk.stroke's g (a declared toolkit function: no forged upvalue)
local lua_g = {nodes = {P(0, 0), P(10, 0), P(10, 10)}, rin = 3, rout = 3,
               g = function(t) return smooth.cubic(t) end}
local sl, sc = stroke(lua_g), stroke{nodes = lua_g.nodes, rin = 3, rout = 3, g = smooth.cubic}
for t = 0, 2, .25 do same(sl(t), sc(t), "a Lua g as smooth.cubic at t = " .. t, 1e-12) end
lua_g.g = function() return "x" end
err(function() stroke(lua_g)(.3) end, "curve: the smoothstep g must return a number, got string",
    "a Lua g's error")

-- 3-D: example 33's first piece (spherical angles) and example 34's explicit vectors ----------------
local K33 = stroke{nodes = {P(1, 0, 1), P(1, 0, .1)}, uin = {0, 0}, uin2 = {-.25, -.25}, rin = .25, rout = .25}
eq(K33.dim, 3, "3-D stroke")
local _, p33, q33 = K33:controls(1)
same(p33, P(1, 0, .75), "P = N + rout e(0, -1/4 turn)"); same(q33, P(1, 0, .35), "Q = N' - rin e")
local pr = oblique(P(320, 240), 150, .3, -pi / 3)
local x33, y33 = pr:xy(K33:piece_xy(1, 0))
near(x33, 395, 1e-9, "example 33: node 0 on the screen x"); near(y33, 128.97, .005, "node 0 screen y")
local C34 = stroke{nodes = {P(.05, 0, 3.9), P(.05, 0, 3.8), P(.6, 0, 3.1)}, ein = {V(0, 0, -1), V(0, 0, -1), V(0, 0, -1)}, rin = .5, rout = .5}
local _, p34, q34 = C34:controls(1)
same(p34, P(.05, 0, 3.4), "example 34: P = N - (0, 0, rout)"); same(q34, P(.05, 0, 4.3), "Q = N' + (0, 0, rin)")
same(sphdir(pi / 2, 0), V(0, 1, 0), "sphdir", 1e-15)

-- fourier: example 12's points (astroid + .3 QBasic RND) ---------------------------------------------
qb.seed(327680)
local n, xs, ys = 16, {}, {}
for i = 0, 2 * n do xs[i] = cos(i * pi / n) ^ 3 + qb.rnd(1) * .3 end
for i = 0, 2 * n do ys[i] = sin(i * pi / n) ^ 3 + qb.rnd(1) * .3 end
near(xs[0], 1 + .7055475 * .3, 1e-7, "first RND value")
local pts = {}
for i = 0, 2 * n - 1 do pts[i + 1] = P(xs[i], ys[i]) end
local F = fourier(pts)
eq(tostring(F), "fourier(32 points, 2-D)", "tostring"); eq(F.n, 16, "n"); eq(F.closed, true, "closed")
for i = 0, 2 * n - 1 do same(F(i * pi / n), pts[i + 1], "through point " .. i, 1e-12) end
same(F(2 * pi + .3), F(.3), "period 2 pi", 1e-12)
local ca, cb = F:coef(1)
local a3 = 0
for i = 0, 2 * n - 1 do a3 = a3 + xs[i] * cos(3 * i * pi / n) / n end
near(ca[3], a3, 1e-13, "a_3 is the listing's sum"); eq(cb[0], 0, "b_0 = 0")

-- sampling: plain Lua steps or QBasic's float32 loop -------------------------------------------------
local function count(c, opts)
  local k = 0
  opts.brush = function() k = k + 1 end
  c:draw(opts)
  return k
end
local lua_count = 0
for _ = 0, 1, .001 do lua_count = lua_count + 1 end
eq(count(c5, {t = {0, 1, .001}}), lua_count, "t = {0, 1, .001} runs like Lua's for")
eq(count(c5, {t = {0, 1, .001}, qb = true}), 1001, "qb = true: 1001 samples, as QBasic")
eq(count(c5, {t = {0, 1, .001, qb = true}}), 1001, "qb inside the range")
eq(count(S, {t = {0, 1, .01, qb = true}}), 303, "a stroke samples each piece")
eq(count(S, {t = qb.range(0, 1, .5)}), 3, "an iterator is used as is (one pass)")
eq(count(F, {}), 1001, "fourier: default 0..2 pi in 1000 steps")
local seen = {}
for X, i, t in S:each{t = {0, 1, .5}} do seen[#seen + 1] = {X, i, t} end
eq(#seen, 9, "each: 3 pieces x 3 values")
same(seen[1][1], P(100, 300), "each: first point"); eq(seen[4][2], 2, "each: piece number"); eq(seen[6][3], 1, "each: t")

-- pixels -------------------------------------------------------------------------------------------------
cls()
S:draw{t = {0, 1, .001}, color = 4}
for i = 1, 4 do eq(point(X10[i], Y10[i]), 4, "the stroke passes through node " .. i) end
cls()
c5:draw{t = {0, 0, 1}, brush = "dot", color = 2}   -- one sample, at A
eq(point(301, 200), 2, "dot brush: a ring of radius 1 around the start")
eq(point(300, 200), 0, "dot brush: the centre of the ring stays empty")
cls()
K33:draw{t = {0, 1, .01}, map = pr, color = 3}
eq(point(395, 129), 3, "3-D stroke through the projection")
cls()
K33:draw{t = {0, 1, .01}, map = function(X) return pr(X) end, color = 5}
eq(point(395, 129), 5, "map as a function of the point")
cls()
plot(function(t) return P(10 + 10 * t, 400) end, {t = {0, 1, .1}, color = 6})
for x = 10, 20 do eq(point(x, 400), 6, "plot pixel " .. x) end
plot(function(t) return 30 + t, 410 end, {t = {0, 4, 1}, color = 7})
eq(point(34, 410), 7, "plot: a function returning numbers")
plot(function(t) return P(t, 0, 1) end, {t = {0, 1, 1}, map = pr, color = 9})
eq(point(320, 90), 9, "plot: 3-D through map")

-- errors -------------------------------------------------------------------------------------------------
err(function() stroke{} end, "stroke: give the nodes", "no nodes")
err(function() stroke{nodes = {P(0, 0)}} end, "stroke: a stroke needs at least 2 nodes, got 1", "one node")
err(function() stroke{nodes = {P(0, 0), P(1, 1, 1)}} end, "stroke: nodes[2] is 3-D, but nodes[1] is 2-D", "mixed dims")
err(function() stroke{nodes = {P(0, 0), V(1, 1)}} end, "stroke: nodes[2] must be a point, got V(1, 1)", "vector node")
err(function() stroke{nodes = {P(0, 0), P(1, 1)}, t0 = 1} end, "stroke: t0[1] must be a number in (0, 1), got 1", "t0")
err(function() stroke{nodes = {P(0, 0), P(1, 1)}, n = {2, "x"}} end, "stroke: n[2] must be a number, got string", "n string")
err(function() stroke{nodes = {P(0, 0), P(1, 1)}, uin = 0, ein = {V(1, 0)}} end, "either as angles (uin, kink) or as vectors", "both")
err(function() stroke{nodes = {P(0, 0), P(1, 1)}, ein = {P(1, 0)}} end, "stroke: ein[1] must be a vector V(...)", "ein point")
err(function() stroke{nodes = {P(0, 0), P(0, 0)}} end, "stroke: node 1: zero vector where a direction is needed", "coincident")
err(function() stroke(5) end, "stroke: argument #1 (spec) must be a table", "not a table")
err(function() spline2(P(0, 0), P(1, 0), P(1, 1), V(1, 0)) end, "spline2: argument #2 (a) must be a vector", "a point")
err(function() spline2(P(0, 0), V(1, 0), P(1, 1, 1), V(1, 0)) end, "spline2: argument #3 (B) is 3-D, but argument #1 (A) is 2-D (mixed dimensions)", "mixed")
err(function() spline2(P(0, 0), V(1, 0), P(1, 1), V(1, 0), 7) end, "spline2: argument #5 (g) must be a smoothstep", "g number")
err(function() spline2(P(0, 0), V(1, 0), P(1, 1), V(1, 0), function() return "x" end)(.5) end, "the smoothstep g must return a number", "g result")
err(function() fourier({P(0, 0), P(1, 0), P(2, 2)}) end, "fourier: argument #1 (points) must hold an even number (2n >= 2) of points, got 3", "odd")
err(function() fourier({P(0, 0), 5}) end, "fourier: argument #1 (points) [2] must be a point, got 5", "not a point")
err(function() fourier({P(0, 0), P(1, 1, 1)}) end, "fourier: argument #1 (points) [2] is 3-D, but [1] is 2-D (mixed dimensions)", "mixed")
err(function() S:piece(4, .5) end, "c:piece: argument #1 (i) must be a piece number 1..3, got 4", "piece number")
err(function() S:xy("a") end, "c:xy: argument #1 (t) must be a finite number, got \"a\"", "xy string")
err(function() F:piece(1, 0) end, "c:piece: a Fourier curve has no pieces", "fourier piece")
-- NaN is the core's "default" marker: a NaN or infinity given by the user is refused, not defaulted
err(function() stroke{nodes = {P(0, 0), P(1, 1)}, uin = {math.huge, 0}} end, "stroke: uin[1] must be a finite number, got inf", "uin inf")
err(function() stroke{nodes = {P(0, 0), P(1, 1)}, rin = 0 / 0} end, "stroke: rin must be a finite number", "rin NaN")
err(function() stroke{x = {0, 1 / 0}, y = {0, 1}} end, "stroke: x[2] must be a finite number, got inf", "x inf")
-- a fractional degree: no extrapolation before the first node or after the last (t^2.5, t < 0)
local Sf = stroke{nodes = {P(0, 0), P(1, 1), P(2, 0)}, n = 2.5, m = {2, 3.5}}
local fx = Sf:xy(.5)
truthy(fx == fx, "a fractional degree inside the pieces")
same(Sf(1.5), Sf:piece(2, .5), "global parameter with fractional degrees")
err(function() Sf(-.5) end, "Sf: argument #1 (t) must be at least 0 (piece 1's half-spline has the fractional degree n = 2.5 and does not extrapolate)", "before the start")
err(function() Sf:xy(2.5) end, "c:xy: argument #1 (t) must be at most 2 (piece 2's half-spline has the fractional degree m = 3.5", "past the end")
err(function() Sf:piece(1, -1) end, "c:piece: argument #2 (t) must be at least 0 (piece 1's half-spline", "piece before its start")
err(function() spline2(P(0, 0), V(1, 0), P(1, 1), V(0, 1), smooth.half(2.5, 2, .5))(-.5) end, "c: argument #1 (t) must be at least 0 (piece 1's half-spline has the fractional degree n = 2.5 and does not extrapolate)", "spline2 fractional n")
err(function() spline2(P(0, 0), V(1, 0), P(1, 1), V(1, 0), function() return 0 / 0 end)(.5) end, "curve: the smoothstep g must return a finite number, got g(0.5) =", "g NaN")
err(function() F:controls() end, "c:controls: a Fourier curve has no pieces", "fourier controls")
err(function() F:coef("a") end, "c:coef: argument #1 (k) must be an integer, got \"a\"", "coef k")
-- every dimension points have: a 5-D spline2 and a 6-D stroke (the old toolkit stopped at 4-D)
local s5 = spline2(P(0, 0, 0, 0, 0), V(1, 0, 0, 0, 0), P(1, 1, 0, 0, 1), V(0, 1, 0, 0, 0))
eq(s5.dim, 5, "5-D spline2"); same(s5(1), P(1, 1, 0, 0, 1), "5-D spline2 ends at B")
local s6 = stroke{nodes = {P(0, 0, 0, 0, 0, 0), P(1, 0, 0, 0, 0, 1), P(1, 1, 0, 0, 0, 2)}}
eq(s6.dim, 6, "6-D stroke"); same(s6(2), P(1, 1, 0, 0, 0, 2), "6-D stroke through its last node")
err(function() K33:draw{t = {0, 1, .1}} end, "c:draw: a 3-D curve needs map = a projection", "3-D without map")
err(function() S:draw{brush = "thick"} end, 'c:draw: brush must be "pset", "dot" or a function(x, y, color), got string', "brush")
err(function() S:draw{t = {0, 1, 0}} end, "c:draw: t step must be a nonzero number, got 0", "zero step")
err(function() S:draw{t = "all"} end, "c:draw: t must be a range {a, b [, step]} or an iterator, got string", "bad range")
err(function() plot(function(t) return P(t, t) end) end, "plot: give the parameter range t = {a, b, step}", "plot without t")
err(function() plot(42, {t = {0, 1}}) end, "plot: argument #1 (curve) must be a function of t or a curve, got 42", "plot number")
err(function() plot(function() return "x" end, {t = {0, 1}}) end, "a curve must return a point or numbers, got string", "plot result")
check.done()
