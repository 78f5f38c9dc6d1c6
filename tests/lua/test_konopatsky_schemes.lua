-- Konopatsky: the schemes' intermediate points that the figures label (oneratio.simplex_scheme,
-- oneratio.levels, oneratio.desargues_scheme; digest konopatsky_ch3_5.md §1.1, §1.3, §1.7) and
-- interp.basis's membership report (§2.7: the exponential prototype (4.39) is not affine).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local same = check.same_within(1e-9)

local A, B, C, D = P(0, 0, 0), P(4, 0, 0), P(1, 3, 0), P(4, 3, 2)

-- Fig. 3.1: N on AC, M on NB, one ratio; M is the point of (3.1) -----------------------------
local s = oneratio.simplex_scheme(A, B, C, 0.3)
same(s.N, P(0.3, 0.9, 0), "N = A t' + C t")
same(s.M, P(1.41, 0.63, 0), "M (digest TV)")
same(s.M, oneratio(A, B, C)(0.3), "M is on (3.1)")
near(sr(s.N, B, s.M) / (0.3 / 0.7), 1, 1e-12, "NM/NB = t")

-- Fig. 3.4: the de Casteljau levels of (3.4) ---------------------------------------------------
local A2, C1, C2, B2 = P(0, 0), P(2, 5), P(8, 5), P(10, 0)
local lv = oneratio.levels({A2, C1, C2, B2}, 0.4)
eq(#lv, 3, "three levels"); eq(#lv[1], 3, "P1 P2 P3"); eq(#lv[2], 2, "Q1 Q2"); eq(#lv[3], 1, "M")
same(lv[1][1], lerp(A2, C1, 0.4), "P1 = (C1 - A)t + A")
same(lv[1][3], lerp(C2, B2, 0.4), "P3 = (B - C2)t + C2 (the print has C2 - B)")
same(lv[2][2], lerp(lv[1][2], lv[1][3], 0.4), "Q2 = (P3 - P2)t + P2")
same(lv[3][1], oneratio.bezier3(A2, C1, C2, B2)(0.4), "M is on (3.4)")
local t, tb = 0.4, 0.6
same(lv[3][1], A2 * tb ^ 3 + C1 * (3 * tb * tb * t) + C2 * (3 * tb * t * t) + B2 * t ^ 3,
     "M = A t'^3 + 3 C1 t'^2 t + 3 C2 t' t^2 + B t^3 (corrected powers)")
local big = oneratio.levels({P(0), P(1), P(3), P(7), P(15)}, 0.5)
eq(#big, 4, "any degree"); same(big[4][1], bezier{P(0), P(1), P(3), P(7), P(15)}(0.5), "quartic")

-- Fig. 3.12: the Desargues arc's T, S, R, N, J, Q, M --------------------------------------------
local d = oneratio.desargues_scheme(A, B, C, D, 0.3)
same(d.M, P(0.874137931, 0.9, 0.09310344828), "M (digest TV)")
same(d.M, oneratio.desargues(A, B, C, D)(0.3), "M is on (3.6)")
same(d.T, (A * 0.49 - B * 0.09) / 0.4, "T = (A t'^2 - B t^2)/(1 - 2t)")
same(d.N, A * 0.49 + C * 0.42 + B * 0.09, "N = A t'^2 + 2C t' t + B t^2")
same(d.Q, lerp(C, B, 0.3), "Q = (B - C)t + C")
same(d.R, lerp(d.T, d.S, 0.3), "TR/TS = t")
near(d.pJ, -0.4, 1e-15, "p_J = 2t - 1"); near(d.qJ, 0.7 / 0.3, 1e-14, "q_J = t'/t")
same(d.J, (d.S - d.T) * d.pJ + (d.N - d.T) * d.qJ + d.T, "J in the simplex S N T")
local K = meet(d.S, d.N, d.T, d.J)
same(K, d.M, "M = SN x TJ")
local h = oneratio.desargues_scheme(A, B, C, D, 0.5)
eq(h.T.w, 0, "T at infinity at t = 1/2"); eq(h.S.w, 0, "S too")
same(h.M, (A + B + C + D) / 4, "M(1/2) is the centroid")

-- interp.basis reports the membership condition ------------------------------------------------
local nodes = {P(0, 0), P(1, 2), P(3, 1)}
local exp_k = {0.5, -1, 2}
local g = {}
for i, k in ipairs(exp_k) do g[i] = function(x) return math.exp(k * x) end end
local cexp, affine, dev = interp.basis(g, nodes, {0, 0.5, 1})
eq(affine, false, "(4.39): the exponential weights do not sum to 1")
truthy(dev > 8e-3 and dev < 9e-3, "(4.39) its largest |sum - 1| is 0.0085")
same(cexp(0.5), nodes[2], "yet it passes through its nodes")
local bern = {function(x) return (1 - x) ^ 2 end, function(x) return 2 * x * (1 - x) end, function(x) return x * x end}
local cb, aff2, dev2 = interp.basis(bern, nodes, {0, 0.5, 1})
eq(aff2, true, "the Bezier prototype is affine")
truthy(dev2 < 1e-12, "to round-off")
same(cb(0.3), interp.lagrange(nodes)(0.3), "and gives the book's curve (4.10)")
local trig = {math.cos, function(x) return 1 - math.cos(x) - math.sin(x) end, math.sin}
local _, aff3 = interp.basis(trig, nodes, {0, math.pi / 2, math.pi}, 0, 2 * math.pi)
eq(aff3, true, "(4.40) the trigonometric prototype is affine")

-- errors --------------------------------------------------------------------------------------------
err(function() oneratio.levels({A2}, 0.5) end, "oneratio.levels: argument #1 (points) must hold 2 to 16 points, got 1", "one point")
err(function() oneratio.levels({A2, C1}, "x") end, "oneratio.levels: argument #2 (t) must be", "t")
err(function() oneratio.desargues_scheme(A, B, C, P(1, 2), 0.5) end, "mixed dimensions", "dims")
err(function() oneratio.simplex_scheme(A, B, C, 0 / 0) end, "oneratio.simplex_scheme: argument #4 (t)", "NaN t")
err(function() oneratio.desargues_scheme(A, B, C, V(1, 2, 3), 0.5) end, "argument #4 (D) must be a point", "vector")

check.done()
