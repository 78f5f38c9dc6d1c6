-- korotky.plane_meet: the standalone meet of two 2-planes of 4-space (issue 24; Korotky 2015,
-- B.4's key construction).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, err = check.eq, check.err
local same = check.same_within(1e-12)

same(korotky.plane_meet(P(0, 0, 0, 0), P(1, 0, 0, 0), P(0, 1, 0, 0), P(0.3, 0.4, 0, 0), P(0.3, 0.4, 1, 0), P(0.3, 0.4, 0, 1)),
     P(0.3, 0.4, 0, 0), "the xy-plane and the plane x = 0.3, y = 0.4")
-- two planes through a known point K0, spanned by unrelated directions
local K0 = P(1.5, -0.5, 2, 0.25)
local u1, u2, v1, v2 = V(1, 2, 0, 1), V(0, 1, -1, 3), V(2, 0, 1, -1), V(-1, 1, 1, 0.5)
local K = korotky.plane_meet(K0 + u1 * 0.7, K0 - u2 * 1.3, K0 + u1 * 0.2 + u2, K0 + v1, K0 + v2 * 2, K0 - v1 * 0.5 + v2)
same(K, K0, "through a common point", 1e-10)
-- a point at infinity spans a plane too
same(korotky.plane_meet(K0, K0 + u1, u2, K0 + v1, v2, K0 - v2), K0, "with directions", 1e-10)
err(function() korotky.plane_meet(P(0, 0, 0, 0), P(1, 0, 0, 0), P(0, 1, 0, 0), P(0, 0, 0, 0), P(1, 0, 0, 0), P(0, 0, 1, 0)) end,
    "korotky.plane_meet: the planes share a line", "a common line")
err(function() korotky.plane_meet(P(0, 0, 0), P(1, 0, 0, 0), P(0, 1, 0, 0), P(0, 0, 0, 0), P(1, 0, 0, 0), P(0, 0, 1, 0)) end,
    "korotky.plane_meet: argument #1 (P1) must be a 4-D point or vector, got P(0, 0, 0)", "3-D")
check.done()
