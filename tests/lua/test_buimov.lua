-- The textbook (Buimov, digest ../shared/reference/buimov_textbook.md) through Lua: the 36 test
-- vectors of the digest's §9.2, numbered as there, each with the corrected value where the book
-- misprints; identities (inverse and composition order, idempotent projections, foreshortening,
-- C2 joints and end conditions, B-spline of order 4 = Bezier, Coons boundaries); reconstruction
-- and calibration; pixels of a projected cube and of a hidden-line wireframe; the errors of
-- plane.* and buimov.*.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local pi, sqrt, cos, sin = math.pi, math.sqrt, math.cos, math.sin
local same = check.same_within(1e-12)
local same6 = check.same_within(5e-7)
local O = P(0, 0, 0)

local function matrix_is(f, want, tol, what)
  local m = f:matrix("row")
  eq(#m, #want, what .. ": rows")
  for i = 1, #want do
    for j = 1, #want[i] do near(m[i][j], want[i][j], tol, what .. " [" .. i .. "][" .. j .. "]") end
  end
end
-- the book's 2x2 matrix [[a, b], [c, d]] in the homogeneous 3x3 form
local function T2(a, b, c, d) return map.matrix({{a, b, 0}, {c, d, 0}, {0, 0, 1}}, "row") end

-- Matrix and 2-D tests ------------------------------------------------------------------------------
-- 1. §1.2.4: the inverse by cofactors, det = 1
local A = map.matrix({{1, 2, 3}, {1, 3, 3}, {1, 2, 4}}, "row")
matrix_is(A:inverse(), {{6, -2, -3}, {-1, 1, 0}, {-1, 0, 1}}, 1e-12, "#1 inverse")
near(buimov.det({{1, 2, 3}, {1, 3, 3}, {1, 2, 4}}), 1, 1e-12, "#1 det")
-- 2. §1.4, Fig 1.7: T = [[1, 2], [3, 1]] (recovered from the printed result)
local T = T2(1, 2, 3, 1)
same(T(P(0, 1)), P(3, 1), "#2 A*"); same(T(P(2, 3)), P(11, 7), "#2 B*"); same(T(P(1, 2)), P(7, 4), "#2 midpoint")
near(buimov.det({{1, 2}, {3, 1}}), -5, 1e-15, "#2 det = -5: the unit square's area times -5 (§1.7.4)")
near(area(T(P(0, 0)), T(P(1, 0)), T(P(1, 1))) * 2, -5, 1e-12, "§1.7.4 S* = S |T|, with orientation")
-- 3. §1.6, Fig 1.8: the intersection (2, 2) goes to (4, 0)
local T8 = T2(1, 2, 1, -2)
for _, c in ipairs({{P(0, 4), P(4, -8)}, {P(4, 0), P(4, 8)}, {P(-1, -1), P(-2, 0)}, {P(3, 3), P(6, 0)}, {P(2, 2), P(4, 0)}}) do
  same(T8(c[1]), c[2], "#3 " .. tostring(c[1]))
end
-- 4. §1.7.1, Fig 1.9: R(90°), R(180°) = -I, R(270°)
local R90 = map.rotate(pi / 2)
same(R90(P(3, -1)), P(1, 3), "#4"); same(R90(P(4, 1)), P(-1, 4), "#4"); same(R90(P(2, 1)), P(-1, 2), "#4")
matrix_is(R90, {{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}, 1e-15, "#4 R(90°)")
matrix_is(map.rotate(pi), {{-1, 0, 0}, {0, -1, 0}, {0, 0, 1}}, 1e-15, "#4 R(180°)")
matrix_is(map.rotate(3 * pi / 2), {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}, 1e-15, "#4 R(270°)")
-- 5. §1.7.2, Fig 1.10: reflections about y = x and y = 0
for _, c in ipairs({{P(8, 1), P(1, 8), P(8, -1)}, {P(6, 2), P(2, 6), P(6, -2)}, {P(7, 3), P(3, 7), P(7, -3)}}) do
  same(T2(0, 1, 1, 0)(c[1]), c[2], "#5 y = x"); same(map.reflect(P(0, 0), V(1, -1))(c[1]), c[2], "#5 map.reflect y = x")
  same(T2(1, 0, 0, -1)(c[1]), c[3], "#5 y = 0")
end
-- 6. §1.7.3, Fig 1.11: 2I
for _, c in ipairs({{P(3, 1), P(6, 2)}, {P(3, 2), P(6, 4)}, {P(1, 2), P(2, 4)}}) do same(map.scale(2, 2)(c[1]), c[2], "#6") end
-- 7. §1.7.3 (corrected): T1 = R(90°), T2 = reflection in x = 0; the book composes left to right
local T1m, T2m = T2(0, 1, -1, 0), T2(-1, 0, 0, 1)
matrix_is(T2m * T1m, {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}}, 0, "#7 T1 T2 (T1 first)")
matrix_is(T1m * T2m, {{0, -1, 0}, {-1, 0, 0}, {0, 0, 1}}, 0, "#7 T2 T1")
same((T2m * T1m)(P(5, 7)), P(7, 5), "#7 (5, 7) through T1 then T2")
same((T1m * T2m)(P(5, 7)), P(-7, -5), "#7 through T2 then T1: [-y -x] (the book prints [-x -y])")
-- 8. §1.7.5: C* = (cos - sin, cos + sin); 30°
same6(map.rotate(pi / 6)(P(1, 1)), P(0.366025, 1.366025), "#8 C* at 30°")
-- 9. §1.7.6, Fig 1.16: p = q = 1; homogeneous representatives of one point
local PQ = map.matrix({{1, 0, 1}, {0, 1, 1}, {0, 0, 1}}, "row")
same(PQ(P(1, 3)), P(0.2, 0.6), "#9 A*"); same(PQ(P(4, 1)), P(2 / 3, 1 / 6), "#9 B*")
for _, h in ipairs({4, 2, 1}) do same(normalize(P(3, 2) * h), P(3, 2), "#9 (" .. 3 * h .. ", " .. 2 * h .. ", " .. h .. ") is (3, 2)") end
-- 10. §1.7.7 (corrected: [4 3 h], not [3 4 h]): towards the point at infinity of y = 3x/4
for _, h in ipairs({1, 1 / 2, 1 / 10, 1 / 100, 1e-6}) do
  same(normalize(P(4, 3) * h + V(4, 3) * (1 - h)), P(4 / h, 3 / h), "#10 h = " .. h, 1e-6)
end
eq(weight(P(4, 3) * 0 + V(4, 3)), 0, "#10 h = 0 is a point at infinity (a direction)")
-- 11. §1.7.8: rotation about (2, 3): the third row
for _, c in ipairs({{pi / 2, 5, 1}, {pi, 4, 6}, {3 * pi / 2, -1, 5}, {pi / 6, 1.767949, -0.598076}}) do
  local row = map.rotate(c[1], P(2, 3)):matrix("row")[3]
  near(row[1], c[2], 5e-7, "#11 row 3 x"); near(row[2], c[3], 5e-7, "#11 row 3 y"); eq(row[3], 1, "#11 row 3 w")
end

-- 3-D transforms and projections -------------------------------------------------------------------
-- 12. §2.3
matrix_is(map.rotate(O, V(1, 0, 0), pi / 2), {{1, 0, 0, 0}, {0, 0, 1, 0}, {0, -1, 0, 0}, {0, 0, 0, 1}}, 1e-15, "#12 Rx")
matrix_is(map.rotate(O, V(0, 1, 0), pi / 2), {{0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}}, 1e-15, "#12 Ry")
matrix_is(map.rotate(O, V(0, 0, 1), pi / 2), {{0, 1, 0, 0}, {-1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}, 1e-15, "#12 Rz")
-- 13. §2.7 (Rodrigues)
matrix_is(map.rotate(O, V(1, 1, 1), 2 * pi / 3), {{0, 1, 0, 0}, {0, 0, 1, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}}, 1e-15, "#13 n = (1,1,1)/sqrt 3, 120°")
same(map.rotate(P(1, 1, 0), V(0, 0, 1), pi / 2)(P(2, 1, 5)), P(1, 2, 5), "#13 axis through (1, 1, 0)")
local th = 0.7
matrix_is(map.rotate(O, V(0, 0, 1), th), {{cos(th), sin(th), 0, 0}, {-sin(th), cos(th), 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}, 1e-15, "#13 e3 gives Rz")
-- 14. §2.8.2 (corrected): the top view Rx(90°) Pz sends (x, y, z) to (x, -z)
local top = map.orthographic() * map.rotate(O, V(1, 0, 0), pi / 2)
local cube = {A = P(0, 0, 0), E = P(0, 0, 1), B = P(0, 1, 0), F = P(0, 1, 1), D = P(1, 0, 0), H = P(1, 0, 1), C = P(1, 1, 0), G = P(1, 1, 1)}
local want = {A = P(0, 0), E = P(0, -1), B = P(0, 0), F = P(0, -1), D = P(1, 0), H = P(1, -1), C = P(1, 0), G = P(1, -1)}
for k, X in pairs(cube) do same(top(X), want[k], "#14 " .. k .. "*") end
-- parallel projections onto z = 0 are idempotent: with the embedding back into space E,
-- (E P)(E P) = E P (an axonometry is such a projection after a rotation, T = R Pz)
local E = affine.frame(O, V(1, 0, 0), V(0, 1, 0))
for _, pr in ipairs({map.orthographic(), map.cavalier(), map.cabinet(), map.oblique(0.7, 1)}) do
  local EP = E * pr
  local a, b = (EP * EP):matrix(), EP:matrix()
  for i = 1, 4 do for j = 1, 4 do near(a[i][j], b[i][j], 1e-15, "a parallel projection onto z = 0 is idempotent") end end
end
-- 15. §2.8.3: dimetric with fz = 1/2
local dm = map.dimetric(0.5)
matrix_is(dm, {{0.925820, 0.133631, 0}, {0, 0.935414, 0}, {0.377964, -0.327327, 0}, {0, 0, 1}}, 5e-7, "#15 T")
near(dist(dm(V(1, 0, 0))), 0.935414, 5e-7, "#15 fx"); near(dist(dm(V(0, 1, 0))), 0.935414, 5e-7, "#15 fy")
near(dist(dm(V(0, 0, 1))), 0.5, 1e-15, "#15 fz")
matrix_is(map.axonometric(22.207654 * pi / 180, 20.704811 * pi / 180), dm:matrix("row"), 1e-7, "#15 phi = 22.207654°, theta = 20.704811°")
-- 16. §2.8.4 (corrected angle formula tan alpha = sin phi sin theta / cos phi): isometric
local iso = map.isometric()
matrix_is(iso, {{0.707107, 0.408248, 0}, {0, 0.816497, 0}, {0.707107, -0.408248, 0}, {0, 0, 1}}, 5e-7, "#16 T")
for _, v in ipairs({V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)}) do near(dist(iso(v)), 0.816497, 5e-7, "#16 foreshortening 0.8165 on every axis") end
near(math.atan(iso(V(1, 0, 0)).y, iso(V(1, 0, 0)).x), pi / 6, 1e-15, "#16 the x axis at 30°")
near(math.atan(iso(V(0, 0, 1)).y, iso(V(0, 0, 1)).x), -pi / 6, 1e-15, "#16 the z axis at -30°")
-- 17. §2.8.5: one-, two- and three-point perspective transforms (vanishing point [0 0 1/r 1], corrected)
local Pz = map.matrix({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 0.5}, {0, 0, 0, 1}}, "row")
same(Pz(P(1, 1, 1)), P(2 / 3, 2 / 3, 0), "#17 perspective projection onto z = 0, h = 1.5")
local one = map.matrix({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0.5}, {0, 0, 0, 1}}, "row")
same(one(V(0, 0, 1)), P(0, 0, 2), "#17 the z vanishing point (0, 0, 1/r)")
same(map.matrix({{1, 0, 0, 0.5}, {0, 1, 0, 0.5}, {0, 0, 1, 0}, {0, 0, 0, 1}}, "row")(P(1, 0, 1)), P(2 / 3, 0, 2 / 3), "#17 two-point")
local three = map.matrix({{1, 0, 0, 0.5}, {0, 1, 0, 0.5}, {0, 0, 1, 0.5}, {0, 0, 0, 1}}, "row")
same(three(P(1, 1, 1)), P(0.4, 0.4, 0.4), "#17 three-point")
local v1, v2, v3 = three:vanishing_points()
same(v1, P(2, 0, 0), "three vanishing points: [1/p 0 0]"); same(v2, P(0, 2, 0), "[0 1/q 0]"); same(v3, P(0, 0, 2), "[0 0 1/r]")
-- 18. §2.8.5, Fig 2.12: Ry(60°), then r = 1/2
local two = one * map.rotate(O, V(0, 1, 0), pi / 3)
matrix_is(two, {{0.5, 0, -0.866025, -0.433013}, {0, 1, 0, 0}, {0.866025, 0, 0.5, 0.25}, {0, 0, 0, 1}}, 5e-7, "#18 T")
local vx, vy, vz = two:vanishing_points()
same6(vx, P(-1.154701, 0, 2), "#18 x direction: (-k cot theta, 0, k)"); same6(vz, P(3.464102, 0, 2), "#18 z direction")
eq(vy, nil, "#18 y stays at infinity")

