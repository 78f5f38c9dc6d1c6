-- interp.arc with a parameter list, approx.mse / approx.optimal_nodes with divisor (issue 23).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err = check.eq, check.near, check.err
local same = check.same_within(1e-12)

local pts = {P(0, 0), P(1, 2), P(3, 2.5), P(4, 0)}
local u = {0, 0.2, 0.7, 1.5}
local a = interp.arc(pts, P(0.3, 1), P(3.8, 1), u)
for j = 1, 4 do same(a(u[j]), pts[j], "through node " .. j .. " at its parameter") end
local a1 = interp.arc(pts, P(0.3, 1), u)              -- one tangent, params third
for j = 1, 4 do same(a1(u[j]), pts[j], "one tangent: node " .. j) end
same(interp.arc(pts, P(0.3, 1), P(3.8, 1))(2 / 3), pts[3], "no params: uniform as before")
err(function() interp.arc(pts, P(0.3, 1), P(3.8, 1), {0, 0.5, 0.4, 1}) end,
    "interp.arc: argument #4 (params) must increase", "params decrease")
err(function() interp.arc(pts, P(0.3, 1), P(3.8, 1), {0, 1}) end, "interp.arc: argument #4 (params) must be a list of 4 numbers", "too few")

local runge = function(x) return 1 / (1 + 25 * x * x) end
local x = {-1, -0.233198, -0.06054, 0.06054, 0.233198, 1}
local mse = approx.mse(runge, x)
near(mse, 2.83922e-5, 1e-10, "the book's SSE/(m + 1)")
near(approx.mse(runge, x, {divisor = "m"}), 2.8676e-5, 1e-9, "SSE/m")
near(approx.mse(runge, x, 100, {divisor = "m-1"}), mse * 101 / 99, 1e-18, "SSE/(m - 1)")
near(approx.mse(runge, x, {m = 100, divisor = "m+1"}), mse, 0, "the default spelled out")
local _, m1 = approx.optimal_nodes(runge, -1, 1, 4)
local _, m2 = approx.optimal_nodes(runge, -1, 1, 4, {divisor = "m"})
near(m2, m1 * 101 / 100, 1e-15, "optimal_nodes rescales its MSE")
err(function() approx.mse(runge, x, {divisor = "n"}) end,
    "approx.mse: option divisor must be \"m+1\" (the book's), \"m\" or \"m-1\", got \"n\"", "bad divisor")
err(function() approx.mse(runge, x, {dvisor = "m"}) end, "approx.mse: unknown option dvisor", "misspelt option")
check.done()
