-- M:expanded(): a point equation's coordinates in powers of its parameter, as the book prints
-- them (the printer of konopatsky.equation): the Bezier form, Fig. 2.17's printed conic entered
-- as the book prints it and as the five-point arc composed with t, the (4.10) and (4.16)
-- interpolation weights, a 3-D polynomial, a scalar, and the refusals.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local t = param "t"

local A, B, C = P(0, 0), P(1, 2), P(4, 0)
local M = A * bar(t)^2 + 2 * B * t * bar(t) + C * t^2
local x, y = M:expanded()
check.eq(x, "x = 2t^2 + 2t", "the Bezier form's x")
check.eq(y, "y = -4t^2 + 4t", "its y")

-- Fig. 2.17: x = 4t(9t + 0,8)/(70t^2 - 75t + 44,2), y = -8t(t - 1)/(14t^2 - 15t + 8,84), the
-- denominator made monic (70t^2 - 75t + 44.2 over 70): t^2 - 1.07143t + 0.631429
local fig = P(4 * t * (9 * t + 0.8) / (70 * t^2 - 75 * t + 44.2), -8 * t * (t - 1) / (14 * t^2 - 15 * t + 8.84))
local fx, fy = fig:expanded()
check.eq(fx, "x = (0.514286t^2 + 0.0457143t)/(t^2 - 1.07143t + 0.631429)", "Fig. 2.17 x as printed, monic")
check.eq(fy, "y = (-0.571429t^2 + 0.571429t)/(t^2 - 1.07143t + 0.631429)", "Fig. 2.17 y: one denominator")
-- the digest's inputs of that figure: the five-point arc composed with t prints the same
local arc = conic.five_points2 { C = P(0.5, 1), A = P(0, 0), B = P(1, 0), p1 = 0.7, p2 = 0.7, q2 = 0.8, q3 = 0.8 }
local ax, ay = arc(t):expanded()
check.eq(ax, fx, "the arc's x(t) is the book's")
check.eq(ay, fy, "the arc's y(t) is the book's")
check.eq(select(1, konopatsky.equation(arc)), ax, "the same printer as konopatsky.equation")

-- (4.10) w1 = t̄(1 - 2t) and (4.16)'s first weight t̄³ - 2.5t̄²t + t̄t², expanded
check.eq((bar(t) * (1 - 2 * t)):expanded(), "2t^2 - 3t + 1", "(4.10) w1")
check.eq(interp.weights(2, t)[1]:expanded(), "2t^2 - 3t + 1", "interp.weights' w1 is (4.10)'s")
check.eq((bar(t)^3 - 2.5 * bar(t)^2 * t + bar(t) * t^2):expanded(), "-4.5t^3 + 9t^2 - 5.5t + 1", "(4.16) w1")
check.eq(interp.weights(3, t)[2]:expanded(), "13.5t^3 - 22.5t^2 + 9t", "(4.16) w2 = 9t̄²t - 4.5t̄t²")

-- 3-D, another parameter's name, a scalar rational
local u = param "u"
local xs, ys, zs = (P(1, 0, 0) * bar(u) + P(0, 2, 0) * u + V(0, 0, 3) * u^3):expanded()
check.eq(xs .. "; " .. ys .. "; " .. zs, "x = -u + 1; y = 2u; z = 3u^3", "3-D in u")
check.eq((1 / (t + 2)):expanded(), "(1)/(t + 2)", "a scalar: no x =")

-- refusals name the call and what to do
check.err(function() return (P(0, 0) + V(1, 0) * math.sin(t)):expanded() end,
  "M:expanded: only an equation rational in its parameter expands in its powers", "sin")
check.err(function() return (P(0, 0) + V(1, 0) * t * u):expanded() end,
  "M:expanded: the equation has the parameters t and u: fix all but one with M:with{...} first", "two parameters")
check.err(function() return (P(0, 0) + V(1, 0) * t ^ 70):expanded() end,
  "of degree up to 64", "degree")
check.done()
