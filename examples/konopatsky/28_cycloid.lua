-- Konopatsky §2.8 (Figs. 2.34-2.36): the cycloid as a contour arc, convex and concave
-- The digest's C(0,0), A(0,2), B(pi,0) (|CA| = 2r, |CB| = pi r: a true cycloid).  The scheme
-- (Fig. 2.34, whose caption the conversion lost): P = (A - C)(1 - cos phi)/2 + C on CA,
-- Q = (B - C)(pi - phi + sin phi)/pi + C on CB and M = P + Q - C (parallel translation), shown
-- at phi = 2 with the rolling circle.  Top: the convex arc "(3.11)" for phi in [0, pi] (green)
-- and [0, 2 pi] (dashed, the whole arch; Fig. 2.35); bottom: the concave "(3.12)" (Fig. 2.36),
-- from B with tangent BC to the cusp at A with tangent AC.
local function mark(p, name, _, c) circle(p, 0.06, c or 15) label(name, p, nil, c or 15) end
local C, A, B = P(0, 0), P(0, 2), P(math.pi, 0)
for row, concave in ipairs{false, true} do
  view(10, 10 + (row - 1) * 235, 630, 235 + (row - 1) * 235)
  window(-4.1, -0.6, 4.6, 2.6)
  line(P(-3.8, 0), P(4.2, 0), 8) path({A, C}, {color = 8})
  local arc = conic.cycloid{C = C, A = A, B = B, concave = concave}
  local whole = conic.cycloid{C = C, A = A, B = B, concave = concave, range = {0, 2 * math.pi}}
  pen{dash = {4, 3}} whole:draw{color = 7} pen()
  arc:draw{color = 10}
  local phi = 2
  local Pp = (A - C) * ((1 - math.cos(phi)) / 2) + C
  local s = concave and -1 or 1
  local Q = (B - C) * ((math.pi - phi + s * math.sin(phi)) / math.pi) + C
  local M = Pp + Q - C
  pen{dash = {3, 2}} line(Pp, M, 11) line(Q, M, 11) pen()
  if not concave then                               -- the rolling circle of radius 1
    local O = P(math.pi - phi, 1)
    local pts = {}
    for i = 0, 40 do local a = 2 * math.pi * i / 40 pts[#pts + 1] = O + V(math.cos(a), math.sin(a)) end
    path(pts, {color = 8})
  end
  mark(C, "$C$", "sw") mark(A, "$A$", "nw") mark(B, "$B$", "s") mark(Pp, "$P$", "w", 11) mark(Q, "$Q$", "s", 11)
  mark(M, "$M$", "ne", 14)
  label(concave and "concave (3.12), Fig. 2.36" or "convex (3.11), Figs. 2.34-2.35", P(-4, 2.3), "e", 7)
end
