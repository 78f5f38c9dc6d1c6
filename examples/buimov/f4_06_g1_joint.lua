-- Two Bezier curves joined with G1 continuity
-- Buimov §4.3, Fig. 4.6 (printed as a second "Fig. 4.4"): the curve P of degree n and Q of
-- degree m join smoothly when Pn = Q0 and n (Pn - Pn-1) = g m (Q1 - Q0) for a g > 0: P(n-1),
-- Pn = Q0 and Q1 on one line (the book prints "g m (g - Q0)"). P = (0, 0), (1, 2), (3, 3),
-- (4, 2) and a quadratic Q with g = 1.5: buimov.g1_next gives Q0 = (4, 2), Q1 = (5, 1), and
-- buimov.joint reads the joint back as G1 with g = 1.5.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local Pp = {P(0, 0), P(1, 2), P(3, 3), P(4, 2)}
local Pc = bezier(Pp)
local q0, q1 = buimov.g1_next(Pc, 2, 1.5)
local Qp = {q0, q1, P(7, 0)}
local Q = bezier(Qp)
local kind, g = buimov.joint(Pc, Q)
fit{around = {P(-0.4, -0.6), P(7.6, 3.6)}, pad = 0.41, band = 20}
for i = 1, 3 do line(Pp[i], Pp[i + 1], 8) end
line(Qp[1], Qp[2], 8); line(Qp[2], Qp[3], 8)
pen{dash = {4, 3}}; line(Pp[3], Qp[2], 12); pen()
Pc:draw{color = 14}; Q:draw{color = 10}
for i, p in ipairs{Pp[1], Pp[2], Pp[3]} do dot(p, "$P_" .. (i - 1) .. "$", 15) end
dot(q0, "$P_3 = Q_0$", 15); dot(q1, "$Q_1$", 15); dot(Qp[3], "$Q_2$", 15)
caption(string.format("n = 3, m = 2, g = 1.5:  Q1 = (%g, %g);  joint: %s, g = %g",
  q1.x, q1.y, kind, g), "bottom", 7)
