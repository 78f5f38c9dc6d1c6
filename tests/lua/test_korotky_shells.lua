-- korotky.* for the 2015 shells and the measuring tools: the sail of the 4-D key
-- construction (Fig. 1b), the rotational conic sweep (Fig. 3b), the composite ridge shell
-- (Fig. 3d), the conic's centre, axes and asymptotes (Fig. 2c) and graphical differentiation
-- (korotky_curves_surfaces.md B.3, B.4, B.6, C.3 12a-15, 20), with the argument errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local same = check.same_within(1e-12)
local sqrt = math.sqrt

-- the sail: omega(u) through C, AB(u), Z at infinity; delta(v) through X at infinity and
-- the points of AC and BC at the level v
local A, B, C = P(0, 0, 0, 0), P(0, 0, 4, 4), P(0, 6, .3, 2)
local foot = bezier{A, P(1.6, 0, 2, 2), B}
local luff = bezier{A, P(0, 3, -.2, 1), C}
local leech = bezier{B, P(0, 3, 2.9, 3), C}
local Z, X = V(0, 0, 1, 0), V(1, 0, 0, 0)
local sail = korotky.two_pencils{omega = {C, foot, Z}, delta = {X, luff, leech}}
eq(sail.dim, 4, "the sail is a 4-D surface")
for i = 0, 4 do
  local s = i / 4
  same(sail(s, 0), foot(s), "the foot at u = " .. s)
  same(sail(0, s), luff(s), "the luff at v = " .. s)
  same(sail(1, s), leech(s), "the leech at v = " .. s)
end
same(sail(.37, 1), C, "the head")
-- the key: x from the ruling C M, z from the chord of the level, t shared
local M, Pv, Qv = foot(.5), luff(.5), leech(.5)
local S = sail(.5, .5)
local lam = (C.y - Pv.y) / (C.y - M.y)
near(S.x, C.x + lam * (M.x - C.x), 1e-12, "x on the ruling")
near(S[4], C[4] + lam * (M[4] - C[4]), 1e-12, "t on the ruling")
near(S.z, Pv.z + (S[4] - Pv[4]) / (Qv[4] - Pv[4]) * (Qv.z - Pv.z), 1e-12, "z on the chord")
-- in xyt the sail is the cone with vertex C over AB: collinear with C and the foot's point
local xyt = map.matrix({{1, 0, 0, 0, 0}, {0, 1, 0, 0, 0}, {0, 0, 0, 1, 0}, {0, 0, 0, 0, 1}})
for _, u in ipairs{.2, .6, .9} do
  local c, m, s = xyt(C), xyt(foot(u)), xyt(sail(u, .3))
  local cr = cross(s - c, m - c)
  near(dot(cr, cr), 0, 1e-24, "the xyt image on the line C M at u = " .. u)
end
-- through a 4-D -> 2-D map, as the figure draws it
local view = map.matrix({{.5, 0, 1, 0, 0}, {.3, 1, 0, 0, 0}, {0, 0, 0, 0, 1}})
same(view(sail(.5, .5)), P(.5 * S.x + S.z, .3 * S.x + S.y), "a 3 x 5 view")
screen(12)
window(-1, -1, 11, 8)
sail:wireframe{nu = 4, nv = 4, map = view}

-- the rotational sweep: perpendicular tangent planes and a semicircular ridge: a sphere
local AA, BB = P(0, -2, 0), P(0, 2, 0)
local ridge = korotky.conic_arc(P(2, 0, 0), V(0, 0, 1), P(-2, 0, 0), V(0, 0, 1), P(0, 0, 2))
local sphere = korotky.conic_revolve{A = AA, B = BB, nA = V(0, 1, 0), nB = V(0, 1, 0), ridge = ridge}
for u = 0, 1, .25 do
  for v = 0, 1, .25 do near(dist(sphere(u, v), P(0, 0, 0)), 2, 1e-12, "on the sphere") end
