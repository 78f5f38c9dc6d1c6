-- korotky.*: the polynomial splines (7) and (9), the Ferguson splines of Examples 1-4 with the
-- printed (28) and (29), the elastic reference and the ranking of the models against it,
-- conic arcs, the conic sweep and the elliptic domes through Lua, and the argument errors
-- (korotky_curves_surfaces.md).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local same = check.same_within(1e-9)
local sqrt = math.sqrt

local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}   -- Table A1

-- (7): natural ends, to the printed digits
local c7, k7 = korotky.poly_spline(pts)
local printed7 = {{.9, 1.2174, 0, .4175}, {2.3, 2.2319, 1.1272, -1.2089},
                  {4, 2.0329, -1.4114, .1464}, {3.2, -2.0516, -.4452, .2968}}
for i = 1, 4 do
  for j = 1, 4 do near(k7[i][j], printed7[i][j], 5e-5, "(7) segment " .. i .. " coefficient " .. j) end
end
for i, p in ipairs(pts) do same(c7(p.x), p, "(7) through point " .. i) end
near(c7:curvature(1.2), 0, 1e-12, "(7) natural end")
local dk, da = korotky.joint_jumps(c7)
truthy(dk < 1e-10 and da < 1e-12, "(7) C2 at B, C, D")

-- (9): clamped 0.2 / -0.3; the printed d3 = +0.0171 is a misprint for -0.0171
local c9, k9 = korotky.poly_spline(pts, {ends = "clamped", s0 = .2, s1 = -.3})
local printed9 = {{.9, .2, 2.0181, -.5688}, {2.3, 2.4504, .4824, -.7336},
                  {4, 2.0473, -1.0583, -.0171}, {3.2, -2.8572, -1.1710, 4.971}}
for i = 1, 4 do
  for j = 1, 4 do near(k9[i][j], printed9[i][j], 5e-5, "(9) segment " .. i .. " coefficient " .. j) end
end
local d = c9:deriv(1.2)
near(d.y / d.x, .2, 1e-12, "(9) clamped at A")
-- affine compression: the spline of the compressed points is the compressed spline
local half = map.scale({1, .5})
local ch = korotky.poly_spline({P(1.2, .45), P(2.1, 1.15), P(2.8, 2), P(5, 1.6), P(5.5, 1.05)})
for x = 1.2, 5.5, .1 do same(ch(x), half(c7(x)), "compressed (7) at " .. x) end

