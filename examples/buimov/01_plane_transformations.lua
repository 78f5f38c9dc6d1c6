-- The textbook's plane transformations: shear, intersecting lines, rotation, reflection, area, projective terms
-- Buimov ch. 1 (row vectors, p* = p T): Fig 1.7 a segment under T = [[1, 2], [3, 1]] (its
-- midpoint stays the midpoint), Fig 1.8 two lines and their meet under [[1, 2], [1, -2]],
-- Fig 1.9 a triangle turned by 90°, Fig 1.10 a triangle reflected about y = x and y = 0,
-- Fig 1.12 the unit square onto a parallelogram of area |det T| = 5, Fig 1.16 the projective
-- terms p = q = 1: x* = x/(x + y + 1). Grey: the figure; yellow: its image.
local function T2(a, b, c, d) return map.matrix({{a, b, 0}, {c, d, 0}, {0, 0, 1}}, "row") end

-- a panel: its origin on the screen and its scale (pixels per unit), axes and a caption
local function panel(ox, oy, s, x0, x1, y0, y1, caption)
  local F = affine.frame(P(ox, oy), V(s, 0), V(0, -s))
  line(F(P(x0, 0)), F(P(x1, 0)), 8); line(F(P(0, y0)), F(P(0, y1)), 8)
  label(caption, P(ox + s * (x0 + x1) / 2, oy - s * y1 - 14), "c", 7)
  return F
end
local function poly(F, pts, colour, closed)
  for i = 1, #pts - (closed and 0 or 1) do line(F(pts[i]), F(pts[i % #pts + 1]), colour) end
end

-- Fig 1.7: the segment AB and its image; the midpoint M goes to the midpoint of A*B*
local F = panel(25, 200, 15, -1, 12, -1, 8, "Fig 1.7: [[1, 2], [3, 1]]")
local T = T2(1, 2, 3, 1)
local A, B = P(0, 1), P(2, 3)
poly(F, {A, B}, 7); poly(F, {T(A), T(B)}, 14)
for _, p in ipairs{{A, "A", "w"}, {B, "B", "n"}, {T(A), "A*", "s"}, {T(B), "B*", "e"}, {T(mid(A, B)), "M*", "se"}} do
  circle(F(p[1]), 2, 15); label(p[2], F(p[1]), p[3], 15)
end

-- Fig 1.8: AB (x + y = 4) and CD (y = x) meet at (2, 2); the images meet at its image (4, 0)
F = panel(290, 140, 8.5, -3, 7, -9, 9, "Fig 1.8: [[1, 2], [1, -2]]")
local T8 = T2(1, 2, 1, -2)
local A8, B8, C8, D8 = P(0, 4), P(4, 0), P(-1, -1), P(3, 3)
poly(F, {A8, B8}, 7); poly(F, {C8, D8}, 7); poly(F, {T8(A8), T8(B8)}, 14); poly(F, {T8(C8), T8(D8)}, 14)
local X = meet(A8, B8, C8, D8)
circle(F(X), 2, 15); label("(2, 2)", F(X), "ne", 7)
circle(F(T8(X)), 2, 15); label("(4, 0)", F(T8(X)), "se", 14)

-- Fig 1.9: rotation by 90° about the origin
F = panel(480, 170, 22, -2, 5, -2, 5, "Fig 1.9: R(90°)")
local tri = {P(3, -1), P(4, 1), P(2, 1)}
poly(F, tri, 7, true)
local rot = {}
for i, p in ipairs(tri) do rot[i] = map.rotate(math.pi / 2)(p) end
poly(F, rot, 14, true)
label("A", F(tri[1]), nil, 7); label("A*", F(rot[1]), nil, 14)

-- Fig 1.10: reflection about y = x (yellow) and about the x axis (cyan)
F = panel(45, 400, 13, -1, 9, -4, 9, "Fig 1.10: reflections")
local tr = {P(8, 1), P(6, 2), P(7, 3)}
local yx, y0 = {}, {}
for i, p in ipairs(tr) do yx[i] = T2(0, 1, 1, 0)(p); y0[i] = T2(1, 0, 0, -1)(p) end
poly(F, tr, 7, true); poly(F, yx, 14, true); poly(F, y0, 11, true)
pen{dash = {3, 3}}; line(F(P(0, 0)), F(P(8.5, 8.5)), 8); pen()

-- Fig 1.12: the unit square onto the parallelogram of rows (1, 2) and (3, 1): area |det| = 5
F = panel(250, 410, 30, -0.5, 4.5, -0.5, 3.5, "Fig 1.12: area x |det T|")
local sq = {P(0, 0), P(1, 0), P(1, 1), P(0, 1)}
local pg = {}
for i, p in ipairs(sq) do pg[i] = T(p) end
poly(F, sq, 7, true); poly(F, pg, 14, true)
label("B* = (a, b)", F(pg[2]), "w", 14); label("D* = (c, d)", F(pg[4]), "e", 14)
label(string.format("det T = %g", buimov.det({{1, 2}, {3, 1}})), F(P(2.5, -0.4)), "c", 15)

-- Fig 1.16: the projective terms p = q = 1 (the homogeneous [x y 1] T = [x, y, x + y + 1])
F = panel(460, 420, 34, -0.3, 4.3, -0.3, 3.4, "Fig 1.16: p = q = 1")
local PQ = map.matrix({{1, 0, 1}, {0, 1, 1}, {0, 0, 1}}, "row")
local A16, B16 = P(1, 3), P(4, 1)
poly(F, {A16, B16}, 7); poly(F, {PQ(A16), PQ(B16)}, 14)
label("A(1, 3)", F(A16), "e", 7); label("B(4, 1)", F(B16), "s", 7)
label("A*(1/5, 3/5)", F(PQ(A16)), "e", 14); label("B*(2/3, 1/6)", F(PQ(B16)), "e", 14)
