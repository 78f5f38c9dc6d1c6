-- Korotky (2015) Fig. 3a: a shell on an arbitrary base, from a hyperbola g to an ellipse e
-- The base guides MN and KL widen from 4 at the inlet (x = 0) to 6 at the outlet (x = 6).  In
-- each plane x = const the generator passes through the points of MN, KL and of the guide l,
-- and touches the conoids (plane of parallelism yz) whose directrices are the lines MT and
-- LT: T is the meet of the inlet hyperbola's end tangents (its W), M and L stand on the
-- vertical end tangents of the outlet ellipse (where W is at infinity).  So the inlet g is a
-- hyperbola (w = 2.75), the outlet e an ellipse, and the conic changes kind along l (the text
-- names M and L twice; here they are the directrices' points).  Axonometry, equal units;
-- the conoids' rulings at the ends and in the middle are drawn thin.
local X = 6
local function w(x) return 2 + (x / X)^2 end                 -- the base's half width
local MN = curve(function(x) return P(x, -w(x), 0) end, 0, X)
local KL = curve(function(x) return P(x, w(x), 0) end, 0, X)
local T, M, L = P(0, 0, 3), P(X, -w(X), 2), P(X, w(X), 2)
local MT, LT = bezier{T, M}, bezier{T, L}                      -- the conoids' directrices
local l = bezier{P(0, 0, 2.2), P(X / 2, 0, 2.7), P(X, 0, 2.6)}
local shell = korotky.conic_sweep{U = MN, V = KL, T = l, P = MT, Q = LT}
local g, e = shell:iso("u", 0), shell:iso("u", 1)

camera(map.translate(V(300, 270)) * map.scale({48, -48}) *
       map.view{azimuth = -130, elevation = 28} * map.translate(V(-3, 0, -1)), {hidden = "dashed"})
shell:wireframe{nu = 9, nv = 0, color = 11}
MN:draw{color = 15}; KL:draw{color = 15}
g:draw{color = 14}; e:draw{color = 14}
l:draw{color = 12}
MT:draw{color = 13}; LT:draw{color = 13}
for _, u in ipairs{0, .5, 1} do
  line(MN(u * X), MT(u), 8)
  line(KL(u * X), LT(u), 8)
end
line(MN(X), M, 7); line(KL(X), L, 7)      -- the outlet's vertical end tangents
label("T", T); label("M", M); label("L", L)
label("N", MN(0)); label("K", KL(0))
label("g", g(.3)); label("e", e(.7)); label("l", l(.5))
camera(nil)
label("inlet g: a hyperbola;  outlet e: an ellipse", P(20, 460), "e", 7)
