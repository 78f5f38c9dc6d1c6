-- The one map type through Lua (docs/maps.md): every map.* constructor with the textbook's
-- numbers (Buimov §1.7, §2.1-§2.8 and the test vectors of the digest's §9.2, corrected where
-- the book misprints), composition across kinds, inverses, vanishing points, the matrix
-- conventions, the printout, and the errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local pi, sqrt, cos, sin = math.pi, math.sqrt, math.cos, math.sin

local same = check.same_within(1e-12)
local same6 = check.same_within(5e-7)

-- the matrix of f in a convention against a printed one
local function matrix_is(f, conv, want, tol, what)
  local m = f:matrix(conv)
  eq(#m, #want, what .. ": rows")
  for i = 1, #want do
    eq(#m[i], #want[i], what .. ": columns of row " .. i)
    for j = 1, #want[i] do near(m[i][j], want[i][j], tol, what .. " [" .. i .. "][" .. j .. "]") end
  end
end

-- map.matrix: the textbook's row vectors, p' = p T --------------------------------------------------
-- §1.4, Fig 1.7: T = [[1, 2], [3, 1]] sends A(0, 1) to (3, 1), B(2, 3) to (11, 7), and the midpoint
-- (1, 2) to (7, 4)
local T = map.matrix({{1, 2, 0}, {3, 1, 0}, {0, 0, 1}}, "row")
same(T(P(0, 1)), P(3, 1), "§1.4 A*"); same(T(P(2, 3)), P(11, 7), "§1.4 B*"); same(T(P(1, 2)), P(7, 4), "§1.4 midpoint")
truthy(T:is_affine(), "a matrix with the last column (0, 0, 1) is affine")
eq(T.nin, 2, "nin"); eq(T.nout, 2, "nout")
-- the same map in the column convention is the transpose
same(map.matrix({{1, 3, 0}, {2, 1, 0}, {0, 0, 1}})(P(2, 3)), P(11, 7), "column vectors: the transpose")
same(map.matrix({{1, 3, 0}, {2, 1, 0}, {0, 0, 1}}, "column")(P(0, 1)), P(3, 1), "\"column\" is the default")
matrix_is(T, "row", {{1, 2, 0}, {3, 1, 0}, {0, 0, 1}}, 0, "T:matrix(\"row\") round trip")
matrix_is(T, nil, {{1, 3, 0}, {2, 1, 0}, {0, 0, 1}}, 0, "T:matrix() in columns")
matrix_is(T, "column", {{1, 3, 0}, {2, 1, 0}, {0, 0, 1}}, 0, "T:matrix(\"column\")")
-- §1.6, Fig 1.8: the lines AB (x + y = 4) and CD (y = x) meet at (2, 2); their images at (4, 0)
local T8 = map.matrix({{1, 2, 0}, {1, -2, 0}, {0, 0, 1}}, "row")
for _, c in ipairs({{P(0, 4), P(4, -8)}, {P(4, 0), P(4, 8)}, {P(-1, -1), P(-2, 0)}, {P(3, 3), P(6, 0)}, {P(2, 2), P(4, 0)}}) do
  same(T8(c[1]), c[2], "§1.6 " .. tostring(c[1]))
end
same(meet(T8(P(0, 4)), T8(P(4, 0)), T8(P(-1, -1)), T8(P(3, 3))), T8(P(2, 2)), "the meet of the images is the image of the meet")
-- §1.7.6, Fig 1.16: the projective terms p = q = 1: A(1, 3) -> (1/5, 3/5), B(4, 1) -> (2/3, 1/6)
local PQ = map.matrix({{1, 0, 1}, {0, 1, 1}, {0, 0, 1}}, "row")
truthy(not PQ:is_affine(), "p, q make a projective map")
same(PQ(P(1, 3)), P(0.2, 0.6), "§1.7.6 A*"); same(PQ(P(4, 1)), P(2 / 3, 1 / 6), "§1.7.6 B*")
-- the overall scale s = 2 (§1.7.6): x* = x/s, an affine map
local S2 = map.matrix({{1, 0, 0}, {0, 1, 0}, {0, 0, 2}}, "row")
truthy(S2:is_affine(), "overall scale: affine"); same(S2(P(6, 4)), P(3, 2), "x* = x/s")
-- §1.7.7: the homogeneous [4 3 h] on y = 3x/4 runs off to the point at infinity [4 3 0]
for _, h in ipairs({1, 1 / 2, 1 / 10, 1 / 100, 1e-6}) do
  same(normalize(P(4, 3) * h + V(4, 3) * (1 - h)), P(4 / h, 3 / h), "§1.7.7 h = " .. h, 1e-6)
end

-- map.translate, map.scale ----------------------------------------------------------------------------
local tr = map.translate(V(1, 2))
same(tr(P(3, 4)), P(4, 6), "translate"); same(tr(V(3, 4)), V(3, 4), "a vector is not moved")
matrix_is(map.translate(V(1, 2, 3)), "row", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {1, 2, 3, 1}}, 0, "§2.5 translation: the last row")
-- §1.7.3, Fig 1.11: 2I: (3, 1), (3, 2), (1, 2) -> (6, 2), (6, 4), (2, 4)
local s2 = map.scale(2, 2)
same(s2(P(3, 1)), P(6, 2), "§1.7.3 scale"); same(s2(P(3, 2)), P(6, 4), "§1.7.3"); same(s2(P(1, 2)), P(2, 4), "§1.7.3")
same(map.scale({3, 0.5})(P(2, 4)), P(6, 2), "Fig 1.3: T = [[3, 0], [0, 1/2]]")
same(map.scale(2, P(1, 1))(P(1, 1)), P(1, 1), "the centre is fixed"); same(map.scale(2, P(1, 1))(P(2, 3)), P(3, 5), "about a centre")
same(map.scale({2, 3, 4}, P(1, 1, 1))(P(2, 1, 5)), P(3, 1, 17), "§2.1 local scaling about a centre")
matrix_is(map.scale({2, 3, 4}), "row", {{2, 0, 0, 0}, {0, 3, 0, 0}, {0, 0, 4, 0}, {0, 0, 0, 1}}, 0, "§2.1 diag(a, e, j, 1)")

-- map.rotate: in the plane ---------------------------------------------------------------------------
local r90 = map.rotate(pi / 2)
matrix_is(r90, "row", {{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}, 1e-15, "§1.7.1 R(90°)")
same(r90(P(3, -1)), P(1, 3), "Fig 1.9"); same(r90(P(4, 1)), P(-1, 4), "Fig 1.9"); same(r90(P(2, 1)), P(-1, 2), "Fig 1.9")
matrix_is(map.rotate(pi), "row", {{-1, 0, 0}, {0, -1, 0}, {0, 0, 1}}, 1e-15, "R(180°)")
-- §1.7.5: the unit square's C* = (cos - sin, cos + sin); 30° gives (0.366025, 1.366025)
same6(map.rotate(pi / 6)(P(1, 1)), P(0.366025, 1.366025), "§1.7.5 C* at 30°")
-- §1.7.8: rotation about (m, n) = (2, 3): the third row of T
for _, c in ipairs({{pi / 2, 5, 1}, {pi, 4, 6}, {3 * pi / 2, -1, 5}, {pi / 6, 1.767949, -0.598076}}) do
  local row3 = map.rotate(c[1], P(2, 3)):matrix("row")[3]
  near(row3[1], c[2], 5e-7, "§1.7.8 row 3 x"); near(row3[2], c[3], 5e-7, "§1.7.8 row 3 y"); eq(row3[3], 1, "§1.7.8 row 3 w")
end
-- = Tr(-m, -n) R Tr(m, n), composed left to right in the book: right to left here
local Rm = map.translate(V(2, 3)) * map.rotate(0.7) * map.translate(V(-2, -3))
same(Rm(P(5, -1)), map.rotate(0.7, P(2, 3))(P(5, -1)), "rotation about a point = Tr R Tr")
-- §1.7.3 with the erratum: T1 = R(90°), T2 = reflection in x = 0; (5, 7) through T1 then T2 gives
-- (7, 5), through T2 then T1 gives (-7, -5) (the book prints [-x -y])
local T1, T2 = map.rotate(pi / 2), map.reflect(P(0, 0), V(1, 0))
same((T2 * T1)(P(5, 7)), P(7, 5), "§1.7.3 T1 then T2")
same((T1 * T2)(P(5, 7)), P(-7, -5), "§1.7.3 T2 then T1 (corrected)")
matrix_is(T2 * T1, "row", {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}}, 1e-15, "T1 T2 = [[0, 1], [1, 0]]")
matrix_is(T1 * T2, "row", {{0, -1, 0}, {-1, 0, 0}, {0, 0, 1}}, 1e-15, "T2 T1 = [[0, -1], [-1, 0]]")

-- map.rotate: in space --------------------------------------------------------------------------------
local O = P(0, 0, 0)
matrix_is(map.rotate(O, V(1, 0, 0), pi / 2), "row", {{1, 0, 0, 0}, {0, 0, 1, 0}, {0, -1, 0, 0}, {0, 0, 0, 1}}, 1e-15, "§2.3 Rx(90°)")
matrix_is(map.rotate(O, V(0, 1, 0), pi / 2), "row", {{0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}}, 1e-15, "§2.3 Ry(90°)")
matrix_is(map.rotate(O, P(0, 0, 1), pi / 2), "row", {{0, 1, 0, 0}, {-1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}, 1e-15, "§2.3 Rz(90°), axis by two points")
-- §2.7: n = (1, 1, 1)/sqrt 3, 120° is the cyclic permutation x -> y -> z
matrix_is(map.rotate(O, V(1, 1, 1), 2 * pi / 3), "row", {{0, 1, 0, 0}, {0, 0, 1, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}}, 1e-15, "§2.7 cyclic")
-- the axis parallel to z through (1, 1, 0), 90°: (2, 1, 5) -> (1, 2, 5)
same(map.rotate(P(1, 1, 0), V(0, 0, 1), pi / 2)(P(2, 1, 5)), P(1, 2, 5), "§2.7 axis through a point")
same(map.rotate(P(1, 1, 0), P(1, 1, 7), pi / 2)(P(2, 1, 5)), P(1, 2, 5), "the axis through two points")
-- Rodrigues (§2.7) for a general axis: the axis is fixed, a point turns about it at its distance
local Rg = map.rotate(P(1, 2, 3), V(1, -2, 2), 0.9)
same(Rg(P(2, 0, 5)), P(2, 0, 5), "a point of the axis stays")
near(dist(Rg(P(4, 4, 4)), P(1, 2, 3)), dist(P(4, 4, 4), P(1, 2, 3)), 1e-12, "distances from the axis point kept")
near(dot(Rg(P(4, 4, 4)) - P(1, 2, 3), V(1, -2, 2)), dot(P(4, 4, 4) - P(1, 2, 3), V(1, -2, 2)), 1e-12, "the height along the axis kept")

-- map.reflect, map.shear -----------------------------------------------------------------------------
local yx = map.reflect(P(0, 0), V(1, -1))
same(yx(P(8, 1)), P(1, 8), "§1.7.2 about y = x"); same(yx(P(6, 2)), P(2, 6), "§1.7.2"); same(yx(P(7, 3)), P(3, 7), "§1.7.2")
same(map.reflect(P(0, 0), V(0, 1))(P(7, 3)), P(7, -3), "§1.7.2 about the x axis")
matrix_is(map.reflect(O, V(0, 0, 1)), "row", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -1, 0}, {0, 0, 0, 1}}, 0, "§2.4 xOy")
same(map.reflect(P(0, 0, 2), V(0, 0, 3))(P(1, 1, 5)), P(1, 1, -1), "a mirror off the origin")
-- §2.2: [x y z 1] T = [x + d y + h z, b x + y + i z, c x + f y + z, 1]
same(map.shear(3, "x", "y", 0.5)(P(2, 1, 5)), P(2.5, 1, 5), "§2.2 x += d y")
same(map.shear(3, 2, 3, -1)(P(2, 1, 5)), P(2, -4, 5), "§2.2 y += i z")
same(map.shear(2, 2, 1, 2)(P(1, 0)), P(1, 2), "Fig 1.5: [x, b x + y]")

