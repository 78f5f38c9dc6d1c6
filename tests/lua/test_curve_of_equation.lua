-- A curve applied to an equation is the composed equation (issue 23): conic.ed(...)(t) with t a
-- param is (2.97) as a point equation, C(u^2) reparametrises, derivatives are exact.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, truthy, err = check.eq, check.near, check.truthy, check.err
local same = check.same_within(1e-12)

local t = param "t"
local A, B, C = P(0, 0), P(4, 0), P(2, 3)
local c = conic.ed(A, B, C, 0.7)
local M = c(t)                                     -- (2.97) without retyping it
local m = curve(M, 0, 1)
for _, x in ipairs{0, 0.25, 0.5, 0.8, 1} do
  same(m(x), c(x), "c(t) at " .. x)
  same(m:deriv(x), c:deriv(x), "its derivative at " .. x, 1e-11)
end
same(M(0.25), P(0.727273, 0.613636), "M(0.25)", 1e-6)
-- C(u^2): the reparametrised curve and the chain rule
local sq = curve(c(t ^ 2), 0, 1)
same(sq(0.5), c(0.25), "C(u^2) at 1/2 is C(1/4)")
same(sq:deriv(0.5), c:deriv(0.25) * (2 * 0.5), "chain rule")
-- a Bezier over another domain, and a polynomial one
local b = bezier{P(0, 0), P(1, 2), P(3, 3), P(4, 0)}
same(curve(b(t), 0, 1)(0.3), b(0.3), "a cubic Bezier")
local h = plane.parabola(0.5, -2, 3)              -- over [-2, 3], the book's parameter
same(curve(h(t), -2, 3)(1.5), h(1.5), "a curve over [-2, 3]")
err(function() return plane.ellipse(P(0, 0), 2, 1)(t) end,
    "curve: only a single-piece Bezier curve", "a function curve")
err(function() return c(P(1, 1) * t) end, "curve: the parameter must be a number or a scalar equation", "a point equation")
check.done()
