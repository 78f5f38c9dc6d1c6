-- Konopatsky §5.3 (Fig. 5.5): the ellipse y = sqrt(b^2 - b^2 x^2/a^2), a = 4, b = 3, by a cubic through optimal nodes
-- The upper half ellipse (white) and the cubic curve (4.16) through four nodes (red) with the
-- ends -a, a fixed and the inner two optimised with m = 10 samples (the count that reproduces
-- the book's MSE 0.00014577 at +-1.877016); the curve in green, its x(t), y(t) at the top as the
-- book prints them (x = -14.67944t^3 + 22.01916t^2 + 0.66028t - 4, y = -11.921353t^2 + 11.921353t;
-- our nodes are symmetric to 1e-8, so y keeps a t^3 term of that size).
local f = function(x) return math.sqrt(math.max(9 - 9 * x * x / 16, 0)) end
window(-4.6, -0.9, 4.6, 4.0)
line(P(-4.5, 0), P(4.5, 0), 8) line(P(0, -0.2), P(0, 3.6), 8)
curve(function(x) return P(x, f(x)) end, -4, 4):draw{color = 15}
local nodes, mse = approx.optimal_nodes(f, -4, 4, 4, 10)
local c = approx.curve(f, nodes)
c:draw{color = 10}
local ex, ey = konopatsky.equation(c)
text{x = 8, y = 14, text = ex, units = "device", color = 10}
text{x = 8, y = 32, text = ey, units = "device", color = 10}
for _, x in ipairs(nodes) do circle(P(x, f(x)), 0.06, 12) end
label(string.format("nodes %.6f, %.6f   MSE %.6g (book 0.00014577 at +-1.877016)", nodes[2], nodes[3], mse),
      P(-4.5, -0.5), "e", 7)
