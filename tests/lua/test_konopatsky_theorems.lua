-- Konopatsky's chapter 1 as functions (issue 23): konopatsky.area_k, area_theorem (1.2) and its
-- corollaries, o_theorem (1.4), simplex_ratio (S- and V-theorems), meet_line_plane (§1.3.5 by
-- the V-theorem, 3-D and n-D), polar (2.118), rotate (2.138) and moving_simplex (Fig. 1.2),
-- digest konopatsky_ch1_2.md §4 and §5.0.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, truthy, err = check.eq, check.near, check.truthy, check.err
local same = check.same_within(1e-12)

-- (1.2) against measured signed areas, and the proof's a, b, c
local A1, A2, A3 = P(0.5, -1), P(4, 1.5), P(-1, 3)
local B1, B2, B3 = lerp(A1, A2, 0.25), lerp(A2, A3, 1.5), lerp(A3, A1, -0.5)
local r = konopatsky.area_theorem(A1, A2, A3, B1, B2, B3)
near(r.k, area(B1, B2, B3) / area(A1, A2, A3), 1e-12, "(1.2) k = S_B/S_A")
near(r.lambda[1], sr(A1, A2, B1), 1e-12, "lambda1 = (A1A2B1)")
near(r.a, sr(B1, A1, A2), 1e-12, "a = (B1A1A2)")
near(konopatsky.area_k(r.lambda[1], r.lambda[2], r.lambda[3]), r.k, 1e-12, "area_k")
eq(r.collinear, false, "not collinear")
-- corollary 1 (Menelaus), 2 (B3 = A3: ab), 3 (B1 = A1, B3 = A3: -b)
local L1, L2 = P(-3, 0.2), P(5, 2.6)
local m = konopatsky.area_theorem(A1, A2, A3, meet(A1, A2, L1, L2), meet(A2, A3, L1, L2), meet(A3, A1, L1, L2))
eq(m.collinear, true, "corollary 1: a transversal")
near(m.lambda[1] * m.lambda[2] * m.lambda[3], -1, 1e-12, "lambda1 lambda2 lambda3 = -1")
local c2 = konopatsky.area_theorem(A1, A2, A3, lerp(A1, A2, 0.3), lerp(A2, A3, 0.8), A3)
near(c2.k, c2.a * c2.b, 1e-12, "corollary 2: k = ab")
local c3 = konopatsky.area_theorem(A1, A2, A3, A1, lerp(A2, A3, 0.8), A3)
near(c3.k, -c3.b, 1e-12, "corollary 3: k = -b")
-- (1.4) with the closing factor
for mm = 3, 7 do
  local poly = {}
  for i = 1, mm do
    local ang = 2 * math.pi * (i - 1) / mm
    poly[i] = P(3 * math.cos(ang) + 0.4 * math.sin(3 * i), 2 * math.sin(ang) + 0.3 * math.cos(i))
  end
  local prod, ratios, B = konopatsky.o_theorem(poly, P(-6, -1.3), P(6, 0.9))
  near(prod, (-1) ^ mm, 1e-10, "(1.4) the product is (-1)^m, m = " .. mm)
  eq(#ratios, mm, "one ratio per side")
  same(B[1], meet(poly[1], poly[2], P(-6, -1.3), P(6, 0.9)), "B1 = A1A2 x d", 1e-12)
end
local prod, ratios, B = konopatsky.o_theorem({P(0, 0), P(2, 0), P(2, 2), P(0, 2)}, P(-1, 1), P(3, 1))
eq(ratios[1], -1, "a side parallel to d: ratio -1")
eq(B[1].w, 0, "its B at infinity")
near(prod, 1, 1e-12, "still (-1)^4")
-- S- and V-theorems
local SA, SB, SC = P(0, 0), P(4, 0), P(0, 3)
local srows = {{0.2, 0.3, 0.5}, {0.6, 0.1, 0.3}, {0.1, 0.7, 0.2}}
local SP = {}
for i = 1, 3 do SP[i] = SA * srows[i][1] + SB * srows[i][2] + SC * srows[i][3] end
near(konopatsky.simplex_ratio(srows), 0.14, 1e-12, "S-theorem: the determinant 0.14")
near(konopatsky.simplex_ratio(srows), area(SP[1], SP[2], SP[3]) / area(SA, SB, SC), 1e-12, "S-theorem: the area ratio")
local T = {P(0, 0, 0), P(2, 0, 0), P(0, 3, 0), P(0, 0, 1)}
local rows = {{0.1, 0.2, 0.3, 0.4}, {0.5, 0.1, 0.2, 0.2}, {0.25, 0.25, 0.25, 0.25}, {0, 0.1, 0.1, 0.8}}
local Q = {}
for i = 1, 4 do Q[i] = T[1] * rows[i][1] + T[2] * rows[i][2] + T[3] * rows[i][3] + T[4] * rows[i][4] end
near(konopatsky.simplex_ratio(rows), volume(Q[1], Q[2], Q[3], Q[4]) / volume(T[1], T[2], T[3], T[4]), 1e-12,
     "V-theorem: the determinant (not det/det = 1)")
-- the line-plane meet by the V-theorem
local K, lam, p, q = konopatsky.meet_line_plane(P(0, 0, -1), P(1, 1, 1), P(1, 0, 0), P(0, 1, 0), P(0, 0, 0))
same(K, P(0.5, 0.5, 0), "K on z = 0")
near(lam, 0.5, 1e-15, "lambda")
near(p, 0.5, 1e-15, "p")
near(q, 0.5, 1e-15, "q")
local b1, b2 = P(0.3, -1.2, 2.5), P(1.7, 2.2, -0.4)
local q1, q2, q3 = P(2, 0.5, 0.3), P(-0.5, 1.5, 1.1), P(0.2, -0.8, -0.6)
K, lam = konopatsky.meet_line_plane(b1, b2, q1, q2, q3)
local V1, V2 = volume(b1, q1, q2, q3), volume(b2, q1, q2, q3)
near(lam, V1 / (V1 - V2), 1e-12, "lambda = V1/(V1 - V2)")
near(volume(K, q1, q2, q3), 0, 1e-12, "K in the plane")
local K4 = konopatsky.meet_line_plane(P(0, 0, -1, 3), P(1, 1, 1, 3), P(1, 0, 0, 3), P(0, 1, 0, 3), P(0, 0, 0, 3))
same(K4, P(0.5, 0.5, 0, 3), "4-D: in the hyperplane w = 3")
local D = konopatsky.meet_line_plane(P(0, 0, 1), P(1, 2, 1), P(1, 0, 0), P(0, 1, 0), P(0, 0, 0))
eq(D.w, 0, "parallel: a point at infinity")
-- (2.138) and (2.118)
local C0, A0, B0 = P(0, 0), P(4, 0), P(1, 3)
same(konopatsky.rotate(C0, A0, B0, math.pi / 6), P(2 * math.sqrt(3), 2), "(2.138) phi = pi/6")
same(konopatsky.rotate(C0, A0, B0, math.pi / 2), P(0, 4), "(2.138) phi = pi/2")
same(konopatsky.rotate(C0, A0, B0, math.pi), P(-4, 0), "(2.138) phi = pi")
same(konopatsky.polar(P(1, 0), P(0, 0), P(0.5, 1), 0.5, 1.1071487177940904), P(0.776393, 0.447214), "(2.118) phi = gamma", 1e-6)
same(konopatsky.polar(P(1, 0), P(0, 0), P(0.5, 1), 0.5, math.pi), P(1.5, 0), "(2.118) phi = pi")
-- Fig. 1.2: the moving simplex on three straight guides, a conic of ch. 2 as the generator
local NA = bezier{P(0, 0, 0), P(0, 0, 2)}
local NB = bezier{P(3, 0, 0), P(3, 0, 3)}
local NC = bezier{P(0, 3, 0), P(0.5, 3, 2.5)}
local gen = conic.ed(P(1, 0), P(0, 1), P(0, 0), 0.7)     -- (p, q) from (1, 0) to (0, 1)
local s = konopatsky.moving_simplex(NA, NB, NC, gen)
same(s(0.5, 0), NA(0.5), "M(u, 0) on guide NA")
same(s(0.5, 1), NB(0.5), "M(u, 1) on guide NB")
local g = gen(0.3)
same(s(0.25, 0.3), (NA(0.25) - NC(0.25)) * g.x + (NB(0.25) - NC(0.25)) * g.y + NC(0.25), "M = (NA - NC)p + (NB - NC)q + NC")
-- errors
err(function() konopatsky.area_theorem(A1, A2, A3, B1 + V(0, 0.1), B2, B3) end,
    "konopatsky.area_theorem: each Bi must lie on its side line", "B1 off")
err(function() konopatsky.area_theorem(P(0, 0), P(1, 1), P(2, 2), B1, B2, B3) end, "the triangle A1A2A3 is flat", "flat")
err(function() konopatsky.area_k(-1, 1, 1) end, "konopatsky.area_k: a lambda is -1", "pole")
err(function() konopatsky.o_theorem({P(0, 0), P(2, 0), P(2, 2), P(0, 2)}, P(0, 0), P(3, 1)) end,
    "konopatsky.o_theorem: the line D1D2 passes through a vertex", "vertex")
err(function() konopatsky.o_theorem({P(0, 0), P(2, 0)}, P(0, 0), P(3, 1)) end,
    "konopatsky.o_theorem: argument #1 (polygon) must hold 3 to 64 points, got 2", "two points")
err(function() konopatsky.simplex_ratio{{0.2, 0.3, 0.4}, {0.6, 0.1, 0.3}, {0.1, 0.7, 0.2}} end,
    "must sum to 1", "membership")
err(function() konopatsky.meet_line_plane(P(0, 0), P(1, 1), P(1, 0), P(0, 1), P(0, 0)) end,
    "konopatsky.meet_line_plane: a line and a plane meet in 3-D or more", "2-D")
err(function() konopatsky.meet_line_plane(P(0, 0, 0), P(1, 2, 0), P(1, 0, 0), P(0, 1, 0), P(0, 0, 0)) end,
    "lies in the plane", "in the plane")
err(function() konopatsky.meet_line_plane(P(0.2, 0.2, -1, 1), P(0.2, 0.2, 1, 1), P(1, 0, 0, 0), P(0, 1, 0, 0), P(0, 0, 0, 0)) end,
    "do not meet", "skew in 4-D")
err(function() konopatsky.meet_line_plane(P(0, 0, 0), P(1, 2, 0), P(1, 0, 0), P(0, 1), P(0, 0, 0)) end,
    "konopatsky.meet_line_plane: argument #4 (P2) is 2-D, but argument #1 (A1) is 3-D", "mixed")
err(function() konopatsky.rotate(P(0, 0), P(1, 0), P(2, 0), 1) end, "C, A, B are collinear", "flat CAB")
err(function() konopatsky.moving_simplex(NA, NB, NC, NA) end, "the generator gen must be 2-D", "3-D generator")
err(function() konopatsky.moving_simplex(NA, NB, NC:sub(0, 0.5), gen) end, "the guides must run over one domain", "domains")
err(function() konopatsky.moving_simplex(NA, NB, P(0, 0, 0), gen) end,
    "konopatsky.moving_simplex: argument #3 (NC) must be a curve, got P(0, 0, 0)", "point guide")
check.done()