-- Plane curves ----------------------------------------------------------------------------------------
-- 19. §3.2 example 1 (the book prints x^2 + y^2 - 5x + y + 4 = 0; -y is right)
local c = plane.circle3(P(1, 1), P(2, 2), P(3, 2))
near(c.d, -5, 1e-12, "#19 d"); near(c.e, -1, 1e-12, "#19 e"); near(c.f, 4, 1e-12, "#19 f")
same(c.centre, P(2.5, 0.5), "#19 centre"); near(c.r, 1.581139, 5e-7, "#19 r")
same(c.arc(c.arc.t0), P(3, 2), "the arc runs counter-clockwise from (3, 2)"); same(c.arc(c.arc.t1), P(1, 1), "to (1, 1)")
near(dist(c.arc((c.arc.t0 + c.arc.t1) / 2), c.centre), c.r, 1e-12, "on the circle")
near(c.curve:length(), 2 * pi * c.r, 1e-9, "the whole circle, a rational Bezier curve")
-- 20. §3.2 example 2 (corrected: the book prints the rounded d = -8.4, e = 5.7, f = 0.7 and omits the second circle)
local c1, c2 = plane.circle2r(P(1, 1), P(3, 2), 5)
same6(c1.centre, P(4.179449, -2.858899), "#20 first centre")
near(c1.d, -8.358899, 5e-7, "#20 d"); near(c1.e, 5.717798, 5e-7, "#20 e"); near(c1.f, 0.641101, 5e-7, "#20 f")
same6(c2.centre, P(-0.179449, 5.858899), "#20 second centre")
for _, k in ipairs({c1, c2}) do near(dist(k.centre, P(1, 1)), 5, 1e-12, "#20 r = 5"); near(dist(k.centre, P(3, 2)), 5, 1e-12, "#20") end
-- 21. §3.2 example 3, Fig 3.1
local s1, s2 = plane.circle_slopes(P(1, 1), 1, 3, 0)
for _, k in ipairs({s1, s2}) do
  near(k.d, -6, 1e-12, "#21 d"); near(k.e, 2, 1e-12, "#21 e"); near(k.f, 2, 1e-12, "#21 f")
  same(k.centre, P(3, -1), "#21 centre"); near(k.r, 2.828427, 5e-7, "#21 r")
