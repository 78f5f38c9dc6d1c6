-- Konopatsky §4.11 (Fig. 4.9): the rational (2,2) curve through five points
-- The book's nodes (1;2), (2;1), (4;1), (6;3), (7;6) at t = 0, 1/4, 1/2, 3/4, 1 and its printed
-- result x = (16t^2 + 2t + 3)/(4t^2 - 4t + 3), y = (136t^2 - 112t + 30)/(16t^2 - 22t + 15),
-- with the polynomial interpolation curve of order 4 for comparison (yellow, dashed).
local nodes = {P(1, 2), P(2, 1), P(4, 1), P(6, 3), P(7, 6)}
window(-0.5, -0.5, 8.5, 6.25)
line(P(0, 0), P(8.2, 0), 8) line(P(0, 0), P(0, 6.2), 8)
pen{dash = {4, 3}}
interp.lagrange(nodes):draw{color = 14}
pen()
local r, co = interp.rational22(nodes)
r:draw{color = 10}
for i, p in ipairs(nodes) do circle(p, 0.06, 15) label("$A_" .. i .. "$", p, nil, 15) end
-- the book prints the fit with the constant of the denominator 3 (x) and 15 (y)
label(string.format("x = (%.4g t^2 %+.4g t %+.4g)/(%.4g t^2 %+.4g t %+.4g)", 3 * co[1][1], 3 * co[1][2],
      3 * co[1][3], 3 * co[1][4], 3 * co[1][5], 3), P(0.3, 5.8), "e", 10)
label(string.format("y = (%.4g t^2 %+.4g t %+.4g)/(%.4g t^2 %+.4g t %+.4g)", 15 * co[2][1], 15 * co[2][2],
      15 * co[2][3], 15 * co[2][4], 15 * co[2][5], 15), P(0.3, 5.4), "e", 10)
