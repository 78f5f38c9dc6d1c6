-- The Bezier G1 joint of the textbook (issue 24; Buimov §4.3: P_n = Q_0 and
-- n (P_n - P_(n-1)) = g m (Q_1 - Q_0)), and the Ceva <-> ED conversion (issue 23, §2.1.7).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err = check.eq, check.near, check.err
local same = check.same_within(1e-12)

local Pc = bezier{P(0, 0), P(1, 2), P(3, 3), P(4, 2)}
local q0, q1 = buimov.g1_next(Pc, 2, 1.5)
same(q0, P(4, 2), "Q0 = P3")
same(q1, P(5, 1), "Q1 = Q0 + n (P3 - P2)/(g m)")
local Q = bezier{q0, q1, P(7, 0)}
same(Pc:deriv(1), Q:deriv(0) * 1.5, "P'(1) = g Q'(0)")
local kind, g = buimov.joint(Pc, Q)
eq(kind, "G1", "a G1 joint")
near(g, 1.5, 1e-12, "with g")
local c0, c1 = buimov.g1_next(Pc, 3)
eq((buimov.joint(Pc, bezier{c0, c1, P(6, 1), P(8, 3)})), "C1", "g = 1 is C1")
eq((buimov.joint(Pc, bezier{P(4, 2), P(5, 2), P(7, 0)})), "C0", "a corner")
eq((buimov.joint(Pc, bezier{P(4.5, 2), P(5, 2), P(7, 0)})), "none", "apart")
err(function() buimov.g1_next(Pc, 2, -1) end, "buimov.g1_next: argument #3 (g) must be a positive number (the tangents keep their direction), got -1", "g < 0")
err(function() buimov.joint(Pc, conic.ed(P(0, 0), P(4, 0), P(2, 3), 0.7)) end,
    "buimov.joint: argument #2 (Q) must be a polynomial Bezier curve", "rational")
near(conic.ceva_to_ed(0.25), 0.5, 1e-15, "Ceva 1/4 is ED 1/2")
near(conic.ed_to_ceva(0.7), (0.7 / 0.6) ^ 2, 1e-15, "ED 0.7")
near(conic.ceva_to_ed(conic.ed_to_ceva(0.3)), 0.3, 1e-15, "round trip")
near(conic.ed(P(0, 0), P(4, 0), P(2, 3), 0.7):conic().k_ceva, conic.ed_to_ceva(0.7), 1e-12, "agrees with c:conic()")
err(function() conic.ed_to_ceva(1.2) end, "conic.ed_to_ceva: argument #1 (k) must be an engineering discriminant in (0, 1)", "k > 1")
check.done()