end
-- tilted planes: the generator's tangent at A lies in pi_A
local nA = V(0, 1, -.5)
local dome = korotky.conic_revolve{A = AA, B = BB, nA = nA, nB = V(0, 1, .5), ridge = ridge}
same(dome(.3, 0), AA, "every generator starts at A")
local t = dome(.3, 1e-6) - AA
near(dot(unit(t), unit(nA)), 0, 1e-5, "tangent at A in the plane pi_A")

-- the ridge shell: a quarter ellipse up to the ridge, a segment down (the crease)
local function seg(a, b) return bezier{a, b} end
local r2 = sqrt(.5)
local shell = korotky.ridge_shell{
  U = seg(P(0, -2, 0), P(4, -2, 0)), R = seg(P(0, 0, 1.5), P(4, 0, 1.5)),
  V = seg(P(0, 2, 0), P(4, 2, 0)),
  T1 = seg(P(0, -2 * r2, 1.5 * r2), P(4, -2 * r2, 1.5 * r2)),
  T2 = seg(P(0, 1, .75), P(4, 1, .75)),
  P = V(0, 0, 1), H = V(0, 1, 0), Q = V(0, 0, 1)}
eq(shell.v1, 2, "two arcs per profile: v in [0, 2]")
for v = 0, 2, .25 do
  local p = shell(.5, v)
  near(p.x, 2, 1e-12, "profile x = 2")
  if v <= 1 then near(p.y ^ 2 / 4 + p.z ^ 2 / 2.25, 1, 1e-12, "the quarter ellipse")
  else near(p.z, .75 * (2 - p.y), 1e-12, "the segment") end
end
same(shell(.5, 1), P(2, 0, 1.5), "the ridge point")

-- the conic's elements: C.3 13 (circle), 14 (parallel tangents), 15 (hyperbola)
local q = korotky.conic_arc(P(1, 0), V(0, 1), P(0, 1), V(-1, 0), P(sqrt(.5), sqrt(.5)))
local e = korotky.conic_elements(q)
eq(e.kind, "ellipse", "quarter circle kind")
same(e.center, P(0, 0), "circle centre")
near(e.semi[1], 1, 1e-12, "circle radius")
eq(e.asymptotes, nil, "an ellipse has no asymptotes")
e = korotky.conic_elements(korotky.conic_arc(P(0, 0), V(0, 1), P(2, 0), V(0, 1), P(1, .5)))
same(e.center, P(1, 0), "(x - 1)^2 + 4 y^2 = 1: centre")
near(e.semi[1], 1, 1e-12, "major semi-axis")
near(e.semi[2], .5, 1e-12, "minor semi-axis")
local w = 3 + 2 * sqrt(3)
local k = w * w - 1
e = korotky.conic_elements(korotky.conic_arc(P(0, 0), V(1, sqrt(3)), P(2, 0), V(-1, sqrt(3)), P(1, 1.5)))
eq(e.kind, "hyperbola", "hyperbola kind")
same(e.center, P(1, sqrt(3) * w * w / k), "hyperbola centre (1, 1.774519)")
near(e.semi[1], sqrt(3) * w / k, 1e-12, "transverse semi-axis 0.274519")
near(e.semi[2], 1 / sqrt(k), 1e-12, "conjugate semi-axis 0.156586")
near(math.abs(e.asymptotes[1].y / e.asymptotes[1].x), 1.753156, 1e-6, "asymptote slope")
local c6 = e.coef
for _, s in ipairs{.1, .5, .8} do
  local m = korotky.conic_arc(P(0, 0), V(1, sqrt(3)), P(2, 0), V(-1, sqrt(3)), P(1, 1.5))(s)
  near(c6[1] * m.x ^ 2 + c6[2] * m.x * m.y + c6[3] * m.y ^ 2 + c6[4] * m.x + c6[5] * m.y + c6[6], 0,
       1e-12, "the arc on its equation")
end
e = korotky.conic_elements({1, 0, 4, -2, 0, 0})
same(e.center, P(1, 0), "from coefficients")

