-- The Bernstein basis of degree 3 and the book's table at t = 0, 1/3, 2/3, 1
-- Buimov §4.3: J_3,i(t) = C(3, i) t^i (1 - t)^(3 - i); the table J30..J33 = 1, 0, 0, 0 at t = 0;
-- 8/27, 4/9, 2/9, 1/27 at t = 1/3; 1/27, 2/9, 4/9, 8/27 at t = 2/3; 0, 0, 0, 1 at t = 1, so
-- P(1/3) = 8/27 P0 + 4/9 P1 + 2/9 P2 + 1/27 P3. A graph: t and J on equal scales.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
fit{around = {P(-0.12, -0.12), P(1.15, 1.08)}, pad = 0.11, band = 20}
axes{x = {-0.12, 1.15}, y = {-0.12, 1.08}, ticks = 0, labels = false, color = 8}
label("$x$", P(1.15, 0), "s", 8); label("$y$", P(0, 1.08), "w", 8)
local colours = {12, 10, 11, 14}
for i = 0, 3 do
  graph(function(t) return buimov.bernstein(3, i, t) end, 0, 1, {color = colours[i + 1]})
end
for _, t in ipairs{1 / 3, 2 / 3} do
  pen{dash = {4, 3}}; line(P(t, 0), P(t, 1), 8); pen()
  for i = 0, 3 do mark(P(t, buimov.bernstein(3, i, t)), "dot", 4, colours[i + 1]) end
end
local names = {"$J_{3,0}$", "$J_{3,1}$", "$J_{3,2}$", "$J_{3,3}$"}
for i = 0, 3 do label(names[i + 1], P(0.04 + 0.3 * i, buimov.bernstein(3, i, 0.04 + 0.3
    * i)), nil, colours[i + 1]) end
label("$t = 1/3$", P(1 / 3, 1), nil, 8); label("$t = 2/3$", P(2 / 3, 1), nil, 8)
label("8/27", P(1 / 3, 8 / 27), nil, 12); label("4/9", P(1 / 3, 4 / 9), nil, 10)
caption("t = 1/3: 8/27, 4/9, 2/9, 1/27;   t = 2/3: 1/27, 2/9, 4/9, 8/27", "bottom", 7)
