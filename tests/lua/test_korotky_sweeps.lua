-- The conic sweeps of Korotky (2015) Figs. 2f, 3a and 3c as the gallery builds them
-- (examples/korotky/13, 14, 16; issue 24): the kinds of the generators, the straight
-- generators of the concave shell, the degenerate inlet AOD (T = W).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, truthy = check.eq, check.near, check.truthy
-- the conic of a generator in its plane x = const, from five of its points as (y, z)
local function conic_of(s, u)
  local q = {}
  for i = 1, 5 do local m = s(u, (2 * i - 1) / 10); q[i] = P(m.y, m.z) end
  return conic.elements(q[1], q[2], q[3], q[4], q[5])
end

-- Fig. 3a: the inlet g is a hyperbola of weight 2.75, the outlet e an ellipse
local X = 6
local function w(x) return 2 + (x / X)^2 end
local MN = curve(function(x) return P(x, -w(x), 0) end, 0, X)
local KL = curve(function(x) return P(x, w(x), 0) end, 0, X)
local T, M, L = P(0, 0, 3), P(X, -w(X), 2), P(X, w(X), 2)
local l = bezier{P(0, 0, 2.2), P(X / 2, 0, 2.7), P(X, 0, 2.6)}
local shell = korotky.conic_sweep{U = MN, V = KL, T = l, P = bezier{T, M}, Q = bezier{T, L}}
local _, wg, kg = korotky.conic_arc(P(0, -2, 0), T - P(0, -2, 0), P(0, 2, 0), T - P(0, 2, 0), P(0, 0, 2.2))
near(wg, 2.75, 1e-12, "the inlet's weight: beta / (1 - beta) with beta = 2.2 / 3")
eq(kg, "hyperbola", "the inlet g")
eq(conic_of(shell, 0).kind, "hyperbola", "the sweep's inlet is g")
eq(conic_of(shell, 1).kind, "ellipse", "the sweep's outlet e")
local e = conic_of(shell, 1)
near(e.center.x, 0, 1e-9, "e is centred on the axis")
near(e.center.y, 0, 1e-9, "e stands on the ground: a semi-ellipse")
near(math.max(e.semi[1], e.semi[2]), 3, 1e-9, "e spans the outlet, half width 3")
near(math.min(e.semi[1], e.semi[2]), 2.6, 1e-9, "e's height is l's end")
for _, u in ipairs{0, .3, .7, 1} do
  near(dist(shell(u, .5), l(u)), 0, 1e-9, "the generator passes through l at u = " .. u)
end

-- Fig. 3c: the inlet is the line pair A O D (weight infinite), the outlet the semicircle
local A, B, C, D = P(0, -1, 0), P(4, -1, 0), P(4, 1, 0), P(0, 1, 0)
local O, B1, C1 = P(0, 0, 1.6), P(4, -1, 1.3), P(4, 1, 1.3)
local hAB, hDC = surface.bilinear(A, B, O, B1), surface.bilinear(D, C, O, C1)
local rect = korotky.conic_sweep{U = bezier{A, B}, V = bezier{D, C}, T = bezier{O, P(2, 0, 1.25), P(4, 0, 1)},
                                 P = hAB:iso("v", 1), Q = hDC:iso("v", 1)}
near(dist(rect(0, 0), A), 0, 1e-12, "the inlet starts at A")
near(dist(rect(0, .5), O), 0, 1e-12, "the inlet's corner is O")
near(dist(rect(0, .25), mid(A, O)), 0, 1e-12, "the inlet runs along AO")
near(dist(rect(0, .75), mid(O, D)), 0, 1e-12, "and along OD")
-- the inlet as korotky.conic_arc gives it: the line pair, whose elements are a clear error
local pair = korotky.conic_arc(P(-1, 0), V(1, 1.6), P(1, 0), V(-1, 1.6), P(0, 1.6))
check.err(function() korotky.conic_elements(pair) end,
          "korotky.conic_elements: the line pair U W V (T = W, the weight infinite) is a degenerate conic: its lines meet at W = P(0.0, 1.6)",
          "the line pair has no centre or axes")
local s = conic_of(rect, 1)
truthy(s.circle, "the outlet is a circle")
near(s.semi[1], 1, 1e-9, "of radius 1")
-- the paraboloids are doubly ruled: straight lines both ways (a bilinear patch)
near(dist(hAB(.5, .5), mid(hAB(.5, 0), hAB(.5, 1))), 0, 1e-12, "a ruling u = const")
near(dist(hAB(.5, .5), mid(hAB(0, .5), hAB(1, .5))), 0, 1e-12, "a ruling v = const")
-- the tangent plane of the shell along AB holds the paraboloid's ruling (they touch)
for _, u in ipairs{.25, .5, .75} do
  local _, _, tv = rect:partials(u, 0)
  local ruling = hAB(u, 1) - hAB(u, 0)
  near(math.abs(dot(unit(tv), unit(ruling))), 1, 1e-9, "the generator leaves AB along the ruling, u = " .. u)
end

-- Fig. 2f: the concave guide crosses the chord twice; there the generators are straight
local function wave(x) return curve(function(y) return P(x, y, .3 * math.sin(math.pi * y / 4)) end, 0, 4) end
local AD, BC = wave(0), wave(6)
local lc = bezier{P(3, 0, 2), P(3, 2, -2.5), P(3, 4, 3)}
local shell2 = korotky.conic_sweep{U = AD, V = BC, T = lc, P = bezier{P(1, 0, 1), P(1, 4, math.sqrt(3))},
                                   Q = bezier{P(5, 0, 1), P(5.6, 2, 1.55), P(5, 4, math.sqrt(3))}}
local function f(u) return lc(u).z - AD(4 * u).z end
local roots = {}
for i = 0, 199 do
  local a, b = i / 200, (i + 1) / 200
  if f(a) * f(b) < 0 then
    for _ = 1, 60 do local m = (a + b) / 2; if f(a) * f(m) <= 0 then b = m else a = m end end
    roots[#roots + 1] = (a + b) / 2
  end
end
eq(#roots, 2, "two straight generators, a and c")
for _, u in ipairs(roots) do
  local U0, V0 = AD(4 * u), BC(4 * u)
  for _, v in ipairs{.2, .5, .8} do
    local m = shell2(u, v)
    near(dist(m, U0 + (V0 - U0) * (dot(m - U0, V0 - U0) / dot(V0 - U0, V0 - U0))), 0, 1e-6,
         "the generator at u = " .. string.format("%.4f", u) .. " is the chord")
  end
end
check.done()
