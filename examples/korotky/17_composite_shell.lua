-- Korotky (2015) Fig. 3d: a composite shell, G1 along the ridge KSK, a crease along SL
-- The contour: the circular arcs AKD and BKC (the side walls x = -3 and x = 3), the polyline
-- ALB in front and the segment CD behind.  Each profile x = const is two conic arcs with a
-- common horizontal tangent on the ridge KSK: in front from the edge ALB up to the ridge
-- (patch AKSL: from the arc AK at x = -3 to the segment SL at x = 0, whose T lies on its
-- chord: weight 0), behind from the ridge down to the edge DOC (patch ODKS: from the arc DK
-- to the elliptic arc OS of the throat line OSL).  Both arcs leave the edges vertically.
-- The patches BKSL and OCKS are the mirror images in the yz plane; all four are one surface
-- here, the guides being polylines through their mirrored vertices (u = 1/2 at x = 0).
-- Drawn: the throat line OSL (the elliptic arc e = SO, G1 at S with the segment SL), the
-- guide d (the middle points of the front arcs), the segment CD through O.
local r2 = math.sqrt(.5)
local mirror = map.reflect(P(0, 0, 0), V(1, 0, 0))
local function poly(a, m) return bspline({a, m, mirror(a)}, 1) end   -- a, m, a mirrored
local A, L, D, O = P(-3, 6, 0), P(0, 8, 0), P(-3, 0, 0), P(0, 0, 0)
local K, S = P(-3, 3, 3), P(0, 3, 3.5)
local d = poly(P(-3, 3 + 3 * r2, 3 * r2), mid(S, L))
local shell = korotky.ridge_shell{
  U = poly(A, L), R = poly(K, S), V = poly(D, O),
  T1 = d,                                                   -- the guide d in front
  T2 = poly(P(-3, 3 - 3 * r2, 3 * r2), P(0, 3 - 3 * r2, 3.5 * r2)),
  P = V(0, 0, 1), H = V(0, 1, 0), Q = V(0, 0, 1)}

local throat = shell:iso("u", .5)       -- x = 0: the segment LS, then the elliptic arc SO

-- two views: from the front (A, L, B) and from behind (D, O, C)
for k, eye in ipairs{P(-5, 18, 12), P(-6, -12, 12)} do
  camera(map.translate(V(k == 1 and 165 or 480, 230)) * map.scale({30, -30}) *
         map.perspective(eye, P(0, 3.5, 1)), {hidden = "dashed"})
  shell:wireframe{nu = 12, nv = 8, color = 11}
  -- the ridge KSK, the throat line OSL (its crease SL), the guide d, the front polyline ALB
  -- and the back segment DOC: strokes of the scene, dashed where the shell hides them
  line(K, S, 12); line(S, mirror(K), 12)
  throat:draw{color = 13}
  d:draw{color = 10}
  line(A, L, 14); line(L, mirror(A), 14)
  line(D, mirror(D), 14)
  label("A", A); label("L", L); label("B", mirror(A))
  label("K", K); label("S", S); label("K", mirror(K))
  label("O", O); label("D", D); label("C", mirror(D))
  label("d", d(.25)); label("e", throat(1.5))
  camera(nil)
end
label("ridge KSK: G1;  SL: a crease (a straight profile)", P(12, 462), "e", 7)
