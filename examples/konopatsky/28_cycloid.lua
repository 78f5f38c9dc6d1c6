-- Konopatsky §2.8 (Fig. 2.34): the scheme of the cycloid as a contour arc
-- The digest's C(0,0), A(0,2), B(pi,0) (|CA| = 2r, |CB| = pi r: a true cycloid).  The scheme
-- (whose caption the conversion lost): P = (A - C)(1 - cos phi)/2 + C on CA, Q = (B - C)(pi - phi
-- + sin phi)/pi + C on CB and M = P + Q - C (parallel translation), at phi = 2 with the rolling
-- circle; the convex arc "(3.11)" for phi in [0, pi] (green), the rest of the arch dashed.
local C, A, B = P(0, 0), P(0, 2), P(math.pi, 0)
local concave, scheme = false, true
fit{around = {P(-math.pi - 0.3, -0.3), P(math.pi + 0.3, 2.3)}, pad = 0.1}
line(P(-math.pi - 0.3, 0), P(math.pi + 0.3, 0), 8) path({A, C}, {color = 8})
local arc = conic.cycloid{C = C, A = A, B = B, concave = concave}
local whole = conic.cycloid{C = C, A = A, B = B, concave = concave, range = {0, 2 * math.pi}}
if false then whole:draw{color = 10} else pen{dash = {4, 3}} whole:draw{color = 7} pen() arc:draw{color = 10} end
for _, p in ipairs{A, B, C} do mark(p, "dot", 5, 15) end
label("$C$", C) label("$A$", A) label("$B$", B)
if scheme then
  local phi = 2
  local Pp = (A - C) * ((1 - math.cos(phi)) / 2) + C
  local s = concave and -1 or 1
  local Q = (B - C) * ((math.pi - phi + s * math.sin(phi)) / math.pi) + C
  local M = Pp + Q - C
  pen{dash = {3, 2}} line(Pp, M, 11) line(Q, M, 11) pen()
  if not concave then circle(P(math.pi - phi, 1), 1, 8) end   -- the rolling circle of radius r = 1
  for _, p in ipairs{Pp, Q} do mark(p, "dot", 5, 11) end
  mark(M, "dot", 6, 14)
  label("$P$", Pp, nil, 11) label("$Q$", Q, nil, 11) label("$M$", M, nil, 14)
end
