-- Korotky (2015) Fig. 3d: a composite shell, G1 along the ridge KSK, a crease along SL
-- The contour: the circular arcs AKD and BKC (the side walls x = -3 and x = 3), the polyline
-- ALB in front and the segment CD behind.  Each profile x = const is two conic arcs with a
-- common horizontal tangent on the ridge KSK: in front from the edge ALB up to the ridge
-- (patch AKSL: from the arc AK at x = -3 to the segment SL at x = 0, whose T lies on its
-- chord: weight 0), behind from the ridge down to the edge DOC (patch ODKS: from the arc DK
-- to the elliptic arc OS of the throat line OSL).  Both arcs leave the edges vertically.
-- The patches BKSL and OCKS are the mirror images in the yz plane; all four are one surface
-- here, the guides being polylines through their mirrored vertices (u = 1/2 at x = 0).
local r2 = math.sqrt(.5)
local mirror = map.reflect(P(0, 0, 0), V(1, 0, 0))
local function poly(a, m) return bspline({a, m, mirror(a)}, 1) end   -- a, m, a mirrored
local A, L, D, O = P(-3, 6, 0), P(0, 8, 0), P(-3, 0, 0), P(0, 0, 0)
local K, S = P(-3, 3, 3), P(0, 3, 3.5)
local shell = korotky.ridge_shell{
  U = poly(A, L), R = poly(K, S), V = poly(D, O),
  T1 = poly(P(-3, 3 + 3 * r2, 3 * r2), mid(S, L)),          -- the guide d in front
  T2 = poly(P(-3, 3 - 3 * r2, 3 * r2), P(0, 3 - 3 * r2, 3.5 * r2)),
  P = V(0, 0, 1), H = V(0, 1, 0), Q = V(0, 0, 1)}

camera(map.translate(V(320, 240)) * map.scale({44, -44}) * map.perspective(P(-5, 18, 12), P(0, 3.5, 1)))
shell:wireframe{nu = 16, nv = 12, color = 11, hidden = "dashed"}
-- the ridge KSK, the crease SL of the throat line, the front edge; the rest is behind
path({K, S, mirror(K)}, {color = 12})
line(S, L, 13)
path({A, L, mirror(A)}, {color = 14})
label("A", A, nil, 15); label("L", L, nil, 15); label("B", mirror(A), nil, 15)
label("K", K, nil, 12); label("S", S, nil, 12); label("K", mirror(K), nil, 12)
camera(nil)
label("ridge KSK: G1;  SL: a crease (a straight profile)", P(12, 462), "e", 7)
