-- Konopatsky §5.2 (Fig. 5.2): Runge's function by Lagrange's polynomial on six uniform nodes
-- f(x) = 1/(1 + 25x^2) on [-1, 1] (red) against the degree-5 Lagrange polynomial through it at
-- six uniform nodes, the comparison of §5.2 (its mean square error over 101 samples in the caption,
-- approx.lagrange_mse).  A graph: x and y have different scales.
local runge = function(x) return 1 / (1 + 25 * x * x) end
local xs = {-1, -0.6, -0.2, 0.2, 0.6, 1}
local function lagrange(x)
  local s = 0
  for j, xj in ipairs(xs) do
    local w = 1
    for m, xm in ipairs(xs) do if m ~= j then w = w * (x - xm) / (xj - xm) end end
    s = s + w * runge(xj)
  end
  return s
end
window(-1.15, -0.3, 1.15, 1.2)
line(P(-1.1, 0), P(1.1, 0), 8) line(P(0, -0.2), P(0, 1.15), 8)
curve(function(x) return P(x, runge(x)) end, -1, 1):draw{color = 12}
curve(function(x) return P(x, lagrange(x)) end, -1, 1):draw{color = 14}
for _, x in ipairs(xs) do mark(P(x, runge(x)), "open", 6, 15) end
caption(string.format("six uniform nodes: MSE = %.6f", approx.lagrange_mse(runge, xs, -1, 1)), "bottom", 7)
