-- Issue 26, item 9: results that overflow to infinity or NaN are errors naming the operation,
-- never values drawn at infinity; a NUL byte in a label is an error, not a shorter label.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local here = arg[0]:match("[^/]*$")

-- the midpoint of two huge equal points is that point, not P(inf, 0)
check.eq(mid(P(1e308, 0), P(1e308, 0)), P(1e308, 0), "mid of huge equal points")
check.eq(mid(P(-1e308, 2), P(1e308, 4)), P(0, 3), "mid across the range")
check.eq(mid(P(0, 0), P(2, 4), P(4, 2)), P(2, 2), "the centroid of three")

-- arithmetic that overflows
check.err(function() return P(1e308, 0) + V(1e308, 0) end,
  "A + B: the result is out of range (not finite: a coordinate overflowed)", "sum")
check.err(function() return P(1e308, 0) - P(-1e308, 0) end, "A - B: the result is out of range", "difference")
check.err(function() return V(1e308, 1) * 10 end, "k * A: the result is out of range", "product")
check.err(function() return 10 * V(0, 1e308) end, "k * A: the result is out of range", "product, k first")
check.err(function() return V(1e308, 1) / 1e-10 end, "A / k: the result is out of range", "quotient")
check.err(function() return V(1e308, 1) * 10 end, here .. ":", "located at the caller's line")
check.eq(V(1e307, 1) * 10, V(1e308, 10), "within the range it works")

-- Lagrange weights far outside the nodes
check.err(function() return interp.weights(3, 1e308) end,
  "interp.weights: the weights are out of range (not finite) for t = 1e+308", "weights")
local w = interp.weights(2, 0.5)   -- the book's order 2: three weights
check.near(w[1] + w[2] + w[3], 1, 1e-12, "weights sum to 1")

-- map.translate by a vector that is not finite (made by overflow, it is refused earlier; a
-- vector field given directly too)
check.err(function() return map.translate(V(1e308, 0) * 10) end, "k * A: the result is out of range", "overflowed vector")
check.eq(map.translate(V(1, 2))(P(0, 0)), P(1, 2), "a finite translation")

-- NUL bytes in text
screen(12)
check.err(function() label("ab\0cd", P(10, 10)) end,
  "label: argument #1 (text) must be a string without NUL bytes", "label")
check.err(function() text(10, 10, "ab\0cd") end,
  "text: argument #3 (text) must be a string without NUL bytes", "text")
label("abcd", P(10, 20), "ne")   -- and without one it draws: four letters' pixels
local lit = 0
for x = 10, 60 do for y = 0, 20 do if point(x, y) ~= 0 then lit = lit + 1 end end end
check.truthy(lit > 20, "a label without NUL draws (" .. lit .. " pixels)")

check.done()
