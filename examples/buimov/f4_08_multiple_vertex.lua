-- Raising the order with a multiple vertex: 4 vertices of order 4, 5 of order 5, 6 of order 6
-- Buimov §4.4, Fig. 4.8: the book's vertex/order pairs 4/4 (the Bezier curve of P0..P3), 5/5 (P1
-- doubled, order 5) and 6/6 (P1 tripled, order 6): each copy of the vertex counts in n and raises
-- the order with it, and the curve is pulled towards P1 while its end slopes stay those of the
-- polygon. The knots are the book's algorithm's: [0 0 0 0 1 1 1 1], [0 0 0 0 0 1 1 1 1 1] and
-- [0 0 0 0 0 0 1 1 1 1 1 1] (buimov.knots).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local base = {P(0, 0), P(1, 3), P(3.5, 3.2), P(4.5, 0.5)}
fit{around = {P(-0.4, -0.4), P(4.9, 3.7)}, pad = 0.37, band = 20}
for i = 1, 3 do line(base[i], base[i + 1], 8) end
local colours = {14, 10, 11}
for copies = 1, 3 do
  local pts = {base[1]}
  for _ = 1, copies do pts[#pts + 1] = base[2] end
  pts[#pts + 1] = base[3]; pts[#pts + 1] = base[4]
  local c = buimov.bspline(pts, #pts)
  c:draw{color = colours[copies]}
  label(#pts .. "/" .. #pts, c(0.35), nil, colours[copies])
end
dot(base[1], "$P_0$", 15)
dot(base[2], "$P_1$ (1, 2, 3 times)", 15)
dot(base[3], "$P_2$", 15)
dot(base[4], "$P_3$", 15)
caption("vertices/order 4/4, 5/5, 6/6:  the multiple vertex P1 pulls the curve", "bottom", 7)
