-- B-splines with the textbook's knot vectors: order, multiple vertices, local control
-- Buimov §4.4: Fig 4.7, four vertices with k = 2 (the polygon), 3 and 4 (the Bezier curve);
-- Fig 4.8, a double vertex P1 pulls the curve to it (knots [0 0 0 1 1 2 3 3 3] for k = 3, the
-- book's "n = 3" read as k = 3; [0 0 1 1 2 3 4 4] for k = 2, misprinted in the book);
-- Fig 4.9, local control: moving P4 to three places changes the curve only from t = 1 on with
-- k = 4 (knots [0 0 0 0 1 2 3 4 4 4 4]); with the book's k = 5 the start would move a little.
local function polygon(F, pts, colour)
  for i = 1, #pts - 1 do line(F(pts[i]), F(pts[i + 1]), colour) end
  for i, p in ipairs(pts) do circle(F(p), 2, 15) end
end
local function knots_text(q) return "[" .. table.concat(q, " ") .. "]" end

-- Fig 4.7
local F = affine.frame(P(25, 180), V(40, 0), V(0, -40))
local four = {P(0, 0), P(1, 3), P(3, 3.2), P(4, 0.5)}
polygon(F, four, 8)
for _, k in ipairs{{2, 12}, {3, 10}, {4, 14}} do buimov.bspline(four, k[1]):draw{color = k[2], map = F} end
label("Fig 4.7: k = 2, 3, 4", P(105, 20), "c", 7)
label("k=2", P(40, 210), "c", 12); label("3", P(80, 210), "c", 10); label("4 (Bezier)", P(140, 210), "c", 14)
for i, p in ipairs(four) do label("P" .. (i - 1), F(p), i == 4 and "e" or "n", 15) end

-- Fig 4.8: P1 doubled
F = affine.frame(P(215, 180), V(36, 0), V(0, -36))
local five = {P(0, 0), P(1, 3), P(3, 3.2), P(4, 0.5), P(5.5, 2)}
local double = {P(0, 0), P(1, 3), P(1, 3), P(3, 3.2), P(4, 0.5), P(5.5, 2)}
polygon(F, double, 8)
buimov.bspline(five, 3):draw{color = 8, map = F}
buimov.bspline(double, 3):draw{color = 14, map = F}
label("Fig 4.8: P1 double, k = 3", P(315, 20), "c", 7)
label(knots_text(buimov.knots(double, 3)), P(315, 210), "c", 14)
label("P1 = P2", F(double[2]), "n", 15)

-- Fig 4.9: local control
F = affine.frame(P(428, 150), V(20, 0), V(0, -20))
local base = {P(0, 2), P(2, 5), P(5, 4), P(4, 1), nil, P(8, 1), P(10, 4)}
local colours = {14, 10, 11}
for j, p4 in ipairs{P(5, 0), P(6, 2), P(7, 4)} do
  base[5] = p4
  local c = buimov.bspline(base, 4)
  c:draw{color = colours[j], map = F}
  circle(F(p4), 3, colours[j])
  circle(F(c(1)), 2, 12)                       -- the curve is the same up to t = 1
end
base[5] = P(6, 2)
polygon(F, base, 8)
label("Fig 4.9: k = 4", P(530, 20), "c", 7)
label("P4", F(P(6, 2)), "e", 15)
label("t = 1", F(buimov.bspline(base, 4)(1)), "w", 12)
label("P4 in 3 places", P(530, 210), "c", 7)

-- the basis functions of the double-vertex polygon, k = 3 (the Cox-de Boor recursion)
local q = buimov.knots(double, 3)
local G = affine.frame(P(90, 440), V(150, 0), V(0, -140))
line(G(P(0, 0)), G(P(3, 0)), 8); line(G(P(0, 0)), G(P(0, 1)), 8)
local cols = {9, 10, 11, 12, 13, 14}
for i = 0, #double - 1 do
  local pts = {}
  for s = 0, 120 do
    local t = 3 * s / 120
    pts[#pts + 1] = G(P(t, buimov.basis(i, 3, t, q)))
  end
  path(pts, {color = cols[i + 1]})
  label("N" .. i .. ",3", pts[i == 0 and 10 or i == 5 and 110 or 20 + 22 * (i - 1)], "n", cols[i + 1])
end
for t = 0, 3 do label(tostring(t), G(P(t, 0)), "s", 7) end
label("basis N(i, 3) on " .. knots_text(q) .. ": a double knot at t = 1", P(320, 265), "c", 7)
