-- Example 23 — Graph of a function erected on an arbitrary segment
-- The segment AB is taken as a piece of an x axis and the graph of f(t) = t^3 - t, t in [-1, 1],
-- is drawn on it.  The frame is affine: origin A, first axis e = B - A, second axis e turned by
-- 90 degrees, perp(x, y) = (y, -x) (to the left of A -> B on the y-down screen, "up" here):
-- X(t1) = A + t1 e + f(a + t1 (b - a)) perp(e)  (graph_on).
-- White: the square of the frame on AB, reaching up and to the left.  Yellow, thick: the graph,
-- from A to B, bulging into the square over its first half and below the segment over the
-- second.  (The prose writes the second axis with the far corner x2; the listing, and this
-- script, use the adjacent corner A + perp(e).)  10000 points, as QBasic's step .0001 runs.

screen(12)
local A, B = P(320, 240), P(480, 200)
local e = B - A
local n = V(e.y, -e.x)                               -- the second axis of the frame
line(A, B); line(B, B + n); line(B + n, A + n); line(A + n, A)

local f = function(t) return t^3 - t end
plot(graph_on(A, B, f, -1, 1), {t = {0, 1, .0001}, qb = true, brush = "dot", color = 14})
