-- The ratio of parallel vectors is a number (issue 23): (T - A)/(T_C - A) of (2.62), an error
-- with the angle between them when they are not parallel.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local near, err = check.near, check.err

local A, TC = P(0, 0), P(4, 3)
local T = lerp(A, TC, 0.35)
near((T - A) / (TC - A), 0.35, 1e-15, "(T - A)/(T_C - A) = t")
near(V(-5, 2.5, 1) / V(2, -1, -0.4), -2.5, 1e-15, "3-D, opposite")
near(V(0, 0) / V(1, 2), 0, 0, "the zero vector over any")
-- (2.62): the parabola through A (t = 0), C (t = tC), B (t = 1); the parameter of a point on
-- the chord AB read back as a ratio
local B = P(4, 0)
near((lerp(A, B, 0.3) - A) / (B - A), 0.3, 1e-15, "a chord parameter")
err(function() return V(1, 0) / V(1, 1) end, "cannot divide vectors that are not parallel: they are 45 degrees apart", "45 degrees")
err(function() return V(1, 0) / V(0, 0) end, "division of a vector by the zero vector", "zero")
err(function() return P(1, 0) / P(1, 1) end, "cannot divide a point by a point: only a vector divides a parallel vector", "points")
err(function() return V(1, 0) / V(1, 0, 0) end, "cannot divide a 2-D vector by a 3-D one", "dimensions")
check.done()