end
same6(s1.finish, P(3, 1.828427), "#21 end point (3, 1.8)"); same6(s2.finish, P(3, -3.828427), "#21 end point (3, -3.8)")
same(s1.arc(s1.arc.t1), P(1, 1), "the arc from (1, 1)"); same(s1.arc(s1.arc.t0), s1.finish, "to its end")
same(unit(s1.arc:deriv(s1.arc.t1)), unit(V(-1, -1)), "leaving (1, 1) with slope 1 (the curve runs backwards)")
-- 22. §3.2: the rational circle and the recurrence
same(plane.points("circle", {A = 1, step = 0.5, n = 1, method = "rational"})[2], P(0.6, 0.8), "#22 t = 0.5")
local rc = plane.points("circle", {A = 1, step = pi / 2, n = 2, method = "recurrence"})
same(rc[1], P(1, 0), "#22 (1, 0)"); same(rc[2], P(0, 1), "#22 -> (0, 1)"); same(rc[3], P(-1, 0), "#22 -> (-1, 0)")
-- 23. §3.3-§3.5: the recurrences after 10 steps (corrected signs)
same6(plane.points("ellipse", {A = 3, B = 2, step = 0.1, n = 10, method = "recurrence"})[11], P(1.620907, 1.682942), "#23 ellipse")
same6(plane.points("parabola", {A = 0.5, step = 0.1, n = 10, method = "recurrence"})[11], P(0.5, 1.0), "#23 parabola (+ y dth)")
same6(plane.points("hyperbola", {A = 2, B = 1.5, step = 0.05, n = 10, method = "recurrence"})[11], P(2.278988, 0.819454), "#23 hyperbola sec/tan (B - y tan)")
same6(plane.points("hyperbola_ch", {A = 2, B = 1.5, step = 0.05, n = 10, method = "recurrence"})[11], P(2.255252, 0.781643), "#23 hyperbola ch/sh")
-- 24. §3.3 (corrected b = 2(c' - a') cos sin): the rotated conic at (1.3, -0.4)
local k = plane.rotate_conic({4, 0, 9, -3, 2, -7}, 0.3)
near(plane.conic_value(k, P(1.3, -0.4)), -3.676332, 5e-7, "#24 rotated form")
near(plane.conic_value({4, 0, 9, -3, 2, -7}, map.rotate(0.3)(P(1.3, -0.4))), -3.676332, 5e-7, "#24 original at (x', y')")
eq(plane.classify(k[1], k[2], k[3]), "ellipse", "rotation keeps the kind")
eq(plane.classify(1, 2, 1), "parabola", "b^2 = 4ac"); eq(plane.classify(1, 0, -1), "hyperbola", "b^2 > 4ac")
local pc = plane.conic_coef("parabola", P(2, -1), 0.5)
near(pc[6], 2, 0, "§3.4 f = m^2 + 4pn (printed m^2 - 4pn)"); near(plane.conic_value(pc, P(4, 1)), 0, 1e-12, "a point of the parabola")

