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
err(function() interp.arc(pts, P(0.3, 1), P(3.8, 1), {0, 1}) end, "interp.arc: argument #4 (params) must hold 4 numbers (one per point), got 2", "too few")

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
    "approx.mse: option 'divisor' must be \"m+1\", \"m\" or \"m-1\", got \"n\"", "bad divisor")
err(function() approx.mse(runge, x, {dvisor = "m"}) end, "approx.mse: unknown option 'dvisor' (did you mean 'divisor'?)", "misspelt option")
err(function() approx.mse(runge, x, {m = 0}) end, "approx.mse: option 'm' must be a number of samples 1..1000000, got 0", "m in the table")
err(function() approx.mse(runge, x, 0) end, "approx.mse: argument #3 (m) must be a number of samples 1..1000000, got 0", "m alone")
err(function() approx.mse(runge, x, {1}) end, "approx.mse: argument #3 (opts) holds [1]; its options are named (key = value)", "the table at #3 is named #3")
err(function() approx.optimal_nodes(runge, -1, 1, 4, 2) end, "approx.optimal_nodes: argument #5 (m) must be a number of samples 4..100000, got 2", "m below N")
err(function() interp.arc(pts, P(0.3, 1), {0, 1}) end, "interp.arc: argument #3 (params) must hold 4 numbers (one per point), got 2", "params third")
err(function() interp.arc(pts, P(0.3, 1), P(1, 1, 1)) end, "interp.arc: argument #3 (Cn) is 3-D", "Cn's dimension")
-- the spec forms' checks (konop_form.c): the row shows the value that broke the condition
err(function() conic.ellipse{by = "diameter", A = P(4, 0), B = P(2, 1), lambda = 0.5} end,
    "conic.ellipse: option 'K' must be a point, got nil", "diameter without K")
err(function() conic.ellipse{by = "diameter", K = P(-4, 0), A = P(4, 0), B = P(2, 1), lambda = 1.5} end,
    "conic.ellipse: option 'lambda' must be a number in (0, 1), got 1.5", "lambda outside (0, 1)")
err(function() conic.ellipse{by = "diameter", K = P(-4, 0), A = P(4, 0), B = P(2, 1)} end,
    "conic.ellipse: option 'lambda' must be a number in (0, 1), got nil", "lambda missing")
err(function() conic.ellipse{A = P(4, 0), B = P(0, 2)} end, "conic.ellipse: option 'C' must be a point, got nil",
    "C missing")
err(function() conic.circle{C = P(0, 0), A = P(1, 0), B = P(0, 1), delta = 4} end,
    "conic.circle: option 'delta' must be an angle in (0, pi), got 4", "delta outside (0, pi)")
check.done()
