-- Konopatsky, chapter 1 (digest konopatsky_ch1_2.md §4, the "== Chapter 1" checks of
-- konopatsky_ch1_2_verify.py): the simple ratio and its permutations, the theorem on triangle
-- areas (1.2) and its corollaries, the O-theorem (1.4) with its closing factor (the print omits
-- it), the S- and V-theorems as determinants of parameters (the printed V-theorem is det/det of
-- one matrix), the meet (1.5) in natural parameters, the metric operator and its properties,
-- and the polar and rotation formulas (2.117), (2.138) of §5.0 — through the existing API:
-- sr, divide, meet, area, volume, simplex, Sigma.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, truthy = check.eq, check.near, check.truthy
local same = check.same_within(1e-6)

-- 3x3 and 4x4 determinants of rows
local function det3(m)
  return m[1][1] * (m[2][2] * m[3][3] - m[2][3] * m[3][2]) - m[1][2] * (m[2][1] * m[3][3] - m[2][3] * m[3][1])
       + m[1][3] * (m[2][1] * m[3][2] - m[2][2] * m[3][1])
end
local function det4(m)
  local s = 0
  for j = 1, 4 do
    local minor = {}
    for i = 2, 4 do
      local r = {}
      for c = 1, 4 do if c ~= j then r[#r + 1] = m[i][c] end end
      minor[#minor + 1] = r
    end
    s = s + (-1) ^ (j + 1) * m[1][j] * det3(minor)
  end
  return s
end

-- §2.3 of the digest: the simple ratio (XYZ) = (X - Z)/(Z - Y) and its permutations --------------
local X, Y = P(1, 2), P(7, 5)
local Z = divide(X, Y, 0.6)                          -- Z = (X + 0.6 Y)/1.6
near(sr(X, Y, Z), 0.6, 1e-14, "(XYZ) = lambda")
local l = sr(X, Y, Z)
near(sr(Y, X, Z), 1 / l, 1e-14, "(YXZ) = 1/lambda")
near(sr(X, Z, Y), -(1 + l), 1e-14, "(XZY) = -(1 + lambda)")
near(sr(Z, X, Y), -1 / (1 + l), 1e-14, "(ZXY) = -1/(1 + lambda)")
near(sr(Y, Z, X), -(1 + l) / l, 1e-14, "(YZX) = -(1 + lambda)/lambda")
near(sr(Z, Y, X), -l / (1 + l), 1e-14, "(ZYX) = -lambda/(1 + lambda)")
near(sr(X, Y, Z) * sr(Y, X, Z), 1, 1e-14, "(XYZ)(YXZ) = 1 (the proof of the O-theorem)")
same(divide(X, Y, 1), mid(X, Y), "lambda = 1: the midpoint")
eq(divide(X, Y, -1).w, 0, "lambda = -1: the point at infinity of XY")
near(sr(X, Y, lerp(X, Y, 0.3)), 0.3 / 0.7, 1e-14, "AP/AC = t gives (ACP) = t/t'")

-- (1.2) the theorem on triangle areas, signed, and the proof's a, b, c --------------------------
local A1, A2, A3 = P(0.5, -1), P(4, 1.5), P(-1, 3)
for _, case in ipairs{{0.25, 1.5, -0.5}, {2, -0.7, 0.4}, {-1.5, 3, 1.2}} do
  local B1, B2, B3 = lerp(A1, A2, case[1]), lerp(A2, A3, case[2]), lerp(A3, A1, case[3])
  local l1, l2, l3 = sr(A1, A2, B1), sr(A2, A3, B2), sr(A3, A1, B3)
  local k = (1 + l1 * l2 * l3) / ((1 + l1) * (1 + l2) * (1 + l3))
  near(area(B1, B2, B3) / area(A1, A2, A3), k, 1e-12, "(1.2) S_B1B2B3/S_A1A2A3 = k")
  local a, b, c = sr(B1, A1, A2), sr(B2, A2, A3), sr(B3, A3, A1)
  near(a, -1 / (1 + l1), 1e-12, "a = -1/(1 + lambda1)")
  same(B1, (A2 - A1) * a + A2, "B1 = (A2 - A1)a + A2", 1e-12)
  near(k, 1 + a + b + c + a * b + a * c + b * c, 1e-12, "k = 1 + a + b + c + ab + ac + bc")
end
-- corollary 1 (1.3), Menelaus: a transversal gives lambda1 lambda2 lambda3 = -1
local L1, L2 = P(-3, 0.2), P(5, 2.6)
local B1, B2, B3 = meet(A1, A2, L1, L2), meet(A2, A3, L1, L2), meet(A3, A1, L1, L2)
near(sr(A1, A2, B1) * sr(A2, A3, B2) * sr(A3, A1, B3), -1, 1e-12, "(1.3) Menelaus")
near(area(B1, B2, B3), 0, 1e-12, "collinear: k = 0")
-- corollary 2: B3 = A3 gives S_B1B2A3/S = ab; corollary 3: B1 = A1, B3 = A3 gives -b
B1, B2 = lerp(A1, A2, 0.3), lerp(A2, A3, 0.8)
near(area(B1, B2, A3) / area(A1, A2, A3), sr(B1, A1, A2) * sr(B2, A2, A3), 1e-12, "corollary 2")
near(area(A1, B2, A3) / area(A1, A2, A3), -sr(B2, A2, A3), 1e-12, "corollary 3")

-- (1.4) the O-theorem with the closing factor (A_m A_1 B_m); the print stops one factor short --
for m = 3, 7 do
  local poly = {}
  for i = 1, m do
    local ang = 2 * math.pi * (i - 1) / m
    poly[i] = P(3 * math.cos(ang) + 0.4 * math.sin(3 * i), 2 * math.sin(ang) + 0.3 * math.cos(i))
  end
  local d1, d2 = P(-6, -1.3), P(6, 0.9)
  local prod, printed = 1, 1
  for i = 1, m do
    local a, b = poly[i], poly[i % m + 1]
    local r = sr(a, b, (meet(a, b, d1, d2)))
    prod = prod * r
    if i < m then printed = printed * r end
  end
  near(prod, (-1) ^ m, 1e-9, "(1.4) O-theorem, m = " .. m)
  truthy(math.abs(printed - (-1) ^ m) > 1e-3, "the printed (1.4) without the closing factor fails, m = " .. m)
end

-- S-theorem (§1.3.3): the signed area ratio is the determinant of the parameters ----------------
local A, B, C = P(0, 0), P(4, 1), P(1, 3)
local S = simplex(C, A, B)                         -- the book's CAB, C the initial point
local Q1, Q2, Q3 = P(1.2, 0.4), P(3.1, 2.2), P(-0.5, 1.9)
local rows_nat, rows_bary = {}, {}
for i, q in ipairs{Q1, Q2, Q3} do
  local p, qq = S:params(q)
  rows_nat[i] = {p, qq, 1}                         -- natural parameters (p, q, 1) in CAB
  rows_bary[i] = {p, qq, 1 - p - qq}               -- barycentric (p, q, r) on A, B, C
end
local ratio = area(Q1, Q2, Q3) / area(C, A, B)
near(det3(rows_nat), ratio, 1e-12, "S-theorem, rows (p, q, 1)")
near(det3(rows_bary), ratio, 1e-12, "S-theorem, barycentric rows")
near((S:ratio(Q1, Q2, Q3)), ratio, 1e-12, "S:ratio")
-- in 3-D (coplanar triangles of a plane simplex): the ratio is affine-invariant
local f = affine({P(0, 0), P(1, 0), P(0, 1)}, {P(1, 2, 3), P(2, 0, 4), P(0, 1, 6)})
local S3 = simplex(f(C), f(A), f(B))
near((S3:ratio(f(Q1), f(Q2), f(Q3))), ratio, 1e-12, "S-theorem in 3-D")

-- V-theorem (§1.3.4): the volume ratio = det of the four points' parameters (the print's
-- V/V = det/det has the same matrix above and below: 1) ------------------------------------------
local D, Av, Bv, Cv = P(0, 0, 0), P(3, 0, 0), P(0.5, 2, 0), P(1, 1, 4)
local T = simplex(D, Av, Bv, Cv)
local Ps = {P(0.5, 0.3, 0.2), P(2, 1, 1), P(1, 2, 2.5), P(0.2, 0.9, 0.4)}
local rows = {}
for i, q in ipairs(Ps) do
  local p, qq, r = T:params(q)
  rows[i] = {p, qq, r, 1 - p - qq - r}
end
local vr = volume(Ps[1], Ps[2], Ps[3], Ps[4]) / volume(Av, Bv, Cv, D)
near(det4(rows), vr, 1e-12, "V-theorem: det of (p, q, r, s)")
truthy(math.abs(vr - 1) > 0.1, "and not the printed det/det = 1")
-- S:ratio measures against the simplex in its own order D, A, B, C (an odd permutation of ABCD)
near((T:ratio(Ps[1], Ps[2], Ps[3], Ps[4])), -det4(rows), 1e-12, "S:ratio against DABC")

-- (1.5) the meet of A1A2 and A3A4 in the natural parameters of CAB -----------------------------
local function nat(p, q) return (A - C) * p + (B - C) * q + C end
for _, pq in ipairs{{0.2, 0.1, 1.3, 0.7, -0.4, 0.8, 0.9, -0.3}, {1.5, -0.2, 0.1, 0.9, 0.3, 0.3, -1, 2}} do
  local p1, q1, p2, q2, p3, q3, p4, q4 = table.unpack(pq)
  local p21, q21, p34, q34 = p2 - p1, q2 - q1, p3 - p4, q3 - q4
  local lam = (q3 * p4 - p3 * q4 - p1 * q34 + q1 * p34) / (p21 * q34 - q21 * p34)
  local K, lk = meet(nat(p1, q1), nat(p2, q2), nat(p3, q3), nat(p4, q4))
  same(K, nat(p21 * lam + p1, q21 * lam + q1), "(1.5) K", 1e-12)
  near(lk, lam, 1e-12, "(1.5) lambda = MA1/A2A1")
  -- the moving triangle M A3 A4 has zero area at that lambda (S-theorem row of M)
  near(det3{{p21 * lam + p1, q21 * lam + q1, 1}, {p3, q3, 1}, {p4, q4, 1}}, 0, 1e-12, "zero area")
end
-- parallel lines: p21 q34 - q21 p34 = 0, the meet is improper (a direction)
local K = meet(nat(0, 0), nat(1, 1), nat(1, 0), nat(2, 1))
eq(K.w, 0, "(1.5) parallel lines: K at infinity")

-- §1.4 the metric operator Sigma^A_BC = (B - A).(C - A) = AH.AB --------------------------------
local Am, Bm, Cm = P(1, 1, 0), P(5, 2, 1), P(2, 4, -1)
local s = Sigma(Am, Bm, Cm)
near(s, 4 * 1 + 1 * 3 + 1 * -1, 1e-14, "Sigma^A_BC in coordinates")
near(s, (dist(Am, Bm) ^ 2 + dist(Am, Cm) ^ 2 - dist(Bm, Cm) ^ 2) / 2, 1e-12, "= (AB^2 + AC^2 - BC^2)/2")
near(s, Sigma(Am, Cm, Bm), 1e-14, "property 1: symmetric in B, C")
near(Sigma(Am, Bm, Bm), dist(Am, Bm) ^ 2, 1e-12, "property 2: Sigma^A_BB = AB^2")
near(Sigma(Am, Am, Bm), 0, 0, "property 3: an upper index among the lower gives 0")
-- property 4: Sigma^A + Sigma^B = AB^2 (at the foot H of the perpendicular from C)
local H = Am + (Bm - Am) * (s / Sigma(Am, Bm, Bm))  -- the foot of the perpendicular from C
near(Sigma(H, Am, Cm), 0, 1e-12, "H: CH is perpendicular to AB (property 5 at H)")
near(Sigma(Am, Bm, H) + Sigma(Bm, Am, H), dist(Am, Bm) ^ 2, 1e-12, "property 4: Sigma^A + Sigma^B = AB^2")
near(s, dist(Am, H) * dist(Am, Bm), 1e-12, "Sigma^A_BC = AH.AB (the print has AN)")
near(math.sqrt(Sigma(Am, Bm, Bm) * Sigma(Am, Cm, Cm) - s * s), 2 * area(Am, Bm, Cm), 1e-12,
     "2S = sqrt(Sigma_BB Sigma_CC - Sigma_BC^2), any dimension")
near(s / (dist(Am, Bm) * dist(Am, Cm)), math.cos(angle(Am, Bm, Cm)), 1e-12, "cos alpha = Sigma/(bc)")
near(Sigma(P(0, 0), P(3, 0), P(0, 5)), 0, 0, "property 5: a right angle at A")

-- §5.0 the polar parametrisation (2.117)/(2.118) and the rotation (2.138): C(0,0), A(4,0), B(1,3) -
local Cr, Ar, Br = P(0, 0), P(4, 0), P(1, 3)
local a, b = dist(Br, Cr), dist(Cr, Ar)
local g = angle(Cr, Ar, Br)
local function rotate(phi)          -- A rotated about C by phi toward B
  return (Ar - Cr) * (math.sin(g - phi) / math.sin(g)) + (Br - Cr) * (b * math.sin(phi) / (a * math.sin(g))) + Cr
end
same(rotate(math.pi / 6), P(3.464102, 2), "(2.138) phi = pi/6")
same(rotate(math.pi / 2), P(0, 4), "(2.138) phi = pi/2")
same(rotate(math.pi), P(-4, 0), "(2.138) phi = pi")
near(area(Cr, Ar, rotate(0.7)) / area(Cr, Ar, Br), b * math.sin(0.7) / (a * math.sin(g)), 1e-12,
     "(2.117): q = S_CAM/S_CAB")
near(dist(Cr, rotate(0.7)), b, 1e-12, "(2.138) keeps |CA|")
near(angle(Cr, Ar, rotate(0.7)), 0.7, 1e-12, "(2.138) turns by phi")

-- the book's printed coordinates (konopatsky.equation): Fig. 2.17's x = 4t(9t + 0,8)/(70t^2 -
-- 75t + 44,2), y = -8t(t - 1)/(14t^2 - 15t + 8,84) from the digest's reconstructed inputs, with
-- the denominator made monic (70 and 14 are the book's own, arbitrary, scales)
local c217 = conic.five_points2{C = P(0.5, 1), A = P(0, 0), B = P(1, 0), p1 = 0.7, p2 = 0.7, q2 = 0.8, q3 = 0.8}
local ex, ey = konopatsky.equation(c217)
check.eq(ex, "x = (0.514286t^2 + 0.0457143t)/(t^2 - 1.07143t + 0.631429)", "Fig. 2.17 x(t)")
check.eq(ey, "y = (-0.571429t^2 + 0.571429t)/(t^2 - 1.07143t + 0.631429)", "Fig. 2.17 y(t)")
-- a polynomial curve prints as ch. 4 prints its interpolants: the order-2 curve through
-- (0,0), (4,5), (9,1) at t = 0, 1/2, 1
local px, py = konopatsky.equation(interp.lagrange{P(0, 0), P(4, 5), P(9, 1)}, "v")
check.eq(px, "x = 2v^2 + 7v", "a quadratic's x(v)")
check.eq(py, "y = -18v^2 + 19v", "a quadratic's y(v)")
check.err(function() konopatsky.equation(curve(function(t) return P(t, t) end, 0, 1)) end,
          "function curve has no power-basis form", "a function curve")
-- Fig. 5.5's cubic through the book's nodes prints as the book prints it:
-- x = -14.67944t^3 + 22.01916t^2 + 0.66028t - 4, y = -11.921353t^2 + 11.921353t
local ell = approx.curve(function(x) return math.sqrt(math.max(9 - 9 * x * x / 16, 0)) end,
                         {-4, -1.877016, 1.877016, 4})
local e55x, e55y = konopatsky.equation(ell)
check.eq(e55x, "x = -14.6794t^3 + 22.0191t^2 + 0.660284t - 4", "Fig. 5.5 x(t)")
check.eq(e55y, "y = -11.9214t^2 + 11.9214t", "Fig. 5.5 y(t)")

check.done()
