-- Korotky (2015) Fig. 3b: a shell on an elliptic base, swept by a conic turned about AB
-- The base is two half-ellipses e1, e2 in the ground plane meeting at A and B; the ridge l
-- rises from the vertex of e1 over the top to the vertex of e2.  For each point T of l the
-- generator lies in the plane through AB and T: the conic through A, B and T whose tangents
-- at A and B are the lines where that plane cuts the fixed tangent planes pi_A and pi_B of
-- the dome (the contact surfaces degenerate to planes).  pi_A and pi_B hold the x direction
-- (so the ground generators are e1 and e2) and lean inward at 60 degrees: the shell is
-- symmetric about the zx plane and changes from e1 to e2.  The support ellipses, the ridge and
-- the axis AB are strokes of the scene: dashed where the shell hides them.
local A, B = P(0, -2.5, 0), P(0, 2.5, 0)
local g = math.rad(60)
local nA, nB = V(0, -math.sin(g), math.cos(g)), V(0, math.sin(g), math.cos(g))
-- the ridge: a conic arc in the zx plane from (-2, 0, 0) to (3.5, 0, 0) through (0.4, 0, 2.4),
-- vertical at both ends
local l = korotky.conic_arc(P(-2, 0, 0), V(0, 0, 1), P(3.5, 0, 0), V(0, 0, 1), P(.4, 0, 2.4))
local dome = korotky.conic_revolve{A = A, B = B, nA = nA, nB = nB, ridge = l}

camera(map.translate(V(320, 235)) * map.scale({70, -70}) * map.perspective(P(9, -8, 8), P(.6, 0, .6)),
       {hidden = "dashed"})
-- the ground ellipses (the generators at the ends of l) and the axis AB
local e1, e2 = dome:iso("u", 0), dome:iso("u", 1)
dome:wireframe{nu = 12, nv = 12, color = 11, silhouette = true}
e1:draw{color = 14}
e2:draw{color = 14}
l:draw{color = 12}
line(A, B, 8)
label("A", A); label("B", B)
label("$e_1$", e1(.5)); label("$e_2$", e2(.5))
label("l", l(.5))
camera(nil)
label("a conic turned about AB, tangent to fixed planes at A and B", P(20, 460), "e", 7)