-- projections (§2.8) -----------------------------------------------------------------------------------
local oz = map.orthographic()
same(oz(P(1, 2, 3)), P(1, 2), "Pz keeps (x, y)"); same(map.orthographic("y")(P(1, 2, 3)), P(1, 3), "\"y\" keeps (x, z)")
same(map.orthographic("x")(P(1, 2, 3)), P(2, 3), "\"x\" keeps (y, z)")
-- the embedding back: P E = id, P E P = P
local E = affine.frame(O, V(1, 0, 0), V(0, 1, 0))
matrix_is(oz * E, nil, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 0, "P E = id")
matrix_is(oz * E * oz, nil, oz:matrix(), 0, "P E P = P")
matrix_is(E * oz, "row", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 1}}, 0, "E P is the book's Pz = diag(1, 1, 0, 1)")
-- §2.8.2, the top view with the corrected signs: T = Rx(90°) Pz, [x y z 1] -> [x, -z]
local top = oz * map.rotate(O, V(1, 0, 0), pi / 2)
matrix_is(top, "row", {{1, 0, 0}, {0, 0, 0}, {0, -1, 0}, {0, 0, 1}}, 1e-15, "§2.8.2 T")
local cube = {A = P(0, 0, 0), E = P(0, 0, 1), B = P(0, 1, 0), F = P(0, 1, 1), D = P(1, 0, 0), H = P(1, 0, 1), C = P(1, 1, 0), G = P(1, 1, 1)}
local want = {A = P(0, 0), E = P(0, -1), B = P(0, 0), F = P(0, -1), D = P(1, 0), H = P(1, -1), C = P(1, 0), G = P(1, -1)}
for k, X in pairs(cube) do same(top(X), want[k], "§2.8.2 " .. k .. "* (corrected)") end
-- §2.8.3: dimetric with f_z = 1/2
local dm = map.dimetric(0.5)
matrix_is(dm, "row", {{0.925820, 0.133631, 0}, {0, 0.935414, 0}, {0.377964, -0.327327, 0}, {0, 0, 1}}, 5e-7, "§2.8.3 T")
near(dist(dm(V(1, 0, 0))), 0.935414, 5e-7, "f_x"); near(dist(dm(V(0, 1, 0))), 0.935414, 5e-7, "f_y"); near(dist(dm(V(0, 0, 1))), 0.5, 1e-15, "f_z")
matrix_is(map.axonometric(22.207654 * pi / 180, 20.704811 * pi / 180), nil, dm:matrix(), 1e-7, "the book's angles phi = 22.207654°, theta = 20.704811°")
-- §2.8.4: isometric
local iso = map.isometric()
matrix_is(iso, "row", {{0.707107, 0.408248, 0}, {0, 0.816497, 0}, {0.707107, -0.408248, 0}, {0, 0, 1}}, 5e-7, "§2.8.4 T")
for _, v in ipairs({V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)}) do near(dist(iso(v)), sqrt(2 / 3), 1e-15, "isometric foreshortening") end
near(math.atan(iso(V(1, 0, 0)).y, iso(V(1, 0, 0)).x), pi / 6, 1e-15, "the x axis at 30°")
near(math.atan(iso(V(0, 0, 1)).y, iso(V(0, 0, 1)).x), -pi / 6, 1e-15, "the z axis at -30°")
local ix, iy = iso:xy(1, 1, 1)
near(ix, sqrt(2), 1e-15, "iso:xy x"); near(iy, sqrt(2 / 3), 1e-15, "iso:xy y")
-- oblique (digest §10): the z unit goes to k (cos alpha, sin alpha)
same(map.oblique(0.5, pi / 6)(P(1, 2, 3)), P(1 + 1.5 * cos(pi / 6), 2 + 0.75), "oblique")
same(map.cavalier()(V(0, 0, 1)), V(sqrt(0.5), sqrt(0.5)), "cavalier: full length at 45°")
same(map.cabinet(pi / 6)(V(0, 0, 1)), V(0.5 * cos(pi / 6), 0.25), "cabinet: half length")
same(map.cavalier(pi / 2)(P(1, 2, 3)), P(1, 5), "cavalier at 90°")