-- Space curves -----------------------------------------------------------------------------------------
-- 25. §4.2 clamped, normalised: P = (0,0), (1,1), (2,-1), (3,0), P'1 = P'4 = (1,1)
local pts = {P(0, 0), P(1, 1), P(2, -1), P(3, 0)}
local sp, tg = buimov.spline(pts, {ends = "clamped", d0 = V(1, 1), d1 = V(1, 1)})
same(tg[2], V(1, -0.8), "#25 P'2"); same(tg[3], V(1, -0.8), "#25 P'3")
local B1, B2, B3, B4 = buimov.hermite_coeffs(pts[1], pts[2], tg[1], tg[2])
same(B1, P(0, 0), "#25 B1"); same(B2, V(1, 1), "#25 B2"); same(B3, V(0, 1.8), "#25 B3"); same(B4, V(0, -1.8), "#25 B4")
same(sp(0.5), P(0.5, 0.725), "#25 segment 1 at 0.5")
local _, _, C3, C4 = buimov.hermite_coeffs(pts[2], pts[3], tg[2], tg[3])
same(C3, V(0, -3.6), "#25 segment 2 B3"); same(C4, V(0, 2.4), "#25 segment 2 B4"); same(sp(1.5), P(1.5, 0), "#25 segment 2 at 0.5")
same(sp(2.5), P(2.5, -0.725), "#25 segment 3 at 0.5")
same(sp:deriv(1, 2), V(0, -7.2), "#25 P'' at the first joint", 1e-11)
same(sp:deriv(2, 2), V(0, 7.2), "#25 P'' at the second joint", 1e-11)
-- 26. chord length: t = (sqrt 2, sqrt 5, sqrt 2)
local spc, tgc = buimov.spline(pts, {ends = "clamped", d0 = V(1, 1), d1 = V(1, 1), param = "chord"})
same6(tgc[2], V(0.505431, -0.147724), "#26 P'2"); same6(tgc[3], V(0.505431, -0.147724), "#26 P'3")
local _, _, D3, D4 = buimov.hermite_coeffs(pts[1], pts[2], tgc[1], tgc[2], sqrt(2))
same6(D3, V(-0.271607, 0.190243), "#26 B3"); same6(D4, V(0.045609, -0.280969), "#26 B4")
same6(spc(sqrt(2) / 2), P(0.587428, 0.702891), "#26 P(t2/2)")
same(buimov.hermite(pts[1], pts[2], tgc[1], tgc[2], sqrt(2))(0.3), spc(0.3), "the Hermite segment in the book's parameter [0, t2]")
-- all four ends, C2 joints and the end conditions
local q = {P(0, 0), P(1, 2), P(3, 2.5), P(4, 0), P(2, -1), P(0.5, -0.4)}
for _, ends in ipairs({"clamped", "natural", "cyclic", "anticyclic"}) do
  for _, param in ipairs({"uniform", "chord"}) do
    local s = buimov.spline(q, {ends = ends, d0 = V(2, -1), d1 = V(0.5, 3), param = param})
    local a1, a2 = s:deriv(s.t0), s:deriv(s.t0, 2)
    local b1, b2 = s:deriv(s.t1), s:deriv(s.t1, 2)
    if ends == "clamped" then same(a1, V(2, -1), "clamped start", 1e-12); same(b1, V(0.5, 3), "clamped end", 1e-12) end
    if ends == "natural" then same(a2, V(0, 0), "natural: P'' = 0 at the start", 1e-11); same(b2, V(0, 0), "and the end", 1e-11) end
    if ends == "cyclic" then same(b1, a1, "cyclic P'", 1e-11); same(b2, a2, "cyclic P''", 1e-10) end
    if ends == "anticyclic" then same(b1, -a1, "anticyclic P'", 1e-11); same(b2, -a2, "anticyclic P''", 1e-10) end
    local kn = s:knots()
    for i = 2, #kn - 1, 1 do
      local l1, l2 = s:deriv(kn[i] - 1e-9), s:deriv(kn[i] - 1e-9, 2)
      local r1, r2 = s:deriv(kn[i] + 1e-9), s:deriv(kn[i] + 1e-9, 2)
      truthy(sqrt(dot(l1 - r1, l1 - r1)) < 1e-6 and sqrt(dot(l2 - r2, l2 - r2)) < 1e-5, ends .. "/" .. param .. ": C2 at the joint " .. i)
    end
  end
