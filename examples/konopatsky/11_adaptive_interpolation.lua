-- Konopatsky §4.10 (Fig. 4.7 a, b): universal against adaptive interpolation
-- The book's nodes x = 8.89, 1.11, 0.33; y = 5, 7, 8.  The universal quadratic (4.31) at
-- v = 0, 1/2, 1 (red) swings to negative x; the adaptive one with v2 = AN/AB = 7.78/8.56
-- (green) runs monotonically from M1 to M3.
local nodes = {P(8.89, 5), P(1.11, 7), P(0.33, 8)}
window(-1.5, 3, 10, 11.6)
line(P(0, 3.2), P(0, 11.4), 8) label("x = 0", P(0, 11.2), "e", 8)
local uni = interp.lagrange(nodes)
local v = interp.adaptive(nodes)
local ada = interp.lagrange(nodes, v)
uni:draw{color = 12}
ada:draw{color = 10}
for i, p in ipairs(nodes) do circle(p, 0.08, 15) label("$M_" .. i .. "$", p, nil, 15) end
local xmin = math.huge
for t = 0, 1, 0.001 do xmin = math.min(xmin, uni(t).x) end
label(string.format("universal (red): min x = %.4f", xmin), P(-1.3, 4.2), "e", 12)
label(string.format("adaptive (green): v2 = %.6f", v[2]), P(-1.3, 3.6), "e", 10)
