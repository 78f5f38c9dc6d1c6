-- Example 24 — Curvilinear quadrilateral bounded by graphs erected on its sides
-- On each side A_i A_(i+1) of the quadrilateral A0 A1 A2 A3 (indices mod 4) the graph of its own
-- function f_i is built as in example 23: X(t) = A_i + t e + f_i(a + t (b - a)) perp(e),
-- e = A_(i+1) - A_i, perp(x, y) = (y, -x) (graph_on).  The quadrilateral runs clockwise on the
-- screen, so positive values point outwards.  White: the quadrilateral A0(100, 100),
-- A1(300, 70), A2(250, 400), A3(150, 350).  Yellow, thick: the four curved sides, which make a
-- curvilinear quadrilateral (the boundary of example 25's coordinate system):
--   side 0: (t^3 - t)/3 on [-1, 1], an S-wave, outward first;
--   side 1: -(t + 1) t (t - 1)(t - 2)/10 on [-1, 2], three lobes;
--   side 2: t (t - 1)/4 on [0, 1], a shallow inward bulge;
--   side 3: (t^2 - 1)/10 on [-1, 1], an inward bulge.
-- 10000 points per side, as QBasic's step .0001 runs.

screen(12)
local A = {P(100, 100), P(300, 70), P(250, 400), P(150, 350)}
local sides = {
  {f = function(t) return (t^3 - t)/3 end,                     a = -1, b = 1},
  {f = function(t) return -(t + 1)*t*(t - 1)*(t - 2)/10 end,   a = -1, b = 2},
  {f = function(t) return t*(t - 1)/4 end,                     a = 0,  b = 1},
  {f = function(t) return (t^2 - 1)/10 end,                    a = -1, b = 1},
}

for i = 1, 4 do line(A[i], A[i % 4 + 1]) end
for i, s in ipairs(sides) do
  plot(graph_on(A[i], A[i % 4 + 1], s.f, s.a, s.b),
       {t = {0, 1, .0001}, qb = true, brush = "dot", color = 14})
end
