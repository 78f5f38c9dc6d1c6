-- The projective terms p = q = 1: a segment of the plane h = x + y + 1 projected onto h = 1
-- Buimov §1.7.6, Fig. 1.16: [x y 1] [[1, 0, p], [0, 1, q], [0, 0, 1]] = [x, y, px + qy + 1]; with p
-- = q = 1, A(1, 3) and B(4, 1) become the homogeneous [1 3 5] and [4 1 6] (barred), points of the
-- plane h = x + y + 1 (grey); the rays from the origin meet the plane h = 1 (blue) in A* = (1/5,
-- 3/5) and B* = (2/3, 1/6). Seen in the space (x, y, h), h up; what the planes hide is dashed.
local PQ = map.matrix({{1, 0, 1}, {0, 1, 1}, {0, 0, 1}}, "row")
local A, B = P(1, 3), P(4, 1)
local At, Bt = P(1, 3, 5), P(4, 1, 6)                 -- [x y 1] T, the homogeneous images
local As, Bs = PQ(A), PQ(B)                           -- divided by h: (1/5, 3/5), (2/3, 1/6)
local view = map.view{azimuth = -62, elevation = 22}
camera(map.translate(V(330, 262)) * map.scale({40, -40}) * view
    * map.translate(V(-2, -2, -3)), {hidden = "dashed"})
local slope = surface(function(u, v) return P(u, v, u + v + 1) end, 0, 4.5, 0, 3.5)
local unit = surface(function(u, v) return P(u, v, 1) end, 0, 4.5, 0, 3.5)
slope:wireframe{nu = 5, nv = 4, boundary = true, color = 8}
unit:wireframe{nu = 0, nv = 0, boundary = true, color = 9}
for _, ax in ipairs{{V(5, 0, 0), "$x$"}, {V(0, 4, 0), "$y$"}, {V(0, 0, 7), "$h$"}} do
  line(P(0, 0, 0), P(0, 0, 0) + ax[1], 7); label(ax[2], P(0, 0, 0) + ax[1], nil, 7)
end
line(P(0, 0, 0), At, 12); line(P(0, 0, 0), Bt, 12)           -- the projectors through the origin
line(At, Bt, 15); line(P(As.x, As.y, 1), P(Bs.x, Bs.y, 1), 14)
line(P(A.x, A.y, 0), P(B.x, B.y, 0), 7)                      -- the segment AB itself, in h = 0
for _, m in ipairs{{At, "$\\bar A$", 15}, {Bt, "$\\bar B$", 15}, {P(As.x, As.y, 1), "$A^*$", 14},
                   {P(Bs.x, Bs.y, 1), "$B^*$", 14}, {P(A.x, A.y, 0), "$A$", 7}, {P(B.x, B.y, 0),
                     "$B$", 7},
                   {P(0, 0, 0), "$O$", 7}} do
  mark(m[1], "dot", 4, m[3]); label(m[2], m[1], nil, m[3])
end
label("$h = x + y + 1$", P(4.5, 3.5, 9), nil, 8); label("$h = 1$", P(4.5, 0, 1), nil, 9)
camera(nil)
caption("p = q = 1:  [1 3 5] -> A* = (1/5, 3/5),  [4 1 6] -> B* = (2/3, 1/6)", "bottom", 7)
