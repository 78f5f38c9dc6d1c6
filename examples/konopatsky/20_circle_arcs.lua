-- Konopatsky §2.1.8.1 (Fig. 2.23): a circular arc by the engineering discriminant, (2.107)
-- The 90-degree arc through A(1,0), K, B(0,1) whose tangents meet at C(1,1) (the digest's
-- data): O the midpoint of the chord c = AB, K on the median CO with
-- k = CK/CO = 1/2 + 2h^2/c^2 = 2 - sqrt 2, h = OK the height of the segment, O1 the centre.
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end

fit{around = {P(-0.3, -0.4), P(1.3, 1.665)}}
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
