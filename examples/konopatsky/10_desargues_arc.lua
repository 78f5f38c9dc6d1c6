-- Konopatsky §3.7 (Fig. 3.13): the space contour arc (3.6) of the Desargues configuration
-- The simplex ABCD with A(0,0,0), B(4,0,0), C(1,3,0), D(4,3,2) (chosen; the book prints none),
-- red; the arc (3.6) (blue) from A with tangent AC to D with tangent BD, through the centroid G,
-- in isometric projection.
local A, B, C, D = P(0, 0, 0), P(4, 0, 0), P(1, 3, 0), P(4, 3, 2)
camera(map.isometric())
fit{around = {P(-0.5, -0.5), P(4.8, 3.8)}}
for _, e in ipairs{{A, B}, {A, C}, {A, D}, {B, C}, {B, D}, {C, D}} do line(e[1], e[2], 12) end
local arc = oneratio.desargues(A, B, C, D)
arc:draw{color = 9}
local G = (A + B + C + D) / 4
for _, p in ipairs{A, B, C, D, G} do mark(p, "dot", 5, 15) end
label("$A$", A) label("$B$", B) label("$C$", C) label("$D$", D) label("$G$", G)
camera()