-- perspective (§2.8.5, digest 9.2 items 17, 18) -----------------------------------------------------
-- the one-point transform r = 1/k, k = 2, keeping z; (1, 1, 1) -> (2/3, 2/3, 2/3)
local one = map.matrix({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0.5}, {0, 0, 0, 1}}, "row")
same(one(P(1, 1, 1)), P(2 / 3, 2 / 3, 2 / 3), "one-point (1, 1, 1)")
same(one(V(0, 0, 1)), P(0, 0, 2), "the z direction goes to its vanishing point [0 0 1/r 1] (corrected)")
local pq = map.matrix({{1, 0, 0, 0.5}, {0, 1, 0, 0.5}, {0, 0, 1, 0}, {0, 0, 0, 1}}, "row")
same(pq(P(1, 0, 1)), P(2 / 3, 0, 2 / 3), "two-point (1, 0, 1)")
same(map.matrix({{1, 0, 0, 0.5}, {0, 1, 0, 0.5}, {0, 0, 1, 0.5}, {0, 0, 0, 1}}, "row")(P(1, 1, 1)), P(0.4, 0.4, 0.4), "three-point (1, 1, 1)")
-- the two-point example of Fig 2.12: Ry(60°), then the one-point transform, k = 2
local two = one * map.rotate(O, V(0, 1, 0), pi / 3)
matrix_is(two, "row", {{0.5, 0, -0.866025, -0.433013}, {0, 1, 0, 0}, {0.866025, 0, 0.5, 0.25}, {0, 0, 0, 1}}, 5e-7, "§2.8.5 Ry(60°) P(r = 1/2)")
local vx, vy, vz = two:vanishing_points()
same6(vx, P(-1.154701, 0, 2), "the x direction's vanishing point"); same(vx, P(-2 / math.tan(pi / 3), 0, 2), "= (-k cot theta, 0, k)")
same6(vz, P(3.464102, 0, 2), "the z direction's vanishing point"); same(vz, P(2 * math.tan(pi / 3), 0, 2), "= (k tan theta, 0, k)")
eq(vy, nil, "y stays at infinity")
same(two(V(0, 1, 0)), V(0, 1, 0), "so its image is a direction")
-- onto the picture z = 0: drop z
local vx2, _, vz2 = (oz * two):vanishing_points()
same6(vx2, P(-1.154701, 0), "picture: x = -1.154701"); same6(vz2, P(3.464102, 0), "picture: x = 3.464102")
-- far points of a line run to its vanishing point
same((oz * two)(P(0.3, 0.2, 0.1) + V(1, 0, 0) * 1e9), vx2, "far along x", 1e-8)
-- map.perspective from the book's centre (0, 0, -2): x to the right as the eye sees it is the
-- book's x mirrored (convention 8), so the vanishing points change sign
local cam = map.perspective(P(0, 0, -2), O, V(0, 1, 0))
truthy(not cam:is_affine(), "a perspective is projective"); eq(cam.nin, 3, "from 3-D"); eq(cam.nout, 2, "to 2-D")
local cx, cy, cz = (cam * map.rotate(O, V(0, 1, 0), pi / 3)):vanishing_points()
same6(cx, P(1.154701, 0), "mirrored x vanishing point"); same6(cz, P(-3.464102, 0), "mirrored z vanishing point"); eq(cy, nil, "y at infinity")
same(cam(P(1, 2, 3)), P(-2 / 5, 4 / 5), "x* = -x k/(z + k), y* = y k/(z + k)")
same(cam(V(0, 0, 1)), P(0, 0), "the principal vanishing point is p0")
same(cam(P(1, 0, -2)), V(-1, 0), "a point of the eye's plane goes to infinity: a direction")
same(cam.C0, P(0, 0), "C0 = p0")
-- the picture plane is kept 1:1, the eye anywhere
local cam2 = map.perspective(P(5, -4, 3), P(1, 1, 1))
same(cam2(P(1, 1, 1)), P(0, 0), "p0 is the picture's origin")
local n = unit(P(1, 1, 1) - P(5, -4, 3))
local up = unit(V(0, 0, 1) - n * dot(V(0, 0, 1), n))
same(cam2(P(1, 1, 1) + up * 2), P(0, 2), "up in the picture plane is y, lengths kept")
same(cam2(P(1, 1, 1) + cross(n, up) * 3), P(3, 0), "right is x")

