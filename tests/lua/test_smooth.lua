-- The smoothsteps through Lua (docs/toolkit.md): the article's numbers (examples 3-8, 10, 14,
-- 20-22 of stepanov_examples.md), the half-spline objects, and the argument errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy

-- sine and cubic: g(0) = 0, g(1) = 1, g(1/2) = 1/2; the cubic extrapolates (example 5)
near(smooth.sine(0), 0, 1e-15, "sine(0)"); near(smooth.sine(1), 1, 1e-15, "sine(1)")
near(smooth.sine(.25), (1 - math.cos(math.pi / 4)) / 2, 1e-15, "sine(1/4)")
near(smooth.cubic(.5), .5, 0, "cubic(1/2)"); near(smooth.cubic(.3), 3 * .09 - 2 * .027, 1e-15, "cubic(.3)")
near(smooth.cubic(-1), 5, 0, "cubic(-1) = 5 (example 5)"); near(smooth.cubic(3), -27, 0, "cubic(3) = -27")

-- the power half-spline (example 7): through (1/2, 1/2), point-symmetric
for n = 2, 8, 2 do
  near(smooth.power(n, .5), .5, 1e-15, "power(" .. n .. ", 1/2)")
  near(smooth.power(n, .25), 2 ^ (n - 1) * .25 ^ n, 1e-15, "power(" .. n .. ", 1/4)")
  near(smooth.power(n, .2) + smooth.power(n, .8), 1, 1e-15, "symmetry n = " .. n)
end
near(smooth.power(5, .1), 16e-5, 1e-18, "example 14: k(.1) with n = 5")
local k5 = smooth.power(5)
eq(tostring(k5), "smooth.half(5, 5, 0.5)", "power(n) is the half-spline (n, n, 1/2)")
near(k5(.1), 16e-5, 1e-18, "the object evaluates"); near(k5.c1, 16, 0, "c1 = 2^(n-1)")

-- the asymmetric half-spline (example 8, n = 8, m = 2) and example 10's nodes
local g = smooth.half(8, 2, .5)
near(g.c1, 51.2, 1e-12, "c1 (8, 2, .5)"); near(g.c2, 3.2, 1e-12, "c2 (8, 2, .5)")
near(g.v, .2, 1e-15, "junction ordinate v(.5) = m t0/(n - n t0 + m t0) = .2")
eq(g.n, 8, "g.n"); eq(g.m, 2, "g.m"); eq(g.t0, .5, "g.t0")
near(g(0), 0, 0, "g(0)"); near(g(1), 1, 0, "g(1)")
near(g:deriv(0), 0, 0, "g'(0)"); near(g:deriv(1), 0, 0, "g'(1)")
near(g(.5 - 1e-9), g(.5), 1e-7, "continuous at t0")
near(g:deriv(.5 - 1e-12), g:deriv(.5), 1e-6, "slope continuous at t0")
local cases = { {8, 2, .1, 2702702.7027027, 1.2012012012012}, {8, 2, .9, 1.6082704471444, 30.769230769231},
                {3, 5, 1 / 3, 12.272727272727, 4.1420454545455}, {2, 7, .3, 6.6666666666667, 4.857062715608},
                {4, 5, .5, 8.8888888888889, 14.222222222222}, {6, 3, .7, 4.5768475589384, 17.094017094017} }
for _, c in ipairs(cases) do
  local h = smooth.half(c[1], c[2], c[3])
  local what = string.format("(%g, %g, %g)", c[1], c[2], c[3])
  near(h.c1, c[4], 1e-9 * c[4], "c1 " .. what); near(h.c2, c[5], 1e-9 * c[5], "c2 " .. what)
  near(h(c[3]), smooth.locus(c[1], c[2], c[3]), 1e-12, "g(t0) = v(t0) " .. what)
  near(smooth.half(c[1], c[2], c[3], .4), h(.4), 0, "the 4-argument form " .. what)
end
near(smooth.locus(8, 2, 0), 0, 0, "v(0) = 0"); near(smooth.locus(8, 2, 1), 1, 0, "v(1) = 1")
near(smooth.locus(3, 3, .4), .4, 1e-15, "n = m: the diagonal")

