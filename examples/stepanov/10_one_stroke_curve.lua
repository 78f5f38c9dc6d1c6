-- Example 10 — "One-stroke" curve through ordered nodes
-- Four nodes (white circles of radius 5) and a white curve (one pixel per sample) through them
-- in one stroke. Per node: the incoming tangent angle (in turns; counter-clockwise on screen,
-- the article's w = y - r sin u), the kink (outgoing = incoming + kink; all 0 here), the
-- incoming and outgoing side lengths rin, rout, and the half-spline (n, m, t0) of the piece
-- leaving it. Piece i -> i+1 is the quadrilateral spline of Example 5 (§H blocks 7 and 8,
-- `stroke`): P = N_i + rout_i e(uout_i), Q = N_(i+1) - rin_(i+1) e(uin_(i+1)),
-- M = N_i + t (P - N_i), N = Q + t (N_(i+1) - Q), X = M + g(t) (N - M), with Example 8's
-- asymmetric half-spline g. The shape is arbitrary, as the article says.
-- 1001 samples per piece, as QBasic (qb = true).

screen(12)
local nodes = {P(100, 300), P(200, 150), P(300, 50), P(400, 100)}
for _, N in ipairs(nodes) do circle(N, 5) end

local S = stroke{nodes = nodes,
  uin  = {0, .3, .85, 0},          -- incoming tangent angles, turns
  kink = 0,                        -- kink angles, turns
  rin  = {50, 60, 40, 50},         -- incoming side lengths
  rout = {70, 30, 80, 40},         -- outgoing side lengths
  n    = {2, 4, 6, 2},             -- degree of the first half-spline
  m    = {7, 5, 3, 2},             -- degree of the second half-spline
  t0   = {.3, .5, .7, .2}}         -- junction point of the half-splines
S:draw{t = {0, 1, .001}, qb = true}
