-- Korotky (2015) Fig. 3c: a shell on a rectangular base, from the triangle AOD to a semicircle
-- The inlet section AOD is the degenerate hyperbola: its middle point on the guide l is O, the
-- meet of its end tangents AO and DO, so T = W and the weight is infinite (korotky.conic_arc
-- gives the line pair A O D as the limit of the arcs).  The outlet e over BC is a semicircle.
-- In each plane x = const the generator passes through the points of the base sides AB, DC
-- and of l, and touches the hyperbolic paraboloids (plane of parallelism yz) along AB and
-- DC: bilinear patches between the side and the line from O to B1 (or C1) above B (or C);
-- moving B1 and C1 up or down changes the fullness.  Axonometry, equal units; the rulings of
-- the paraboloids thin, hidden by the shell where it lies in front.
local A, B, C, D = P(0, -1, 0), P(4, -1, 0), P(4, 1, 0), P(0, 1, 0)
local O, B1, C1 = P(0, 0, 1.6), P(4, -1, 1.3), P(4, 1, 1.3)
local hAB = surface.bilinear(A, B, O, B1)      -- its u-lines are its rulings, at x = 4u
local hDC = surface.bilinear(D, C, O, C1)
local l = bezier{O, P(2, 0, 1.25), P(4, 0, 1)}
local shell = korotky.conic_sweep{U = bezier{A, B}, V = bezier{D, C}, T = l,
                                  P = hAB:iso("v", 1), Q = hDC:iso("v", 1)}
local inlet, e = shell:iso("u", 0), shell:iso("u", 1)

camera(map.translate(V(330, 290)) * map.scale({80, -80}) *
       map.view{azimuth = -130, elevation = 25} * map.translate(V(-2, 0, -.6)), {hidden = "dashed"})
shell:wireframe{nu = 9, nv = 0, color = 11}
for k = 0, 4 do
  hAB:iso("u", k / 4):draw{color = 8}
  hDC:iso("u", k / 4):draw{color = 8}
end
hAB:iso("v", 1):draw{color = 13}; hDC:iso("v", 1):draw{color = 13}
line(A, B, 15); line(B, C, 15); line(C, D, 15); line(D, A, 15)
inlet:draw{color = 14}; e:draw{color = 14}
l:draw{color = 12}
label("A", A); label("B", B); label("C", C); label("D", D); label("O", O)
label("$B_1$", B1); label("$C_1$", C1)
label("e", e(.3)); label("l", l(.5))
camera(nil)
label("AOD: T = W, weight infinite;  contact surfaces: hyperbolic paraboloids", P(20, 460), "e", 7)
