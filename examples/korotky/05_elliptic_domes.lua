-- Korotky (2015) Fig. 4: the elliptic domes, through the camera with hidden lines left out
-- Left (4a): the dome over the rectangle ABCD, 2a0 x 2b0 = 4 x 2, height c0 = 1.5: the two
-- families of semi-ellipses x = const and y = const, vertical tangent planes along the sides;
-- it is an exact rational biquadratic patch (yellow: the near half of the section x = a0).  Right (4b): the dome over the right triangle ABC
-- with legs 1.6, apex D of height 1 over the centroid, z^2 = 27 h^2 l1 l2 l3: the ellipse
-- families parallel to each side (family a parallel to BC, b parallel to AB, and the guide n's
-- family parallel to AC).  Both seen in perspective from the front left, z up.
camera(map.translate(V(165, 250)) * map.scale({62, -62}) * map.perspective(P(-5, -9, 7), P(2, 1, .4)))
local rect = korotky.dome_rect(2, 1, 1.5)
rect:wireframe{nu = 10, nv = 8, color = 11, hidden = "hide"}
local A, B, C, D = P(0, 0, 0), P(4, 0, 0), P(4, 2, 0), P(0, 2, 0)
path({D, A, B}, {color = 7})             -- the near sides of the base (the dome hides the others)
for n, p in pairs{A = A, B = B, C = C, D = D} do label(n, p, nil, 15) end
label("c0", P(2, 1, 1.5), nil, 15)
rect:iso("u", .5):sub(0, .5):draw{color = 14}   -- the section x = a0 up to the top (its near half)

camera(map.translate(V(480, 260)) * map.scale({120, -120}) * map.perspective(P(-2.5, -4.5, 3.5), P(.55, .55, .3)))
local TA, TB, TC = P(0, 0, 0), P(1.6, 0, 0), P(0, 1.6, 0)
-- one parametrisation per vertex: its u-isolines are the sections parallel to the opposite side
korotky.dome_tri(TA, TB, TC, 1):wireframe{nu = 8, nv = 1, color = 10, hidden = "hide"}
korotky.dome_tri(TB, TC, TA, 1):wireframe{nu = 8, nv = 1, color = 13, hidden = "hide"}
korotky.dome_tri(TC, TA, TB, 1):wireframe{nu = 8, nv = 1, color = 11, hidden = "hide"}
local top = P(1.6 / 3, 1.6 / 3, 1)
circle(top, 2, 15)
label("D", top, nil, 15)
label("A", TA, nil, 15)
label("B", TB, nil, 15)
label("C", TC, nil, 15)
camera(nil)
label("4a  dome on a rectangle", P(40, 460), "e", 11)
label("4b  dome on a triangle", P(380, 460), "e", 10)
