-- The affine compression of Korotky & Vitovtov (2021) through the kernel's general axial
-- affinity (issue 24's API gap), with the digest's numbers (C.3 items 4 and 5): the
-- compression toward the x axis with k = 0.5 is map.axial_affinity(O, (1, 0), (0, 1), 0.5).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local near, truthy = check.near, check.truthy
local same = check.same_within(1e-12)

local f = map.axial_affinity(P(0, 0), V(1, 0), V(0, 1), .5)
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local low = {}
for i, p in ipairs(pts) do low[i] = f(p) end
same(low[1], P(1.2, .45), "A' midway between A and the axis")
same(low[5], P(5.5, 1.05), "E'")
-- a line and its image meet on the axis: the end tangents of Tables A2 and A3 (slopes 1.134,
-- 0.567 at A, A' and -2.460, -1.230 at E, E') cut the x axis at 0.406349 and 6.353659
local function x_cut(p, d) local q = meet(p, p + d, P(0, 0), P(1, 0)); return q.x end
near(x_cut(pts[1], V(1, 1.134)), 0.406349, 1e-6, "A's tangent cuts the axis at 0.406349")
near(x_cut(low[1], f(V(1, 1.134))), 0.406349, 1e-6, "and A''s, its image")
near(f(V(1, 1.134)).y, 0.567, 1e-12, "the slope is halved: 0.567 as measured")
near(x_cut(pts[5], V(1, -2.460)), 6.353659, 1e-6, "E's tangent at 6.353659")
near(x_cut(low[5], f(V(1, -2.460))), 6.353659, 1e-6, "and E''s")
-- a general axial affinity (an oblique axis and direction) keeps its axis pointwise and the
-- ratio of distances measured along s
local g = map.axial_affinity(P(1, 2), V(2, 1), V(-1, 3), -0.75)
same(g(P(3, 3)), P(3, 3), "a point of the axis is fixed")
local M = P(0, 5)
local M1 = g(M)
local foot = meet(M, M + V(-1, 3), P(1, 2), P(3, 3))          -- M's foot on the axis along s
near(cross(M1 - foot, V(-1, 3)), 0, 1e-12, "M moves along s")
near(dot(M1 - foot, V(-1, 3)) / dot(M - foot, V(-1, 3)), -0.75, 1e-12, "its distance from the axis times k")
-- the polynomial spline is linear in the data: spline(compress(P)) = compress(spline(P)),
-- clamped with the end slopes scaled by k (0.1 and -0.15)
local c7, c7h = korotky.poly_spline(pts), korotky.poly_spline(low)
local c9 = korotky.poly_spline(pts, {ends = "clamped", s0 = .2, s1 = -.3})
local c9h = korotky.poly_spline(low, {ends = "clamped", s0 = .1, s1 = -.15})
for _, x in ipairs{1.65, 2.45, 3.9, 5.25} do
  same(c7h(x), f(c7(x)), "(7) compressed at x = " .. x)
  same(c9h(x), f(c9(x)), "(9) compressed at x = " .. x)
end
near(c7(1.65).y, 1.4859, 5e-5, "(7) at 1.65 (the digest's sample)")
near(c9(3.9).y, 4.9487, 5e-5, "(9) at 3.9")
-- the elastic line is not affine-covariant: the slope at B changes by 2.40, not 2
local e, eh = korotky.elastic(pts), korotky.elastic(low)
local dB, dBh = e:deriv(1), eh:deriv(1)
local r = (dB.y / dB.x) / (dBh.y / dBh.x)
truthy(math.abs(r - 2) > .3, "the ruler deforms non-affinely at B")
near(r, 2.41, .02, "the digest's ratio 2.41 (measured 2.36)")
check.done()
