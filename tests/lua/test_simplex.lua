-- Simplices through Lua: natural and barycentric evaluation, parameters of a point in any
-- dimension, measure, the S- and V-theorems, the chapter 1 theorems written as scripts, and
-- every error message of the simplex binding.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, approx, err, truthy = check.eq, check.near, check.err, check.truthy

local same = check.same_within(1e-12)             -- points/vectors equal within tol

-- simplex CAB: M = (A - C)p + (B - C)q + C ---------------------------------------------------------
local C, A, B = P(1, 1), P(5, 2), P(2, 4)
local S = simplex(C, A, B)
eq(tostring(S), "simplex(P(1, 1), P(5, 2), P(2, 4))", "tostring")
eq(#S, 3, "#S is the number of vertices")
truthy(S[1] == C and S[2] == A and S[3] == B, "S[i] are the vertices, the initial point first")
eq(S[4], nil, "S[4] is nil")
eq(getmetatable(S), "simplex", "protected metatable")
same(S(0.3, 0.6), (A - C) * 0.3 + (B - C) * 0.6 + C, "S(p, q) is the initial-point form")
same(S(1, 0), A, "A has parameters (1, 0)"); same(S(0, 1), B, "B (0, 1)"); same(S(0, 0), C, "C (0, 0)")
same(S:bary(0.3, 0.6, 0.1), A * 0.3 + B * 0.6 + C * 0.1, "S:bary(p, q, r) = Ap + Bq + Cr")
same(S:bary(0.3, 0.6, 0.1), S(0.3, 0.6), "the two forms agree when p + q + r = 1")
eq(S:bary(1, 1, 0).w, 2, "coefficients summing to 2 give a weighted value")
err(function() return S:bary(1, 1, 0).x end, "has weight 2", "and it cannot be read as a location")
local p, q, res = S:params(S(0.3, 0.6))
approx(p, 0.3, 1e-15, "params p"); approx(q, 0.6, 1e-15, "params q"); approx(res, 0, 1e-14, "residual 0")
local M = P(-2.5, 7.25)
same(S(S:params(M)), M, "S(S:params(M)) == M (S ignores the trailing residual)", 1e-12)
same(S(0.2, 0.3, 0.5), S:bary(0.2, 0.3, 0.5), "natural parameters p, q are barycentric p, q, 1 - p - q")
same(S(0.2, 0.3, 123), S(0.2, 0.3), "a trailing number (the residual of S:params) is ignored")
eq(S:measure(), 5.5, "the measure of a triangle is its signed area")
eq(simplex(C, B, A):measure(), -5.5, "the orientation follows the vertex order")

-- any ambient dimension ---------------------------------------------------------------------------
local T = simplex(P(1, 0, 0), P(0, 1, 0), P(0, 0, 1))
p, q, res = T:params(P(0.2, 0.3, 0.5))
approx(p, 0.3, 1e-15, "3-D params p"); approx(q, 0.5, 1e-15, "3-D params q"); approx(res, 0, 1e-15, "in the plane")
p, q, res = T:params(P(0.2, 0.3, 0.5) + V(1, 1, 1) * (0.7 / math.sqrt(3)))
approx(p, 0.3, 1e-14, "projection p"); approx(q, 0.5, 1e-14, "projection q"); approx(res, 0.7, 1e-14, "residual = distance to the plane")
approx(T:measure(), math.sqrt(3) / 2, 1e-15, "unsigned area of a triangle in space")
local S4 = simplex(P(1, 2, 3, 4), P(2, 2, 3, 5), P(1, 4, 3, 4), P(1, 2, 6, 3))
local X = S4(0.25, -0.5, 1.5)
local r1, r2, r3, r4 = S4:params(X)
approx(r1, 0.25, 1e-13, "4-D p"); approx(r2, -0.5, 1e-13, "4-D q"); approx(r3, 1.5, 1e-13, "4-D r"); approx(r4, 0, 1e-13, "4-D residual")
approx(simplex(P(0), P(3)):measure(), 3, 0, "a 1-simplex is a segment")
approx(simplex(P(0, 0, 0), P(3, 0, 0), P(0, 2, 0), P(0, 0, 4)):measure(), 4, 1e-15, "a tetrahedron")

-- S-theorem and V-theorem ----------------------------------------------------------------------------
local P1, P2, P3 = P(0.5, 0.2), P(2.5, -1), P(-1.5, 2)
local ratio, rres = S:ratio(P1, P2, P3)
approx(ratio, area(P1, P2, P3) / area(C, A, B), 1e-13, "S-theorem: det of parameters = area ratio")
approx(rres, 0, 1e-14, "the points are in the plane")
approx(S:ratio(C, A, B), 1, 1e-15, "the simplex itself gives 1")
approx(S:ratio(A, C, B), -1, 1e-15, "swapped vertices give -1")
local D3 = simplex(P(0, 0, 0), P(3, 0, 0), P(0, 2, 0), P(0, 0, 4))
local Q1, Q2, Q3, Q4 = P(1, 0.5, 0.2), P(0.1, 1.5, 1), P(0.3, 0.2, 2.5), P(2, 1, 1)
approx(D3:ratio(Q1, Q2, Q3, Q4), volume(Q1, Q2, Q3, Q4) / 4, 1e-13, "V-theorem")

-- chapter 1 as scripts -----------------------------------------------------------------------------
-- theorem on triangle areas (1.2) and its numbers: lambda = 1/3, -3, -1/3, k = -3/4
local A1, A2, A3 = P(0, 0), P(4, 1), P(1, 3)
local B1, B2, B3 = lerp(A1, A2, 0.25), lerp(A2, A3, 1.5), lerp(A3, A1, -0.5)
local l1, l2, l3 = sr(A1, A2, B1), sr(A2, A3, B2), sr(A3, A1, B3)
approx(l1, 1/3, 1e-15, "lambda1"); approx(l2, -3, 1e-15, "lambda2"); approx(l3, -1/3, 1e-15, "lambda3")
local k = (1 + l1*l2*l3) / ((1 + l1)*(1 + l2)*(1 + l3))
approx(k, -0.75, 1e-15, "k")
approx(area(B1, B2, B3) / area(A1, A2, A3), k, 1e-15, "(1.2): S_B/S_A = k")
-- Menelaus (1.3): collinear B1, B2, B3 give lambda1 lambda2 lambda3 = -1
local L1, L2 = P(-3, 0.5), P(4, 1.7)
local prod = 1
local poly = {A1, A2, A3}
for i = 1, 3 do
  local a, b = poly[i], poly[i % 3 + 1]
  prod = prod * sr(a, b, (meet(a, b, L1, L2)))
end
approx(prod, -1, 1e-12, "Menelaus")
-- O-theorem (1.4), with the closing factor (ERRATUM): product over a hexagon = +1
local hex = {}
for i = 0, 5 do hex[#hex + 1] = P(2 * math.cos(i * math.pi / 3) + 0.3 * math.sin(i * i), 2 * math.sin(i * math.pi / 3)) end
prod = 1
for i = 1, 6 do
  local a, b = hex[i], hex[i % 6 + 1]
  prod = prod * sr(a, b, (meet(a, b, L1, L2)))
end
approx(prod, 1, 1e-10, "O-theorem, m = 6")
-- intersection (1.5) in the natural parameters of CAB
local function nat(pp, qq) return (A - C) * pp + (B - C) * qq + C end
local p1, q1, p2, q2, p3, q3, p4, q4 = 0.2, 0.1, 1.3, 0.7, -0.4, 0.8, 0.9, -0.3
local p21, q21, p34, q34 = p2 - p1, q2 - q1, p3 - p4, q3 - q4
local lam = (q3*p4 - p3*q4 - p1*q34 + q1*p34) / (p21*q34 - q21*p34)
local K = meet(nat(p1, q1), nat(p2, q2), nat(p3, q3), nat(p4, q4))
same(K, nat(p21*lam + p1, q21*lam + q1), "(1.5) agrees with meet", 1e-12)
-- metric operator: 2S = sqrt(Sigma_BB Sigma_CC - Sigma_BC^2)
local s = Sigma(A1, A2, A3)
approx(math.sqrt(Sigma(A1, A2) * Sigma(A1, A3) - s * s), 2 * area(A1, A2, A3), 1e-12, "Sigma and the area")

-- errors -----------------------------------------------------------------------------------------------
err(function() return simplex(P(0, 0), P(1, 1), P(2, 2)) end, "simplex: the 3 points are collinear: a flat (degenerate) triangle", "flat triangle")
err(function() return simplex(P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(1, 1, 0)) end, "simplex: the 4 points are coplanar: a flat (degenerate) tetrahedron", "flat tetrahedron")
err(function() return simplex(P(0, 0), P(1, 1), P(1, 1 + 1e-14)) end, "collinear", "nearly flat")
err(function() return simplex(P(0, 0), P(0, 0), P(2, 2)) end, "simplex: argument #2 coincides with argument #1 (the initial point): a degenerate simplex", "repeated vertex")
err(function() return simplex(P(0, 0), P(1, 0), P(0, 1), P(1, 1)) end, "simplex: 4 points in 2-D are always dependent: a simplex has at most dimension + 1 = 3 vertices", "too many vertices")
err(function() return simplex(P(0, 0)) end, "simplex: argument #2 (A) must be a point, got nil", "one vertex")
err(function() return simplex() end, "simplex: argument #1 (C) must be a point, got nil", "no vertex")
err(function() return simplex(P(0, 0), P(1, 0, 0)) end, "simplex: argument #2 (A) is 3-D, but argument #1 (C) is 2-D (mixed dimensions)", "mixed dimensions")
err(function() return simplex(P(0, 0), V(1, 0)) end, "simplex: argument #2 (A) must be a point, got V(1, 0); a point has weight 1: to place a vector, add it to a point, e.g. P(0, 0) + v", "vector vertex")
err(function() return S(1) end, "S: a 2-simplex takes 2 natural parameters, got 1 (for barycentric parameters use S:bary)", "S arity")
err(function() return S(1, "a") end, "S: argument #2 (parameter 2) must be a finite number, got \"a\"", "S parameter")
err(function() return S(1, 2, 3, 4) end, "S: a 2-simplex takes 2 natural parameters, got 4", "S too many")
err(function() return S(1, 2, "r") end, "S: argument #3 (parameter 3) must be a finite number, got \"r\"", "S residual checked")
err(function() return S(1, 0/0) end, "S: argument #2 (parameter 2) must be a finite number, got ", "S NaN")
err(function() return S(1, math.huge) end, "S: argument #2 (parameter 2) must be a finite number, got inf", "S inf")
err(function() return S:bary(1, 2) end, "bary: a 2-simplex takes 3 barycentric parameters, got 2", "bary arity")
err(function() return S:bary(1, 2, {}) end, "S:bary: argument #3 must be a finite number, got table", "bary parameter")
err(function() return S:params(P(1, 2, 3)) end, "params: argument #1 (M) is 3-D, but the simplex is in 2-D: dimensions cannot be mixed", "params dims")
err(function() return S:params(5) end, "params: argument #1 (M) must be a point, got 5", "params number")
err(function() return S:params(V(1, 1)) end, "S:params: argument #1 (M) must be a point, got V(1, 1); a point has weight 1: to place a vector, add it to a point, e.g. P(0, 0) + v", "params vector")
err(function() return S.params(5) end, "params: must be called on a simplex, as S:params(...)", "bad self")
err(function() return S:ratio(P1, P2) end, "ratio: a 2-simplex compares with 3 points, got 2", "ratio arity")
err(function() return S:ratio(P1, P2, P(1, 2, 3)) end, "ratio: argument #3 is 3-D, but the simplex is in 2-D", "ratio dims")

check.done()
