-- Konopatsky §5.2 (Fig. 5.4 a, b): Runge's function on [-2.5, 2.5] by the curves through optimal nodes
-- f(x) = 1/(1 + 25x^2) (red) and the approximation curve (green) through the optimal nodes
-- (white) found by approx.optimal_nodes with m = 100: (a) order 5, 6 nodes, (b) order 6,
-- 7 nodes.  The book prints only the MSE (0.0005587 and 0.00001936); the nodes are ours.
local runge = function(x) return 1 / (1 + 25 * x * x) end
local book = {[6] = 0.0005587, [7] = 0.00001936}
for i, N in ipairs{6, 7} do
  view(5 + (i - 1) * 315, 60, 310 + (i - 1) * 315, 420)
  window(-2.7, -0.35, 2.7, 1.25)
  line(P(-2.6, 0), P(2.6, 0), 8) line(P(0, -0.1), P(0, 1.15), 8)
  curve(function(x) return P(x, runge(x)) end, -2.5, 2.5):draw{color = 12}
  local nodes, mse = approx.optimal_nodes(runge, -2.5, 2.5, N)
  approx.curve(runge, nodes):draw{color = 10}
  for _, x in ipairs(nodes) do circle(P(x, runge(x)), 0.03, 15) end
  label(string.format("(%s) %d nodes, MSE %.4g", i == 1 and "a" or "b", N, mse), P(-2.6, -0.15), "e", 7)
  label(string.format("book %.4g", book[N]), P(-2.6, -0.27), "e", 7)
end
