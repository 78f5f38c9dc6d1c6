-- Konopatsky §2.1.8 (Figs. 2.23, 2.24): a circular arc by the engineering discriminant, and the construction of (2.115)
-- Left (2.107): the 90-degree arc through A(1,0), K, B(0,1) whose tangents meet at C(1,1)
-- (the digest's data): O the midpoint of the chord c = AB, K on the median CO with
-- k = CK/CO = 1/2 + 2h^2/c^2 = 2 - sqrt 2, h = OK the height of the segment, O1 the centre.
-- Right (2.115): A, C and the side B, the angle phi = MCA at C and the angle delta = AMC at M
-- (the book's Fig. 2.25 data A(0;0), B(0,5;1), C(1;0), delta = pi/3; M at phi = 1.0).
local function mark(p, name, _, c, r) circle(p, r or 0.02, c or 15) label(name, p, nil, c or 15) end

view(5, 40, 315, 440)
window(-0.3, -0.4, 1.3, 1.665)
local A, B, C = P(1, 0), P(0, 1), P(1, 1)
local O, O1 = mid(A, B), P(0, 0)
path({A, C, B}, {color = 8}) line(A, B, 8)
local k = conic.circle_k(A, B, C)
local arc = conic.circle{A = A, B = B, C = C}
arc:draw{color = 10}
local K = arc(0.5)
pen{dash = {4, 3}} line(C, O1, 7) line(O1, A, 8) line(O1, B, 8) pen()
mark(A, "$A$", "se") mark(B, "$B$", "nw") mark(C, "$C$", "ne") mark(O, "$O$", "sw") mark(O1, "$O_1$", "sw")
mark(K, "$K$", "ne", 14)
label(string.format("k = 1/2 + 2h^2/c^2 = %.6f", k), P(-0.3, -0.2), "e", 7)
label(string.format("h = %.4f  c = %.4f", dist(O, K), dist(A, B)), P(-0.3, -0.28), "e", 7)

view(325, 40, 635, 440)
window(-0.15, -0.45, 1.15, 1.23)
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
