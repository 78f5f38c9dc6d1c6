-- interp.weights by the book's order, numeric and symbolic (issue 23): the exact test vectors
-- of digest konopatsky_ch3_5.md §2.3 (uniform nodes j/n, t = 3/10) and the Maple output of §4.8.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err = check.eq, check.near, check.err

local tv = {
  [2] = {7 / 25, 21 / 25, -3 / 25},
  [3] = {77 / 2000, 2079 / 2000, -189 / 2000, 33 / 2000},
  [4] = {-21 / 625, 504 / 625, 189 / 625, -56 / 625, 9 / 625},
  [5] = {-7 / 256, 105 / 256, 105 / 128, -35 / 128, 21 / 256, -3 / 256},
  [6] = {-616 / 78125, 8316 / 78125, 16632 / 15625, -3696 / 15625, 1512 / 15625, -2079 / 78125, 264 / 78125},
}
local t = param "t"
for n = 2, 6 do
  local w = interp.weights(n, 0.3)
  eq(#w, n + 1, "order " .. n .. ": n + 1 weights")
  for j = 1, n + 1 do near(w[j], tv[n][j], 1e-14, "order " .. n .. " weight " .. j) end
  local sw = interp.weights(n, t)
  eq(#sw, n + 1, "symbolic weights, order " .. n)
  for j = 1, n + 1 do near(sw[j](0.3), tv[n][j], 1e-12, "the symbolic weight at 3/10") end
end
-- the Maple program's M1 for n = 5: -625u^5/24 + 625u^4/8 - 2125u^3/24 + 375u^2/8 - 137u/12 + 1
local m1 = interp.weights(5, t)[1]
for _, u in ipairs{0.1, 0.45, 0.9} do
  near(m1(u), -625 * u ^ 5 / 24 + 625 * u ^ 4 / 8 - 2125 * u ^ 3 / 24 + 375 * u ^ 2 / 8 - 137 * u / 12 + 1, 1e-12, "M1")
end
-- a curve built from the symbolic weights is the interpolation curve
local nodes = {P(0, 0), P(1, 3), P(2, 1), P(3, 4)}
local w3 = interp.weights(3, t)
local M = nodes[1] * w3[1] + nodes[2] * w3[2] + nodes[3] * w3[3] + nodes[4] * w3[4]
local c = curve(M, 0, 1)
near(dist(c(0.3), P(9 / 10, 309 / 100)), 0, 1e-12, "M(3/10) = (9/10, 309/100)")
-- node parameters, numeric and symbolic
local sp = interp.weights({0, 0.2, 0.7, 1}, t)
local np = interp.weights({0, 0.2, 0.7, 1}, 0.44)
for j = 1, 4 do near(sp[j](0.44), np[j], 1e-12, "params: symbolic = numeric") end
err(function() interp.weights(0, 0.3) end,
    "interp.weights: argument #1 (n) must be the book's order 1..64 (a curve through n + 1 nodes; not the number of nodes)", "order 0")
err(function() interp.weights({0, 0.5, 0.5}, t) end, "interp.weights: argument #1 (params) must be distinct", "repeated")
check.done()