-- graphical differentiation: (7) sampled every 0.01 gives its knot slopes (C.3 12a)
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local c7 = korotky.poly_spline(pts)
local samples = {}
for i = 0, 430 do samples[#samples + 1] = c7(1.2 + i / 100) end
local want = {1.2174, 2.2319, 2.0329, -2.0516, -2.2742}
for i, p in ipairs(pts) do
  local m, deg = korotky.graphical_slope(samples, p.x)
  near(m, want[i], 2e-3, "graphical slope at knot " .. i)
  near(deg, math.deg(math.atan(m)), 1e-12, "its angle in degrees")
end

-- errors
err(function() korotky.two_pencils{omega = {C, foot}, delta = {X, luff, leech}} end,
    "korotky.two_pencils: option 'omega' must be a list of three 4-D points, vectors or curves, got table")
err(function() korotky.two_pencils{omega = {C, foot, P(1, 2, 3)}, delta = {X, luff, leech}} end,
    "korotky.two_pencils: option 'omega' [3] must be a 4-D point, vector or curve, got P(1, 2, 3)")
err(function() korotky.two_pencils{omega = {C, foot, Z}, delta = {C, Z, luff}} end,
    "korotky.two_pencils: no single meet at u = v = 0.5: the planes share a line")
err(function() korotky.two_pencils(3) end,
    "korotky.two_pencils: argument #1 (pencils) must be a table {omega =, delta =}, got 3")
err(function() korotky.conic_revolve{A = AA, B = BB, nA = V(0, 1, 0), nB = V(0, 1, 0),
                                     ridge = bezier{P(0, 0, 0), P(1, 0, 1)}} end,
    "korotky.conic_revolve: the ridge point lies on the axis AB at u = 0")
err(function() korotky.conic_revolve{A = AA, B = BB, nA = V(0, 0, 1), nB = V(0, 1, 0), ridge = ridge} end,
    "korotky.conic_revolve: no conic through A, B and the ridge point with those tangent planes at u = 0")
err(function() korotky.conic_revolve{A = AA, B = BB, nA = P(0, 1, 0), nB = V(0, 1, 0), ridge = ridge} end,
    "korotky.conic_revolve: option 'nA' must be a 3-D vector, got P(0, 1, 0); a vector has weight 0: a difference of points is a vector, e.g. B - A")
err(function() korotky.conic_revolve{A = AA, B = BB, nA = V(0, 1, 0), nB = V(0, 1, 0), ridge = c7} end,
    "korotky.conic_revolve: option 'ridge' must be a 3-D curve, got a 2-D one")
err(function() korotky.ridge_shell{U = P(0, 0, 0)} end,
    "korotky.ridge_shell: option 'R' must be a 3-D curve, point or vector, got nil")
err(function()
      korotky.ridge_shell{U = P(0, -2, 0), R = P(0, 0, 1.5), V = P(0, 2, 0), T1 = P(0, -3, 3),
                          T2 = P(0, 1, .75), P = V(0, 0, 1), H = V(0, 1, 0), Q = V(0, 0, 1)}
    end, "korotky.ridge_shell: no conic arc of the profile at u = 0 (a T must lie between the tangent lines)")
err(function() korotky.conic_elements(c7) end,
    "korotky.conic_elements: argument #1 (arc | {a, b, c, d, e, f}) must be a 2-D conic arc (a rational quadratic Bezier curve) or the coefficients {a, b, c, d, e, f}, got curve")
err(function() korotky.conic_elements({1, 0, -1, 0, 0, 0}) end,
    "korotky.conic_elements: a degenerate conic (a line pair, or no real points)")
err(function() korotky.conic_elements(korotky.conic_arc(P(0, 0), V(1, 1), P(2, 0), V(-1, 1), P(1, 0))) end,
    "korotky.conic_elements: the arc is a straight segment (weight 0): no conic")
err(function() korotky.graphical_slope(samples, 7) end,
    "korotky.graphical_slope: argument #2 (x) must lie within the samples [1.2, 5.5], got 7")
err(function() korotky.graphical_slope({P(0, 0), P(0, 1), P(1, 1)}, .5) end,
    "korotky.graphical_slope: argument #1 (samples) [2] must lie right of the sample before (x must increase)")
err(function() korotky.graphical_slope(samples, 2, 2) end,
    "korotky.graphical_slope: argument #3 (window) must be an integer 3 to 431, got 2")
check.done()
