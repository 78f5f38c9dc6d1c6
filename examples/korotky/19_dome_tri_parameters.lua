-- The parameters (u, v) of korotky.dome_tri, the triangular dome of Korotky (2015)
-- korotky.dome_tri(A, B, C, h) runs over (u, v) in [0, 1]^2; its plan point is
-- A + (B - A) u(1 - v) + (C - A) uv, so over A = (0, 0), B = (1, 0), C = (0, 1) it is
-- x = u(1 - v), y = uv.  Left, the plan: u = const (cyan) are the lines parallel to BC
-- (u = 0 is the corner A, u = 1 the side BC), v = const (yellow) the rays from A (v = 0 the
-- side AB, v = 1 the side AC).  Right: the same isolines on the dome of height 1 over the
-- centroid, in perspective, hidden lines left out: the u-lines are its ellipses parallel to BC.
local A, B, C = P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)
local dome = korotky.dome_tri(A, B, C, 1)
local function plan(u, v) local m = dome(u, v); return P(m.x, m.y) end

-- the plan, equal units
view(0, 0, 319, 419)
window(-.2, -.35, 1.2, 1.49)
for k = 1, 4 do
  local u = k / 5
  line(plan(u, 0), plan(u, 1), 11)
  local v = k / 5
  line(plan(0, v), plan(1, v), 14)
end
local a, b, c = P(0, 0), P(1, 0), P(0, 1)
line(a, b, 15); line(b, c, 15); line(c, a, 15)
label("A", a); label("B", b); label("C", c)
for k = 1, 4 do label(string.format("%.1f", k / 5), plan(k / 5, 0), "s", 11) end
for k = 1, 4 do label(string.format("%.1f", k / 5), plan(1, k / 5), "ne", 14) end
label("u", P(.5, -.2), "c", 11); label("v", P(.62, .62), "ne", 14)
local M = plan(.6, .3)
circle(M, .015, 15)
label("M", M)
view()
window()

-- the dome
camera(map.translate(V(480, 250)) * map.scale({190, -190}) *
       map.perspective(P(-2.2, -3.5, 3), P(.35, .35, .3)), {hidden = "hide"})
dome:wireframe{nu = 5, nv = 0, color = 11}
for k = 1, 4 do dome:iso("v", k / 5):draw{color = 14} end
line(A, B, 15); line(B, C, 15); line(C, A, 15)
label("A", A); label("B", B); label("C", C)
camera(nil)
label("x = u(1 - v),  y = uv", P(20, 430), "e", 15)
label("M: u = 0.6, v = 0.3, (0.42, 0.18)", P(20, 455), "e", 7)
label("$z^2 = 27 h^2 \\lambda_1 \\lambda_2 \\lambda_3$", P(340, 440), "e", 7)
