-- Derivatives of any order and on either side of a joint, and power-basis coefficients
-- (issues 23, 24): c:deriv(t, order, "left"|"right"), c:monomial().
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err = check.eq, check.near, check.err
local same = check.same_within(1e-12)

-- §3.7: the cubic's third derivative is 6(P3 - 3 P2 + 3 P1 - P0), the fourth 0
local A, B, C, D = P(0, 0), P(1, 3), P(4, 2), P(6, -1)
local c = bezier{A, B, C, D}
same(c:deriv(0.3, 3), (D - C * 3 + B * 3 - A) * 6, "third derivative")
same(c:deriv(0.7, 4), V(0, 0), "fourth derivative")
same(c:deriv(0.3, 2), c:deriv(0.3, 2, "left"), "inside a piece the sides agree")
-- a joint: two quadratic pieces over [0, 1] and [1, 3] with a kink at (2, 0) (a double knot)
local k = bspline({P(0, 0), P(1, 1), P(2, 0), P(4, 1), P(5, 0)}, 2, {0, 0, 0, 1, 1, 3, 3, 3})
same(k:deriv(1, "left"), V(2, -2), "left of the joint: 2(P2 - P1)")
same(k:deriv(1, "right"), V(2, 1), "right of the joint: 2(P1 - P0)/2")
same(k:deriv(1), k:deriv(1, "right"), "the default is the right-hand side")
same(k:deriv(1, 1, "left"), V(2, -2), "order and side together")
-- monomial coefficients: x(t) = 3t + 6t^2 - 3t^3, y(t) = 9t - 12t^2 + 2t^3
local m = c:monomial()
for i, a in ipairs{0, 3, 6, -3} do near(m[1][i], a, 1e-13, "x coefficient " .. i - 1) end
for i, a in ipairs{0, 9, -12, 2} do near(m[2][i], a, 1e-13, "y coefficient " .. i - 1) end
eq(m.w, nil, "a polynomial curve has no weight polynomial")
local m2 = k:monomial(2)
for _, t in ipairs{1, 1.5, 2.2, 3} do
  local x = m2[1][1] + m2[1][2] * t + m2[1][3] * t * t
  near(x, k(t).x, 1e-12, "piece 2 in the curve's own t")
end
local q = conic.ed(P(0, 0), P(4, 0), P(2, 3), 0.7):monomial()
near(q.w[1], 0.7, 1e-14, "a rational curve: the weight polynomial")
-- errors
err(function() c:deriv(0.3, 0) end, "c:deriv: argument #2 (order) must be a whole number from 1 to 64", "order 0")
err(function() c:deriv(0.3, "middle") end, "c:deriv: argument #2 (side) must be \"left\" or \"right\"", "bad side")
err(function() curve(function(t) return P(t, t * t) end, 0, 1):deriv(0.5, 3) end,
    "c:deriv: a function curve gives derivatives up to order 2, not 3", "FUNC order 3")
err(function() k:monomial(3) end, "c:monomial: argument #1 (piece) must be from 1 to 2", "piece")
err(function() curve(function(t) return P(t, t) end, 0, 1):monomial() end, "c:monomial: a function curve", "FUNC")
check.done()
