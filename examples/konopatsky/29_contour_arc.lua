-- Konopatsky §2.7: the general contour arc (2.161) with two free functions
-- The digest's A1(0,0), A2(4,0), A3(2,4): B1 = A1(1 - u) + A3 u, B2 = A3(1 - v) + A2 v and M on
-- B1B2 with w = u'v/(u'v + v'(1 - u)), so that B1B2 is the tangent.  u = v = t gives the
-- parabola (2.58) (yellow); u = t, v = t^2 (green, the digest's vector) and u = sin(pi t/2),
-- v = t^3 (cyan, chosen); the tangent B1B2 of the green arc at t = 0.5.
local function mark(p, name, _, c) circle(p, 0.04, c or 15) label(name, p, nil, c or 15) end
local A1, A2, A3 = P(0, 0), P(4, 0), P(2, 4)
window(-0.6, -0.9, 4.6, 4.3)
path({A1, A3, A2}, {color = 8})
local id = function(t) return t end
local one = function() return 1 end
conic.contour(A1, A2, A3, id, id, one, one):draw{color = 14}
local sq = function(t) return t * t end
local arc = conic.contour(A1, A2, A3, id, sq, one, function(t) return 2 * t end)
arc:draw{color = 10}
conic.contour(A1, A2, A3, function(t) return math.sin(math.pi * t / 2) end, function(t) return t ^ 3 end,
              function(t) return math.pi / 2 * math.cos(math.pi * t / 2) end, function(t) return 3 * t * t end):draw{color = 11}
local t = 0.5
local B1, B2 = lerp(A1, A3, t), lerp(A3, A2, t * t)
local M = arc(t)
pen{dash = {4, 3}} line(B1, B2, 7) pen()
mark(A1, "$A_1$", "sw") mark(A2, "$A_2$", "se") mark(A3, "$A_3$", "n") mark(B1, "$B_1$", "w", 7) mark(B2, "$B_2$", "e", 7)
mark(M, "$M$", "n", 14)
label("u = v = t", P(-0.5, -0.45), "e", 14)
label("u = t, v = t^2", P(1.2, -0.45), "e", 10)
label("u = sin(pi t/2), v = t^3", P(-0.5, -0.75), "e", 11)
