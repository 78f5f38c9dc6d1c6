-- Example 6 — Closed curves through the vertices of regular n-gons, tangent to the circumcircles
-- Twelve nested green closed curves (colour 2, thick dots) around C = (320, 240). Each passes
-- through the vertices of a regular decagon inscribed in a circle of radius rc = 50, 60, ..., 160
-- and is tangent to that circle there: every side is Example 5's two-point curve (§H block 7,
-- `spline2` with the cubic smoothstep g = -2t^3 + 3t^2) from vertex i, leaving along the circle's
-- tangent (angle i du + pi/2), to vertex i + 1, arriving along its tangent. The quadrilateral
-- side r grows with the ring (5, 45, ..., 445), so the inner ring is almost a decagon and the
-- outer ones bulge between the vertices and overshoot into loops (a spider web).
-- Screen angles (y down). The listing runs i = 0 .. n, drawing the first side twice; this
-- script draws the n sides once (the same pixels). 101 dots per side, as QBasic.

screen(12)
local C, n = P(320, 240), 10
local du = 2*math.pi/n
local function e(u) return V(math.cos(u), math.sin(u)) end   -- screen angle u (y down)

local r = 5
for rc = 50, 160, 10 do
  for i = 0, n - 1 do
    local u0, u1 = i*du, (i + 1)*du                         -- the two vertices' angles
    local A, B = C + e(u0)*rc, C + e(u1)*rc
    spline2(A, e(u0 + math.pi/2)*r, B, e(u1 + math.pi/2)*r)  -- tangent to the circle at both
      :draw{t = {0, 1, .01}, qb = true, brush = "dot", color = 2}
  end
  r = r + 40
end