-- Example 3: given tangents, Newton reaches (28)
local tg3 = {1.134, 2.840, 0.985, -1.8154, -2.460}
local f28, z = korotky.ferguson_tangents(pts, tg3)
local printed28 = {2.175, 1.784, 1.845, 2.0335, 4.850, 1.1935}
for i = 1, 6 do near(z[i + 1], printed28[i], 5e-3, "(28) z" .. i) end
near(z[2], 2.1741, 1e-4, "converged z1")
eq(#z, 8, "moduli w_A, z1..z6, w_E")
dk, da = korotky.joint_jumps(f28)
truthy(dk < 1e-9 and da < 1e-12, "Example 3 is G2")
same(f28(2.5), P(3.7883, 4.3097), "CD at t = 0.5", 1e-4)
-- the printed (28) as moduli: G2 only to the rounding
local r28 = korotky.ferguson(pts, tg3, {1, 2.175, 1.784, 1.845, 2.0335, 4.850, 1.1935, 1})
dk = korotky.joint_jumps(r28)
truthy(dk < 1e-2, "printed (28) nearly G2")

-- Example 4: substitution from w_A = w_B(1) = 2 gives (29)
local f29, z29, quads = korotky.ferguson_substitution(pts, {0.2, 5.16, 0.83, -4.36, -0.3}, 2, 2)
local printed29 = {1.978, 1.723, 2.493, 3.672, 1.292, 1.356}
for i = 1, 6 do near(z29[i + 2], printed29[i], 5e-4, "(29) value " .. i) end
near(quads[1][1], .0775, 1e-3, "quadratic at B")
near(quads[3][3], 36.8125, 1e-3, "quadratic at D")
-- on Example 3's data the substitution gives Newton's root; "max" the other root at D
local _, s3 = korotky.ferguson_substitution(pts, tg3, 1, z[2])
near(s3[8], 1, 1e-8, "w_E from the substitution")
local _, s4 = korotky.ferguson_substitution(pts, tg3, 1, z[2], "max")
near(s4[7], 1.3209, 1e-4, "the larger root at D")

-- Example 1: fixed lambdas; curvature continuous
local f1 = korotky.ferguson_lambda(pts, {TA = 1.134, TE = -2.460, lambda = {1, 2, .5}})
dk = korotky.joint_jumps(f1)
truthy(dk < 1e-9, "Example 1 curvature continuous")
near(f1:curvature(2), -1.0710, 1e-4, "Example 1 curvature at C")
local d1 = f1:deriv(1)
near(d1.x, .8234, 1e-4, "Example 1 derivative at B")

-- the elastic reference and the article's ranking of the models
local el, E = korotky.elastic(pts)
near(E, 1.8188, 2e-4, "elastic energy")
dk, da = korotky.joint_jumps(el)
truthy(dk < 1e-9 and da < 1e-12, "the elastic line is curvature-continuous at every joint")
near(korotky.energy(el), E, 1e-6, "energy of the curve")
near(el:curvature(0), 0, 1e-12, "free end A")
local measured = {1.134, 2.840, 0.985, -1.815, -2.460}
for i = 1, 5 do
  local t = el:deriv(i - 1)
  truthy(math.abs(math.atan(t.y / t.x) - math.atan(measured[i])) < 3 * math.pi / 180,
         "elastic slope within 3 degrees of Table A2 at knot " .. i)
end
local h28, h1, h7 = korotky.deviation(f28, el), korotky.deviation(f1, el), korotky.deviation(c7, el)
near(h28, .0458, .01, "Ferguson (28) against the elastic line")
near(h7, .5136, .01, "polynomial (7) against the elastic line")
truthy(h28 < h1 and h1 < h7, "ranking: (28) < Example 1 < (7)")
truthy(korotky.energy(c7) > korotky.energy(f1) and korotky.energy(f1) > korotky.energy(f28)
       and korotky.energy(f28) > E, "energies rank as the distances")
local ec, Ec = korotky.elastic(pts, {ends = {.2, -.3}, pieces = 1})
truthy(Ec > 4.7 and Ec < 4.8, "clamped elastic energy near the digest's 4.7407")
d = ec:deriv(4)
near(d.y / d.x, -.3, 1e-12, "clamped at E")

-- conics: the quarter circle, parallel tangents, a hyperbola
local q, w, kind = korotky.conic_arc(P(1, 0), V(0, 1), P(0, 1), V(-1, 0), P(sqrt(.5), sqrt(.5)))
near(w, sqrt(.5), 1e-12, "quarter circle weight")
eq(kind, "ellipse", "quarter circle kind")
near(dist(q(.3), P(0, 0)), 1, 1e-12, "on the unit circle")
local e2 = korotky.conic_arc(P(0, 0), V(0, 1), P(2, 0), V(0, 1), P(1, .5))
local m = e2(.3)
near((m.x - 1) ^ 2 + 4 * m.y ^ 2, 1, 1e-12, "semi-ellipse of parallel tangents")
local _, wh, kh = korotky.conic_arc(P(0, 0), V(1, sqrt(3)), P(2, 0), V(-1, sqrt(3)), P(1, 1.5))
near(wh, 6.4641, 1e-4, "hyperbola weight")
eq(kh, "hyperbola", "hyperbola kind")
local sp = korotky.conic_arc(P(0, 3, 0), V(0, 0, 1), P(4, 3, 0), V(0, 0, 1), P(2, 3, 2))
same(sp(.5), P(2, 3, 2), "semi-ellipse in space")

-- domes
local dr = korotky.dome_rect(2, 1, 1.5)
same(dr(.5, .5), P(2, 1, 1.5), "rectangular dome top")
eq(dr.kind, "korotky.dome_rect", "dome kind")
for u = 0, 1, .25 do
  for v = 0, 1, .25 do
    local p = dr(u, v)
    near(p.z ^ 2 / 2.25, p.x * (4 - p.x) * p.y * (2 - p.y) / 4, 1e-12, "rectangular dome equation")
  end
end
local dt = korotky.dome_tri(P(0, 0), P(1, 0), P(0, 1), 1)
same(dt(2 / 3, .5), P(1 / 3, 1 / 3, 1), "triangular dome apex")
near(dt(.75, 1 / 3).z, .918559, 1e-6, "triangular dome at (0.5, 0.25)")
local dD = korotky.dome_tri(P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(1 / 3, 1 / 3, 2))
near(dD(2 / 3, .5).z, 2, 1e-12, "dome through the apex D")

-- the conic sweep: at u = 0 the frontal conic DC
local function seg(A, B) return bezier{A, B} end
local sw = korotky.conic_sweep{U = seg(P(0, 0, 0), P(0, 4, 0)), V = seg(P(6, 0, 0), P(6, 4, 0)),
                               T = seg(P(3, 0, 2), P(3, 4, 3)),
                               P = seg(P(1, 0, 1), P(1, 4, sqrt(3))), Q = seg(P(5, 0, 1), P(5, 4, sqrt(3)))}
local dc = korotky.conic_arc(P(0, 0, 0), V(1, 0, 1), P(6, 0, 0), V(-1, 0, 1), P(3, 0, 2))
for t = 0, 1, .125 do same(sw(0, t), dc(t), "sweep at u = 0, v = " .. t) end
same(sw(1, .5), P(3, 4, 3), "sweep through l at u = 1")

-- drawing the domes with hidden lines through the camera
screen(12)
camera(map.translate(V(320, 300)) * map.scale({100, -100}) * map.isometric())
dr:wireframe{nu = 6, nv = 6, hidden = "hide"}
dt:wireframe{nu = 6, nv = 1, hidden = "dashed"}
camera(nil)

-- errors
err(function() korotky.poly_spline({P(1, 1), P(1, 2)}) end,
    "korotky.poly_spline: argument #1 (points) [2] must lie right of the point before (x must increase)")
err(function() korotky.poly_spline(pts, {ends = "periodic"}) end,
    "korotky.poly_spline: option 'ends' must be \"natural\" or \"clamped\", got \"periodic\"")
err(function() korotky.poly_spline(pts, {ends = "clamped"}) end,
    "korotky.poly_spline: clamped ends need the end slopes s0 and s1 (numbers)")
err(function() korotky.poly_spline({P(1, 1)}) end,
    "korotky.poly_spline: argument #1 (points) must hold 2 to 32 points, got 1")
err(function() korotky.poly_spline({P(1, 1), P(1, 2, 3)}) end,
    "korotky.poly_spline: argument #1 (points) [2] must be a 2-D point, got P(1, 2, 3)")
err(function() korotky.ferguson_tangents(pts, {1, 2, 3}) end,
    "korotky.ferguson_tangents: argument #2 (tangents) must hold one tangent per point (5), got 3")
err(function() korotky.ferguson_tangents(pts, {1, 2, "x", 4, 5}) end,
    "korotky.ferguson_tangents: argument #2 (tangents) [3] must be a slope or a 2-D vector, got string")
err(function() korotky.ferguson_tangents(pts, {1.134, -2.84, .985, -1.8154, -2.46}) end,
    "korotky.ferguson_tangents: no positive derivative moduli at knot #2")
err(function() korotky.ferguson_tangents(pts, {1.134, V(0, 0), .985, -1.8154, -2.46}) end,
    "korotky.ferguson_tangents: the tangent is the zero vector at knot #2")
err(function() korotky.ferguson_lambda(pts, {TA = 1, TE = 1, lambda = {1, 0, 1}}) end,
    "korotky.ferguson_lambda: option 'lambda' [2] (at knot #3) must be positive")
err(function() korotky.ferguson_lambda(pts, {TA = 1, TE = 1, lambda = {1, 1}}) end,
    "korotky.ferguson_lambda: option 'lambda' must hold 3 numbers, got 2")
err(function() korotky.ferguson_lambda(pts, {TA = 1, TE = 1}) end,
    "korotky.ferguson_lambda: option 'lambda' must be a list of 3 numbers, got nil")
err(function() korotky.ferguson_substitution(pts, tg3, 1, 0) end,
    "korotky.ferguson_substitution: argument #4 (z1) must be a positive number, got 0")
err(function() korotky.ferguson_substitution(pts, tg3, 1, 2, "mid") end,
    "korotky.ferguson_substitution: argument #5 (root) must be \"min\" or \"max\", got \"mid\"")
err(function() korotky.ferguson(pts, tg3, {1, 2}) end,
    "korotky.ferguson: argument #3 (moduli) must hold 8 numbers, got 2")
err(function() korotky.elastic({P(0, 0), P(0, 0), P(1, 1)}) end,
    "korotky.elastic: two consecutive points coincide")
err(function() korotky.elastic(pts, {pieces = 9}) end,
    "korotky.elastic: option 'pieces' must be an integer from 1 to 4, got 9")
err(function() korotky.elastic(pts, {pieces = 2.5}) end,
    "korotky.elastic: option 'pieces' must be an integer from 1 to 4, got 2.5")
err(function() korotky.deviation(c7, 3) end,
    "korotky.deviation: argument #2 (reference) must be a curve, got 3")
err(function() korotky.deviation(c7, sp) end,
    "korotky.deviation: argument #2 (reference) is 3-D, but argument #1 (model) is 2-D (mixed dimensions)")
err(function() korotky.conic_arc(P(0, 0), V(1, 0), P(0, 0), V(0, 1), P(1, 1)) end,
    "korotky.conic_arc: U and V coincide")
err(function() korotky.conic_arc(P(0), V(1), P(1), V(1), P(0.5)) end, "korotky.conic_arc: the points must be 2-D or more")
err(function() korotky.conic_arc(P(0, 0), V(1, sqrt(3)), P(2, 0), V(-1, sqrt(3)), P(-1, 1)) end,
    "korotky.conic_arc: T must lie between the tangent lines")
err(function() korotky.conic_arc(P(0, 3, 0), V(0, 1, 1), P(4, 3, 0), V(0, 0, 1), P(2, 3, 2)) end,
    "korotky.conic_arc: the tangents must lie in the plane of U, V and T")
err(function() korotky.conic_arc(P(0, 0), P(1, 0), P(2, 0), V(0, 1), P(1, 1)) end,
    "korotky.conic_arc: argument #2 (tU) must be a vector, got P(1, 0); a vector has weight 0: a difference of points is a vector, e.g. B - A")
err(function() korotky.dome_rect(0, 1, 1) end,
    "korotky.dome_rect: argument #1 (a0) must be a positive number, got 0")
err(function() korotky.dome_tri(P(0, 0), P(1, 0), P(2, 0), 1) end,
    "korotky.dome_tri: the triangle ABC is flat in plan")
err(function() korotky.dome_tri(P(0, 0), P(1, 0), P(0, 1), P(1, 1, 1)) end,
    "korotky.dome_tri: argument #4 (h | D) must stand above the inside of the triangle, got P(1, 1, 1)")
err(function() korotky.conic_sweep{U = c7} end,
    "korotky.conic_sweep: option 'U' must be a 3-D curve, got a 2-D one")
err(function()
      korotky.conic_sweep{U = seg(P(0, 0, 0), P(0, 4, 0)), V = seg(P(6, 0, 0), P(6, 4, 0)),
                          T = seg(P(3, 0, 2), P(-3, 4, -3)),
                          P = seg(P(1, 0, 1), P(1, 4, 2)), Q = seg(P(5, 0, 1), P(5, 4, 2))}
    end, "korotky.conic_sweep: no conic through U, V, T with the tangents towards P and Q at u = 0.")
check.done()
