-- Konopatsky §5.3 (Fig. 5.6): y = sin x + sin 10x on [-0.5, 0.5] by the curve through optimal nodes
-- The quintic (4.25) through 6 nodes optimised with m = 100 (approx.optimal_nodes; the book:
-- +-0.265069, +-0.084952, MSE 2.47e-6): the function (white), the curve (green) and its nodes.
-- At the top the curve's x(t), y(t) as the book prints them (its x = 1.25933t^5 - 3.1483t^4 + ...,
-- y = 219.35774t^5 - ..., from unrounded nodes). A graph: x and y have different scales.
local f = function(x) return math.sin(x) + math.sin(10 * x) end
window(-0.6, -2.5, 0.6, 2.3)
line(P(-0.55, 0), P(0.55, 0), 8)
curve(function(x) return P(x, f(x)) end, -0.5, 0.5):draw{color = 15}
local nodes, mse = approx.optimal_nodes(f, -0.5, 0.5, 6)
local c = approx.curve(f, nodes)
c:draw{color = 10}
local ex, ey = konopatsky.equation(c)
text{x = 8, y = 14, text = ex, units = "device", color = 10}
text{x = 8, y = 32, text = ey, units = "device", color = 10}
for _, x in ipairs(nodes) do mark(P(x, f(x)), "open", 6, 12) end
caption(string.format("6 nodes: MSE %.4g at +-%.6f, +-%.6f", mse, nodes[5], nodes[4]), "bottom", 7)
