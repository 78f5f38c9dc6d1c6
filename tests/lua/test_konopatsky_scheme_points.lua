-- The scheme helpers return the points (issue 23): conic.ed_scheme (§2.1.6, Fig. 2.21) and
-- conic.five_scheme (§2.1.4, Fig. 2.15), against the digest's vectors and the curves.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local same = check.same_within(1e-12)

local A, B, C = P(0, 0), P(4, 0), P(2, 3)
local s = conic.ed_scheme(A, B, C, 0.7, 0.25)
same(s.M, P(0.727273, 0.613636), "M(0.25), k = 0.7", 1e-6)
same(s.M, conic.ed(A, B, C, 0.7)(0.25), "M is (2.97) at u")
same(s.T1, P(2, 0), "T1 the midpoint of AB")
same(s.K, P(2, 0.9), "K = (T1 - C)k + C")
same(s.T, P(1, 0), "T = A u' + B u")
same(s.N, P(-2, 0), "N the harmonic conjugate of T")
near(sr(A, B, s.N), -sr(A, B, s.T), 1e-12, "(ABN) = -(ABT)")
same(s.P, meet(A, s.K, C, s.T), "P = AK x CT")
same(s.Q, meet(B, s.K, C, s.T), "Q = BK x CT")
same(s.M, meet(s.K, s.N, B, s.P), "M = KN x BP as well")
eq(conic.ed_scheme(A, B, C, 0.7, 0.5).N.w, 0, "N at infinity at u = 1/2")
local F = {P(1, 0), P(0, 1), P(0, 0), P(0.3, 0.8), P(0.7, 0.6)}
local f = conic.five_scheme(F[1], F[2], F[3], F[4], F[5], 0.25)
same(f.S, P(0.25, 0.857143), "S = BE x AD", 1e-6)
same(f.M, P(0.3, 0.066667), "M(0.25)", 1e-6)
same(f.U_B, P(1.75, 0), "U_B: u_B = 1.75")
same(f.U_D, P(1.9, 0), "U_D: u_D = 1.9")
same(f.U_E, P(2.557692308, 0), "U_E: u_E = 2.557692308", 1e-9)
same(conic.five_scheme(F[1], F[2], F[3], F[4], F[5], 1.5).M, P(-8.1, 7.2), "M(1.5)")
-- §3.6: the chain of M_n (Fig. 3.9 for n = 2), the digest's TV A(0,0,0), B(4,0,0), C(1,3,0), t = 0.3
local A3, B3, C3 = P(0, 0, 0), P(4, 0, 0), P(1, 3, 0)
local tvm = {P(0.78, 1.26, 0), P(0.6683544304, 1.594936709, 0), P(0.6279310345, 1.716206897, 0)}
for n = 1, 3 do
  local ch = oneratio.smooth_scheme(A3, B3, C3, n, 0.3)
  same(ch.M, tvm[n], "M_" .. n .. "(0.3)", 1e-9)
  same(ch.M, oneratio.smooth(A3, B3, C3, n)(0.3), "M_" .. n .. " on oneratio.smooth")
  eq(#ch.P, n, "n points P")
end
local ch = oneratio.smooth_scheme(A3, B3, C3, 2, 0.3)
near(dist(A3, ch.P[1]) / dist(A3, ch.P[2]), 0.3, 1e-12, "AP1/AP2 = t")
near(dist(ch.P[1], ch.P[2]) / dist(ch.P[1], C3), 0.3, 1e-12, "P1P2/P1C = t")
near(dist(C3, ch.Q[1]) / dist(C3, ch.Q[2]), 0.3, 1e-12, "CQ1/CQ2 = t")
near(dist(ch.Q[1], ch.Q[2]) / dist(ch.Q[1], B3), 0.3, 1e-12, "Q1Q2/Q1B = t")
near(dist(ch.P[2], ch.M) / dist(ch.P[2], ch.Q[1]), 0.3, 1e-12, "P2M/P2Q1 = t")
err(function() oneratio.smooth_scheme(A3, B3, C3, 0, 0.3) end, "oneratio.smooth_scheme: argument #4 (n) must be the smoothness order 1..40", "n = 0")
-- §2.6: the excluded parameters (2.148), (2.151), (2.153)
local ex = conic.cones_excluded(0.3, 0.4)
eq(#ex, 5, "five excluded u for two hyperbolas")
local r = 1 / math.sqrt(1 - 0.6)
local function has(x) for _, v in ipairs(ex) do if math.abs(v - x) < 1e-12 then return true end end return false end
truthy(has((1 - r) / 2) and has((1 + r) / 2), "(2.151) with the roots summing to 1")
eq(#conic.cones_excluded(0.6, 0.9), 1, "two ellipses: only (2.148)'s pole")
-- foci, e, p of §2.1.1 / §2.1.2
local F1, F2, e, p = conic.foci(P(0, 0), P(3, 0), P(0, 2))
same(F1, P(math.sqrt(5), 0), "F1 on the side of A")
same(F2, P(-math.sqrt(5), 0), "F2")
near(e, math.sqrt(5) / 3, 1e-15, "e")
near(p, 4 / 3, 1e-15, "p = b^2/a")
local E = conic.ellipse{C = P(0, 0), A = P(3, 0), B = P(0, 2)}
local M = E(0.9)
near(dist(M, F1) + dist(M, F2), 6, 1e-12, "|MF1| + |MF2| = 2a on conic.ellipse")
local H1, H2, he = conic.foci(P(0, 0), P(2, 0), P(0, 1.5), "hyperbola")
same(H1, P(2.5, 0), "the hyperbola's focus: c = sqrt(a^2 + b^2)")
near(he, 1.25, 1e-15, "its e")
err(function() conic.foci(P(0, 0), P(3, 0), P(1, 2)) end, "conic.foci: CA and CB must be the axes (perpendicular)", "oblique")
err(function() conic.foci(P(0, 0), P(3, 0), P(0, 2), "circle") end, "conic.foci: argument #4 (kind) must be \"ellipse\" or \"hyperbola\"", "kind")
err(function() conic.ed_scheme(A, B, P(8, 0), 0.5, 0.3) end, "conic.ed_scheme: A, B, C are collinear", "flat")
err(function() conic.ed_scheme(A, B, C, 0, 0.3) end, "conic.ed_scheme: argument #4 (k) must not be 0", "k = 0")
err(function() conic.five_scheme(F[1], F[2], F[3], F[4], P(0, 0, 1), 0.3) end,
    "conic.five_scheme: argument #5 (E) is 3-D, but argument #1 (A) is 2-D", "mixed")
check.done()