end
-- 27. §5.5: the Hermite blending functions
local F = {buimov.blend(0.5)}
near(F[1], 0.5, 0, "#27 F1(.5)"); near(F[2], 0.5, 0, "#27 F2"); near(F[3], 0.125, 0, "#27 F3"); near(F[4], -0.125, 0, "#27 F4")
F = {buimov.blend(0.25)}
near(F[1], 0.84375, 0, "#27 F1(.25)"); near(F[2], 0.15625, 0, "#27 F2"); near(F[3], 0.140625, 0, "#27 F3"); near(F[4], -0.046875, 0, "#27 F4")
-- 28. §4.3: Bernstein and the cubic Bezier
local J1, J2 = {8 / 27, 4 / 9, 2 / 9, 1 / 27}, {1 / 27, 2 / 9, 4 / 9, 8 / 27}
for i = 0, 3 do
  near(buimov.bernstein(3, i, 1 / 3), J1[i + 1], 1e-15, "#28 J3," .. i .. "(1/3)")
  near(buimov.bernstein(3, i, 2 / 3), J2[i + 1], 1e-15, "#28 J3," .. i .. "(2/3)")
end
local bz = bezier{P(1, 1), P(2, 3), P(4, 3), P(3, 1)}
same(bz(0.5), P(2.75, 2.5), "#28 P(0.5)")
same(bz(0.15), P(1.504, 1.765), "#28 P(0.15)", 5e-4); same(bz(0.85), P(3.261, 1.765), "#28 P(0.85)", 5e-4)
same(bz:deriv(0), V(3, 6), "#28 P'(0) = 3(P1 - P0)"); same(bz:deriv(1), V(-3, -6), "#28 P'(1)")
-- 29. §4.4: knot vectors (corrected: n + k + 1 knots; the double vertex with k = 2)
local function knots_are(got, want, what)
  eq(#got, #want, what .. ": count")
  for i = 1, #want do eq(got[i], want[i], what .. " [" .. i .. "]") end
end
local five = {P(0, 0), P(1, 2), P(3, 1), P(4, 2), P(5, 0)}
knots_are(buimov.knots(five, 2), {0, 0, 1, 2, 3, 4, 4}, "#29 n = 4, k = 2")
knots_are(buimov.knots(five, 3), {0, 0, 0, 1, 2, 3, 3, 3}, "#29 n = 4, k = 3")
knots_are(buimov.knots({five[1], five[2], five[3], five[4]}, 2), {0, 0, 1, 2, 3, 3}, "#29 n = 3, k = 2")
knots_are(buimov.knots({five[1], five[2], five[3], five[4]}, 4), {0, 0, 0, 0, 1, 1, 1, 1}, "#29 n = 3, k = 4")
local double = {P(0, 0), P(1, 2), P(1, 2), P(3, 1), P(4, 2), P(5, 0)}
knots_are(buimov.knots(double, 2), {0, 0, 1, 1, 2, 3, 4, 4}, "#29 double P1, k = 2 (printed [0 0 1 1 2 2 3 3 4 4])")
knots_are(buimov.knots(double, 3), {0, 0, 0, 1, 1, 2, 3, 3, 3}, "#29 double P1, k = 3 (the book's \"n = 3\")")
-- 30. §4.4: the k = 2 table on [0 0 1 2 3 3], t_max closed
local q2 = {0, 0, 1, 2, 3, 3}
local tab = {{1, 0, 0, 0}, {.5, .5, 0, 0}, {0, 1, 0, 0}, {0, .5, .5, 0}, {0, 0, 1, 0}, {0, 0, .5, .5}, {0, 0, 0, 1}}
for r = 1, 7 do
  for i = 0, 3 do near(buimov.basis(i, 2, (r - 1) / 2, q2), tab[r][i + 1], 1e-15, "#30 N" .. i .. ",2(" .. (r - 1) / 2 .. ")") end
end
local poly = buimov.bspline({P(0, 0), P(2, 1), P(3, 3), P(5, 2)}, 2)
same(poly(3), P(5, 2), "#30 P(t_max) = P3"); same(poly(0.5), P(1, 0.5), "#30 P(0.5) = (P0 + P1)/2")
local triple = buimov.bspline({P(0, 0), P(0, 0), P(0, 0), P(1, 1)}, 2)
knots_are(buimov.knots({P(0, 0), P(0, 0), P(0, 0), P(1, 1)}, 2), {0, 0, 0, 0, 1, 1}, "a triple vertex")
same(triple(0), P(0, 0), "it starts at the triple vertex"); same(triple(0.5), P(0.5, 0.5), "then runs to P3")
-- 31. §4.4: order 4 on 4 points is the Bezier curve; order 3
local cp = {P(1, 1), P(2, 3), P(4, 3), P(3, 1)}
local b4 = buimov.bspline(cp, 4)
for t = 0, 1, 0.125 do same(b4(t), bz(t), "#31 k = 4 is the Bezier curve at " .. t) end
local b3 = buimov.bspline(cp, 3)
knots_are(buimov.knots(cp, 3), {0, 0, 0, 1, 2, 2, 2}, "#31 k = 3 knots")
same(b3(0.5), P(2, 2.5), "#31 P(0.5)"); same(b3(1), P(3, 3), "#31 P(1)"); same(b3(1.5), P(3.5, 2.5), "#31 P(1.5)")
local kn3 = buimov.knots(cp, 3)
for i, w in ipairs({0.25, 0.625, 0.125, 0}) do near(buimov.basis(i - 1, 3, 0.5, kn3), w, 1e-15, "#31 weight " .. i) end
-- 32. §4.4, Fig 4.9 with k = 4 (with the book's k = 5 the start moves slightly: the digest's note)
local at2 = {P(4.3333, 1.3333), P(4.5, 1.6667), P(4.6667, 2.0)}
for j, P4 in ipairs({P(5, 0), P(6, 2), P(7, 4)}) do
  local c = buimov.bspline({P(0, 2), P(2, 5), P(5, 4), P(4, 1), P4, P(8, 1), P(10, 4)}, 4)
  same(c(0.4), P(2.1333, 4.1280), "#32 P(0.4) whatever P4", 5e-5)
  same(c(2), at2[j], "#32 P(2) for P4 = " .. tostring(P4), 5e-5)
  local c5 = buimov.bspline({P(0, 2), P(2, 5), P(5, 4), P(4, 1), P4, P(8, 1), P(10, 4)}, 5)
  same(c5(0.3), ({P(2.0930, 4.0366), P(2.0934, 4.0375), P(2.0939, 4.0384)})[j], "k = 5 at t = 0.3 (the start moves)", 5e-5)
end

-- Surfaces ----------------------------------------------------------------------------------------------
-- 33. §5.1 (corrected y = sin th sin ph, S_th, S_ph, N_B = -(e1 + e3)/2)
local S, St, Sp, Stp, N = buimov.sphere_frame(0, pi / 4)
local r2 = sqrt(0.5)
same(S, P(r2, 0, r2), "#33 S at B"); same(St, V(0, r2, 0), "#33 S_th"); same(Sp, V(r2, 0, -r2), "#33 S_ph")
same(Stp, V(0, r2, 0), "#33 twist"); same(N, V(-0.5, 0, -0.5), "#33 N_B = -(e1 + e3)/2 (printed -(e1 + e2)/2)")
S, St, Sp, Stp, N = buimov.sphere_frame(pi / 2, pi / 4)
same(N, V(0, -0.5, -0.5), "#33 N_C"); same(St, V(-r2, 0, 0), "#33 S_th at C")
S, St, Sp, Stp, N = buimov.sphere_frame(0, pi / 2)
same(N, V(-1, 0, 0), "#33 N_A = -e1"); same(Sp, V(0, 0, -1), "#33 S_ph at A")
local patch = buimov.sphere(0, pi / 2, pi / 4, pi / 2)
same(patch:normal(0.4, 1), -unit(patch(0.4, 1) - O), "#33 the unit normal is -S (inwards)")
local _, pu, pv = patch:partials(0, pi / 4)
same(pu, V(0, r2, 0), "the patch's partials are S_th"); same(pv, V(r2, 0, -r2), "and S_ph")
-- 34. §5.2: bilinear, P00 = (0,0,1), P01 = (0,1,0), P10 = (1,0,0), P11 = (1,1,1) (surface.bilinear takes P00, P10, P01, P11)
local bl = surface.bilinear(P(0, 0, 1), P(1, 0, 0), P(0, 1, 0), P(1, 1, 1))
same(bl(0.5, 0.5), P(0.5, 0.5, 0.5), "#34 Q(.5, .5)"); same(bl(0.25, 0.75), P(0.25, 0.75, 0.375), "#34 Q(.25, .75)")
-- 35. §5.4: linear Coons
local cu0 = curve(function(u) return P(u, 0, sin(pi * u)) end, 0, 1)
local cu1, c0w, c1w = bezier{P(0, 1, 0), P(1, 1, 0)}, bezier{P(0, 0, 0), P(0, 1, 0)}, bezier{P(1, 0, 0), P(1, 1, 0)}
local co = surface.coons(cu0, cu1, c0w, c1w)
same(co(0.5, 0.5), P(0.5, 0.5, 0.5), "#35 Q(.5, .5)"); same6(co(0.25, 0.5), P(0.25, 0.5, 0.353553), "#35 Q(.25, .5)")
same(co(0.5, 0), P(0.5, 0, 1), "#35 the boundary Q(u, 0) = P(u, 0)")
for t = 0, 1, 0.25 do
  same(co(t, 0), cu0(t), "Coons reproduces P(u, 0)"); same(co(t, 1), cu1(t), "P(u, 1)")
  same(co(0, t), c0w(t), "P(0, w)"); same(co(1, t), c1w(t), "P(1, w)")
end
local naive = surface.ruled(cu0, cu1)(0, 0) + surface.ruled(c0w, c1w)(0, 0)
eq(weight(naive), 2, "#35 the naive sum counts the corner twice: Q(0, 0) = 2 P00")
same(normalize(naive), P(0, 0, 0), "#35 (2 P00 normalised is P00)")
-- 36. §5.6: a 4 x 4 Bezier net, z = 1 on the inner 2 x 2
local net = {}
for i = 0, 3 do
  net[i + 1] = {}
  for j = 0, 3 do net[i + 1][j + 1] = P(i, j, (i == 1 or i == 2) and (j == 1 or j == 2) and 1 or 0) end
end
local bs = surface.bezier(net)
same(bs(0.5, 0.5), P(1.5, 1.5, 0.5625), "#36 Q(.5, .5)"); same(bs(0.25, 0.5), P(0.75, 1.5, 0.421875), "#36 Q(.25, .5)")
same(bs(0, 0), P(0, 0, 0), "only the corners lie on the surface"); same(bs(1, 1), P(3, 3, 0), "corner P44")

-- Reconstruction and calibration (§2.8.6) -----------------------------------------------------------------
local X = P(0.7, -1.2, 2.5)
local views = {top, map.isometric()}
local got, res = buimov.reconstruct(views, {views[1](X), views[2](X)})
same(got, X, "a point from the top view and the isometric view"); near(res, 0, 1e-12, "consistent views")
local camx = map.translate(V(320, 240)) * map.scale({200, -200}) * map.perspective(P(5, -7, 4), P(0.5, 0.5, 0.5))
local box = {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(1, 1, 0), P(0, 0, 1), P(1, 0, 1), P(0, 1, 1), P(1, 1, 1.5)}
local imgs = {}
for i, X in ipairs(box) do imgs[i] = camx(X) end
local cal, rms = buimov.calibrate(box, imgs)
near(rms, 0, 1e-9, "six or more points fix the camera")
same(cal(P(0.3, 2, -1)), camx(P(0.3, 2, -1)), "the calibrated camera projects any point as the camera", 1e-8)
same(buimov.reconstruct({cal, map.isometric()}, {cal(X), map.isometric()(X)}), X, "a perspective view too", 1e-9)

-- Pixels: a projected cube and a hidden-line wireframe ---------------------------------------------------
local function ink_at(x, y, c)
  for dy = -1, 1 do for dx = -1, 1 do if point(x + dx, y + dy) == c then return true end end end
  return false
end
screen(12)
-- the book's isometric matrix typed as printed, then 100 px per unit, y up, origin at (320, 240)
local bookiso = map.matrix({{0.707107, 0.408248, 0, 0}, {0, 0.816497, 0, 0}, {0.707107, -0.408248, 0, 0}, {0, 0, 0, 1}}, "row")
camera(map.translate(V(320, 240)) * map.scale({100, -100}) * map.isometric())
for _, X in pairs(cube) do pset(X, 14) end
for name, X in pairs(cube) do
  local b = bookiso(X)
  local px, py = math.floor(320 + 100 * b.x + 0.5), math.floor(240 - 100 * b.y + 0.5)
  eq(point(px, py), 14, "cube corner " .. name .. " at (" .. px .. ", " .. py .. ") where the book's matrix puts it")
end
eq(point(320, 240 - 82), 14, "B = (0, 1, 0) straight up by 0.816497 * 100 px")
cls()
-- the whole sphere seen isometrically: the back half of its equator is left out or dashed
local sph = buimov.sphere()
-- the isometric viewer looks along the null vector of the map: its side is r1 x r2 of the
-- picture's rows (x right, y up): (-1, 1, 1)/sqrt 3
local m = map.isometric():matrix()
local toward = cross(V(m[1][1], m[1][2], m[1][3]), V(m[2][1], m[2][2], m[2][3]))
same(toward, unit(V(-1, 1, 1)), "the isometric line of sight", 1e-15)
local function equator_ink(mode)
  cls()
  sph:wireframe{nu = 1, nv = 2, color = 11, hidden = mode}    -- v = pi/2 is the equator, u = 0 a back meridian
  local front, back, nback = 0, 0, 0
  local f = camera()
  for i = 0, 63 do
    local th = 2 * pi * i / 64
    local X = sph(th, pi / 2)
    local x, y = f:xy(X)
    local seen = dot(X - O, toward) > 0.2
    local behind = dot(X - O, toward) < -0.2
    local hit = ink_at(math.floor(x + 0.5), math.floor(y + 0.5), 11)
    if seen and hit then front = front + 1 end
    if behind then nback = nback + 1; if hit then back = back + 1 end end
  end
  return front, back, nback
end
local fs, bs_, nb = equator_ink("show")
local fh, bh = equator_ink("hide")
local fd, bd = equator_ink("dashed")
eq(bs_, nb, "all of the back of the equator is drawn without hidden-line removal")
eq(bh, 0, "hidden = \"hide\": none of the back of the equator is drawn")
truthy(bd > 0 and bd < nb, "hidden = \"dashed\": the back is drawn in dashes (" .. bd .. " of " .. nb .. ")")
eq(fh, fs, "the front is drawn in full either way"); eq(fd, fs, "also with dashes")
camera(nil)

-- Errors ------------------------------------------------------------------------------------------------
err(function() plane.circle3(P(1, 1), P(2, 2), P(3, 3)) end, "plane.circle3: the three points lie on one line", "collinear")
err(function() plane.circle3(P(1, 1), P(1, 1), P(3, 3)) end, "plane.circle3: two of the points coincide", "coincident")
err(function() plane.circle3(P(1, 1), P(2, 2), 5) end, "plane.circle3: argument #3 (C) must be a 2-D point, got 5", "not a point")
err(function() plane.circle3(P(1, 1), P(2, 2), P(3, 3, 3)) end, "plane.circle3: argument #3 (C) must be a 2-D point, got P(3, 3, 3)", "3-D")
err(function() plane.circle2r(P(1, 1), P(3, 2), 1) end, "plane.circle2r: the points are 2.2360679774998 apart, farther than the diameter 2r = 2", "too small r")
err(function() plane.circle2r(P(1, 1), P(3, 2), -1) end, "plane.circle2r: argument #3 (r) must be a positive number, got -1", "negative r")
err(function() plane.circle2r(P(1, 1), P(1, 1), 1) end, "plane.circle2r: the points A and B coincide", "A = B")
err(function() plane.circle_slopes(P(1, 1), 1, 1, 0) end, "plane.circle_slopes: argument #3 (x_end) equals the abscissa of A", "x_end")
err(function() plane.circle_slopes(P(1, 1), 0, 3, 0) end, "plane.circle_slopes: no circle through A has these slopes", "no circle")
err(function() plane.circle_slopes(P(1, 1), 0 / 0, 3, 0) end, "plane.circle_slopes: argument #2 (m1) must be a finite number", "NaN slope")
err(function() plane.classify(0, 0, 0) end, "plane.classify: a = b = c = 0 is a line, not a conic", "no conic")
err(function() plane.rotate_conic({1, 2, 3}, 1) end, "plane.rotate_conic: argument #1 (coef) must hold 6 numbers, got 3", "coef")
err(function() plane.ellipse(P(0, 0), 1, -2) end, "plane.ellipse: argument #3 (B) must be a positive number, got -2", "ellipse axes")
err(function() plane.ellipse(P(0, 0), 1, 2, 1, 1) end, "plane.ellipse: need th0 < th1", "ellipse range")
err(function() plane.parabola(0, 0, 1) end, "plane.parabola: argument #1 (p) must be a positive number, got 0", "parabola p")
err(function() plane.hyperbola(1, 1, 0, 400) end, "plane.hyperbola: argument #4 (t1) must be a number from -300 to 300, got 400", "hyperbola range")
err(function() plane.points("spiral", {}) end, "plane.points: argument #1 (kind) must be \"circle\"", "kind")
err(function() plane.points("ellipse", {A = 1, B = 1, step = 0.1, n = 10, method = "rational"}) end, "plane.points: the rational method is the circle's only", "method")
err(function() plane.points("circle", {A = 1, step = 0.5, n = 5, method = "explicit"}) end, "plane.points: the steps leave the curve's domain", "explicit domain")
err(function() plane.points("circle", {A = 1, step = 0.5}) end, "plane.points: option 'n' must be an integer from 0 to 1000000, got nil", "n missing")
err(function() buimov.knots({P(0, 0), P(1, 1)}, 3) end, "buimov.knots: argument #2 (k) must be an integer from 2 to 2 (at most the number of points), got 3", "k too big")
err(function() buimov.knots({P(0, 0), P(1, 1, 1)}, 2) end, "buimov.knots: argument #1 (points) [2] is 3-D, but [1] is 2-D (mixed dimensions)", "mixed")
err(function() buimov.bspline({P(0, 0), V(1, 1)}, 2) end, "buimov.bspline: argument #1 (points) [2] must be a point, got V(1, 1); a point has weight 1: to place a vector, add it to a point, e.g. P(0, 0) + v", "a vector")
err(function() buimov.basis(4, 2, 0.5, {0, 0, 1, 2, 3, 3}) end, "buimov.basis: N(i = 4, k = 2) needs the knots", "basis range")
err(function() buimov.basis(0, 2, 0.5, {0, 2, 1}) end, "buimov.basis: argument #4 (knots) must not decrease", "knots decrease")
err(function() buimov.hermite(P(0, 0), P(1, 1), V(1, 0), P(1, 1)) end, "buimov.hermite: argument #4 (D2) must be a vector, got P(1, 1); a vector has weight 0: a difference of points is a vector, e.g. B - A", "D2 a point")
err(function() buimov.hermite(P(0, 0), P(1, 1), V(1, 0), V(1, 1), 0) end, "buimov.hermite: argument #5 (t) must be a positive number", "t = 0")
err(function() buimov.spline(pts, {ends = "clamped", d0 = V(1, 1)}) end, "buimov.spline: clamped ends need both end tangents d0 and d1", "clamped without d1")
err(function() buimov.spline(pts, {ends = "loose"}) end, "buimov.spline: option 'ends' must be \"clamped\", \"natural\", \"cyclic\" or \"anticyclic\", got \"loose\"", "bad ends")
err(function() buimov.spline({P(0, 0), P(1, 1), P(2, 0)}, {ends = "cyclic"}) end, "buimov.spline: cyclic and anticyclic ends need at least 4 points, got 3", "cyclic too short")
err(function() buimov.spline({P(0, 0), P(0, 0), P(2, 0)}, {param = "chord"}) end, "buimov.spline: two consecutive points coincide", "zero chord")
err(function() buimov.spline(pts, {d0 = V(1, 1, 1), d1 = V(1, 1)}) end, "buimov.spline: option 'd0' is 3-D, but argument #1 (points) is 2-D (mixed dimensions)", "d0 dims")
err(function() buimov.helix(0, 1, 0, 1) end, "buimov.helix: argument #1 (a) must be a nonzero radius, got 0", "helix radius")
err(function() buimov.sphere(0, 1, 1, 0) end, "buimov.sphere: need th0 < th1 and ph0 < ph1", "sphere range")
err(function() buimov.reconstruct({top}, {P(0, 0)}) end, "buimov.reconstruct: argument #2 (images) must hold 2 to 64 points, got 1", "one view")
err(function() buimov.reconstruct({top, top}, {P(0, 0), P(0, 0)}) end, "buimov.reconstruct: the views do not fix a point", "same view twice")
err(function() buimov.reconstruct({top, map.rotate(1)}, {P(0, 0), P(0, 0)}) end, "buimov.reconstruct: argument #1 (views) [2] must be a map from 3-D to 2-D, got map", "2-D map")
err(function() buimov.calibrate({P(0, 0, 0), P(1, 0, 0)}, {P(0, 0), P(1, 0)}) end, "buimov.calibrate: argument #1 (points) must hold at least 6 points, got 2", "too few points")
local flat = {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(1, 1, 0), P(2, 1, 0), P(1, 3, 0)}
local fimg = {}
for i, X in ipairs(flat) do fimg[i] = camx(X) end
err(function() buimov.calibrate(flat, fimg) end, "buimov.calibrate: the points do not fix a camera", "coplanar")
fimg[7] = P(0, 0)
err(function() buimov.calibrate(flat, fimg) end, "buimov.calibrate: 6 points but 7 images", "a point per image")
err(function() buimov.det({{1, 2}, {3}}) end, "buimov.det: argument #1 (rows) row [2] must be a list of 2 numbers", "det ragged")
err(function() buimov.det({{1, 2}, {3, 0 / 0}}) end, "buimov.det: argument #1 (rows) entry [2][2] must be a finite number", "det NaN")
err(function() buimov.det({}) end, "buimov.det: argument #1 (rows) must hold 1 to 17 rows, got 0", "det empty")

check.done()
