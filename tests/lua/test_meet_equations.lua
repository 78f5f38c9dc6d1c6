-- meet of point equations is an equation with exact derivatives (issue 23): the scheme of
-- Fig. 2.21 written as the book writes it, P = AK x CT, Q = BK x CT, M = AQ x BP, compiled
-- with curve() and compared with (2.97); an equation met with a fixed line; n-D.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, truthy, err = check.eq, check.near, check.truthy, check.err
local same = check.same_within(1e-12)

local u = param "u"
local A, B, C, k = P(0, 0), P(4, 0), P(2, 3), 0.7
local K = (mid(A, B) - C) * k + C
local T = A * bar(u) + B * u
local Pt = meet(A, K, C, T)
local Q = meet(B, K, C, T)
local M = meet(A, Q, B, Pt)
local scheme = curve(M, 0.05, 0.95)
local ed = conic.ed(A, B, C, k)
for _, x in ipairs{0.1, 0.25, 0.5, 0.75, 0.9} do
  same(scheme(x), ed(x), "the scheme's M is (2.97) at u = " .. x)
  same(scheme:deriv(x), ed:deriv(x), "exact first derivative", 1e-10)
  same(scheme:deriv(x, 2), ed:deriv(x, 2), "exact second derivative", 1e-9)
end
same(scheme(0.25), P(0.727273, 0.613636), "the digest's M(0.25)", 1e-6)
-- lambda and mu come as equations too
local K2, lam, mu = meet(A, K, C, T)
near(lam(0.25), dist(A, Pt(0.25)) / dist(A, K), 1e-12, "lambda = AP/AK")
same(C + (T(0.25) - C) * mu(0.25), Pt(0.25), "mu on CT")
-- an equation and a fixed line; 3-D
-- in 3-D: the line from (0, 2u, 0) to (1, 0, 0) meets y = 1 at x = (2u - 1)/(2u)
local c3 = curve(meet(P(0, 0, 0) * bar(u) + P(0, 2, 0) * u, P(1, 0, 0), P(0, 1, 0), P(2, 1, 0)), 0.6, 1)
for _, x in ipairs{0.6, 0.8, 1} do same(c3(x), P((2 * x - 1) / (2 * x), 1, 0), "3-D meet at u = " .. x) end
same(c3:deriv(0.8), V(1 / (2 * 0.8 ^ 2), 0, 0), "its exact derivative", 1e-10)
err(function() meet(A, K, V(1, 0) * u, T) end, "meet: argument #3 (B1) must be a point (weight 1)", "a vector equation")
err(function() meet(A, K, C, P(0, 0, 0) * bar(u) + P(1, 1, 1) * u) end,
    "meet: argument #4 (B2) is 3-D, but argument #1 is 2-D", "mixed dimensions")
check.done()
