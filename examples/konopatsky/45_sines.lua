-- Konopatsky §5.3 (Figs. 5.6, 5.7): y = sin x + sin 10x by curves through optimal nodes
-- (a, Fig. 5.6) On [-0.5, 0.5]: the quintic (4.25) through 6 nodes optimised with m = 100
-- (the book: +-0.265069, +-0.084952, MSE 2.47e-6).  (b, Fig. 5.7) On [-1, 1] with 10 nodes:
-- the book's nodes (red curve, MSE 0.000462 at m = 50) and the better minimum the digest's
-- search reaches from them, +-0.09003, +-0.273767, +-0.470413, +-0.696219 (green).
local f = function(x) return math.sin(x) + math.sin(10 * x) end
local function graph(a, b) curve(function(x) return P(x, f(x)) end, a, b):draw{color = 15} end

view(5, 60, 310, 420)
window(-0.6, -2.4, 0.6, 2.4)
line(P(-0.55, 0), P(0.55, 0), 8)
graph(-0.5, 0.5)
local nodes, mse = approx.optimal_nodes(f, -0.5, 0.5, 6)
approx.curve(f, nodes):draw{color = 10}
for _, x in ipairs(nodes) do circle(P(x, f(x)), 0.012, 12) end
label(string.format("(a) MSE %.4g", mse), P(-0.58, -2.0), "e", 7)
label(string.format("nodes +-%.6f +-%.6f", nodes[5], nodes[4]), P(-0.58, -2.25), "e", 7)

view(325, 60, 630, 420)
window(-1.1, -2.4, 1.1, 2.4)
line(P(-1.05, 0), P(1.05, 0), 8)
graph(-1, 1)
local bookn = {-1, -0.52455, -0.3, -0.128125, -0.030585, 0.030585, 0.128125, 0.3, 0.52455, 1}
local ours = {-1, -0.696219, -0.470413, -0.273767, -0.09003, 0.09003, 0.273767, 0.470413, 0.696219, 1}
approx.curve(f, bookn):draw{color = 12}
approx.curve(f, ours):draw{color = 10}
for _, x in ipairs(ours) do circle(P(x, f(x)), 0.02, 10) end
-- two lines, as panel (a): on one the caption ran past the view's right edge
label(string.format("(b) m = 50: book %.4g,", approx.mse(f, bookn, 50)), P(-1.08, -2.0), "e", 7)
label(string.format("ours %.3g", approx.mse(f, ours, 50)), P(-1.08, -2.25), "e", 7)
