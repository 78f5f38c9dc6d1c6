-- Konopatsky §5.2 (Fig. 5.1): Runge's function by the curve through six optimal nodes
-- f(x) = 1/(1 + 25x^2) on [-1, 1] (red) and the order-5 curve through the 6 nodes found by the
-- optimal-node search (green, approx.optimal_nodes; the book's nodes +-0.233198, +-0.06054, MSE
-- 2.84e-5), its nodes marked.  A graph: x and y have different scales.
local runge = function(x) return 1 / (1 + 25 * x * x) end
window(-1.15, -0.3, 1.15, 1.2)
line(P(-1.1, 0), P(1.1, 0), 8) line(P(0, -0.2), P(0, 1.15), 8)
curve(function(x) return P(x, runge(x)) end, -1, 1):draw{color = 12}
local nodes, mse = approx.optimal_nodes(runge, -1, 1, 6)
approx.curve(runge, nodes):draw{color = 10}
for _, x in ipairs(nodes) do mark(P(x, runge(x)), "open", 6, 15) end
caption(string.format("optimal nodes +-%.6f, +-%.6f:  MSE = %.6g", nodes[5], nodes[4], mse), "bottom", 7)
