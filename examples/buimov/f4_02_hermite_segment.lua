-- A cubic segment by its end points and end tangents
-- Buimov §4.2, Fig. 4.2: P(t) = B1 + B2 t + B3 t^2 + B4 t^3 on [0, t2] with P(0) = P1, P(t2) = P2,
-- P'(0) = P'1, P'(t2) = P'2: B1 = P1, B2 = P'1, B3 = 3(P2 - P1)/t2^2 - 2P'1/t2 - P'2/t2,
-- B4 = 2(P1 - P2)/t2^3 + P'1/t2^2 + P'2/t2^2 (the book prints the last two with "-"). Here
-- P1 = (0, 0), P2 = (4, 1), P'1 = (2, 3), P'2 = (3, -2), t2 = 1; the tangents drawn at a third.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local P1, P2, D1, D2 = P(0, 0), P(4, 1), V(2, 3), V(3, -2)
local seg = buimov.hermite(P1, P2, D1, D2)
local B1, B2, B3, B4 = buimov.hermite_coeffs(P1, P2, D1, D2)
fit{around = {P(-0.6, -0.8), P(5.6, 2.4)}, pad = 0.32, band = 20}
axes{x = {-0.6, 5.6}, y = {-0.8, 2.4}, ticks = 0, labels = false, color = 8}
label("$x$", P(5.6, 0), "s", 8); label("$y$", P(0, 2.4), "w", 8)
seg:draw{color = 14}
vector(P1, D1 / 3, 12); vector(P2, D2 / 3, 12)
dot(P1, "$P_1$", 15); dot(P2, "$P_2$", 15)
label("$P'_1$", P1 + D1 / 3, nil, 12); label("$P'_2$", P2 + D2 / 3, nil, 12)
caption(string.format("B3 = (%g, %g), B4 = (%g, %g)", B3.x, B3.y, B4.x, B4.y), "bottom", 7)
