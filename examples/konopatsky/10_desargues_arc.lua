-- Konopatsky §3.7 (Figs. 3.13, 3.14): the contour arc of the Desargues configuration
-- Left: the space arc (3.6) in the simplex ABCD (red), from A with tangent AC to D with tangent
-- BD, through the centroid G, in isometric projection.  Right: the planar case C = B (Fig. 3.14).
local A, B, C, D = P(0, 0, 0), P(4, 0, 0), P(1, 3, 0), P(4, 3, 2)
view(10, 40, 315, 440)
camera(map.isometric())
window(-2.5, -2, 6.5, 8)
for _, e in ipairs{{A, B}, {A, C}, {A, D}, {B, C}, {B, D}, {C, D}} do line(e[1], e[2], 12) end
local arc = oneratio.desargues(A, B, C, D)
arc:draw{color = 9}
local G = (A + B + C + D) / 4
circle(G, 0.06, 14)
for name, p in pairs{A = A, B = B, C = C, D = D, G = G} do label(name, p, nil, 15) end
camera()
view(325, 40, 630, 440)
window(-1, -1.5, 11, 8)
local a, b, d = P(0, 0), P(5, 7), P(10, 0)
path({a, b, d}, {color = 12})
oneratio.desargues(a, b, b, d):draw{color = 9}
label("$A$", a, nil, 15) label("$B = C$", b, "n", 15) label("$D$", d, nil, 15)
