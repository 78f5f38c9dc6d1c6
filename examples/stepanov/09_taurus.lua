-- Example 9 — Stylised zodiac sign Taurus
-- All green (colour 2, thick dots). The head: two curvilinear pentagons inscribed, as in
-- Example 6, in two concentric ellipses about C = (320, 300) with vertical scale k = .8: every
-- side is the two-point curve of Example 5 (§H block 7, `spline2`, cubic smoothstep) from
-- vertex i to vertex i + 1, leaving and arriving along the circle's tangent direction at the
-- vertex angle (not the ellipse's), with sides k r. The outer pentagon (rc = 140, r = 20) is
-- nearly polygonal, the inner one (rc = 120, r = 50) rounder.
-- The horns: the asymmetric half-spline of Example 8 (n = 3, m = 5, t0 = 1/3, §H block 5) in
-- the degenerate quadrilateral V1 X0 X0 V2, whose middle vertices coincide at the bottom vertex
-- X0 of the inner pentagon: M = V1 + t (X0 - V1), N = X0 + t (V2 - X0), X = M + g(t) (N - M).
-- The second horn runs the other way (V2 to V1), so the two are mirror images and cross on the
-- head. The listing finds X0 as the vertex left over from its pentagon loop; here it is named.
-- Screen angles (y down); loop counts as in QBasic (qb = true).

screen(12)
local C, k = P(320, 300), .8
local du = 2*math.pi/5
local function e(u) return V(math.cos(u), math.sin(u)) end    -- screen angle u (y down)
local function vertex(rc, u) return C + V(rc*math.cos(u), k*rc*math.sin(u)) end

for _, ring in ipairs{{rc = 140, r = 20}, {rc = 120, r = 50}} do
  for i = 0, 4 do
    local u0, u1 = i*du + math.pi/2, (i + 1)*du + math.pi/2    -- vertex 0 points down
    local A, B = vertex(ring.rc, u0), vertex(ring.rc, u1)
    spline2(A, e(u0 + math.pi/2)*(k*ring.r), B, e(u1 + math.pi/2)*(k*ring.r))
      :draw{t = {0, 1, .01}, qb = true, brush = "dot", color = 2}
  end
end

local X0 = vertex(120, math.pi/2)                              -- (320, 396)
local V1 = C + V(250*math.cos(3*math.pi/4), -250*math.sin(3*math.pi/4) - 100)
local V2 = C + V(250*math.cos(math.pi/4), -250*math.sin(math.pi/4) - 100)
local g = smooth.half(3, 5, 1/3)
for _, horn in ipairs{{V1, V2}, {V2, V1}} do
  local A, B = horn[1], horn[2]
  spline2(A, X0 - A, B, B - X0, g):draw{t = {0, 1, .001}, qb = true, brush = "dot", color = 2}
end