-- the clamp of examples 20-22, and the listings' strict IF chain
near(smooth.clamp(-1), 0, 0, "clamp below"); near(smooth.clamp(.25), .125, 1e-15, "clamp 2t^2")
near(smooth.clamp(.75), .875, 1e-15, "clamp 1 - 2(1-t)^2"); near(smooth.clamp(9), 1, 0, "clamp above")
near(smooth.clamp(.5), .5, 0, "clamp(1/2)")
near(smooth.clamp_qb(.5), 0, 0, "clamp_qb keeps the previous value (default 0) at t = 1/2")
near(smooth.clamp_qb(.5, .3), .3, 0, "clamp_qb(.5, prev)"); near(smooth.clamp_qb(1, .7), .7, 0, "clamp_qb(1, prev)")
near(smooth.clamp_qb(0, .7), .7, 0, "clamp_qb(0, prev)")
near(smooth.clamp_qb(.25, .7), .125, 1e-15, "clamp_qb elsewhere = clamp")

-- errors
err(function() smooth.half(8, 2, 1) end, "smooth.half: argument #3 (t0) must be a number in (0, 1), got 1", "t0 = 1")
err(function() smooth.half(0, 2, .5) end, "smooth.half: argument #1 (n) must be a positive number, got 0", "n = 0")
err(function() smooth.half(2, "x", .5) end, "smooth.half: argument #2 (m) must be a positive number, got \"x\"", "m string")
err(function() smooth.power(-1) end, "smooth.power: argument #1 (n) must be a positive number, got -1", "power n < 0")
err(function() smooth.sine() end, "smooth.sine: argument #1 (t) must be a finite number, got nil", "sine()")
err(function() smooth.cubic(0 / 0) end, "smooth.cubic: argument #1 (t) must be a finite number", "cubic(NaN)")
err(function() smooth.clamp_qb(0 / 0, .7) end, "smooth.clamp_qb: argument #1 (t) must be a finite number", "clamp_qb(NaN) kept prev")
err(function() smooth.locus(2, 2, 2) end, "smooth.locus: argument #3 (t0) must be a number from 0 to 1, got 2", "locus t0")
err(function() g("x") end, "g: argument #1 (t) must be a finite number, got \"x\"", "g(string)")
-- a fractional degree does not extrapolate: t^2.5 is not real for t < 0 (no NaN comes back)
local frac = smooth.half(2.5, 3.5, .5)
near(frac(.25), frac.c1 * .25 ^ 2.5, 1e-15, "fractional degrees inside [0, 1]")
near(smooth.half(2.5, 2, .5, 1.5), 1 - smooth.half(2.5, 2, .5).c2 * .25, 1e-15, "a whole m extrapolates past 1")
err(function() frac(-.1) end, "frac: argument #1 (t) must be at least 0 (the degree n = 2.5 is fractional", "fractional n, t < 0")
err(function() frac:deriv(1.2) end, "g:deriv: argument #1 (t) must be at most 1 (the degree m = 3.5 is fractional", "fractional m, t > 1")
err(function() smooth.half(2.5, 2, .5, -.1) end, "smooth.half: argument #4 (t) must be at least 0", "4-argument form")
err(function() smooth.power(1.5, 2) end, "smooth.power: argument #2 (t) must be at most 1 (the degree m = 1.5", "power")
err(function() smooth.half(.5, 2, .5):deriv(0) end, "g:deriv: the slope at t = 0 is infinite (a degree below 1)", "vertical tangent")
-- degrees so large that c1, c2 overflow (t0^(n-1) underflows) are refused, not inf and NaN
err(function() smooth.half(2000, 2, .5) end, "smooth.half: the degrees n = 2000, m = 2 are too large for t0 = 0.5", "huge n")
err(function() smooth.power(1100, .25) end, "smooth.power: the degrees n = 1100, m = 1100 are too large", "huge power")
near(smooth.power(500, .25), 2 ^ -501, 1e-165, "degree 500 is still fine: 2^499 (1/4)^500")
check.done()
