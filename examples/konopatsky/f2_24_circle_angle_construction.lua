-- Konopatsky §2.1.8.2 (Fig. 2.24): the construction of the circle by an angular parameter, (2.115)
-- A, C and the side B, the angle phi = MCA at C and the angle delta = AMC at M (the book's
-- Fig. 2.25 data A(0;0), B(0,5;1), C(1;0), delta = pi/3; M at phi = 1.0).
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end

fit{around = {P(-0.15, -0.45), P(1.15, 1.23)}}
local A2, B2, C2, delta = P(0, 0), P(0.5, 1), P(1, 0), math.pi / 3
path({A2, B2, C2, A2}, {color = 8})
local circ = conic.circle{A = A2, B = B2, C = C2, delta = delta}
circ:draw{color = 10}
local phi = 1.0
local M = circ(phi)
line(C2, M, 11) line(A2, M, 11)
-- the angles as small arcs: phi at C from CA toward CM, delta at M from MC to MA
local function arcmark(at, from, to, r, c)
  local u, v = unit(from - at), unit(to - at)
  local a0, a1 = math.atan(u.y, u.x), math.atan(v.y, v.x)
  if a1 - a0 > math.pi then a1 = a1 - 2 * math.pi elseif a0 - a1 > math.pi then a1 = a1 + 2 * math.pi end
  local pts = {}
  for i = 0, 16 do local a = a0 + (a1 - a0) * i / 16 pts[#pts + 1] = at + V(math.cos(a), math.sin(a)) * r end
  path(pts, {color = c})
  return at + unit(u + v) * (r * 1.5)
end
label("$\\varphi$", arcmark(C2, A2, M, 0.12, 14), "c", 14)
label("$\\delta$", arcmark(M, C2, A2, 0.12, 14), "c", 14)
mark(A2, "$A$", "sw") mark(B2, "$B$", "n") mark(C2, "$C$", "se") mark(M, "$M$", "n", 14)
label("angle AMC = delta = pi/3", P(-0.12, -0.38), "e", 7)
