-- Konopatsky §5.3 (Fig. 5.7): y = sin x + sin 10x on [-1, 1] by curves through 10 nodes
-- The book's nodes (red curve, MSE 0.000462 at m = 50) and the better minimum the digest's
-- search reaches from them, +-0.09003, +-0.273767, +-0.470413, +-0.696219 (green, its nodes
-- marked); the function in white.  A graph: x and y have different scales.
local f = function(x) return math.sin(x) + math.sin(10 * x) end
window(-1.1, -2.5, 1.1, 2.3)
line(P(-1.05, 0), P(1.05, 0), 8)
curve(function(x) return P(x, f(x)) end, -1, 1):draw{color = 15}
local bookn = {-1, -0.52455, -0.3, -0.128125, -0.030585, 0.030585, 0.128125, 0.3, 0.52455, 1}
local ours = {-1, -0.696219, -0.470413, -0.273767, -0.09003, 0.09003, 0.273767, 0.470413, 0.696219, 1}
approx.curve(f, bookn):draw{color = 12}
approx.curve(f, ours):draw{color = 10}
for _, x in ipairs(ours) do mark(P(x, f(x)), "open", 6, 10) end
caption(string.format("m = 50:  the book's nodes MSE %.4g,  ours %.3g", approx.mse(f, bookn, 50),
  approx.mse(f, ours, 50)), "bottom", 7)