-- composition across kinds ------------------------------------------------------------------------------
-- an affine map of the screen, an oblique projection (Stepanov's), a rotation in space
local flip = affine({P(0, 0), P(1, 0), P(0, 1)}, {P(0, 480), P(1, 480), P(0, 479)})
local ob = oblique(P(320, 240), 150, .3, -pi / 3)
local turn = map.rotate(P(0, 0, 0), V(0, 0, 1), 0.4)
local chain = flip * ob * turn
truthy(chain:is_affine(), "affine all along"); eq(chain.nin, 3, "3-D in"); eq(chain.nout, 2, "2-D out")
for _, X in ipairs({P(1, 0, 1), P(-0.3, 0.7, 2), P(5, -4, 0)}) do
  same(chain(X), flip(ob(turn(X))), "flip * oblique * rotate = one after the other", 1e-9)
end
same(flip:compose(ob):compose(turn)(P(1, 2, 3)), chain(P(1, 2, 3)), "f:compose(g) = f * g", 1e-12)
-- with a perspective in the chain the result is projective
local pchain = flip * map.perspective(P(0, -10, 2), P(0, 0, 0)) * turn
truthy(not pchain:is_affine(), "projective when one map is")
same(pchain(P(1, 2, 3)), flip(map.perspective(P(0, -10, 2), P(0, 0, 0))(turn(P(1, 2, 3)))), "and still one after the other", 1e-12)
-- a 3-D map before a textbook matrix after
same((map.isometric() * map.scale(2, 3))(P(1, 1, 1)), map.isometric()(P(2, 2, 2)), "scale then project")

-- inverses ------------------------------------------------------------------------------------------------
for _, f in ipairs({map.rotate(0.3, P(1, 2)), map.rotate(P(1, 2, 3), V(1, 1, 0), 1.1), map.shear(3, 1, 3, 2),
                    map.scale({2, 3, 4}, P(1, 1, 1)), map.reflect(P(1, 1), V(1, 2)), PQ, one, two,
                    map.matrix({{2, 1, 0, 1}, {0, 1, 1, 0}, {1, 0, 3, 2}, {0.1, 0.2, 0, 1}})}) do
  local fi = f:inverse()
  local n = f.nin
  local id = (f * fi):matrix()
  for i = 1, n + 1 do for j = 1, n + 1 do near(id[i][j], i == j and 1 or 0, 1e-12, "f * f^-1 = id") end end
  id = (fi * f):matrix()
  for i = 1, n + 1 do for j = 1, n + 1 do near(id[i][j], i == j and 1 or 0, 1e-12, "f^-1 * f = id") end end
  eq(fi:is_affine(), f:is_affine(), "the inverse is of the same kind")
end
same(map.rotate(0.3):inverse()(P(1, 0)), map.rotate(-0.3)(P(1, 0)), "R(a)^-1 = R(-a)")
same(PQ:inverse()(P(0.2, 0.6)), P(1, 3), "the projective inverse maps back")

-- printing: tostring and f:show ---------------------------------------------------------------------------
eq(tostring(map.translate(V(1, 2))), "affine map 2-D -> 2-D [1 0 | 1; 0 1 | 2]", "tostring of an affine map")
eq(tostring(PQ), "projective map 2-D -> 2-D [1 0 | 0; 0 1 | 0; 1 1 | 1]", "tostring of a projective map: the weight row too")
local lines = {}
local real_print = print
print = function(s) lines[#lines + 1] = s end
two:show("row")
map.rotate(pi / 2):show()
print = real_print
eq(lines[1], "projective map 3-D -> 3-D, row vectors p' = p T:\n" ..
             "        0.5  0  -0.866025  | -0.433013\n" ..
             "          0  1          0  |         0\n" ..
             "   0.866025  0        0.5  |      0.25\n" ..
             "          0  0          0  |         1", "f:show(\"row\")")
eq(lines[2], "affine map 2-D -> 2-D, column vectors p' = M p:\n" ..
             "   0  -1  | 0\n" ..
             "   1   0  | 0\n" ..
             "   0   0  | 1", "f:show() in columns: rounding noise shows as 0")

-- f:xy and the fields --------------------------------------------------------------------------------------
local a, b, c = map.rotate(O, V(0, 0, 1), pi / 2):xy(1, 0, 5)
near(a, 0, 1e-15, "xy of a 3-D map: x"); near(b, 1, 1e-15, "y"); near(c, 5, 0, "z")
same(ob.C0, P(320, 240), "C0 of a projection"); same(ob.C3, P(320, 90), "C3")
same(T.C1, P(1, 2), "C1 of the book's T is its first row"); eq(T.C3, nil, "no C3 in 2-D")

-- errors --------------------------------------------------------------------------------------------------
err(function() return map.rotate() end, "map.rotate: argument #1 (angle) must be a finite number, got nil", "rotate nil")
err(function() return map.rotate(0 / 0) end, "map.rotate: argument #1 (angle) must be a finite number, got ", "rotate NaN")
err(function() return map.rotate(1, P(1, 2, 3)) end, "map.rotate: argument #2 (centre | B) must be 2-D, got 3-D (a rotation in space is map.rotate(A, B or direction, angle))", "rotate centre 3-D")
err(function() return map.rotate(P(0, 0), V(1, 0), 1) end, "map.rotate: argument #1 (angle | A) must be 3-D, got 2-D (a rotation in the plane is map.rotate(angle [, centre]))", "rotate axis 2-D")
err(function() return map.rotate(O, O, 1) end, "map.rotate: the axis points A and B coincide", "rotate A = B")
err(function() return map.rotate(O, V(0, 0, 0), 1) end, "map.rotate: argument #2 (direction) is the zero vector", "rotate zero direction")
err(function() return map.rotate(O, V(0, 0, 1)) end, "map.rotate: argument #3 (angle) must be a finite number, got nil", "rotate no angle")
err(function() return map.rotate(O, V(0, 1), 1) end, "map.rotate: argument #2 (direction) is 2-D, but argument #1 is 3-D (mixed dimensions)", "rotate mixed")
err(function() return map.translate(P(1, 2)) end, "map.translate: argument #1 (V) must be a vector, got P(1, 2); a vector has weight 0: a difference of points is a vector, e.g. B - A", "translate a point")
err(function() return map.scale(2) end, "map.scale: argument #2 (centre) must be a point or a dimension", "scale without dimension")
err(function() return map.scale({2, "x"}) end, "map.scale: argument #1 (k) [2] must be a finite number, got \"x\"", "scale list")
err(function() return map.scale({2, 3}, P(1, 1, 1)) end, "map.scale: argument #2 (centre) is 3-D, but argument #1 is 2-D (mixed dimensions)", "scale centre dims")
err(function() return map.reflect(P(0, 0), V(0, 0)) end, "map.reflect: argument #2 (normal) is the zero vector", "reflect zero normal")
err(function() return map.reflect(P(0, 0), P(1, 1)) end, "map.reflect: argument #2 (normal) must be a vector, got P(1, 1); a vector has weight 0: a difference of points is a vector, e.g. B - A", "reflect point normal")
err(function() return map.shear(3, 1, 1, 2) end, "map.shear: arguments #2 and #3 (i, j) name the same axis", "shear same axis")
err(function() return map.shear(2, "z", 1, 2) end, "map.shear: argument #2 (i) must be an axis 1..2", "shear axis")
err(function() return map.shear(2, 1, 2) end, "map.shear: argument #4 (k) must be a finite number, got nil", "shear k")
err(function() return map.orthographic("w") end, "map.orthographic: argument #1 (axis) must be \"x\", \"y\" or \"z\", got \"w\"", "orthographic axis")
err(function() return map.dimetric(1.5) end, "map.dimetric: argument #1 (fz) must be a number between 0 and 1", "dimetric domain")
err(function() return map.axonometric(1) end, "map.axonometric: argument #2 (theta) must be a finite number, got nil", "axonometric")
err(function() return map.oblique(1, math.huge) end, "map.oblique: argument #2 (alpha) must be a finite number, got inf", "oblique inf")
err(function() return map.perspective(P(1, 1, 1), P(1, 1, 1)) end, "map.perspective: the eye and p0 coincide", "perspective eye = p0")
err(function() return map.perspective(P(0, 0, 5), O) end, "map.perspective: the default up, the z axis, is along the line of sight", "perspective default up")
err(function() return map.perspective(P(0, 5, 0), O, V(0, 2, 0)) end, "map.perspective: argument #3 (up) is along the line of sight", "perspective up")
err(function() return map.perspective(P(0, 5), O) end, "map.perspective: argument #1 (eye) must be a 3-D point, got P(0, 5)", "perspective 2-D eye")
err(function() return map.matrix({{1, 0}, {0, 0 / 0}}) end, "map.matrix: argument #1 (rows) entry [2][2] must be a finite number", "matrix NaN")
err(function() return map.matrix({{1, 0, 0}, {0, 1}}) end, "map.matrix: argument #1 (rows) row [2] holds 2 numbers, row [1] 3", "matrix ragged")
err(function() return map.matrix({{0, 0}, {0, 0}}) end, "map.matrix: the zero matrix is no map", "matrix zero")
err(function() return map.matrix({{1, 0}, 5}) end, "map.matrix: argument #1 (rows) row [2] must be a table of numbers, got 5", "matrix row not a table")
err(function() return map.matrix({{1}, {0}}) end, "map.matrix: argument #1 (rows) row [1] holds 1 numbers; a matrix here has 2..17 columns", "matrix one column")
err(function() return map.matrix({{1, 0}}) end, "map.matrix: argument #1 (rows) holds 1 rows", "matrix one row")
err(function() return map.matrix({{1, 0}, {0, 1}}, "rows") end, "map.matrix: argument #2 (convention) must be \"row\" or \"column\", got \"rows\"", "matrix convention")
err(function() return map.matrix(5) end, "map.matrix: argument #1 (rows) must be a table of rows (tables of numbers), got 5", "matrix not a table")
err(function() return map.scale({1, 0}):inverse() end, "inverse: the map is singular (it flattens space), so it has no inverse", "singular inverse")
err(function() return map.matrix({{1, 0, 0}, {0, 1, 0}, {1, 1, 0}}):inverse() end, "inverse: the map is singular", "singular projective inverse")
err(function() return map.isometric():inverse() end, "inverse: a map from 3-D to 2-D (a projection or an embedding) has no inverse", "non-square inverse")
err(function() return iso(P(1, 2)) end, "iso: argument #1 is 2-D, but the map takes 3-D: dimensions cannot be mixed", "wrong dimension")
err(function() return iso(1, 0 / 0, 2) end, "iso: argument #2 must be a finite number, got ", "apply NaN")
err(function() return iso:xy(P(1, 2, 3) * 2) end, "xy: argument #1 (X) must be a point (weight 1), got weight 2", "xy weighted")
err(function() return cam:xy(P(1, 0, -2)) end, "xy: the image of argument #1 is at infinity (a direction); f(X) gives it as a vector", "xy at infinity")
err(function() return cam(P(0, 0, -2)) end, "cam: argument #1 is the centre of the projection, which has no image", "the eye")
local huge = map.scale(1e308, 2)
err(function() return huge(P(10, 10)) end, "huge: the image of argument #1 is out of range (not finite: a coordinate overflowed)", "an image that overflows")
err(function() return huge:xy(10, 10) end, "xy: the image of argument #1 is out of range", "xy of an image that overflows")
err(function() return map.rotate(1):vanishing_points() end, "vanishing_points: the map goes from 2-D to 2-D", "vanishing points of a 2-D map")
err(function() return T:matrix("rows") end, "f:matrix: argument #1 (convention) must be \"row\" or \"column\", got \"rows\"", "f:matrix convention")
err(function() return iso * map.rotate(1) end, "cannot compose: the first map applied gives 2-D, the second takes 3-D", "compose dims")
err(function() return PQ * 2 end, "cannot multiply a projective map by a number", "projective * number")

check.done()
