-- Konopatsky §5.2 (Figs. 5.1-5.3): Runge's function by the curve through optimal nodes
-- f(x) = 1/(1 + 25x^2) on [-1, 1] (red).  The order-5 curve through 6 nodes found by the
-- optimal-node search (green; the book's nodes +-0.233198, +-0.06054, MSE 2.84e-5), against
-- Lagrange's polynomial on 6 uniform nodes (yellow) and on 6 Chebyshev nodes (cyan).
local runge = function(x) return 1 / (1 + 25 * x * x) end
window(-1.15, -0.45, 1.15, 1.275)
line(P(-1.1, 0), P(1.1, 0), 8) line(P(0, -0.4), P(0, 1.2), 8)
local function graph(f, color)
  curve(function(x) return P(x, f(x)) end, -1, 1):draw{color = color}
end
local function lagrange(xs)
  return function(x)
    local s = 0
    for j, xj in ipairs(xs) do
      local w = 1
      for m, xm in ipairs(xs) do if m ~= j then w = w * (x - xm) / (xj - xm) end end
      s = s + w * runge(xj)
    end
    return s
  end
end
graph(lagrange{-1, -0.6, -0.2, 0.2, 0.6, 1}, 14)
graph(lagrange(approx.chebyshev(6)), 11)
graph(runge, 12)
local nodes, mse = approx.optimal_nodes(runge, -1, 1, 6)
approx.curve(runge, nodes):draw{color = 10}
for _, x in ipairs(nodes) do circle(P(x, runge(x)), 0.012, 15) end
label(string.format("optimal nodes: +-%.6f, +-%.6f   MSE = %.6g", nodes[5], nodes[4], mse),
      P(-1.1, -0.3), "e", 10)
label(string.format("uniform %.4f   Chebyshev %.4f (Lagrange, 101 x)",
      approx.lagrange_mse(runge, {-1, -0.6, -0.2, 0.2, 0.6, 1}, -1, 1),
      approx.lagrange_mse(runge, approx.chebyshev(6), -1, 1)), P(-1.1, -0.38), "e", 7)
