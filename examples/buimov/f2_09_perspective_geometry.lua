-- The geometry of the one-point perspective: the centre at [0 0 -k], similar triangles
-- Buimov §2.8.5, Fig. 2.9: seen along x, the picture plane z = 0 is the vertical line through O;
-- the point P = (y, z) = (2, 3) seen from the centre C = (0, -k), k = 2, meets it at
-- y* = y k/(z + k) = y/(rz + 1) = 0.8 with r = 1/k (likewise x*). As k grows the projectors turn
-- parallel and the view becomes axonometric. Equal units on both axes: z to the right, y up.

local k, y, z = 2, 2, 3
local ys = y / (z / k + 1)
local s = 90                                              -- pixels per unit
window(-k - 0.6, -1.0, -k - 0.6 + 640 / s, -1.0 + 480 / s)
arrow(P(-k - 0.5, 0), P(4.2, 0), "end", 8); label("$z$", P(4.2, 0), "s", 8)
arrow(P(0, -0.8), P(0, 3.6), "end", 8); label("$y$", P(0, 3.6), "w", 8)
line(P(-k, 0), P(z, y), 12)                               -- the projector from C through P
pen{dash = {4, 3}}; line(P(z, 0), P(z, y), 8); pen()
for _, m in ipairs{{P(-k, 0), "$C$", 12}, {P(z, y), "$P$", 15}, {P(0, ys), "$P^*$", 14}, {P(0, 0),
  "$O$", 7}, {P(z, 0), "$z$", 8}} do
  mark(m[1], "dot", 4, m[3]); label(m[2], m[1], nil, m[3])
end
dimension(P(-k, 0), P(0, 0), 22, "k", 7)
dimension(P(0, 0), P(0, ys), -18, "$y^*$", 14)
dimension(P(z, 0), P(z, y), -18, "$y$", 15)
caption(string.format("y*/k = y/(z + k):  y* = %g for y = 2, z = 3, k = 2", ys), "bottom", 7)
